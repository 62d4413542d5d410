// Nodal time step and mass scaling (/DT/NODA/CST) (docs/theory/time-step.md, "Nodal step").
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// Each element gives each of its n nodes the stiffness estimate k = 2 (m_e / n) / dt_e^2, the stiffness for
// which a mass m_e / n has the element's critical step (eq. T-2).
template <class State>
void add_element_stiffness(const ElementTable& table, const State& st, std::vector<double>& k) {
  const int n = nodes_per_element(table.kind);
  for (std::size_t e = 0; e < table.size(); ++e) {
    if (element_condition(st.deleted[e]) != kElementActive || !(st.critical_dt[e] > 0.0)) continue;
    const double share = 2.0 * st.mass[e] / n / (st.critical_dt[e] * st.critical_dt[e]);
    const std::int32_t* nodes = table.nodes_of(e);
    for (int a = 0; a < n; ++a) k[static_cast<std::size_t>(nodes[a])] += share;
  }
}

}  // namespace

NodalStep nodal_time_step(const Model& m, SolverState& s) {
  const TimeStepControl& cst = m.run.dt_nodal_cst;
  const double scale = cst.scale > 0.0 ? cst.scale : 0.9;
  std::vector<double>& k = s.nodal_stiffness;
  k.assign(s.nodes.size(), 0.0);
  add_element_stiffness(m.elements[static_cast<int>(ElementKind::Shell4)], s.shells, k);
  add_element_stiffness(m.elements[static_cast<int>(ElementKind::Shell3)], s.shells3, k);
  add_element_stiffness(m.elements[static_cast<int>(ElementKind::Brick8)], s.bricks, k);
  NodalStep step{std::numeric_limits<double>::infinity(), -1};
  // The smallest nodal mass that keeps scale * sqrt(2 m / k) >= dt_min (eq. T-3).
  const double target = cst.minimum / scale;
  for (std::size_t node = 0; node < k.size(); ++node) {
    if (!(k[node] > 0.0)) continue;
    double& mass = s.nodes.mass[node];
    const double needed = 0.5 * k[node] * target * target;
    if (mass < needed) {
      // A shell node's rotational inertia grows in the same ratio (eq. T-3a): its element's rotation modes keep
      // their frequency ratio to the translational ones and stay stable at the step the mass now gives.
      if (mass > 0.0) s.nodes.inertia[node] *= needed / mass;
      s.mass_added += needed - mass;
      mass = needed;
    }
    const double dt = scale * std::sqrt(2.0 * mass / k[node]);
    if (dt < step.dt) step = {dt, static_cast<std::int32_t>(node)};
  }
  return step;
}

double next_output_time(double t, double start, double interval) {
  const double reached = t * (1.0 + 1e-12);  // an output is due once t >= next (1 - 1e-12)
  double next = start + (std::floor((reached - start) / interval) + 1.0) * interval;
  if (next <= reached) next += interval;  // rounding of the quotient
  return std::max(next, start);
}

}  // namespace crumple::solver
