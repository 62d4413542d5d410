#pragma once
// State owned by the 4-node and 3-node shell kernels: stresses at the through-thickness points and the
// element histories. Point arrays are element-major within a group: point k of element e of group g is at
// point_offset[g] + (e - group.begin) * points[g] + k. For the fully integrated Ishell 12 an element has
// 4 N points, Gauss point by Gauss point (point j of Gauss point i is k = i N + j).
#include <cstdint>
#include <limits>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/state/element_kind_state.hpp"

namespace crumple {

// Hourglass generalized stresses per 4-node shell (ShellState::hourglass): membrane x, y, the transverse shear
// varying along y, rotations x, y, the transverse shear varying along x (docs/theory/shell4.md, S-5, S-11, S-13).
inline constexpr std::size_t kShellHourglassModes = 6;
// Viscous forces a shell keeps from one cycle to the next (ShellState::viscous): 3 membrane, 6 hourglass.
inline constexpr std::size_t kShellViscousForces = 3 + kShellHourglassModes;

struct ShellState : ElementKindState {  // points: through thickness
  // Per through-thickness point, in the element's co-rotational frame [stress]; stored in point_real (double, or
  // single in the mixed build: core/precision.hpp).
  std::vector<point_real> sxx, syy, sxy;
  std::vector<point_real> eps_rate;  // strain rate the yield stress saw last cycle, filtered (eq. RF) [1/T]
  std::vector<point_real> hardening_term;  // Johnson-Cook b eps_p^n kept with eps_p (NaN until first used) [stress]

  // Per element (index in the kind's ElementTable).
  std::vector<double> qx, qy;           // transverse shear resultants (per unit length) [M T^-2]
  std::vector<double> thickness;        // current thickness [L]
  std::vector<double> bending_stress;   // 6 M / t^2 (xx, yy, xy) per element of N = 0 groups; empty if none [stress]
  std::vector<double> hourglass;        // kShellHourglassModes hourglass generalized stresses per element
  std::vector<double> initial_length;   // characteristic length of the first cycle (Ismstr 1, 3) [L]
  std::vector<double> initial_shape;    // local x then y of the nodes of the reference shape (small strain) [L]
  std::vector<std::uint8_t> small_strain;  // 1 once an Ismstr 2 element runs on its frozen shape (eq. S-16)
  std::vector<double> gauss_shear;      // Ishell 12: Qx, Qy at each of the 4 Gauss points; empty if none [M T^-2]
  std::vector<double> gauss_bending;    // Ishell 12, N = 0: 6 M / t^2 (xx, yy, xy) at each Gauss point [stress]
  // The last cycle's viscous forces, whose work is counted on the trapezoid (docs/theory/shell4.md, eq. S-9e):
  // dm's membrane resultants (xx, yy, xy) [M T^-2], then Ishell 24's six dn hourglass forces, per element. In
  // single precision: they only weigh the previous cycle's half of a damping work (a relative 6e-8 of it).
  std::vector<float> viscous;

  // Sizes the per-element arrays for n elements of the given thickness, every other value zero.
  void resize_elements(std::size_t n, double initial_thickness) {
    resize_common(n);
    for (auto* v : {&qx, &qy, &initial_length}) v->assign(n, 0.0);
    thickness.assign(n, initial_thickness);
    hourglass.assign(kShellHourglassModes * n, 0.0);
    viscous.assign(kShellViscousForces * n, 0.0f);
    small_strain.assign(n, 0);
  }
  // Sizes the per-point arrays for `total` through-thickness points, every value zero (the kept term NaN).
  void resize_points(std::size_t total) {
    for (auto* v : {&sxx, &syy, &sxy, &eps_p, &eps_rate}) v->assign(total, point_real{0});
    hardening_term.assign(total, std::numeric_limits<point_real>::quiet_NaN());
  }
};

}  // namespace crumple
