#pragma once
// State owned by the beam kernel (docs/theory/beam.md): per beam, its lengths, its turning frame and its six section
// resultants; its one point's plastic strain is ElementKindState::eps_p.
#include <cstddef>
#include <vector>

#include "crumple/state/element_kind_state.hpp"

namespace crumple {

inline constexpr int kBeamResultants = 6;  // N, Vy, Vz (axial and shear forces), T, My, Mz (torsion, bending)

struct BeamState : ElementKindState {  // one point per beam: eps_p[e], points 1 per group
  // Per element (index in the Beam ElementTable).
  std::vector<double> length0;  // length at t = 0 [L]
  std::vector<double> length;   // length at the last cycle [L]
  std::vector<double> area;     // its section's area, which stays (BM-1) [L^2] (the nodal steps' volume A L)
  std::vector<double> frame_y;  // 3 per beam: its local y, normal to its chord, turning with it (BM-0)
  // kBeamResultants per beam, in the beam's frame, on the face towards node 2, the moments at mid-length
  // (BM-2 to BM-4): N [F] positive in tension, Vy Vz [F], T My Mz [F L].
  std::vector<double> resultant;
  std::vector<double> off;  // 1 intact; once failed, times 0.8 a cycle, the resultants with it (BM-9)

  void resize_elements(std::size_t n) {
    resize_common(n);
    for (auto* v : {&length0, &length, &area}) v->assign(n, 0.0);
    frame_y.assign(3 * n, 0.0);
    resultant.assign(kBeamResultants * n, 0.0);
    off.assign(n, 1.0);
    eps_p.assign(n, point_real(0));
  }
};

}  // namespace crumple
