#pragma once
// State owned by the 8-node brick kernels (docs/theory/brick8.md): the stresses at the integration points and the
// element histories. Point arrays are element-major within a group: point k of element e of group g is at
// point_offset[g] + (e - group.begin) * points[g] + k (one point for Isolid 1 and 24, eight for Isolid 14).
#include <cstdint>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/state/element_records.hpp"

namespace crumple {

struct BrickState {
  // Per element group (index into Model::element_groups; unused for other kinds).
  std::vector<std::size_t> point_offset;  // index of the group's first point
  std::vector<int> points;                // integration points per element of the group

  // Per integration point: Cauchy stress in the global frame [stress], equivalent plastic strain; stored in
  // point_real (double, or single in the mixed build: core/precision.hpp).
  std::vector<point_real> sxx, syy, szz, sxy, syz, szx;
  std::vector<point_real> eps_p;
  std::vector<point_real> eps_rate;  // strain rate the yield stress saw last cycle, filtered (eq. RF) [1/T]

  // Per element (index in the Brick8 ElementTable).
  std::vector<double> volume0;           // initial volume (eq. B-2) for the current density rho0 V0 / V [L^3]
  std::vector<double> volume_scale;      // one-point bricks: the integrated share of the volume (eq. B-2b), else 1
  std::vector<std::uint8_t> degenerate;  // 1 for a brick that repeats nodes (a prism, pyramid or tetrahedron)
  std::vector<double> hourglass;         // 12 hourglass generalized stresses per element, Isolid 24 (eq. B-9) [F]
  std::vector<double> internal_energy;   // [M L^2 T^-2]
  std::vector<double> hourglass_energy;  // [M L^2 T^-2]
  std::vector<double> critical_dt;       // critical step of the last cycle (eq. B-12) [T]
  std::vector<double> mass;              // element mass [M] (nodal time-step estimate)
  std::vector<std::uint8_t> deleted;     // 1 once the element has failed
  ElementRecords records;                // the last cycle's loads and energies per element (several domains, or
                                         // the groups of the cut sections /TH/SECTIO writes)
  std::vector<double> section_work;      // /TH/SECTIO WORK per element and node (ShellState::section_work)
  // Small strain (Ismstr 1, 3 from t = 0; Ismstr 2 once /DT/BRICK/CST switches it, docs/theory/brick8.md B-14):
  // the element computes its strains, forces and step on the frozen reference shape.
  std::vector<std::uint8_t> small_strain;  // 1 when the element runs on its reference shape
  std::vector<double> reference_shape;     // 24 per element: node coordinates minus the centroid at the freeze [L]
  std::vector<double> reference_frame;     // 9 per element: the element frame R (eq. B-8) at the freeze, row-major

  // Sizes the per-element arrays for n elements, every value zero.
  void resize_elements(std::size_t n) {
    for (auto* v : {&volume0, &internal_energy, &hourglass_energy, &critical_dt, &mass}) v->assign(n, 0.0);
    volume_scale.assign(n, 1.0);
    degenerate.assign(n, 0);
    hourglass.assign(12 * n, 0.0);
    reference_shape.assign(24 * n, 0.0);
    reference_frame.assign(9 * n, 0.0);
    deleted.assign(n, 0);
    small_strain.assign(n, 0);
  }
  // Sizes the per-point arrays for `total` integration points, every value zero.
  void resize_points(std::size_t total) {
    for (auto* v : {&sxx, &syy, &szz, &sxy, &syz, &szx, &eps_p, &eps_rate}) v->assign(total, point_real{0});
  }
};

}  // namespace crumple
