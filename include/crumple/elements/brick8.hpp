#pragma once
// 8-node bricks (docs/theory/brick8.md, "Formulations"): one point with viscous hourglass control (Isolid 1, and 2
// without orthogonalisation), one point with assumed-strain physical stabilisation (Isolid 24), 2x2x2 Gauss points
// (Isolid 12, 17, and 14, 18 with assumed shears), the pressure constant over the element with Icpre 1. Node
// order: 1-4 one face, 5-8 the opposite face (node k + 4 above node k).
#include <cstddef>

#include "crumple/elements/group_result.hpp"
#include "crumple/materials/hardening.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/state/brick_state.hpp"
#include "crumple/state/nodal_state.hpp"

namespace crumple {

// Everything a brick kernel needs about a group that is the same for all its elements.
struct BrickGroupParameters {
  materials::Hardening hardening;
  double young = 0.0, poisson = 0.0, density = 0.0;  // density: initial density rho0
  int isolid = 1;                  // the deck's formulation; the kernel follows the flags below
  bool plain_hourglass = false;    // one point: hourglass base vectors not orthogonalised (Isolid 2, eq. B-6a)
  double qa = 1.1, qb = 0.05;      // quadratic and linear bulk viscosity coefficients (eq. B-7)
  double hourglass = 0.1;          // viscous hourglass coefficient h (Isolid 1, 2, eq. B-6)
  double numerical_damping = 0.0;  // dn of the Isolid 24 stabilisation (eq. B-9b); the property default is 0.1
  bool constant_pressure = false;  // Icpre 1: the pressure is constant over the element (eq. B-9a, B-10)
  bool plastic_pressure = false;   // Icpre 2 (2x2x2 points): the constant pressure's share follows plasticity (B-9c)
  bool assumed_shear = false;      // 2x2x2 points: shears of the element frame averaged (eq. B-10a), Isolid 14
  int points = 1;                  // integration points per element: 1, or 8 (2x2x2)
  bool corotational = false;       // Iframe 2: stresses turn with the element frame, not the material spin (B-3a)
  int ismstr = 4;                  // 1, 3 small strain from t = 0; 2 switchable to small strain; 4 never (B-14)
  std::size_t first_point = 0;     // BrickState index of the group's first element's first point
  double failure_strain = 0.0;     // plastic strain that deletes the element (0: none)
};

// Sets the kernel flags of `p` for a formulation Isolid with its resolved Icpre (docs/theory/brick8.md,
// "Formulations"): 1, 2, 24 one point; 12, 14, 17, 18 2x2x2 points.
void brick8_configure(int isolid, int icpre, BrickGroupParameters& p);

// Updates the stresses of the group's elements over the step dt (the velocities of `nodes` act over dt, the
// rate of deformation is taken on the mid-step geometry x - dt v / 2), then subtracts their internal forces at the
// current geometry from the nodal force accumulators. Dispatches once per group on p.isolid.
GroupStepResult brick8_forces(const ElementTable& table, const ElementGroup& group, const BrickGroupParameters& p,
                              NodalState& nodes, BrickState& state, double dt);

// Freezes the current shape of brick `element` (index in the Brick8 table) as its reference shape and switches it
// to small strain (eq. B-14): from then on its strains, forces and critical step are computed on that shape,
// turned with the element frame (Ismstr 1, 2) or not (Ismstr 3), so its step no longer falls. Called by the setup
// for Ismstr 1 and 3, and by the time loop for an Ismstr 2 element that /DT/BRICK/CST switches.
void brick8_switch_to_small_strain(const ElementTable& table, std::int32_t element, const NodalState& nodes,
                                   BrickState& state);

// The two kernels behind brick8_forces: one point (Isolid 1, 2 and 24) and 2x2x2 Gauss points (12, 14, 17, 18).
GroupStepResult brick8_one_point_forces(const ElementTable& table, const ElementGroup& group,
                                        const BrickGroupParameters& p, NodalState& nodes, BrickState& state,
                                        double dt);
GroupStepResult brick8_full_forces(const ElementTable& table, const ElementGroup& group,
                                   const BrickGroupParameters& p, NodalState& nodes, BrickState& state, double dt);

}  // namespace crumple
