// /RBE3: a dependent node's loads spread over its independent nodes, and its motion the weighted least-squares rigid
// motion of theirs (docs/theory/rigid-bodies.md, RI-1 to RI-6). The system's sums are exact, each node's terms from
// the domain that owns it, combined over the domains, so that every domain solves the same system; each domain then
// loads its own independent nodes.
#include <cmath>

#include <fmt/format.h>

#include "crumple/core/deck_error.hpp"
#include "crumple/model/interpolation.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// Per constraint: the matrix without the rotational weights (36), the sum of the rotational weights (3) and of the
// independent nodes' distances from the dependent node (1).
constexpr std::size_t kSystemSums = 40;

Vec3 lever(const NodalState& n, std::int32_t node, const Vec3& dependent) { return node_position(n, node) - dependent; }

void add_system_terms(const InterpolationConstraint& c, const InterpolationState& g, const SolverState& s,
                      bool whole_model, ExactSum* sum) {
  const NodalState& n = s.nodes;
  const Vec3 x_d = node_position(n, c.dependent_node);
  for (std::size_t i = 0; i < c.independent.size(); ++i) {
    const auto k = static_cast<std::size_t>(c.independent[i].node);
    if (!whole_model && !s.domain.owns(k)) continue;
    const Vec3 r = lever(n, c.independent[i].node, x_d);
    const auto& w = g.weight[i];
    Matrix6 a{};
    add_interpolation_node(r, {w[0], w[1], w[2], 0.0, 0.0, 0.0}, a);
    for (std::size_t e = 0; e < 36; ++e) sum[e].add(a[e]);
    for (std::size_t d = 0; d < 3; ++d) sum[36 + d].add(w[3 + d]);
    sum[39].add(norm(r));
  }
}

// A with the rotational weights scaled by Lc^2, Lc the mean distance of the independent nodes from the dependent
// node (RI-2), and its inverse; false when A leaves a motion of the dependent node unheld.
bool solve_system(const InterpolationConstraint& c, const ExactSum* sum, InterpolationState& g) {
  const double lc = sum[39].value() / static_cast<double>(c.independent.size());
  g.length_squared = lc * lc;
  Matrix6 a{};
  for (std::size_t e = 0; e < 36; ++e) a[e] = sum[e].value();
  for (std::size_t d = 0; d < 3; ++d) a[6 * (3 + d) + 3 + d] += g.length_squared * sum[36 + d].value();
  const InterpolationInverse inverse = invert_interpolation(a);
  g.inverse = inverse.inverse;
  return inverse.constrained;
}

Vector6 scaled_weight(const InterpolationState& g, std::size_t i) {
  const auto& w = g.weight[i];
  const double l2 = g.length_squared;
  return {w[0], w[1], w[2], l2 * w[3], l2 * w[4], l2 * w[5]};
}

}  // namespace

void setup_interpolation_constraints(const Model& m, SolverState& s) {
  if (m.interpolation_constraints.empty()) return;
  const NodalState& n = s.nodes;
  s.interpolations.assign(m.interpolation_constraints.size(), InterpolationState{});
  for (std::size_t c = 0; c < m.interpolation_constraints.size(); ++c) {
    const InterpolationConstraint& ic = m.interpolation_constraints[c];
    InterpolationState& g = s.interpolations[c];
    // A node without rotational inertia takes no moment: its rotation codes are dropped, as the reference does (RI-1).
    for (const InterpolationNode& node : ic.independent) {
      std::array<double, 6> w = node.weight;
      if (!(n.inertia[static_cast<std::size_t>(node.node)] > 0.0)) w[3] = w[4] = w[5] = 0.0;
      g.weight.push_back(w);
    }
    std::vector<ExactSum> sums(kSystemSums);  // every domain holds every node here
    add_system_terms(ic, g, s, true, sums.data());
    if (!solve_system(ic, sums.data(), g))
      throw DeckError(ic.where, fmt::format("/RBE3/{}", ic.user_id), "grnod_IDi",
                      "independent nodes that hold every motion of the dependent node (three not on one line, or "
                      "rotations that take part), as the reference requires (its error 706)",
                      "a motion of the dependent node they do not hold");
  }
  interpolate_dependent_motion(m, s, true);
}

// After the loads (RI-3): q = A^-1 (F, M) of the dependent node's load on its Trarot_ref dofs; each independent node
// takes W_i X_i q. The dependent node keeps none.
void spread_interpolation_loads(const Model& m, SolverState& s) {
  if (m.interpolation_constraints.empty()) return;
  NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(kSystemSums * m.interpolation_constraints.size(), ExactSum{});
  for (std::size_t c = 0; c < m.interpolation_constraints.size(); ++c)
    add_system_terms(m.interpolation_constraints[c], s.interpolations[c], s, false, &sums[kSystemSums * c]);
  s.reducer.sum(sums);
  for (std::size_t c = 0; c < m.interpolation_constraints.size(); ++c) {
    const InterpolationConstraint& ic = m.interpolation_constraints[c];
    InterpolationState& g = s.interpolations[c];
    solve_system(ic, &sums[kSystemSums * c], g);  // held at the start (set-up); its pseudo-inverse after
    const auto d = static_cast<std::size_t>(ic.dependent_node);
    Vector6 load{n.fx[d], n.fy[d], n.fz[d], n.mx[d], n.my[d], n.mz[d]};
    for (std::size_t k = 0; k < 6; ++k)
      if (!ic.reference_dofs[k]) load[k] = 0.0;  // the reference drops them (measured)
    n.fx[d] = n.fy[d] = n.fz[d] = n.mx[d] = n.my[d] = n.mz[d] = 0.0;
    const Vector6 q = multiply(g.inverse, load);
    const Vec3 x_d = node_position(n, ic.dependent_node);
    for (std::size_t i = 0; i < ic.independent.size(); ++i) {
      const auto k = static_cast<std::size_t>(ic.independent[i].node);
      if (!s.domain.is_local(k)) continue;
      const Vector6 f = interpolation_node_load(lever(n, ic.independent[i].node, x_d), scaled_weight(g, i), q);
      n.fx[k] += f[0], n.fy[k] += f[1], n.fz[k] += f[2], n.mx[k] += f[3], n.my[k] += f[4], n.mz[k] += f[5];
    }
  }
}

// After every other condition (RI-4): the dependent node's motion A^-1 sum X_i^T W_i (v_i, w_i) on its Trarot_ref
// dofs, from the independent nodes' final velocities.
void interpolate_dependent_motion(const Model& m, SolverState& s, bool whole_model) {
  if (m.interpolation_constraints.empty()) return;
  NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(6 * m.interpolation_constraints.size(), ExactSum{});
  for (std::size_t c = 0; c < m.interpolation_constraints.size(); ++c) {
    const InterpolationConstraint& ic = m.interpolation_constraints[c];
    const InterpolationState& g = s.interpolations[c];
    const Vec3 x_d = node_position(n, ic.dependent_node);
    for (std::size_t i = 0; i < ic.independent.size(); ++i) {
      const auto k = static_cast<std::size_t>(ic.independent[i].node);
      if (!whole_model && !s.domain.owns(k)) continue;
      const Vector6 y{n.vx[k], n.vy[k], n.vz[k], n.wx[k], n.wy[k], n.wz[k]};
      const Vector6 b = interpolation_node_motion(lever(n, ic.independent[i].node, x_d), scaled_weight(g, i), y);
      for (std::size_t e = 0; e < 6; ++e) sums[6 * c + e].add(b[e]);
    }
  }
  if (!whole_model) s.reducer.sum(sums);
  for (std::size_t c = 0; c < m.interpolation_constraints.size(); ++c) {
    const InterpolationConstraint& ic = m.interpolation_constraints[c];
    Vector6 b{};
    for (std::size_t e = 0; e < 6; ++e) b[e] = sums[6 * c + e].value();
    const Vector6 q = multiply(s.interpolations[c].inverse, b);
    const auto d = static_cast<std::size_t>(ic.dependent_node);
    double* v[6] = {&n.vx[d], &n.vy[d], &n.vz[d], &n.wx[d], &n.wy[d], &n.wz[d]};
    for (std::size_t e = 0; e < 6; ++e)
      if (ic.reference_dofs[e]) *v[e] = q[e];
  }
}

}  // namespace crumple::solver
