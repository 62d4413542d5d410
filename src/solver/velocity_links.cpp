// /VEL/TRA: nodes linked along axes move with their mass-weighted mean velocity (docs/theory/loads.md, L-8). The
// momentum of each link along each axis is an exact sum over the owned nodes, combined over the domains, so the
// linked velocity is the same on every domain and for any partition.
#include "solver/cycle.hpp"
#include "solver/monitor.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

SkewAxes link_axes(const SolverState& s, const RunControl::VelocityLink& link) {
  return link.skew < 0 ? SkewAxes{} : s.skew_axes[static_cast<std::size_t>(link.skew)];
}

}  // namespace

void link_velocities(const Model& m, SolverState& s) {
  const auto& links = m.run.velocity_links;
  if (links.empty()) return;
  NodalState& n = s.nodes;
  // Per link: the mass, then the momentum along its three axes (eq. L-8).
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(4 * links.size(), ExactSum{});
  for (std::size_t l = 0; l < links.size(); ++l) {
    const SkewAxes axes = link_axes(s, links[l]);
    for (std::int32_t node : links[l].nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (!s.domain.owns(k)) continue;
      sums[4 * l].add(n.mass[k]);
      for (std::size_t d = 0; d < 3; ++d) sums[4 * l + 1 + d].add(n.mass[k] * dot(node_velocity(n, k), axes.axis[d]));
    }
  }
  s.reducer.sum(sums);
  for (std::size_t l = 0; l < links.size(); ++l) {
    const double mass = sums[4 * l].value();
    if (!(mass > 0.0)) continue;  // massless nodes: nothing to share
    const SkewAxes axes = link_axes(s, links[l]);
    for (std::int32_t node : links[l].nodes) {
      const auto k = static_cast<std::size_t>(node);
      Vec3 v = node_velocity(n, k);
      for (std::size_t d = 0; d < 3; ++d)
        if (links[l].along[d]) v = with_component(v, axes.axis[d], sums[4 * l + 1 + d].value() / mass);
      n.vx[k] = v.x, n.vy[k] = v.y, n.vz[k] = v.z;
    }
  }
}

void start_velocity_links(const Model& m, SolverState& s) {
  if (m.run.velocity_links.empty()) return;
  update_energies(m, s);
  const double before = s.energy.kinetic_translational;
  link_velocities(m, s);
  update_energies(m, s);
  // The deck's state is the linked one: the energy balance starts from it, as the reference's does (L-8).
  s.energy.initial_kinetic += s.energy.kinetic_translational - before;
}

}  // namespace crumple::solver
