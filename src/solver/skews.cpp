// The skews' axes at the current positions (docs/theory/skews.md, SK-3): fixed skews once, moving skews after every
// position update, from their three nodes' positions, the same on every domain.
#include "solver/internal.hpp"

namespace crumple::solver {

void update_skew_axes(const Model& m, SolverState& s) {
  const bool first_call = s.skew_axes.size() != m.skews.size();  // fixed skews do not move: their axes once
  s.skew_axes.resize(m.skews.size());
  const NodalState& n = s.nodes;
  // Several domains: a domain may not advance a moving skew's nodes, so each node's position comes from its owner
  // (an exact sum of one term), and every domain makes the same axes.
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(s.reducer.several() ? 9 * m.skews.size() : 0, ExactSum{});
  if (s.reducer.several()) {
    for (std::size_t i = 0; i < m.skews.size(); ++i)
      for (std::size_t c = 0; c < 3 && m.skews[i].kind == SkewKind::Moving; ++c) {
        const auto k = static_cast<std::size_t>(m.skews[i].nodes[c]);
        if (!s.domain.owns(k)) continue;
        sums[9 * i + 3 * c].add(n.x[k]), sums[9 * i + 3 * c + 1].add(n.y[k]), sums[9 * i + 3 * c + 2].add(n.z[k]);
      }
    s.reducer.sum(sums);
  }
  for (std::size_t i = 0; i < m.skews.size(); ++i) {
    const Skew& skew = m.skews[i];
    if (skew.kind == SkewKind::Fixed && !first_call) continue;
    if (skew.kind == SkewKind::Fixed || !s.reducer.several()) {
      s.skew_axes[i] = skew_axes(skew, n.x, n.y, n.z);
      continue;
    }
    Vec3 p[3];
    for (std::size_t c = 0; c < 3; ++c)
      p[c] = {sums[9 * i + 3 * c].value(), sums[9 * i + 3 * c + 1].value(), sums[9 * i + 3 * c + 2].value()};
    s.skew_axes[i] = axes_from_directions(skew.first_axis, p[1] - p[0], p[2] - p[0]);
  }
}

}  // namespace crumple::solver
