#pragma once
// The state of selective mass scaling, /DT/AMS (docs/theory/time-step.md, SM-1 to SM-6).
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/model/elements.hpp"

namespace crumple {

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

}  // namespace crumple
