#pragma once
// State owned by the truss kernel (docs/theory/truss.md): per truss, its length at rest and last cycle's, its
// cross-section, its stress and force; its one point's plastic strain is ElementKindState::eps_p.
#include <cstddef>
#include <vector>

#include "crumple/state/element_kind_state.hpp"

namespace crumple {

struct TrussState : ElementKindState {  // one point per truss: eps_p[e], points 1 per group
  // Per element (index in the Truss ElementTable).
  std::vector<double> length0;  // length at t = 0 [L]
  std::vector<double> length;   // length at the last cycle [L] (the strain increment, TR-1)
  std::vector<double> area;     // current cross-section [L^2] (TR-3)
  std::vector<double> stress;   // axial Cauchy stress, positive in tension [F/L^2] (TR-2)
  std::vector<double> force;    // axial force off A sigma, positive in tension [F] (TR-4)
  std::vector<double> off;      // 1 intact; once failed, times 0.8 a cycle until deleted below 0.1 (TR-7)

  void resize_elements(std::size_t n) {
    resize_common(n);
    for (auto* v : {&length0, &length, &area, &stress, &force}) v->assign(n, 0.0);
    off.assign(n, 1.0);
    eps_p.assign(n, point_real(0));
  }
};

}  // namespace crumple
