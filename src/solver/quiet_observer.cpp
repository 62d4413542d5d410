// An observer that writes nothing (solver/quiet_observer.hpp).
#include "crumple/solver/quiet_observer.hpp"

namespace crumple {

RunSummary QuietObserver::finish(const SolverState& s, const RunEvents& events, const PhaseTimes& phases, double dt,
                                 double wall_seconds) {
  RunSummary summary;
  summary.cycles = s.cycle, summary.cycles_total = s.cycles_done + s.cycle;
  summary.time = s.time, summary.dt = dt;
  const EnergyBalanceState& e = s.energy;
  summary.energy = {e.internal, e.kinetic_translational, e.kinetic_rotational, e.contact, e.hourglass, e.external_work,
                    e.internal + e.kinetic_translational + e.kinetic_rotational + e.hourglass + e.contact,
                    e.error_percent()};
  summary.phases = phases, summary.wall_seconds = wall_seconds;
  summary.status = status_of(events.stop);
  return summary;
}

}  // namespace crumple
