#pragma once
// Internal to the solver: the steps of one cycle, each a plain function over the solver state.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/solver/solver_state.hpp"
#include "solver/cycle.hpp"

namespace crumple::solver {

// Value of a load's time function, scale_y * f(t / scale_x); a load without a function (funct_IDT blank, as /GRAV
// allows) is constant, scale_y.
inline double load_curve(const Model& m, std::int32_t function, double scale_x, double scale_y, double t) {
  return function < 0 ? scale_y : scale_y * m.functions[static_cast<std::size_t>(function)](t / scale_x);
}

// Calls f(node) for every node of a load's node group; a load without a group (grnod_ID blank, as /GRAV allows)
// acts on every node of the model.
template <class F>
void for_each_load_node(const Model& m, std::int32_t group, F f) {
  if (group < 0) {
    for (std::size_t k = 0; k < m.nodes.size(); ++k) f(static_cast<std::int32_t>(k));
    return;
  }
  for (std::int32_t node : m.node_groups[static_cast<std::size_t>(group)].nodes) f(node);
}

// Start state of a run; `notes` receives start-up remarks for the listing and the console.
SolverState make_state(const Model& model, std::vector<std::string>& notes, Domain domain);
// A run of several domains that repartitions (docs/parallel.md, "Rebalancing"): the state, whose every element and
// node is up to date in every domain, takes `domain`, and everything made of the old one is made again.
void rebind_domain(const Model& model, SolverState& state, Domain domain);
void setup_rigid_bodies(const Model& model, SolverState& state);
// The skews' axes at the current positions (SK-3): at the start and after every position update.
void update_skew_axes(const Model& model, SolverState& state);
// Brick groups' parameters and state (setup_bricks.cpp, docs/theory/brick8.md).
void setup_bricks(const Model& model, SolverState& state);
// Spring groups' parameters and state (setup_springs.cpp, docs/theory/spring.md).
void setup_springs(const Model& model, SolverState& state);
// Beam groups' parameters and state, and their nodes' rotational inertia (setup_beams.cpp, docs/theory/beam.md).
void setup_beams(const Model& model, SolverState& state);
// Truss groups' parameters and state (setup_trusses.cpp, docs/theory/truss.md).
void setup_trusses(const Model& model, SolverState& state);
// The springs' steps again from the masses SpringState::node_held holds (after a tie changed a node's, TI-12).
void refresh_spring_steps(const Model& model, SolverState& state);
// /PROP/TYPE45: each joint's blocking stiffness, damping and step from the bodies it joins at the engine deck's first
// step `dt` (docs/theory/spring.md, SP-25).
void resolve_joints(const Model& model, SolverState& state, double dt);
bool has_joints(const Model& model);
void setup_rigid_walls(const Model& model, SolverState& state);

// Nodal time step of the cycle with mass scaling (/DT/NODA/CST): adds mass where the nodal step (on the stiffness
// of nodal_interface_stiffness and the contacts') would fall below the card's minimum and returns the smallest
// scaled nodal step and its node, reduced over the domains (docs/theory/time-step.md, T-2, T-3).
struct NodalStep {
  double dt;
  std::int32_t node;
};
NodalStep nodal_time_step(const Model& model, SolverState& state);
// The reference's nodal step of a deck with a TYPE7 interface or an /RBE3 (docs/theory/time-step.md, eq. T-4): on when the
// deck has one and neither /DT/NODA/CST nor /DT/INTER/CST; each element's stiffness (this domain's), their sums
// per node (every node, after the exchange), and the step over this domain's nodes with the contact's, reduced.
bool interface_nodal_step_on(const Model& model);
// Whether the cycle computes the nodes' stiffness: for T-4 or for /DT/NODA/CST (T-2).
bool nodal_stiffness_on(const Model& model);
void element_interface_stiffness(const Model& model, SolverState& state);
void nodal_interface_stiffness(const Model& model, SolverState& state);
NodalStep interface_nodal_step(const Model& model, SolverState& state);

// Selective (advanced) mass scaling, /AMS with /DT/AMS (docs/theory/time-step.md, SM-1 to SM-6): whether the run
// has it; the step an element of critical step dt_e allows under it, max(s dt_e, dt_min) (eq. SM-0); each cycle,
// the elements' added mass from their steps (SM-1, SM-3) and the accelerations of (M + dM) a = F (SM-5); the
// factor on a node's rotational inertia (SM-3a); the kinetic energy of dM, 1/2 v . dM v (SM-6).
bool selective_mass_on(const Model& model);
double selective_mass_step(const Model& model, double critical_dt);
void size_selective_mass(const Model& model, SolverState& state);  // at the start (a restart reads into it)
void scale_selective_mass(const Model& model, SolverState& state);
struct SelectiveSolve {
  long long iterations = 0;
  bool converged = true;
  double residual = 0.0;  // the last residual's D^-1 norm over the right-hand side's
};
SelectiveSolve solve_selective_mass(const Model& model, SolverState& state, double dt_average, double dt_next);
double selective_inertia_factor(const SolverState& state, std::size_t node);
double selective_inertia_factor_before(const SolverState& state, std::size_t node);  // the cycle before's
double selective_mass_kinetic_energy(const Model& model, SolverState& state);

// The first output time start + k interval (k >= 0 whole) after t, with the loop's relative tolerance 1e-12 on
// times, in O(1) whatever the ratio of the interval to the step (/ANIM/DT, /TFILE).
double next_output_time(double t, double start, double interval);

// Translational and rotational kinetic energy of the current half-step velocities: exact sums over the owned nodes,
// combined over the domains (every domain calls it at the same cycles); with `whole_model`, over every node of this
// domain's arrays and without the exchange (the start, where every domain holds every node).
std::pair<double, double> kinetic_energy(SolverState& state, bool whole_model = false);
// Internal and hourglass energy: exact sums of every element's running energy (its own increments, summed by its
// kernel), over this domain's elements, combined over the domains. The order of the elements and the partition
// change nothing (docs/theory/energy.md).
std::pair<double, double> element_energies(SolverState& state);

// Adds /CLOAD and /GRAV forces at time t; returns nothing (their work is counted with the velocity update).
void add_external_forces(const Model& model, SolverState& state, double time);
// The same forces into state.recorded.external_force (3 per node, moments left out), for the field frames.
void record_external_forces(const Model& model, SolverState& state, double time);
// The loads' work over the step on the owned nodes into `work`: each force on the mean of the velocities before
// (`before`: x y z rx ry rz) and after the update, times dt_average (energy.md).
void add_load_work(const Model& model, const SolverState& state, const std::array<std::vector<double>, 6>& before,
                   double time, double dt_average, ExactSum& work);

// Tied interfaces (/INTER/TYPE2, docs/theory/tied-interfaces.md): at the start, the ties and their nodes' mass
// lumped on the segments (TI-3, TI-7); each cycle after the loads, the tied nodes' forces passed to the segments (TI-4);
// after the velocity update and the other conditions, the tied nodes' velocities from the segments' (TI-5).
void setup_ties(const Model& model, SolverState& state);
void bind_ties_to_domain(SolverState& state);  // after a new partition: the owners of the tie nodes
void transfer_tied_forces(SolverState& state);
void tie_velocities(SolverState& state);
// TI-10: what Spotflag 2 and 4 take off and add to the translational kinetic energy, the same in every domain.
double tied_kinetic_correction(const SolverState& state);

// A rigid body's inertia tensor about its centre in global axes, R J R^T (row by row).
std::array<double, 9> body_inertia_global(const RigidBodyState& body);
// Moves the secondary nodes' forces and moments to their rigid body's centre (after the element forces).
void gather_rigid_body_forces(SolverState& state);
// Rigid bodies after the free velocity update: new momentum, rotation and the secondary nodes' velocities. Fixed
// and imposed dofs of a main node drive its body; returns the work of those conditions over the step.
double update_rigid_bodies(const Model& model, SolverState& state, double dt_average, double dt_next);
// The velocity v (x y z rx ry rz) of a main node as its fixed dofs (/BCS) and its /IMPVEL, /IMPDISP cards set it
// (RB-4, RE-4); true when any acts.
bool drive_main_node(const Model& model, const SolverState& state, std::int32_t main_node,
                     const std::vector<std::int32_t>& conditions, const std::vector<std::int32_t>& skewed_fixes,
                     std::array<double, 6>& v, double dt_next);
// The /IMPVEL, /IMPDISP cards (indices into Model::imposed) and the /BCS in a skew that hold `main_node`.
void find_main_node_conditions(const Model& model, std::int32_t main_node, std::vector<std::int32_t>& conditions,
                               std::vector<std::int32_t>& skewed_fixes);
// /RBE2 (docs/theory/rigid-bodies.md, RE-1 to RE-5). At the start: each group's mass and inertia, and the secondary
// nodes moving with their main node. Each cycle after the loads: the secondary nodes' forces and the moments they
// make about the main node gathered on it; after the velocity update: the main node's motion from them, the
// secondary nodes placed rigidly about it. Returns the work of the conditions that drive main nodes.
void setup_rigid_elements(const Model& model, SolverState& state);
void gather_rigid_element_forces(const Model& model, SolverState& state);
double update_rigid_elements(const Model& model, SolverState& state, const std::array<std::vector<double>, 6>& before,
                             double dt_average, double dt_next);
// /RBE3 (docs/theory/rigid-bodies.md, RI-1 to RI-6). At the start: the weights the solver uses (an /RBE3 whose
// independent nodes do not hold its dependent node is a DeckError) and the dependent node's motion. Each cycle after
// the loads: the dependent node's load spread over the independent nodes; after every other condition: the
// dependent node's motion from theirs (`whole_model`: every node's terms, at the start).
void setup_interpolation_constraints(const Model& model, SolverState& state);
void spread_interpolation_loads(const Model& model, SolverState& state);
void interpolate_dependent_motion(const Model& model, SolverState& state, bool whole_model = false);
// The translational velocity of node k.
inline Vec3 node_velocity(const NodalState& n, std::size_t k) { return {n.vx[k], n.vy[k], n.vz[k]}; }
// /VEL/TRA of the engine deck: each link's nodes take their mass-weighted mean velocity along its axes (L-8).
void link_velocities(const Model& model, SolverState& state);
// The same at the start of the engine deck; the energy balance starts from the linked velocities.
void start_velocity_links(const Model& model, SolverState& state);
// /RBODY/ON, /RBODY/OFF of the engine deck about to run: bodies switched off release their nodes, bodies switched
// on are formed again from the nodes' current positions and velocities (docs/theory/rigid-bodies.md).
void switch_rigid_bodies(const Model& model, SolverState& state);
// Bodies with a sensor: off while it is on, formed again when it turns off (docs/theory/rigid-bodies.md, RB-6).
bool rigid_bodies_have_sensors(const Model& model);
// The step of the elements a sensor body carries, on their initial shape (a rigid motion keeps it): they are not
// computed while the body is on, but are from the cycle it turns off, so their step bounds the run's all along.
// (The reference steps over a body-only stretch at once, measured; a step that then falls by orders of magnitude
// gives the first free cycle a velocity kick, so Crumple keeps the elements' step, RB-6.)
StepBound sensor_bodies_step(const Model& model, double scale);
void switch_rigid_bodies_by_sensors(const Model& model, SolverState& state);

// The velocity that /IMPVEL or /IMPDISP card `im` imposes on node k over the step from t to t + dt_next, or nullopt
// when the card does not act then (its time window).
std::optional<double> imposed_velocity(const Model& model, const SolverState& state, const ImposedMotion& im,
                                       std::size_t k, double t, double dt_next);
// The velocity that brings node `i` of an /IMPDISP/FGEO card to f(t^(n+1) / scale_x) times its displacement to the
// final position at the end of the step (eq. L-9), or nullopt outside Tstart..Tstop or while its sensor is off.
std::optional<Vec3> final_geometry_velocity(const Model& model, const SolverState& state, const FinalGeometry& g,
                                            std::size_t i, double t, double dt_next);

// Kinematic conditions on the half-step velocities v^(n+1/2): fixed dofs, imposed velocity and displacement at
// time t_next = t^(n+1) (the position the step reaches), then rigid walls.
void impose_kinematics(const Model& model, SolverState& state, double time, double dt_next);
void apply_rigid_walls(const Model& model, SolverState& state, double dt_average, double dt_next);
// Before selective mass scaling's solve: the nodes each wall will hold over the step, from their velocities before
// it, join those it held at the last (RigidWallState::active, held_normal; docs/theory/time-step.md, SM-4).
void predict_wall_holds(const Model& model, SolverState& state, double dt_average, double dt_next);

}  // namespace crumple::solver
