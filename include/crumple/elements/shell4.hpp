#pragma once
// 4-node shells: the one-point Belytschko-Tsay formulation with hourglass stiffness (Ishell 1, 24) and the fully
// integrated Batoz shell (Ishell 12); the 3-node C0 triangle (docs/theory/shell4.md).
#include <array>
#include <cstdint>

#include "crumple/core/vec3.hpp"
#include "crumple/elements/group_result.hpp"
#include "crumple/materials/hardening.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/shell_state.hpp"

namespace crumple {

// Everything a shell kernel needs about a group that is the same for all its elements.
struct ShellGroupParameters {
  materials::Hardening hardening;
  double young = 0.0, poisson = 0.0, density = 0.0;
  double shear_factor = 5.0 / 6.0;  // transverse shear correction
  double hm = 0.01, hf = 0.01, hr = 0.01;  // hourglass stiffness coefficients (membrane, out-of-plane, rotation)
  bool small_strain = false;               // Ismstr 1 or 3: strains and step on the initial shape (eq. S-15)
  bool small_strain_switchable = false;    // Ismstr 2: /DT/SHELL/CST, /DT/SH_3N/CST may switch an element (S-16)
  bool fully_integrated = false;           // Ishell 12 (QBAT): four Gauss points, assumed shear (eqs.)
  bool physical_hourglass = false;         // Ishell 24 (QEPH): stiffness from the material, eqs. S-10 to S-14
  bool orthogonal_hourglass = true;        // false for Ishell 2: hourglass vector not orthogonalised (eq. S-17)
  // Ishell 3 (eqs. S-18 to S-18b): membrane and transverse hourglass stresses limited by the yield stress, their
  // rates free of the rigid rotation of a warped element, and purely viscous rotation modes; Ishell 1, 2 damp
  // their rotation modes instead (eq. S-19). Neither has a rotation hourglass stiffness.
  bool elastoplastic_hourglass = false;
  double numerical_damping = 0.015;        // dn: viscous fraction on the physical hourglass modes (eq. S-14), or
                                           // on the membrane and bending resultants of Ishell 12 (eq. Q-8)
  // dm: membrane damping, a viscous mean stress sqrt(2) dm rho c l (d + ...), l = min(sqrt(A), 2 L_step), that is not
  // stored and whose work is internal energy on the trapezoid, and the step factor sqrt(1 + dm^2) - dm (eqs. S-9d
  // to S-9f, T-1c): the 3-node shell's (0.015
  // when blank and Ishell 24) and the QEPH shell's (0.015 when blank); as given for Ishell 1 to 4.
  double membrane_damping = 0.0;
  int points = 1;                          // through-thickness integration points (1 when resultant_plasticity)
  bool resultant_plasticity = false;       // N = 0: plasticity on the stress resultants (RP-1 to RP-3)
  bool radial_return = true;               // Iplas 2 at the points (PS-5); false: the iterative projection (PS-3)
  std::size_t first_point = 0;             // ShellState index of the group's first element's first point
  const double* zeta = nullptr;            // point heights in units of the thickness, in [-1/2, 1/2]
  const double* membrane_weight = nullptr; // N = t sum w_i sigma_i (weights sum to 1)
  const double* bending_weight = nullptr;  // M = t^2 sum b_i sigma_i
  bool thickness_update = false;           // Ithick = 1
  double failure_strain = 0.0;             // plastic strain that deletes the element (0: none)
};

// Updates the stresses of the group's elements over the step dt (the velocities of `nodes` act over dt), then
// adds their internal forces and moments (with a minus sign) to the nodal force and moment accumulators.
// Runs the fully integrated kernel when p.fully_integrated (Ishell 12), the one-point kernel otherwise.
GroupStepResult shell4_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                              NodalState& nodes, ShellState& state, double dt);
// The fully integrated Batoz shell, Ishell 12 (docs/theory/shell4.md, "QBAT", eqs. ).
GroupStepResult shell4_qbat_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                                   NodalState& nodes, ShellState& state, double dt);
// The same for 3-node shells (C0 triangle, docs/theory/shell4.md "Triangles"): constant membrane strain and
// curvature, no hourglass mode.
GroupStepResult shell3_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                              NodalState& nodes, ShellState& state, double dt);

// Small-strain switch of Ismstr 2 (docs/theory/shell4.md, eq. S-16), for /DT/SHELL/CST (4-node) and
// /DT/SH_3N/CST (3-node): freezes the element's current shape, seen in its current co-rotational frame, as the
// reference shape on which its strains, forces and constant critical step are computed from the next cycle on.
// `table` is the element's kind table (Shell4 or Shell3) and `state` the matching ShellState. Returns true when
// the element switched; false when its group cannot switch (Ismstr 1, 3: already small strain from t = 0;
// Ismstr 4: the switch has no effect), when it already switched or was deleted, or when its shape has no frame.
bool shell_switch_to_small_strain(const ElementTable& table, const ShellGroupParameters& p, const NodalState& nodes,
                                  ShellState& state, std::int32_t element);

// What a shell element's state holds at the end of the last cycle, for output (docs/output-format.md,
// "/history/th"): the stress resultants per unit length in the element's co-rotational frame (eq. S-4) - membrane
// forces N (xx, yy, xy) [F/L], moments M (xx, yy, xy) [F L/L], transverse shears Q (x, z and y, z) [F/L] - and the
// equivalent plastic strain at the lower (zeta = -1/2) and upper (+1/2) surface points and the mean filtered strain
// rate of the points [1/T]. Ishell 12: the mean over the four Gauss points. N = 0 and N = 1: one point, both
// surfaces.
struct ShellElementOutput {
  double n[3] = {0.0, 0.0, 0.0}, m[3] = {0.0, 0.0, 0.0}, q[2] = {0.0, 0.0};
  double plastic_strain_lower = 0.0, plastic_strain_upper = 0.0;
  double strain_rate = 0.0;
};
// `element` is an index of the kind's ElementTable within `group`, `p` and `state` the group's parameters and its
// kind's ShellState.
ShellElementOutput shell_element_output(const ShellGroupParameters& p, const ShellState& state,
                                        const ElementGroup& group, std::int32_t element);

// A shell's membrane stress (sxx, syy, sxy in its co-rotational frame, eq. S-1, at node positions `x` of its
// `nodes` = 3 or 4 nodes) as a symmetric tensor in the global axes, sxx syy szz sxy syz szx (VTK's order):
// sigma = sxx e1 e1 + syy e2 e2 + sxy (e1 e2 + e2 e1). The zero tensor when the element has no normal.
std::array<double, 6> shell_stress_in_global_axes(const Vec3* x, int nodes, const double (&local)[3]);

// Lumped rotational inertia an element of mass `element_mass` gives each of its `nodes` nodes [M L^2]:
// (m / n) (t^2 / 12 + A / 9) (docs/theory/shell4.md, eq. S-8), the reference solver's.
inline double shell_node_rotational_inertia(double element_mass, double thickness, double area, int nodes) {
  return element_mass / nodes * (thickness * thickness / 12.0 + area / 9.0);
}

// The share X of each node's rotational inertia, I = (m / n) X [L^2], an element of the group gives its nodes
// (`x`: its n = 3 or 4 nodes at the start, `thickness` [L]): the reference's t^2 / 12 + A / 9 (eq. S-8), raised
// where the element's transverse-shear mode would not be stable at `scale` times its critical step (eq. S-8a: a
// node's rotation and its neighbours' deflection exchange through the shear; with a low Poisson ratio that mode
// is faster than the membrane mode the step is made for).
double shell_rotational_inertia_share(const ShellGroupParameters& p, int nodes, const Vec3* x, double thickness,
                                      double scale);

// Through-thickness rule for n = 1..10 points (docs/theory/shell4.md, eq. S-4): n equally spaced points from the
// lower to the upper surface; the stress between points is taken linear, so the membrane weights are the
// integrals of the hat functions and the bending weights the integrals of z times them. n = 1: the mid-plane,
// membrane only.
void through_thickness_rule(int n, double* zeta, double* membrane_weight, double* bending_weight);

}  // namespace crumple
