#pragma once
// State owned by the 4-node and 3-node shell kernels: stresses at the through-thickness points and the
// element histories. Point arrays are element-major within a group: point k of element e of group g is at
// point_offset[g] + (e - group.begin) * points[g] + k. For the fully integrated Ishell 12 an element has
// 4 N points, Gauss point by Gauss point (point j of Gauss point i is k = i N + j).
#include <cstdint>
#include <limits>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/state/element_records.hpp"

namespace crumple {

// Viscous forces a shell keeps from one cycle to the next (ShellState::viscous): 3 membrane, 5 hourglass.
inline constexpr std::size_t kShellViscousForces = 8;

struct ShellState {
  // Per element group (index into Model::element_groups; unused for other kinds).
  std::vector<std::size_t> point_offset;  // index of the group's first point
  std::vector<int> points;                // through-thickness points of the group's elements

  // Per through-thickness point, in the element's co-rotational frame [stress]; stored in point_real (double, or
  // single in the mixed build: core/precision.hpp).
  std::vector<point_real> sxx, syy, sxy;
  std::vector<point_real> eps_p;     // equivalent plastic strain
  std::vector<point_real> eps_rate;  // strain rate the yield stress saw last cycle, filtered (eq. RF) [1/T]
  std::vector<point_real> hardening_term;  // Johnson-Cook b eps_p^n kept with eps_p (NaN until first used) [stress]

  // Per element (index in the kind's ElementTable).
  std::vector<double> qx, qy;           // transverse shear resultants (per unit length) [M T^-2]
  std::vector<double> thickness;        // current thickness [L]
  std::vector<double> bending_stress;   // 6 M / t^2 (xx, yy, xy) per element of N = 0 groups; empty if none [stress]
  std::vector<double> hourglass;        // 5 hourglass generalized stresses per element (membrane x, y, w, rx, ry)
  std::vector<double> internal_energy;  // [M L^2 T^-2]
  std::vector<double> critical_dt;      // critical step of the last cycle [T] (nodal time step, mass scaling)
  std::vector<double> initial_length;   // characteristic length of the first cycle (Ismstr 1, 3) [L]
  std::vector<double> initial_shape;    // local x then y of the nodes of the reference shape (small strain) [L]
  std::vector<std::uint8_t> small_strain;  // 1 once an Ismstr 2 element runs on its frozen shape (eq. S-16)
  std::vector<double> gauss_shear;      // Ishell 12: Qx, Qy at each of the 4 Gauss points; empty if none [M T^-2]
  std::vector<double> gauss_bending;    // Ishell 12, N = 0: 6 M / t^2 (xx, yy, xy) at each Gauss point [stress]
  std::vector<double> mass;             // element mass [M] (nodal stiffness estimate of the nodal time step)
  std::vector<double> hourglass_energy; // [M L^2 T^-2]
  // The last cycle's viscous forces, whose work is counted on the trapezoid (docs/theory/shell4.md, eq. S-9e):
  // dm's membrane resultants (xx, yy, xy) [M T^-2], then Ishell 24's five dn hourglass forces, per element. In
  // single precision: they only weigh the previous cycle's half of a damping work (a relative 6e-8 of it).
  std::vector<float> viscous;
  std::vector<std::uint8_t> deleted;    // 1 once the element has failed
  ElementRecords records;               // the last cycle's loads and energies per element (several domains, or
                                        // the groups of the cut sections /TH/SECTIO writes)
  // /TH/SECTIO WORK: per element and node, the work of the element's load at the node since the start, for the
  // elements of the sections a request asks WORK of; empty otherwise [M L^2 T^-2].
  std::vector<double> section_work;

  // Sizes the per-element arrays for n elements of the given thickness, every other value zero.
  void resize_elements(std::size_t n, double initial_thickness) {
    for (auto* v : {&qx, &qy, &internal_energy, &critical_dt, &initial_length, &mass, &hourglass_energy}) v->assign(n, 0.0);
    thickness.assign(n, initial_thickness);
    hourglass.assign(5 * n, 0.0);
    viscous.assign(kShellViscousForces * n, 0.0f);
    deleted.assign(n, 0);
    small_strain.assign(n, 0);
  }
  // Sizes the per-point arrays for `total` through-thickness points, every value zero (the kept term NaN).
  void resize_points(std::size_t total) {
    for (auto* v : {&sxx, &syy, &sxy, &eps_p, &eps_rate}) v->assign(total, point_real{0});
    hardening_term.assign(total, std::numeric_limits<point_real>::quiet_NaN());
  }
};

}  // namespace crumple
