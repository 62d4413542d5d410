#pragma once
// State owned by the 8-node brick kernels (docs/theory/brick8.md): the stresses at the integration points and the
// element histories. Point arrays are element-major within a group: point k of element e of group g is at
// point_offset[g] + (e - group.begin) * points[g] + k (one point for Isolid 1 and 24, eight for Isolid 14).
#include <cstdint>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/state/element_kind_state.hpp"

namespace crumple {

struct BrickState : ElementKindState {  // points: one for Isolid 1 and 24, eight for Isolid 14
  // Per integration point: Cauchy stress in the global frame [stress]; stored in point_real (double, or single
  // in the mixed build: core/precision.hpp).
  std::vector<point_real> sxx, syy, szz, sxy, syz, szx;
  std::vector<point_real> eps_rate;  // strain rate the yield stress saw last cycle, filtered (eq. RF) [1/T]

  // Per element (index in the Brick8 ElementTable).
  std::vector<double> volume0;           // initial volume (eq. B-2) for the current density rho0 V0 / V [L^3]
  std::vector<double> volume_scale;      // one-point bricks: the integrated share of the volume (eq. B-2b), else 1
  std::vector<std::uint8_t> degenerate;  // 1 for a brick that repeats nodes (a prism, pyramid or tetrahedron)
  std::vector<double> hourglass;         // 12 hourglass generalized stresses per element, Isolid 24 (eq. B-9) [F]
  // Small strain (Ismstr 1, 3 from t = 0; Ismstr 2 once /DT/BRICK/CST switches it, docs/theory/brick8.md B-14):
  // the element computes its strains, forces and step on the frozen reference shape.
  std::vector<std::uint8_t> small_strain;  // 1 when the element runs on its reference shape
  std::vector<double> reference_shape;     // 24 per element: node coordinates minus the centroid at the freeze [L]
  std::vector<double> reference_frame;     // 9 per element: the element frame R (eq. B-8) at the freeze, row-major

  // Sizes the per-element arrays for n elements, every value zero.
  void resize_elements(std::size_t n) {
    resize_common(n);
    volume0.assign(n, 0.0);
    volume_scale.assign(n, 1.0);
    degenerate.assign(n, 0);
    hourglass.assign(12 * n, 0.0);
    reference_shape.assign(24 * n, 0.0);
    reference_frame.assign(9 * n, 0.0);
    small_strain.assign(n, 0);
  }
  // Sizes the per-point arrays for `total` integration points, every value zero.
  void resize_points(std::size_t total) {
    for (auto* v : {&sxx, &syy, &szz, &sxy, &syz, &szx, &eps_p, &eps_rate}) v->assign(total, point_real{0});
  }
};

}  // namespace crumple
