// The outputs' side of a cycle (docs/theory/time-loop.md, "One cycle"): the integrals of the step, recorded after
// the kinematic conditions (record_step_outputs), and step 7, the monitor, after the positions are advanced.
#include "solver/monitor.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "crumple/solver/accelerometers.hpp"
#include "crumple/solver/node_rotations.hpp"
#include "crumple/solver/sections.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// a^n from the velocity change of the step, after the kinematic conditions (field frames, /ANIM/VECT/ACC).
void record_acceleration(SolverState& s, const VelocityScratch& scratch, double dt_average) {
  std::vector<double>& out = s.recorded.acceleration;
  if (out.empty() || !(dt_average > 0.0)) return;
  const NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(), [&](std::size_t k) {
    out[3 * k] = (n.vx[k] - scratch.before[0][k]) / dt_average;
    out[3 * k + 1] = (n.vy[k] - scratch.before[1][k]) / dt_average;
    out[3 * k + 2] = (n.vz[k] - scratch.before[2][k]) / dt_average;
  });
}

// Hourglass energy above 10 % of the internal energy is a mesh or formulation problem the user must see
// (docs/theory/energy.md): one event, the first time it happens once the energy counts (above 0.1 % of the
// balance's scale, so that the first cycles' round-off does not raise it).
void warn_hourglass_share(const SolverState& s, RunEvents& events) {
  const EnergyBalanceState& e = s.energy;
  const double scale = std::abs(e.initial_kinetic) + std::abs(e.external_work);
  if (events.hourglass_warned || !(e.hourglass > 0.1 * std::abs(e.internal)) || !(e.hourglass > 1e-3 * scale)) return;
  events.hourglass_warned = true;
  RunEvent event{RunEvent::Kind::HourglassShare, s.cycle, s.time};
  event.value = e.internal != 0.0 ? e.hourglass / std::abs(e.internal) : std::numeric_limits<double>::infinity();
  events.pending.push_back(event);
}

// An energy error beyond 10 % (5 % under a preset) means the balance is not kept: an instability growing, or a
// remedy (mass scaling, a contact released deep in its gap) adding or taking energy. A run must not end "normal"
// without saying so (docs/theory/energy.md): one event, the first time, unless /STOP Emax stops the run before.
void warn_energy_error(const RunControl& rc, const SolverState& s, RunEvents& events) {
  const double error = s.energy.error_percent();
  if (events.energy_error_warned || !(std::abs(error) > rc.energy_error_warning)) return;
  events.energy_error_warned = true;
  RunEvent event{RunEvent::Kind::EnergyErrorLarge, s.cycle, s.time};
  event.value = error, event.second_value = rc.energy_error_warning;
  events.pending.push_back(event);
}

}  // namespace

void record_step_outputs(const Model& m, SolverState& s, const VelocityScratch& scratch, double dt_average,
                         double dt_next) {
  record_acceleration(s, scratch, dt_average);
  // /ACCEL: only a deck with accelerometers has any (a loop over them, not over the nodes).
  update_accelerometers(m.accelerometers, s.nodes, {&scratch.before[0], &scratch.before[1], &scratch.before[2]},
                        dt_average, s.skew_axes, s.histories);
  // /TH/SECTIO WORK: only a deck that asks it (a loop over the sections' elements, not over the model).
  add_section_work(m, s, scratch.before, dt_average);
  // /TH/NODE DRX DRY DRZ: only the nodes a request asks them of (none: no loop).
  integrate_node_rotations(s.nodes, dt_next, s.histories);
}

// A continued run's outputs follow its own /ANIM/DT and /TFILE from where it starts (the one at its first time
// was written by the run before).
OutputSchedule::OutputSchedule(const RunControl& rc, double time, long long max)
    : next_frame(std::numeric_limits<double>::infinity()),
      next_history(std::numeric_limits<double>::infinity()),
      print_every(rc.print_every != 0 ? std::llabs(rc.print_every) : 100),
      max_cycles(max),
      last_frame_cycle(std::numeric_limits<long long>::min() / 2) {
  if (rc.anim_interval > 0.0)
    next_frame = time > rc.anim_start ? next_output_time(time, rc.anim_start, rc.anim_interval) : rc.anim_start;
  if (rc.history_interval > 0.0) next_history = time > 0.0 ? next_output_time(time, 0.0, rc.history_interval) : 0.0;
  if (rc.history_every_cycle()) next_history = 0.0;  // due at every cycle
}

void keep_requested_results(const RunControl& rc, SolverState& s) {
  const std::size_t values = 3 * s.nodes.size();
  RecordedNodalResults& r = s.recorded;
  r.acceleration.assign(rc.anim.acceleration ? values : 0, 0.0);
  r.internal_force.assign(rc.anim.internal_force ? values : 0, 0.0);
  r.external_force.assign(rc.anim.external_force ? values : 0, 0.0);
}

bool frame_due(const SolverState& s, const OutputSchedule& schedule) {
  return s.time >= schedule.next_frame;
}

bool MonitorDue::energies() const { return print || frame || history || cycle % 64 == 0; }

// T-0 (docs/theory/time-loop.md, "The end of a run"): the run's last state is the last one whose time does not
// pass the end time (no step is cut to land on it), unless frames are written and the last was 100 cycles or more
// before the next: then the next cycle, past the end time, is the last, and its frame is the run's end frame.
static bool run_ends_here(const RunControl& rc, const SolverState& s, const OutputSchedule& schedule,
                          bool frame_now, double dt_next) {
  if (s.time >= rc.end_time) return true;
  if (!(s.time + dt_next > rc.end_time)) return false;
  const long long next_cycle = s.cycles_done + s.cycle + 1;
  const long long last_frame = frame_now ? next_cycle - 1 : schedule.last_frame_cycle;
  return !(rc.anim_interval > 0.0 && next_cycle - last_frame >= kEndFrameCycles);
}

bool resumed_at_the_end(const Model& m, const SolverState& s, const OutputSchedule& schedule) {
  return run_ends_here(m.run, s, schedule, false, s.dt);
}

MonitorDue outputs_due(const Model& m, const SolverState& s, const OutputSchedule& schedule, double dt_next) {
  MonitorDue due{};
  due.cycle = s.cycle;
  due.frame = frame_due(s, schedule);
  due.finished = run_ends_here(m.run, s, schedule, due.frame, dt_next) || dt_next <= 0.0 ||
                 (schedule.max_cycles >= 0 && s.cycle >= schedule.max_cycles);
  due.print = s.cycle % schedule.print_every == 0 || due.finished;
  due.history = s.time >= schedule.next_history * (1.0 - 1e-12);
  return due;
}

void update_energies(const Model& m, SolverState& s) {
  const auto [translational, rotational] = kinetic_energy(s);
  // Under selective mass scaling the deformation modes' added mass moves too (eq. SM-6), as the reference lists it.
  s.energy.kinetic_translational = translational + selective_mass_kinetic_energy(m, s);
  s.energy.kinetic_rotational = rotational;
  const auto [internal, hourglass] = element_energies(s);
  s.energy.internal = internal;
  s.energy.hourglass = hourglass;
}

// A step far below what the elements allow (a contact closing fast on a small gap, a node's mass) slows the run
// by that factor without failing it: the user must see it once (docs/theory/time-step.md, "Step drops").
void warn_step_drop(const SolverState& s, double element_step, double dt, const StepControl& control, RunEvents& events) {
  if (events.step_drop_warned || !(dt < 1e-3 * element_step) || !(element_step < 1e300)) return;
  events.step_drop_warned = true;
  RunEvent event{RunEvent::Kind::StepDropped, s.cycle, s.time};
  event.value = dt, event.second_value = element_step, event.control = control;
  events.pending.push_back(event);
}

namespace {

// No element computed any more: every one deleted (an element in a rigid body is still there).
bool no_element_left(const SolverState& s) {
  for (ElementKind kind : kAllElementKinds)
    for (std::uint8_t e : element_state(s, kind).deleted)
      if (element_condition(e) != kElementDeleted) return false;
  return true;
}

// A run whose elements were all deleted by numerical causes (turned inside out, below their minimum step) has no
// answer to give, unlike one whose elements failed by their material's failure model (which runs on, as the
// reference does): it stops, abnormally. Looked for when such deletions have happened since the last look.
bool every_element_lost(const SolverState& s, RunEvents& events) {
  const long long numerical = events.deleted_inverted + events.deleted_below_minimum_step;
  if (numerical == events.numerical_deletions_checked) return false;
  events.numerical_deletions_checked = numerical;
  return no_element_left(s);
}

}  // namespace

void check_run_limits(const Model& m, const SolverState& s, RunEvents& events) {
  const RunControl& rc = m.run;
  warn_hourglass_share(s, events);
  warn_energy_error(rc, s, events);
  StopReason& stop = events.stop;
  const double total = s.energy.internal + s.energy.kinetic_translational + s.energy.kinetic_rotational;
  if (every_element_lost(s, events)) {
    stop.kind = StopReason::Kind::EveryElementLost, stop.cycle = s.cycle, stop.time = s.time;
    stop.index = static_cast<std::int32_t>(events.deleted_inverted);
    stop.value = static_cast<double>(events.deleted_below_minimum_step);
  } else if (!std::isfinite(total)) {
    stop.kind = StopReason::Kind::EnergyNotFinite, stop.cycle = s.cycle, stop.time = s.time;
  } else if (const double error = s.energy.error_percent(); std::abs(error) > kDivergedEnergyErrorPercent) {
    stop.kind = StopReason::Kind::Diverged, stop.cycle = s.cycle, stop.time = s.time, stop.value = error;
  } else if (rc.stop_mass_error > 0.0 && s.mass_added > rc.stop_mass_error * s.mass_initial) {
    stop.kind = StopReason::Kind::AddedMassLimit, stop.cycle = s.cycle, stop.time = s.time;
    stop.value = s.mass_added, stop.minimum = rc.stop_mass_error;
  } else if (const double ratio = std::abs(s.energy.error_percent()) / 100.0;
             rc.stop_energy_error > 0.0 && ratio > rc.stop_energy_error) {
    stop.kind = StopReason::Kind::EnergyErrorLimit, stop.cycle = s.cycle, stop.time = s.time;
    stop.value = ratio;
  }
}

bool stop_requested(const std::atomic<int>* request, SolverState& s, RunEvents& events, Exchange* exchange,
                    bool check_now) {
  int signal = request != nullptr ? request->load(std::memory_order_relaxed) : 0;
  if (s.domain.several()) {
    // Every domain stops at the same cycle: the requests are combined every 64 cycles (the energy checks' rhythm).
    if (!check_now) return false;
    std::vector<std::int32_t>& any = s.domain_scratch.group_share.stop_signal;
    any.assign(1, signal);
    exchange->max(any);
    signal = any[0];
  }
  if (signal == 0) return false;
  StopReason& stop = events.stop;
  stop.kind = StopReason::Kind::Requested, stop.cycle = s.cycle, stop.time = s.time, stop.index = signal;
  return true;
}

void advance_schedule(const Model& m, const SolverState& s, const MonitorDue& due, OutputSchedule& schedule) {
  const RunControl& rc = m.run;
  if (due.frame) schedule.next_frame = next_output_time(s.time, rc.anim_start, rc.anim_interval);
  if (due.frame) schedule.last_frame_cycle = s.cycles_done + s.cycle;
  if (due.history && !rc.history_every_cycle())
    schedule.next_history = next_output_time(s.time, 0.0, rc.history_interval);
}

}  // namespace crumple::solver
