// /RBE2: secondary nodes carried rigidly by a main node that stays where it is (docs/theory/rigid-bodies.md,
// RE-1 to RE-5). Each group's sums are exact, each node's terms from the domain that owns it, combined over the
// domains, so that every domain moves the main node alike; every domain then places its own secondary nodes.
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// The sums of a group over its nodes (eq. RE-2): force, moment about the main node on the axes it turns, mass,
// the main node's inertia plus sum 2 m_s |r_s|^2, and the secondary nodes' own inertia.
enum Sum : std::size_t { kFx, kFy, kFz, kMx, kMy, kMz, kMass, kLever, kOwnInertia, kSums };

// Adds the mass terms of the group's nodes that this domain owns (every node: `whole_model`) to `sum` (kSums values).
void add_mass_terms(const RigidElement& e, const SolverState& s, ExactSum* sum, bool whole_model = false) {
  const NodalState& n = s.nodes;
  const auto main = static_cast<std::size_t>(e.main_node);
  if (whole_model || s.domain.owns(main)) sum[kMass].add(n.mass[main]), sum[kLever].add(n.inertia[main]);
  const Vec3 x_main = node_position(n, e.main_node);
  for (std::int32_t node : e.secondary_nodes) {
    const auto k = static_cast<std::size_t>(node);
    if (!whole_model && !s.domain.owns(k)) continue;
    const Vec3 r = node_position(n, node) - x_main;
    sum[kMass].add(n.mass[k]), sum[kLever].add(2.0 * n.mass[k] * dot(r, r)), sum[kOwnInertia].add(n.inertia[k]);
  }
}

void keep_mass_terms(const RigidElement& e, const ExactSum* sum, RigidElementState& g) {
  g.mass = sum[kMass].value();
  for (std::size_t d = 0; d < 3; ++d)
    g.inertia[d] = e.turns_about(d) ? sum[kLever].value() + (e.rotation[d] ? sum[kOwnInertia].value() : 0.0) : 0.0;
}

// A secondary node's velocity `u` (eq. RE-3), and the main node's angular velocity on its coupled rotations.
void carry_secondary(const RigidElement& e, NodalState& n, std::size_t k, Vec3 u, Vec3 omega) {
  n.vx[k] = u.x, n.vy[k] = u.y, n.vz[k] = u.z;
  if (e.rotation[0]) n.wx[k] = omega.x;
  if (e.rotation[1]) n.wy[k] = omega.y;
  if (e.rotation[2]) n.wz[k] = omega.z;
}

// The part of the main node's angular velocity the secondary nodes turn with (RE-1).
Vec3 turning(const RigidElement& e, Vec3 omega) {
  return {e.turns_about(0) ? omega.x : 0.0, e.turns_about(1) ? omega.y : 0.0, e.turns_about(2) ? omega.z : 0.0};
}

}  // namespace

void setup_rigid_elements(const Model& m, SolverState& s) {
  if (m.rigid_elements.empty()) return;
  NodalState& n = s.nodes;
  std::vector<ExactSum> sums(kSums * m.rigid_elements.size());  // every domain holds every node here
  for (std::size_t i = 0; i < m.rigid_elements.size(); ++i)
    add_mass_terms(m.rigid_elements[i], s, &sums[kSums * i], true);
  s.rigid_elements.assign(m.rigid_elements.size(), RigidElementState{});
  for (std::size_t i = 0; i < m.rigid_elements.size(); ++i) {
    const RigidElement& e = m.rigid_elements[i];
    RigidElementState& g = s.rigid_elements[i];
    keep_mass_terms(e, &sums[kSums * i], g);  // with mass: the reader refuses a group without (RE-6)
    find_main_node_conditions(m, e.main_node, g.main_node_conditions, g.main_node_skewed_fixes);
    const auto main = static_cast<std::size_t>(e.main_node);
    // The secondary nodes start with the main node's motion (RE-3): an /INIVEL of the main node moves the group,
    // one of the secondary nodes alone does not (measured on the reference).
    const Vec3 v = node_velocity(n, main), omega{n.wx[main], n.wy[main], n.wz[main]};
    const Vec3 x_main = node_position(n, e.main_node);
    for (std::int32_t node : e.secondary_nodes) {
      const auto k = static_cast<std::size_t>(node);
      carry_secondary(e, n, k, v + cross(turning(e, omega), node_position(n, node) - x_main), omega);
    }
  }
}

// After the loads (eq. RE-2): each group's force and moment about its main node onto the main node; the secondary
// nodes keep none in the degrees of freedom the group carries.
void gather_rigid_element_forces(const Model& m, SolverState& s) {
  if (m.rigid_elements.empty()) return;
  NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(kSums * m.rigid_elements.size(), ExactSum{});
  for (std::size_t i = 0; i < m.rigid_elements.size(); ++i) {
    const RigidElement& e = m.rigid_elements[i];
    ExactSum* sum = &sums[kSums * i];
    add_mass_terms(e, s, sum);
    const auto main = static_cast<std::size_t>(e.main_node);
    if (s.domain.owns(main)) {
      const double own[6] = {n.fx[main], n.fy[main], n.fz[main], n.mx[main], n.my[main], n.mz[main]};
      for (std::size_t c = 0; c < 6; ++c) sum[c].add(own[c]);
    }
    const Vec3 x_main = node_position(n, e.main_node);
    for (std::int32_t node : e.secondary_nodes) {
      const auto k = static_cast<std::size_t>(node);
      double* moment[3] = {&n.mx[k], &n.my[k], &n.mz[k]};
      if (s.domain.owns(k)) {
        const Vec3 f{n.fx[k], n.fy[k], n.fz[k]};
        const Vec3 lever = cross(node_position(n, node) - x_main, f);
        sum[kFx].add(f.x), sum[kFy].add(f.y), sum[kFz].add(f.z);
        for (std::size_t d = 0; d < 3; ++d)
          if (e.turns_about(d)) sum[kMx + d].add(lever[d] + (e.rotation[d] ? *moment[d] : 0.0));
      }
      n.fx[k] = n.fy[k] = n.fz[k] = 0.0;
      for (std::size_t d = 0; d < 3; ++d)
        if (e.rotation[d]) *moment[d] = 0.0;
    }
  }
  s.reducer.sum(sums);
  for (std::size_t i = 0; i < m.rigid_elements.size(); ++i) {
    const RigidElement& e = m.rigid_elements[i];
    const ExactSum* sum = &sums[kSums * i];
    keep_mass_terms(e, sum, s.rigid_elements[i]);
    const auto main = static_cast<std::size_t>(e.main_node);
    n.fx[main] = sum[kFx].value(), n.fy[main] = sum[kFy].value(), n.fz[main] = sum[kFz].value();
    double* moment[3] = {&n.mx[main], &n.my[main], &n.mz[main]};
    for (std::size_t d = 0; d < 3; ++d)
      if (e.turns_about(d)) *moment[d] = sum[kMx + d].value();  // the other axes keep the main node's own moment
  }
}

// After the velocity update (eq. RE-2, RE-3, RE-4): the main node's velocity from the group's force over its mass,
// its angular velocity on the turning axes from the moment over the group's inertia; conditions on the main node
// drive the group; each secondary node goes where the rigid turn about the main node puts it at t^(n+1).
double update_rigid_elements(const Model& m, SolverState& s, const std::array<std::vector<double>, 6>& before,
                             double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  double work = 0.0;
  for (std::size_t i = 0; i < m.rigid_elements.size(); ++i) {
    const RigidElement& e = m.rigid_elements[i];
    const RigidElementState& g = s.rigid_elements[i];
    const auto main = static_cast<std::size_t>(e.main_node);
    const double force[3] = {n.fx[main], n.fy[main], n.fz[main]}, moment[3] = {n.mx[main], n.my[main], n.mz[main]};
    std::array<double, 6> v{n.vx[main], n.vy[main], n.vz[main], n.wx[main], n.wy[main], n.wz[main]};
    for (std::size_t d = 0; d < 3; ++d) {
      if (g.mass > 0.0) v[d] = before[d][main] + dt_average * force[d] / g.mass;
      if (e.turns_about(d))
        v[3 + d] = before[3 + d][main] + (g.inertia[d] > 0.0 ? dt_average * moment[d] / g.inertia[d] : 0.0);
    }
    const std::array<double, 6> free = v;
    if (drive_main_node(m, s, e.main_node, g.main_node_conditions, g.main_node_skewed_fixes, v, dt_next))
      for (std::size_t d = 0; d < 6; ++d) {
        const double carried = d < 3 ? g.mass : g.inertia[d - 3];
        work += carried * (v[d] - free[d]) * 0.5 * (v[d] + before[d][main]);
      }
    n.vx[main] = v[0], n.vy[main] = v[1], n.vz[main] = v[2];
    n.wx[main] = v[3], n.wy[main] = v[4], n.wz[main] = v[5];
    const Vec3 velocity{v[0], v[1], v[2]}, omega{v[3], v[4], v[5]};
    const Vec3 turn = scaled(turning(e, omega), dt_next);
    const Vec3 x_main = node_position(n, e.main_node);
    for (std::int32_t node : e.secondary_nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (!s.domain.is_local(k)) continue;
      const Vec3 r = node_position(n, node) - x_main;
      // x_s^(n+1) = x_m^(n+1) + R(w dt) r: the velocity that lands there keeps |r| exactly.
      const Vec3 step = dt_next > 0.0 ? scaled(rotated(r, turn) - r, 1.0 / dt_next) : Vec3{};
      carry_secondary(e, n, k, velocity + step, omega);
    }
  }
  return work;
}

}  // namespace crumple::solver
