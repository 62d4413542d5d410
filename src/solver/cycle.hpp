#pragma once
// Internal to the solver: the named phases of one cycle of the time loop (docs/theory/time-loop.md, "One cycle").
// Each is a plain function over the model and the state; time_loop.cpp calls them in order.
#include <array>
#include <atomic>
#include <limits>
#include <vector>

#include "crumple/core/exact_sum.hpp"
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

// /DAMP (damping.cpp, docs/theory/damping.md): the factor the active mass damping takes off the scaled step dt
// (eq. D-3); the damping forces of the step added to the nodal forces (eq. D-2), before the velocity update; their
// work on the step's velocities into the external work (eq. D-4).
double damping_step_factor(const Model& model, const SolverState& state, double dt);
void apply_damping(const Model& model, SolverState& state, double dt_average);
// Stiffness damping (a beta > 0): sizes its node arrays (setup, and when an engine deck sets a beta); after the
// elements' forces, each damped node's -beta times their rate over the last step (eq. D-5).
void setup_damping(const Model& model, SolverState& state);
void stiffness_damping_forces(const Model& model, SolverState& state);
void add_damping_work(const Model& model, const SolverState& state, const VelocityScratch& scratch, double dt_average,
                      ExactSum& work);

// The phases' exchanges between domains are in solver/domain_sharing.hpp, step 7's monitor in solver/monitor.hpp.

// 1. Element internal forces at x^n and the element critical steps; per-type step control (/DT/<type>): elements
// below their minimum are deleted, switched to small strain, or stop the run. Returns the scaled bound; sets
// `elements_deleted` when an element failed or was deleted this cycle.
StepBound compute_element_forces(const Model& model, SolverState& state, RunEvents& events, bool& elements_deleted,
                                  Exchange* exchange);
// Its two halves: every group's kernel (SolverState::group_results, the nodal sums), then the groups' results in
// model order: stops, the per-type step control and the bound. A group's step control touches only its own
// elements, so the halves give what one pass group by group gives. With `exchange` (several domains) the first half
// also starts the records' halo (Exchange::halo_start) once it has computed the last group with a sent element;
// share_element_results (domain_sharing.hpp) completes it.
void run_element_kernels(const Model& model, SolverState& state, Exchange* exchange = nullptr);
StepBound combine_group_results(const Model& model, SolverState& state, RunEvents& events, bool& elements_deleted);

// 1b. Contact at x^n with v^(n-1/2), when the model has interfaces: the interface step joins `bound`.
void compute_contact_forces(const Model& model, SolverState& state, RunEvents& events, bool elements_deleted,
                            StepBound& bound);

// 2. External forces at t^n; rigid bodies gather their nodes' forces.
void apply_loads(const Model& model, SolverState& state);

// 3. dt^(n+1/2): the elements' and contact's bound, or the nodal step with mass scaling; never cut to land on the
// end time (T-0), 0 at or past it. Records a stop in `events` when the step is below the minimum or nothing bounds it.
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
