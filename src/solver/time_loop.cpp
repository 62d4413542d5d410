// The explicit time loop (docs/theory/time-loop.md): one cycle is the named phases of solver/cycle.hpp, in order.
#include <chrono>

#include "crumple/solver/sections.hpp"
#include "crumple/solver/snapshot.hpp"
#include "crumple/solver/solver.hpp"
#include "solver/cycle.hpp"
#include "solver/domain_sharing.hpp"
#include "solver/monitor.hpp"
#include "solver/internal.hpp"

namespace crumple {
namespace {

// Wall time per phase (the listing's TIME PROFILE): one clock read per phase boundary.
class PhaseClock {
 public:
  void lap(double& bucket) {
    const auto now = std::chrono::steady_clock::now();
    bucket += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// /RFILE Ncycle: a snapshot every Ncycle cycles of the engine deck (and one at its end, below).
bool restart_due(const Model& m, const SolverState& s) {
  return m.run.restart_every > 0 && s.cycle > 0 && s.cycle % m.run.restart_every == 0;
}

// The snapshot at the end of a cycle, with the monitor's marks (solver/snapshot.hpp).
void write_snapshot(RunObserver& observer, SolverState& s, const SolverOptions& options, const RunEvents& events,
                    const solver::OutputSchedule& schedule) {
  ResumeMarks marks;
  marks.engine_deck = options.engine_deck;
  marks.next_frame = schedule.next_frame, marks.next_history = schedule.next_history;
  marks.last_frame_cycle = schedule.last_frame_cycle;
  marks.deleted_below_minimum_step = events.deleted_below_minimum_step;
  marks.switched_to_small_strain = events.switched_to_small_strain;
  marks.deleted_inverted = events.deleted_inverted;
  marks.hourglass_warned = events.hourglass_warned;
  marks.energy_error_warned = events.energy_error_warned;
  marks.step_drop_warned = events.step_drop_warned;
  observer.restart(s, marks);
}

// A resumed run's monitor carries on from the snapshot's marks: the same output times, no warning twice.
void resume_monitor(const ResumeMarks& marks, RunEvents& events, solver::OutputSchedule& schedule) {
  schedule.next_frame = marks.next_frame, schedule.next_history = marks.next_history;
  schedule.last_frame_cycle = marks.last_frame_cycle;
  events.deleted_below_minimum_step = marks.deleted_below_minimum_step;
  events.switched_to_small_strain = marks.switched_to_small_strain;
  events.deleted_inverted = marks.deleted_inverted;
  events.hourglass_warned = marks.hourglass_warned;
  events.energy_error_warned = marks.energy_error_warned;
  events.step_drop_warned = marks.step_drop_warned;
}

// The state an engine deck starts from, when a frame is due at its time (t = 0 for the first): written before the
// first cycle, so that the frames are on the /ANIM/DT grid from Tstart on.
void write_first_frame(const Model& m, const SolverState& s, RunObserver& observer, solver::OutputSchedule& schedule) {
  if (!solver::frame_due(s, schedule)) return;
  observer.frame(s);
  solver::MonitorDue written{};
  written.frame = true;
  solver::advance_schedule(m, s, written, schedule);
}

// A /TFILE row of the state, with the velocity change of the cycle that led to it (accelerations, reactions).
void write_history_row(SolverState& s, solver::VelocityScratch& scratch, double dt_average, double dt_next,
                       RunObserver& observer, const SolverOptions& options) {
  share_section_records(s, options.exchange);  // /TH/SECTIO, several domains: the sections' element loads
  VelocityChange change;
  for (std::size_t d = 0; d < 6; ++d) change.before[d] = &scratch.before[d], change.free[d] = &scratch.free[d];
  change.dt = dt_average;
  observer.history(s, dt_next, change);
  if (options.on_history_row) options.on_history_row(s);
}

// E-3, E-3b (docs/theory/energy.md): the reference's row at t^n from a state whose forces were computed at x^n and
// whose velocities were just integrated: the elements' energies at x^n, the kinetic energy of v^n between the half
// steps around t^n (`scratch.before` and `bodies_before` the one before), v^n = v^(n-1/2) + w (v^(n+1/2) - v^(n-1/2))
// with w the weight of the last half step in dt^n (1/2 at a constant step; the share of the step before at a changing
// one; 0 in a run's first cycle), and the work and contact energy to t^n likewise from `before`. Leaves the state's
// velocities at t^n.
EnergyBalanceState energies_at_cycle_time(const Model& m, SolverState& s, const solver::VelocityScratch& scratch,
                                          const std::vector<RigidBodyState>& bodies_before,
                                          const EnergyBalanceState& before, double dt_average) {
  const double w = s.cycle + s.cycles_done == 0 ? 0.0 : 0.5 * s.dt / dt_average;
  auto at_cycle = [w](double before_value, double after) { return before_value + w * (after - before_value); };
  NodalState& n = s.nodes;
  const std::array<std::vector<double>*, 6> v{&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  for (std::size_t d = 0; d < 6; ++d)
    for (std::size_t k = 0; k < n.size(); ++k) (*v[d])[k] = at_cycle(scratch.before[d][k], (*v[d])[k]);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (std::size_t i = 0; i < 3; ++i) {
      s.bodies[b].velocity[i] = at_cycle(bodies_before[b].velocity[i], s.bodies[b].velocity[i]);
      s.bodies[b].omega[i] = at_cycle(bodies_before[b].omega[i], s.bodies[b].omega[i]);
    }
  const EnergyBalanceState loop = s.energy;
  solver::update_energies(m, s);
  EnergyBalanceState row = s.energy;
  row.external_work = at_cycle(before.external_work, loop.external_work);
  row.contact = at_cycle(before.contact, loop.contact);
  return row;
}

// E-3: the energies of the state the run ends at, as the reference's last row gives them: the next cycle is taken on
// a copy of the state, so that a restart and the next engine deck go on from the loop's state, and its energies at
// t^N read as E-3b's; false when a phase of that cycle stops.
bool end_state_energies(const Model& m, const SolverState& s, Exchange* exchange, bool selective,
                        EnergyBalanceState& end) {
  using namespace solver;
  SolverState next = s;
  RunEvents quiet;
  bool deleted = false;
  StepBound bound = compute_element_forces(m, next, quiet, deleted, exchange);
  stiffness_damping_forces(m, next);
  if (!next.contact.interfaces.empty()) compute_contact_forces(m, next, quiet, deleted, bound);
  apply_loads(m, next);
  choose_time_step(m, next, quiet, bound);
  const double dt_next = bound.dt;  // the step past the end time the loop would take
  if (quiet.stop.stopped() || !(dt_next > 0.0) || !(dt_next < 1e300)) return false;
  const double dt_average = next.cycle + next.cycles_done == 0 ? 0.5 * dt_next : 0.5 * (next.dt + dt_next);
  apply_damping(m, next, dt_average);
  if (selective) solve_accelerations(m, next, quiet, dt_average, dt_next);
  if (quiet.stop.stopped()) return false;
  VelocityScratch scratch(next.nodes.size());
  const std::vector<RigidBodyState> bodies_before = next.bodies;
  integrate(next, scratch, dt_average, selective);
  apply_constraints(m, next, scratch, dt_average, dt_next);
  end = energies_at_cycle_time(m, next, scratch, bodies_before, s.energy, dt_average);
  return true;
}

// E-3b: a printed row of cycle n, taken in the cycle that computes the forces at x^n once its velocities are
// integrated; the loop's state is left as it was.
EnergyBalanceState energies_at_cycle(const Model& m, SolverState& s, const solver::VelocityScratch& scratch,
                                     const std::vector<RigidBodyState>& bodies_before,
                                     const EnergyBalanceState& before, double dt_average) {
  NodalState& n = s.nodes;
  const std::array<std::vector<double>*, 6> v{&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  std::array<std::vector<double>, 6> integrated;
  for (std::size_t d = 0; d < 6; ++d) integrated[d] = *v[d];
  std::vector<RigidBodyState> bodies_integrated = s.bodies;
  const EnergyBalanceState loop = s.energy;
  const EnergyBalanceState row = energies_at_cycle_time(m, s, scratch, bodies_before, before, dt_average);
  s.energy = loop;
  for (std::size_t d = 0; d < 6; ++d) *v[d] = std::move(integrated[d]);
  s.bodies = std::move(bodies_integrated);
  return row;
}

}  // namespace

RunSummary run_engine_deck(const Model& m, const SolverOptions& options, RunObserver& observer, SolverState& s,
                           const std::vector<std::string>& notes) {
  using namespace solver;
  const auto started = std::chrono::steady_clock::now();
  s.reducer = Reducer(options.exchange);
  if (options.resume == nullptr) switch_rigid_bodies(m, s);  // a resumed state has them switched already
  if (options.resume == nullptr) start_velocity_links(m, s);  // the links act on the velocities the deck starts with
  for (const DampingChange& change : m.run.damping_changes) {  // engine /DAMP: from this deck on
    s.damping.alpha[static_cast<std::size_t>(change.damping)] = change.alpha;
    s.damping.beta[static_cast<std::size_t>(change.damping)] = change.beta;
  }
  setup_damping(m, s);
  const bool selective = selective_mass_on(m);
  if (!selective) s.selective_mass = SelectiveMassState{}, s.contact.selective_mass_added = nullptr;  // after one with it
  s.contact.interface_nodal_step = interface_nodal_step_on(m);  // each engine deck: its /DT cards decide
  update_energies(m, s);  // for the listing's row of cycle 0
  observer.start(s, notes);
  RunEvents events;
  OutputSchedule schedule(m.run, s.time, options.max_cycles);
  const ElementStateNeed history_need = history_needs(m);  // several domains: what a history row gathers
  const bool history_nodes = histories_read_nodes(m);
  if (options.resume != nullptr) resume_monitor(*options.resume, events, schedule);
  keep_requested_results(m.run, s);
  if (options.resume == nullptr) write_first_frame(m, s, observer, schedule);
  VelocityScratch scratch(s.nodes.size());
  if (!m.skews.empty()) update_skew_axes(m, s);  // a resumed run's positions
  PhaseTimes phases;
  const double sort_seconds_before = s.contact.sort_seconds;  // this engine deck's searches only
  long long sorts_before = 0;
  for (const ContactInterface& in : s.contact.interfaces) sorts_before += in.sorts;
  PhaseClock clock;
  double dt_next = 0.0;
  StepControl control;
  auto keep = [&control](const StepBound& bound) {
    if (bound.control.source != StepControl::Source::None) control = bound.control;
  };
  bool ended_on_a_cycle = false;  // the loop's last cycle completed: positions, time and outputs advanced
  const bool body_sensors = rigid_bodies_have_sensors(m);
  const StepBound carried = body_sensors ? sensor_bodies_step(m, step_scale(m.run)) : StepBound{};
  // SP-25: the joints' stiffness at this engine deck's first step; a resumed run keeps the one its snapshot holds,
  // so that it ends where the run it resumes would have.
  bool joints_unresolved = options.resume == nullptr && has_joints(m);
  // E-3b: the listing's row of a cycle is printed in that cycle (not at the start's, which observer.start printed).
  const long long start_cycle = s.cycle;
  double row_dt = s.dt;  // the step that led to the row's time, and what set it
  StepControl row_control;
  EnergyBalanceState energy_before;  // at the start of a cycle whose row is printed
  std::vector<RigidBodyState> bodies_before;
  long long last_history_cycle = -1;  // the cycle of the last history row, and the mean step of the last cycle
  double last_dt_average = 0.0;
  // Resumed from the snapshot of its own end: no cycle past it (T-0), nothing written twice.
  const bool nothing_left = options.resume != nullptr && resumed_at_the_end(m, s, schedule);
  while (!nothing_left) {
    const bool row_now = s.cycle != start_cycle && s.cycle % schedule.print_every == 0;
    if (row_now) energy_before = s.energy, bodies_before = s.bodies;
    if (body_sensors) switch_rigid_bodies_by_sensors(m, s);
    bool elements_deleted = false;
    StepBound bound = compute_element_forces(m, s, events, elements_deleted, options.exchange);
    stiffness_damping_forces(m, s);
    if (carried.dt < bound.dt) bound.dt = carried.dt, bound.control = carried.control;  // RB-6
    const double element_step = bound.dt;
    keep(bound);
    clock.lap(phases.elements);
    if (events.stop.stopped()) break;
    if (!s.contact.interfaces.empty()) {
      compute_contact_forces(m, s, events, elements_deleted, bound);
      keep(bound);
      ++phases.contact_passes;
      clock.lap(phases.contact);
    }
    apply_loads(m, s);
    dt_next = choose_time_step(m, s, events, bound);
    keep(bound);
    if (joints_unresolved && !events.stop.stopped()) resolve_joints(m, s, dt_next), joints_unresolved = false;
    warn_step_drop(s, element_step, dt_next, control, events);
    if (events.stop.stopped()) break;
    clock.lap(phases.loads);

    // dt^n (CD-2); the very first cycle of a run is a half step from the initial velocities.
    const double dt_average = s.cycle + s.cycles_done == 0 ? 0.5 * dt_next : 0.5 * (s.dt + dt_next);
    apply_damping(m, s, dt_average);
    if (selective) {
      solve_accelerations(m, s, events, dt_average, dt_next);
      if (events.stop.stopped()) break;
    }
    integrate(s, scratch, dt_average, selective);
    apply_constraints(m, s, scratch, dt_average, dt_next);
    record_step_outputs(m, s, scratch, dt_average, dt_next);
    if (row_now) {
      const EnergyBalanceState loop_energy = s.energy;
      s.energy = energies_at_cycle(m, s, scratch, bodies_before, energy_before, dt_average);
      observer.row(s, row_dt, row_control);
      s.energy = loop_energy;
    }
    row_dt = dt_next, row_control = control;
    advance_positions(s, dt_next);
    if (!m.skews.empty()) update_skew_axes(m, s);  // SK-3: the loads, conditions and histories of the new positions
    clock.lap(phases.update);

    const MonitorDue due = outputs_due(m, s, schedule, dt_next);
    const bool show_progress = observer.progress_due();
    // The kinetic energy is a sum over the domains: every domain takes it at the same cycles, so a run of several
    // shows the progress line with the last one taken.
    if (due.energies() || (show_progress && !s.domain.several())) update_energies(m, s);
    if (due.energies()) {
      // A printed row: in the next cycle (E-3b); the last row after the loop (E-3).
      check_run_limits(m, s, events);
      if (!events.pending.empty()) observer.events(events);
      if (events.stop.stopped()) break;
    }
    const bool restart_now = restart_due(m, s) && !due.finished;
    if (s.domain.several() && (due.frame || due.history || restart_now)) {
      share_element_state(s, *options.exchange, due.frame || restart_now ? ElementStateNeed::All : history_need);
      if (due.frame || restart_now || history_nodes) share_node_state(m, s, *options.exchange, restart_now);
    }
    if (due.frame) observer.frame(s);
    if (due.history) {
      write_history_row(s, scratch, dt_average, dt_next, observer, options);
      last_history_cycle = s.cycle;
    }
    last_dt_average = dt_average;
    advance_schedule(m, s, due, schedule);
    if (restart_now) write_snapshot(observer, s, options, events, schedule);
    if (show_progress) observer.progress(s, dt_next, control);
    clock.lap(phases.output);
    if (due.finished || stop_requested(options.stop_request, s, events, options.exchange, due.energies())) {
      ended_on_a_cycle = true;
      break;
    }
    if (rebalance_due(s)) rebalance(m, s, *options.exchange, events, options.repartition);
  }
  update_energies(m, s);
  if (s.domain.several()) share_element_state(s, *options.exchange), share_node_state(m, s, *options.exchange, true);
  observer.events(events);
  // A snapshot at the end with /RFILE, and always when the run was asked to stop (it can go on from there); never
  // after a failure (NaN, inverted element), whose state is not worth resuming.
  const bool resumable = !events.stop.stopped() || events.stop.requested() || events.stop.is_limit();
  // The histories end on the state the run ends at (T-0), also off the /TFILE grid: a row as every other.
  if (ended_on_a_cycle && std::isfinite(schedule.next_history) && last_history_cycle != s.cycle)
    write_history_row(s, scratch, last_dt_average, dt_next, observer, options);
  // The last row and the summary show the end state's energies (E-3); the loop's go on into a restart and the next
  // engine deck.
  const EnergyBalanceState loop_energy = s.energy;
  EnergyBalanceState end;
  const bool end_state =
      (ended_on_a_cycle || nothing_left) && resumable && end_state_energies(m, s, options.exchange, selective, end);
  if (end_state) s.energy = end;
  observer.row(s, dt_next, control);  // the cycle the run ended at
  s.energy = loop_energy;
  if (resumable && (m.run.restart_every > 0 || events.stop.requested()))
    write_snapshot(observer, s, options, events, schedule);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  phases.contact_sort = s.contact.sort_seconds - sort_seconds_before;
  phases.contact_sorts = -sorts_before;
  for (const ContactInterface& in : s.contact.interfaces) phases.contact_sorts += in.sorts;
  if (end_state) s.energy = end;
  RunSummary summary = observer.finish(s, events, phases, dt_next, wall);
  s.energy = loop_energy;
  return summary;
}

SolverState initial_state(const Model& m, std::vector<std::string>& notes) {
  return solver::make_state(m, notes, single_domain(m));
}

SolverState initial_state(const Model& m, std::vector<std::string>& notes, Domain domain) {
  return solver::make_state(m, notes, std::move(domain));
}

void continue_from(SolverState& s) {
  s.cycles_done += s.cycle;
  s.cycle = 0;
  EnergyBalanceState& e = s.energy;
  e.initial_kinetic = e.internal + e.kinetic_translational + e.kinetic_rotational + e.hourglass + e.contact;
  e.external_work_at_start = e.external_work;
}

}  // namespace crumple
