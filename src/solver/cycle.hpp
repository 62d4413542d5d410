#pragma once
// Internal to the solver: the named phases of one cycle of the time loop (docs/theory/time-loop.md, "One cycle").
// Each is a plain function over the model and the state; time_loop.cpp calls them in order.
#include <array>
#include <atomic>
#include <limits>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/parallel/exchange.hpp"
#include "crumple/parallel/partition.hpp"
#include "crumple/solver/run_events.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple::solver {

// The smallest step found so far in the cycle, already scaled, and what sets it.
struct StepBound {
  double dt = std::numeric_limits<double>::infinity();
  StepControl control;
  // The contact's own bound, kept apart: the nodal step of /DT/NODA/CST replaces the elements' bound, never the
  // contact's (docs/theory/time-step.md, T-3b).
  double contact_dt = std::numeric_limits<double>::infinity();
  StepControl contact_control{};
  // The deck as written's step, elements' and contacts', where --accuracy draft takes the larger of it and the
  // nodal step (T-3c).
  double as_written_dt = std::numeric_limits<double>::infinity();
  StepControl as_written_control{};
};

// Velocities before the update and after the free update (CD-2), for the work of the kinematic conditions.
struct VelocityScratch {
  std::array<std::vector<double>, 6> before, free;  // x y z rx ry rz
  explicit VelocityScratch(std::size_t nodes) {
    for (auto& v : before) v.assign(nodes, 0.0);
    for (auto& v : free) v.assign(nodes, 0.0);
  }
};

// The /DT scale (default 0.9).
double step_scale(const RunControl& run);

// 1. Element internal forces at x^n and the element critical steps; per-type step control (/DT/<type>): elements
// below their minimum are deleted, switched to small strain, or stop the run. Returns the scaled bound; sets
// `elements_deleted` when an element failed or was deleted this cycle.
StepBound compute_element_forces(const Model& model, SolverState& state, RunEvents& events, bool& elements_deleted,
                                  Exchange* exchange);
// Its two halves: every group's kernel (SolverState::group_results, the nodal sums), then the groups' results in
// model order: stops, the per-type step control and the bound. A group's step control touches only its own
// elements, so the halves give what one pass group by group gives. With `exchange` (several domains) the first half
// also starts the records' halo (Exchange::halo_start) once it has computed the last group with a sent element;
// share_element_results completes it.
void run_element_kernels(const Model& model, SolverState& state, Exchange* exchange = nullptr);
// Between them in a run of several domains (docs/parallel.md, "Assembly"): what each domain computed of its own
// elements reaches every domain, and every node's sum is assembled in the model's order.
void share_element_results(const Model& model, SolverState& state, Exchange& exchange);
// Before an output of a run of several domains: every element's whole state from the domain that computes it, so
// that the domain that writes (0) writes what one domain writes.
enum class ElementStateNeed : std::uint8_t { None, Energies, All };
void share_element_state(SolverState& state, Exchange& exchange, ElementStateNeed need = ElementStateNeed::All);
// Before an output of a run of several domains: every node's state (and the output-only integrals of the nodes)
// from the domain that owns it; between outputs a domain keeps only its local nodes right (parallel/domain.hpp).
// `restart`: before a restart snapshot, with the contact state of the pairs each domain computes.
void share_node_state(const Model& model, SolverState& state, Exchange& exchange, bool restart);
// What the model's time histories read of the elements: their whole state (shells, bricks, sections), their
// energies (parts, subsets) or nothing.
ElementStateNeed history_needs(const Model& model);
// Whether a history row reads nodal state (/TH/NODE, PART, SUBS, SECTIO, ACCEL); the others (rigid walls and
// bodies, interfaces, the energies) read what every domain holds alike.
bool histories_read_nodes(const Model& model);
StepBound combine_group_results(const Model& model, SolverState& state, RunEvents& events, bool& elements_deleted);

// 1b. Contact at x^n with v^(n-1/2), when the model has interfaces: the interface step joins `bound`.
void compute_contact_forces(const Model& model, SolverState& state, RunEvents& events, bool elements_deleted,
                            StepBound& bound);

// 2. External forces at t^n; rigid bodies gather their nodes' forces.
void apply_loads(const Model& model, SolverState& state);

// 3. dt^(n+1/2): the elements' and contact's bound, or the nodal step with mass scaling; cut to land on the end
// time. Records a stop in `events` when the step is below the minimum or nothing bounds it.
double choose_time_step(const Model& model, SolverState& state, RunEvents& events, StepBound& bound);

// 3b. Selective mass scaling (/DT/AMS): the elements' added mass from their steps and the accelerations of
// (M + dM) a^n = F^n (docs/theory/time-step.md, SM-1 to SM-5). A solve that does not converge stops the run.
void solve_accelerations(const Model& model, SolverState& state, RunEvents& events, double dt_average,
                         double dt_next);

// 4. Free central-difference velocity update v^(n+1/2) = v^(n-1/2) + dt^n a^n (CD-2); with `selective`, the
// translational accelerations of 3b and the scaled rotational inertia (SM-3a).
void integrate(SolverState& state, VelocityScratch& scratch, double dt_average, bool selective);

// 5. Kinematic conditions on v^(n+1/2) (rigid bodies, fixed and imposed dofs, rigid walls), and the work of the
// loads, the kinematic conditions and the contact forces over the step.
void apply_constraints(const Model& model, SolverState& state, VelocityScratch& scratch, double dt_average,
                       double dt_next);

// 6. Positions x^(n+1) = x^n + dt^(n+1/2) v^(n+1/2) (CD-3), time and cycle.
void advance_positions(SolverState& state, double dt_next);

// The nodal results the engine deck's /ANIM cards ask for that the cycle keeps only then (SolverState::recorded):
// sized (zero) when asked for, emptied when not.
void keep_requested_results(const RunControl& run, SolverState& state);

// 7. Monitor: which outputs are due after a cycle, the energies they need, and the /STOP limits.
struct OutputSchedule {
  double next_frame, next_history;  // /ANIM/DT and /TFILE times [T] (infinite: none)
  long long print_every;            // listing row every |/PRINT| cycles (default 100)
  long long max_cycles;             // stop after this many cycles (-1: no limit)
  // The first outputs of a run that starts at `time` (0, or where a continued run takes over).
  OutputSchedule(const RunControl& run, double time, long long max_cycles);
};
struct MonitorDue {
  bool finished, print, frame, history;
  bool energies() const;  // the kinetic energy and the stop limits are checked (also every 64 cycles)
  long long cycle;
};
MonitorDue outputs_due(const Model& model, const SolverState& state, const OutputSchedule& schedule, double dt_next);
// A field frame is due at the state's time (also before the first cycle: the frame at t = 0).
bool frame_due(const SolverState& state, const OutputSchedule& schedule);
// The balance's energies, when it is checked: kinetic energies of v^(n+1/2), and the internal and hourglass
// energies as exact sums of each element's running energy (docs/theory/energy.md), combined over the domains
// (every domain calls it at the same cycles).
void update_energies(const Model& model, SolverState& state);
// NaN in the balance, /STOP added-mass and energy-error limits: recorded in `events.stop`.
void check_run_limits(const Model& model, const SolverState& state, RunEvents& events);
// Once per run: the step `dt` fell below 1/1000 of the elements' scaled step `element_step` (set by `control`).
void warn_step_drop(const SolverState& state, double element_step, double dt, const StepControl& control,
                    RunEvents& events);
// A stop asked from outside the solver (SolverOptions::stop_request, which the app's SIGINT and SIGTERM handlers
// set): recorded in `events.stop` at the end of the cycle; true when there is one. One relaxed load per cycle.
bool stop_requested(const std::atomic<int>* request, SolverState& state, RunEvents& events,
                    Exchange* exchange, bool check_now);
// The next output times once a frame or a history row has been written at the state's time.
void advance_schedule(const Model& model, const SolverState& state, const MonitorDue& due, OutputSchedule& schedule);

// 8. Several domains (solver/rebalance.cpp, docs/parallel.md "Rebalancing"): every kRebalanceEvery cycles the
// estimated imbalance is checked, and above kRebalanceTolerance every domain takes its share of a new partition.
inline constexpr long long kRebalanceEvery = 100;
inline constexpr double kRebalanceTolerance = 0.05;
bool rebalance_due(const SolverState& state);
// `repartition` (tests): the new partition to take, whatever the imbalance; empty: METIS with the yielded elements
// weighed, when the imbalance is above the tolerance.
void rebalance(const Model& model, SolverState& state, Exchange& exchange, RunEvents& events,
               const Repartition& repartition);

}  // namespace crumple::solver
