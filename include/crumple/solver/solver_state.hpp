#pragma once
// Everything the time loop advances: nodal state, element state, rigid bodies, walls and the energy balance.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"
#include "crumple/state/contact_state.hpp"
#include "crumple/elements/brick8.hpp"
#include "crumple/elements/shell4.hpp"
#include "crumple/model/model.hpp"
#include "crumple/parallel/domain.hpp"
#include "crumple/parallel/reducer.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/shell_state.hpp"

namespace crumple {

struct EnergyBalanceState {
  double internal = 0.0;          // element internal energy (stress work)
  double hourglass = 0.0;         // hourglass energy
  double kinetic_translational = 0.0;
  double kinetic_rotational = 0.0;
  double external_work = 0.0;     // work of loads and of kinematic conditions (rigid walls, imposed motion)
  double contact = 0.0;
  // E_0: the energy at the start of the engine deck being run: the initial kinetic energy for the first one, the
  // whole energy (internal, kinetic, hourglass, contact) where a continued run takes over.
  double initial_kinetic = 0.0;
  double external_work_at_start = 0.0;  // W_ext when the engine deck started (0 for the first one)
  // (E_int + E_kin + E_hg + E_contact - E_0 - dW_ext) / (E_0 + dW_ext) in percent with dW_ext the work since the
  // engine deck started (docs/theory/energy.md)
  double error_percent() const;
};

struct RigidBodyState {
  std::int32_t main_node = -1;
  std::vector<std::int32_t> secondary;  // secondary nodes (without the main node)
  std::vector<double> rx, ry, rz;       // secondary node positions relative to the centre of mass, body frame
  double mass = 0.0;                     // total mass [M]
  std::array<double, 9> inertia_body{};  // inertia tensor about the centre of mass in the body frame [M L^2]
  std::array<double, 9> inertia_added{}; // the part of it no nodal mass carries: the card's Jxx..Jxz, the main
                                         // node's mass where it was (ICoG 1)
  Vec3 first_moment{};  // sum of m r over the secondary nodes, body frame [M L]: 0 when the centre is theirs (RB-7)
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // body frame -> global
  Vec3 velocity{};          // velocity of the centre of mass at t^(n-1/2)
  Vec3 momentum_angular{};  // angular momentum about the centre of mass (global) at t^(n-1/2)
  Vec3 omega{};             // angular velocity (global) at t^(n-1/2)
  bool active = true;                        // /RBODY/OFF sets it off: the secondary nodes move on their own
  // /IMPVEL and /IMPDISP cards (indices into Model::imposed) acting on the main node: they drive the body.
  std::vector<std::int32_t> main_node_conditions;
  // /BCS cards in a skew (indices into Model::boundary_conditions) holding the main node (SK-5).
  std::vector<std::int32_t> main_node_skewed_fixes;
};

struct RigidWallState {
  std::vector<std::int32_t> nodes;   // candidate secondary nodes
  std::vector<std::uint8_t> tied;    // tied walls: 1 once the node touched
  std::vector<std::uint8_t> active;  // scratch of the cycle: 1 when the node is held by the wall
  // Selective mass scaling's prediction of the step (docs/theory/time-step.md, SM-4), from the velocities before
  // it: per candidate node, the wall's normal there (3 each), whether it holds every direction (tied), and the
  // normal velocity it leaves the node [L/T]; `active` says which it holds.
  std::vector<double> held_normal;
  std::vector<std::uint8_t> held_tied;
  std::vector<double> held_speed;
  Vec3 force{};     // force of the wall on the nodes during the last cycle [F]
  Vec3 normal_force{};  // its part along the wall's normal at each node it held [F]
  Vec3 velocity{};  // wall velocity v^(n+1/2) [L/T]
  Vec3 origin{};    // current point M [L]
  // Moving walls: translation dofs (bit 0 x, 1 y, 2 z) in which the wall node is free, i.e. neither fixed nor
  // imposed; in those the wall takes the nodes' reaction (eq. RW-2), in the others it is driven.
  std::uint8_t free_dofs = 0;
};

// Nodal results a field frame asks for that the cycle would otherwise not keep (/ANIM/VECT/ACC, FINT, FEXT): 3 per
// node (x y z), sized by the solver only when the engine deck asks for them, else empty. Output only: no phase of
// the cycle reads them.
struct RecordedNodalResults {
  std::vector<double> acceleration;    // a^n = (v^(n+1/2) - v^(n-1/2)) / dt^n, after the kinematic conditions
  std::vector<double> internal_force;  // the elements' forces on the node at x^n [M L T^-2]
  std::vector<double> external_force;  // /CLOAD and /GRAV forces at t^n [M L T^-2]
};

// What the /TH outputs need integrated over every cycle and the cycle would otherwise not keep (docs/output-format.md,
// "ACCEL", and "NODE" for DRX DRY DRZ): sized by the solver at the start only when the deck asks for it, else empty,
// so that a deck without them pays nothing. Output only: no phase of the cycle reads it.
struct HistoryIntegrals {
  // /ACCEL, in the order of Model::accelerometers; 3 values (x y z, global) per accelerometer.
  std::vector<double> accel_filtered;  // the filtered acceleration AX AY AZ [L/T^2]
  std::vector<double> accel_velocity;  // WX WY WZ: the sum of the raw accelerations a^n dt^n since the start [L/T]
  // 18 per accelerometer, 6 per component: the filter's last two inputs and the last two outputs of each of its
  // two sections (x1 x2 y1 y2 z1 z2), zero at the start.
  std::vector<double> accel_memory;
  // /TH/NODE DRX DRY DRZ: the nodes a request asks them of (dense indices, sorted) and, 3 per node, the integral of
  // their angular velocity, sum w^(n+1/2) dt^(n+1/2) since the start (global axes) [-].
  std::vector<std::int32_t> rotation_nodes;
  std::vector<double> rotation;
  // /TH/SECTIO (solver/sections.hpp): per element kind, the elements of the sections a request asks WORK of (the
  // cycle integrates their work, ShellState::section_work), and in a run of several domains each element's domain
  // when a written section reads it, else -1 (their records travel at a history row).
  std::array<std::vector<std::int32_t>, kElementKinds> section_work_elements, section_record_owner;
};

// Selective (advanced) mass scaling, /AMS with /DT/AMS (docs/theory/time-step.md, SM-1 to SM-6): the mass matrix
// M + dM, dM a sum of element matrices that leave rigid translation alone. Sized at the first cycle that scales;
// every value is made again each cycle from the elements' steps, so nothing of it is carried by a restart.
struct SelectiveMassState {
  // Per element kind, per element: the mass the scaling gives its deformation modes this cycle (eq. SM-1),
  // m_e ((dt_min / (s dt_e))^2 - 1) when its scaled step is below dt_min, else 0 [M]; and the elements it is
  // positive for.
  std::array<std::vector<double>, kElementKinds> element_added;
  std::array<std::vector<std::int32_t>, kElementKinds> scaled;
  // The same at the cycle before, the change since, and the elements it changed for (eq. SM-5a). `started`: the
  // first cycle has been scaled (the one before is the state's own).
  std::array<std::vector<double>, kElementKinds> element_added_before, element_change;
  std::array<std::vector<std::int32_t>, kElementKinds> changed;
  bool started = false;
  // Per 3-node shell, its corners' shares of its mass (eq. S-9c), 3 each; the other kinds share evenly.
  std::vector<double> shell3_fraction;
  std::vector<double> shell4_step_factor;  // per 4-node shell: sqrt(1 - nu^2), its step on the plate wave speed (SM-1a)
  std::vector<double> node_added;     // per node: the diagonal of dM, the sum of its elements' shares [M]
  std::vector<double> node_added_before;  // the same at the cycle before (eq. SM-5b)
  std::vector<std::uint8_t> solved;   // per node: bit d set when translation d is solved for (not held, eq. SM-4)
  std::vector<double> wall_normal;    // per node, 3: the normal of the rigid wall that holds it, else 0 (SM-4)
  std::vector<double> prescribed;     // 3 per unknown: the accelerations the conditions give the held dofs (SM-4)
  std::vector<double> forces;         // 3 per unknown: F (a body's gathered), kept for the reactions
  double reaction_work = 0.0;         // the held dofs' reactions' work over the step (SM-4b) [M L^2 T^-2]
  std::vector<double> wall_reaction;  // per node, 3: the force a rigid wall puts on it this cycle (SM-4c) [M L T^-2]
  std::vector<double> ax, ay, az;     // the accelerations of the cycle [L/T^2]
  // The solve's vectors, 3 per node (eq. SM-5): solution, right-hand side, preconditioner, residual, its
  // preconditioned form, search direction and its product.
  std::vector<double> x, b, diagonal, r, z, p, q;
  std::vector<double> velocity;  // v^(n-1/2), 3 per node, for the change of the matrix
  std::vector<double> spread;    // a vector with the rigid bodies' values spread to their nodes (SM-4a)
  std::vector<double> lumped;         // 3 per node: the lumped mass of a solved dof, 0 for a held one [M]
  std::vector<std::int32_t> held_nodes;  // the nodes with a held dof or a wall's normal this cycle
  std::vector<double> body_inertia;   // per rigid body, 9: its inertia tensor in global axes this cycle [M L^2]
  std::vector<std::uint8_t> body_rotation_solved;  // per rigid body: bit d when its rotation d is solved for
  long long solved_cycle = -1;           // the cycle the accelerations and the reaction work are of
  bool warm = false;                     // x holds the last solve's answer (the next one's first guess)
  long long solves = 0, iterations = 0;  // cycles solved and their conjugate-gradient iterations, summed
  long long max_iterations = 0;          // the most one cycle took
};

struct SolverState {
  NodalState nodes;
  std::vector<double> x0, y0, z0;                  // initial coordinates
  std::vector<std::uint8_t> fixed;                  // per node: bit k set when dof k (x y z rx ry rz) is fixed
  ShellState shells;   // 4-node shells
  ShellState shells3;  // 3-node shells
  std::vector<ShellGroupParameters> shell_groups;  // per element group (meaningful for shell groups only)
  std::vector<double> shell_zeta, shell_membrane_weight, shell_bending_weight;  // through-thickness rules, 11 per n
  BrickState bricks;                                // 8-node bricks
  std::vector<BrickGroupParameters> brick_groups;  // per element group (meaningful for brick groups only)
  std::vector<RigidBodyState> bodies;
  std::vector<RigidWallState> walls;
  ContactState contact;                             // TYPE7 interfaces (empty without /INTER/TYPE7)
  SelectiveMassState selective_mass;                // /DT/AMS (empty without it)
  std::vector<std::int32_t> rigid_owner;           // per node: rigid body index, -1 when none
  std::vector<SkewAxes> skew_axes;                  // per skew of the model: its axes at the current positions (SK-3)
  double time = 0.0;
  double dt = 0.0;        // step of the last position update dt^(n-1/2) [T]
  long long cycle = 0;         // cycles of the engine deck being run (the listing's CYCLE)
  long long cycles_done = 0;   // cycles of the earlier engine decks of a continued run
  EnergyBalanceState energy;
  double mass_initial = 0.0;
  double mass_added = 0.0;         // mass added by /DT/NODA/CST [M]
  std::vector<double> nodal_stiffness;  // scratch of the nodal time steps: sum of element stiffness estimates (T-2, T-4)
  // The interface nodal step (TYPE7 decks, docs/theory/time-step.md, T-4): per element kind, per element, the
  // stiffness it gives each of its nodes this cycle, from its owner [F/L].
  std::array<std::vector<double>, kElementKinds> interface_stiffness;
  std::vector<GroupStepResult> group_results;  // scratch of the element phase: per element group of the model
  Domain domain;  // the elements this state computes: all of them, or one domain's of a run of several
  Reducer reducer;  // sums over the domains of a run of several (none for one domain)
  // Several domains: per element kind, the domain of each integration point (its element's).
  std::array<std::vector<std::int32_t>, kElementKinds> point_owner;
  // Scratch of the element phase's exchange (several domains only): per element group, its smallest step and the
  // element that has it, the last element that inverted and the last with NaN forces, the failed count and the
  // energies.
  struct GroupShare {
    std::vector<double> min_dt;
    std::vector<std::int32_t> controlling, last_inverted, last_non_finite, failed, inverted_count;
    std::vector<std::int32_t> stop_signal;  // the combined stop request
    std::vector<double> energies;           // per group: internal and hourglass energy of the cycle
    // Owners of what travels at a sort and before an output (kept, so that the exchange's layouts, made once per
    // owner array, stay valid): per accelerometer and per /TH/NODE rotation node, the owner of its node; per
    // interface and node, its owner when it is one of the interface's nodes, else -1.
    std::vector<std::int32_t> accelerometer_owner, rotation_owner;
    std::vector<std::vector<std::int32_t>> interface_node_owner;  // per interface
    // Per interface, per secondary node, and per candidate pair (renewed at each sort): the owner of the
    // secondary node, for a restart snapshot of the contact state.
    std::vector<std::vector<std::int32_t>> secondary_owner, pair_owner;
    std::vector<std::vector<std::int32_t>> wall_node_owner;  // per rigid wall, per candidate node: its owner
  } group_share;
  RecordedNodalResults recorded;
  HistoryIntegrals histories;
  // Several domains, rebalancing (solver/rebalance.cpp): per element kind, every point's plastic strain at the last
  // check (its growth since tells which points flow).
  struct Rebalancing {
    std::array<std::vector<point_real>, kElementKinds> eps_p_at_check;
  } rebalancing;
};

// What every element kind has per element, for code that treats the kinds alike: the status byte
// (state/element_status.hpp), the critical step of the last cycle and the records of a run of several domains.
struct ElementStateView {
  std::vector<std::uint8_t>& status;
  std::vector<double>& critical_dt;
  ElementRecords& records;
};
inline ElementStateView element_view(SolverState& s, ElementKind kind) {
  if (kind == ElementKind::Brick8) return {s.bricks.deleted, s.bricks.critical_dt, s.bricks.records};
  ShellState& shells = kind == ElementKind::Shell4 ? s.shells : s.shells3;
  return {shells.deleted, shells.critical_dt, shells.records};
}

}  // namespace crumple
