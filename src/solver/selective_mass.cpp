// Selective (advanced) mass scaling, /AMS with /DT/AMS (docs/theory/time-step.md, "Selective mass scaling",
// SM-0 to SM-7): the elements whose scaled step is below dt_min give their deformation modes mass, in a matrix that
// leaves rigid translation alone; the accelerations solve (M + dM) a = F by preconditioned conjugate gradients, the
// kinematic conditions' dofs held at the accelerations they impose, a rigid body as six unknowns.
#include <algorithm>
#include <cmath>

#include "crumple/model/mass.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

using PerKind = std::array<std::vector<double>, kElementKinds>;
using ElementLists = std::array<std::vector<std::int32_t>, kElementKinds>;

const std::vector<double>& critical_steps(const SolverState& s, ElementKind kind) {
  return element_state(s, kind).critical_dt;
}
const std::vector<double>& element_masses(const SolverState& s, ElementKind kind) {
  return element_state(s, kind).mass;
}
const std::vector<std::uint8_t>& element_status(const SolverState& s, ElementKind kind) {
  return element_state(s, kind).deleted;
}

// The share f_a of corner a of element e in its mass (eq. SM-1): the 3-node shell's by its corner angles, the
// others' even.
double corner_share(const SelectiveMassState& sm, ElementKind kind, std::size_t e, int a, int n) {
  return kind == ElementKind::Shell3 ? sm.shell3_fraction[3 * e + static_cast<std::size_t>(a)] : 1.0 / n;
}

// The factor c of eq. SM-2, measured on the reference solver kind by kind: n / (n - 1) for shells, which makes the
// diagonal of dM at an even shell's node the mass nodal scaling would add there; 1 for bricks.
double coupling_factor(ElementKind kind) {
  return kind == ElementKind::Shell4 ? 4.0 / 3.0 : kind == ElementKind::Shell3 ? 1.5 : 1.0;
}

// Whether a rigid body moves in the solve (eq. SM-4a): an active one with mass.
bool in_solve(const RigidBodyState& b) { return b.active && b.mass > 0.0; }

// The dofs the kinematic conditions hold over the step, and the accelerations they give them (eq. SM-4), from the
// velocities before it: a fixed translation is brought to rest, an imposed one to its velocity, a node a rigid wall
// will hold to the wall's normal velocity (all three on a tied wall; its tangential ones stay in the solve). A rigid
// body's nodes move with its centre: its main node carries the body's translation in the solve, its secondary
// nodes none of their own (SM-4a).
void hold_constrained_dofs(const Model& m, SolverState& s, double dt_average, double dt_next) {
  SelectiveMassState& sm = s.selective_mass;
  const NodalState& n = s.nodes;
  const std::size_t nodes = n.size();
  const std::vector<double>* v[3] = {&n.vx, &n.vy, &n.vz};
  auto hold = [&](std::size_t k, std::size_t d, double velocity) {
    sm.solved[k] &= static_cast<std::uint8_t>(~(1u << d));
    sm.prescribed[3 * k + d] = dt_average > 0.0 ? (velocity - (*v[d])[k]) / dt_average : 0.0;
  };
  sm.solved.assign(nodes, 7);
  std::fill(sm.prescribed.begin(), sm.prescribed.end(), 0.0);
  std::fill(sm.wall_normal.begin(), sm.wall_normal.end(), 0.0);
  for (std::size_t k = 0; k < nodes; ++k) {
    for (std::size_t d = 0; d < 3; ++d)
      if (s.fixed[k] & (1u << d)) hold(k, d, 0.0);
    if (s.rigid_owner[k] >= 0) sm.solved[k] = 0;
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    const auto main = static_cast<std::size_t>(b.main_node);
    sm.solved[main] = in_solve(b) ? static_cast<std::uint8_t>(~s.fixed[main] & 7) : 0;
    sm.body_rotation_solved[i] = in_solve(b) ? static_cast<std::uint8_t>((~s.fixed[main] >> 3) & 7) : 0;
    const std::array<double, 9> inertia = body_inertia_global(b);
    std::copy(inertia.begin(), inertia.end(), sm.body_inertia.begin() + static_cast<std::ptrdiff_t>(9 * i));
  }
  for (const ImposedMotion& im : m.imposed) {
    const auto d = static_cast<std::size_t>(im.dof);
    if (im.kind == ImposedKind::Force || im.node_group < 0 || d >= 3) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes)
      if (const auto velocity = imposed_velocity(m, s, im, static_cast<std::size_t>(node), s.time, dt_next))
        hold(static_cast<std::size_t>(node), d, *velocity);
  }
  for (const FinalGeometry& g : m.final_geometries)
    for (std::size_t i = 0; i < g.nodes.size(); ++i)
      if (const auto velocity = final_geometry_velocity(m, s, g, i, s.time, dt_next))
        for (std::size_t d = 0; d < 3; ++d) hold(static_cast<std::size_t>(g.nodes[i]), d, (*velocity)[d]);
  for (const RigidWallState& w : s.walls)
    for (std::size_t i = 0; i < w.nodes.size(); ++i) {
      const auto k = static_cast<std::size_t>(w.nodes[i]);
      if (!w.active[i] || s.rigid_owner[k] >= 0) continue;
      const double* normal = &w.held_normal[3 * i];
      if (w.held_tied[i]) {
        for (std::size_t d = 0; d < 3; ++d) hold(k, d, w.velocity[d]);
        continue;
      }
      const double vn = normal[0] * n.vx[k] + normal[1] * n.vy[k] + normal[2] * n.vz[k];
      const double an = dt_average > 0.0 ? (w.held_speed[i] - vn) / dt_average : 0.0;
      for (std::size_t d = 0; d < 3; ++d) sm.wall_normal[3 * k + d] = normal[d], sm.prescribed[3 * k + d] = an * normal[d];
    }
  sm.held_nodes.clear();
  for (std::size_t k = 0; k < nodes; ++k)
    if (sm.solved[k] != 7 || sm.wall_normal[3 * k] != 0.0 || sm.wall_normal[3 * k + 1] != 0.0 || sm.wall_normal[3 * k + 2] != 0.0)
      sm.held_nodes.push_back(static_cast<std::int32_t>(k));
}

}  // namespace

// The scratch is made once; what a cycle leaves for the next (the elements' and nodes' added mass, `started`) is
// kept when a restart gave it back already.
void size_selective_mass(const Model& m, SolverState& s) {
  SelectiveMassState& sm = s.selective_mass;
  const std::size_t nodes = s.nodes.size();
  const std::size_t unknowns = 3 * nodes + 3 * s.bodies.size();  // the nodes' translations, then the bodies' rotations
  if (sm.x.size() == unknowns) return;
  for (ElementKind kind : kAllElementKinds) {
    const auto k = static_cast<std::size_t>(kind);
    const std::size_t count = m.elements[static_cast<int>(kind)].size();
    if (sm.element_added[k].size() != count) sm.element_added[k].assign(count, 0.0), sm.started = false;
    sm.element_added_before[k].assign(count, 0.0);
    sm.element_change[k].assign(count, 0.0);
  }
  if (sm.node_added.size() != nodes) sm.node_added.assign(nodes, 0.0), sm.started = false;
  // The 4-node shells' step with the plate wave speed (eq. SM-1a, measured on the reference solver).
  const ElementTable& quads = m.elements[static_cast<int>(ElementKind::Shell4)];
  sm.shell4_step_factor.resize(quads.size());
  for (std::size_t e = 0; e < quads.size(); ++e) {
    const Part& part = m.parts[static_cast<std::size_t>(quads.part[e])];
    const double nu = m.materials[static_cast<std::size_t>(part.material)].poisson;
    sm.shell4_step_factor[e] = std::sqrt(1.0 - nu * nu);
  }
  const ElementTable& triangles = m.elements[static_cast<int>(ElementKind::Shell3)];
  sm.shell3_fraction.resize(3 * triangles.size());
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const std::array<double, 8> f = corner_mass_fractions(m, ElementKind::Shell3, triangles.nodes_of(e));
    std::copy(f.begin(), f.begin() + 3, sm.shell3_fraction.begin() + static_cast<std::ptrdiff_t>(3 * e));
  }
  sm.node_added_before.assign(nodes, 0.0);
  for (auto* v : {&sm.ax, &sm.ay, &sm.az}) v->assign(nodes, 0.0);
  for (auto* v : {&sm.x, &sm.b, &sm.diagonal, &sm.r, &sm.z, &sm.p, &sm.q, &sm.velocity, &sm.spread, &sm.prescribed, &sm.forces})
    v->assign(unknowns, 0.0);
  sm.wall_normal.assign(3 * nodes, 0.0);
  sm.wall_reaction.assign(3 * nodes, 0.0);
  sm.body_inertia.assign(9 * s.bodies.size(), 0.0);
  sm.body_rotation_solved.assign(s.bodies.size(), 0);
  sm.lumped.assign(3 * nodes, 0.0);
}

namespace {

// y += dM x (eq. SM-2) over the listed elements of one kind, n corners each, of weights `added`: each gives its
// corners c f_a A_e (x_a - sum_b f_b x_b); `shares` the 3-node shells' f_a, null for even shares.
template <int n>
void add_kind_product(const ElementTable& table, double c, const std::vector<double>& added, const double* shares,
                      const std::vector<std::int32_t>& elements, const double* x, double* y) {
  for (std::int32_t e : elements) {
    const auto ue = static_cast<std::size_t>(e);
    const std::int32_t* corner = table.nodes_of(ue);
    double f[n];
    for (int a = 0; a < n; ++a) f[a] = shares != nullptr ? shares[n * ue + static_cast<std::size_t>(a)] : 1.0 / n;
    double mean[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < n; ++a) {
      const double* xa = x + 3 * static_cast<std::size_t>(corner[a]);
      mean[0] += f[a] * xa[0], mean[1] += f[a] * xa[1], mean[2] += f[a] * xa[2];
    }
    for (int a = 0; a < n; ++a) {
      const double weight = c * f[a] * added[ue];
      const std::size_t i = 3 * static_cast<std::size_t>(corner[a]);
      y[i] += weight * (x[i] - mean[0]), y[i + 1] += weight * (x[i + 1] - mean[1]), y[i + 2] += weight * (x[i + 2] - mean[2]);
    }
  }
}

// y += dM x (eq. SM-2) for the element matrices of weights `added` over the listed elements, kind by kind.
void add_element_mass_product(const Model& m, const SelectiveMassState& sm, const PerKind& weights,
                              const ElementLists& elements, const std::vector<double>& x, std::vector<double>& y) {
  auto table = [&](ElementKind kind) -> const ElementTable& { return m.elements[static_cast<int>(kind)]; };
  constexpr auto quads = static_cast<std::size_t>(ElementKind::Shell4), triangles = static_cast<std::size_t>(ElementKind::Shell3),
                 bricks = static_cast<std::size_t>(ElementKind::Brick8);
  add_kind_product<4>(table(ElementKind::Shell4), coupling_factor(ElementKind::Shell4), weights[quads], nullptr,
                      elements[quads], x.data(), y.data());
  add_kind_product<3>(table(ElementKind::Shell3), coupling_factor(ElementKind::Shell3), weights[triangles],
                      sm.shell3_fraction.data(), elements[triangles], x.data(), y.data());
  add_kind_product<8>(table(ElementKind::Brick8), coupling_factor(ElementKind::Brick8), weights[bricks], nullptr,
                      elements[bricks], x.data(), y.data());
}

// The held parts of a solve vector set to 0: the held dofs, a wall's normal (eq. SM-4), a body's held rotations.
void project_on_solved(const SelectiveMassState& sm, std::vector<double>& v) {
  for (std::size_t i = 0; i < sm.body_rotation_solved.size(); ++i)
    for (std::size_t d = 0; d < 3; ++d)
      if (!(sm.body_rotation_solved[i] & (1u << d))) v[3 * sm.solved.size() + 3 * i + d] = 0.0;
  for (std::int32_t node : sm.held_nodes) {  // the nodes with a held dof or a wall
    const auto k = static_cast<std::size_t>(node);
    double* vk = &v[3 * k];
    for (std::size_t d = 0; d < 3; ++d)
      if (!(sm.solved[k] & (1u << d))) vk[d] = 0.0;
    const double* normal = &sm.wall_normal[3 * k];
    const double along = vk[0] * normal[0] + vk[1] * normal[1] + vk[2] * normal[2];
    if (along != 0.0)
      for (std::size_t d = 0; d < 3; ++d) vk[d] -= along * normal[d];
  }
}

// A rigid body in the solve (eq. SM-4a): its main node's translation and, after the nodes' 3 N values, its rotation
// (3 per body). Its secondary nodes move with it, a_h = a + alpha x r_h with r_h from its centre (the main node);
// `gather` is the transpose: a secondary node's value joins the translation, its moment about the centre the
// rotation, and its own is 0.
Vec3 arm(const SolverState& s, const RigidBodyState& b, std::int32_t node) {
  const auto k = static_cast<std::size_t>(node), c = static_cast<std::size_t>(b.main_node);
  const NodalState& n = s.nodes;
  return {n.x[k] - n.x[c], n.y[k] - n.y[c], n.z[k] - n.z[c]};
}

void spread_bodies(const SolverState& s, std::vector<double>& v) {
  const std::size_t rotations = 3 * s.nodes.size();
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    if (!in_solve(b)) continue;
    const std::size_t main = 3 * static_cast<std::size_t>(b.main_node);
    const Vec3 alpha{v[rotations + 3 * i], v[rotations + 3 * i + 1], v[rotations + 3 * i + 2]};
    for (std::int32_t k : b.secondary) {
      const Vec3 turn = cross(alpha, arm(s, b, k));
      for (std::size_t d = 0; d < 3; ++d) v[3 * static_cast<std::size_t>(k) + d] = v[main + d] + turn[d];
    }
  }
}

void gather_bodies(const SolverState& s, std::vector<double>& v) {
  const std::size_t rotations = 3 * s.nodes.size();
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    if (!in_solve(b)) continue;
    const std::size_t main = 3 * static_cast<std::size_t>(b.main_node);
    for (std::int32_t k : b.secondary) {
      double* vk = &v[3 * static_cast<std::size_t>(k)];
      const Vec3 moment = cross(arm(s, b, k), Vec3{vk[0], vk[1], vk[2]});
      for (std::size_t d = 0; d < 3; ++d) v[main + d] += vk[d], v[rotations + 3 * i + d] += moment[d], vk[d] = 0.0;
    }
  }
}

// The lumped mass a dof's acceleration meets: a rigid body's whole mass at its main node.
double lumped_mass(const SolverState& s, std::size_t k) {
  const std::int32_t body = s.rigid_owner[k];
  if (body >= 0) {
    const RigidBodyState& b = s.bodies[static_cast<std::size_t>(body)];
    if (b.main_node == static_cast<std::int32_t>(k) && in_solve(b)) return b.mass;
  }
  return s.nodes.mass[k];
}

// q = (M + dM) p on the solved dofs, 0 on the held ones; a rigid body's motion is its 6 dofs (SM-4a).
void apply_mass(const Model& m, SolverState& s, const std::vector<double>& p, std::vector<double>& q) {
  SelectiveMassState& sm = s.selective_mass;
  const std::size_t nodes = s.nodes.size();
  const bool bodies = !s.bodies.empty();
  if (bodies) sm.spread = p, spread_bodies(s, sm.spread);
  for (std::size_t i = 0; i < 3 * nodes; ++i) q[i] = sm.lumped[i] * p[i];
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {  // the body's inertia tensor (global axes) on its rotation
    const double* inertia = &sm.body_inertia[9 * i];
    const double* theta = &p[3 * nodes + 3 * i];
    for (std::size_t r = 0; r < 3; ++r)
      q[3 * nodes + 3 * i + r] = inertia[3 * r] * theta[0] + inertia[3 * r + 1] * theta[1] + inertia[3 * r + 2] * theta[2];
  }
  add_element_mass_product(m, sm, sm.element_added, sm.scaled, bodies ? sm.spread : p, q);
  gather_bodies(s, q);
  project_on_solved(sm, q);
}

double inner(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

}  // namespace

bool selective_mass_on(const Model& m) { return m.run.dt_ams.given && m.ams_selected; }

double selective_mass_step(const Model& m, double critical_dt) {
  const SelectiveMassControl& ams = m.run.dt_ams;
  return std::max(ams.scale_or_default() * critical_dt, ams.minimum);
}

void scale_selective_mass(const Model& m, SolverState& s) {
  size_selective_mass(m, s);
  SelectiveMassState& sm = s.selective_mass;
  const SelectiveMassControl& ams = m.run.dt_ams;
  const double scale = ams.scale_or_default();
  sm.node_added_before.swap(sm.node_added);
  sm.node_added.assign(s.nodes.size(), 0.0);
  for (ElementKind kind : kAllElementKinds) {
    const auto k = static_cast<std::size_t>(kind);
    const ElementTable& table = m.elements[static_cast<int>(kind)];
    const std::vector<double>& dt = critical_steps(s, kind);
    const std::vector<double>& mass = element_masses(s, kind);
    const std::vector<std::uint8_t>& status = element_status(s, kind);
    std::vector<double>& added = sm.element_added[k];
    sm.element_added_before[k].swap(added);
    sm.scaled[k].clear();
    const int n = nodes_per_element(kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      added[e] = 0.0;
      if (element_condition(status[e]) != kElementActive || !(dt[e] > 0.0) || !(scale * dt[e] < ams.minimum)) continue;
      const double step = kind == ElementKind::Shell4 ? sm.shell4_step_factor[e] * dt[e] : dt[e];
      const double ratio = std::max(ams.minimum / (scale * step), 1.0);
      added[e] = mass[e] * (ratio * ratio - 1.0);  // eq. SM-1
      sm.scaled[k].push_back(static_cast<std::int32_t>(e));
      const double c = coupling_factor(kind);
      for (int a = 0; a < n; ++a) {
        const double f = corner_share(sm, kind, e, a, n);
        sm.node_added[static_cast<std::size_t>(table.nodes_of(e)[a])] += c * f * (1.0 - f) * added[e];  // eq. SM-3
      }
    }
  }
  // What each element's matrix changed by since the last cycle (eq. SM-5a); none at the first, whose velocities
  // are taken as moving with the scaled mass already.
  for (ElementKind kind : kAllElementKinds) {
    const auto k = static_cast<std::size_t>(kind);
    if (!sm.started) sm.element_added_before[k] = sm.element_added[k], sm.node_added_before = sm.node_added;
    sm.changed[k].clear();
    for (std::size_t e = 0; e < sm.element_added[k].size(); ++e) {
      sm.element_change[k][e] = sm.element_added[k][e] - sm.element_added_before[k][e];
      if (sm.element_change[k][e] != 0.0) sm.changed[k].push_back(static_cast<std::int32_t>(e));
    }
  }
  // The run's first scaling: the initial velocities' energy E_0 includes what dM carries of them (SM-6), as the
  // reference's cycle 0 lists it.
  if (!sm.started && s.cycle + s.cycles_done == 0) s.energy.initial_kinetic += selective_mass_kinetic_energy(m, s);
  sm.started = true;
}

double selective_inertia_factor(const SolverState& s, std::size_t k) {
  const SelectiveMassState& sm = s.selective_mass;
  if (sm.node_added.empty() || !(s.nodes.mass[k] > 0.0)) return 1.0;
  return 1.0 + sm.node_added[k] / s.nodes.mass[k];  // eq. SM-3a
}

double selective_inertia_factor_before(const SolverState& s, std::size_t k) {
  const SelectiveMassState& sm = s.selective_mass;
  if (sm.node_added_before.empty() || !(s.nodes.mass[k] > 0.0)) return 1.0;
  return 1.0 + sm.node_added_before[k] / s.nodes.mass[k];
}

namespace {

// The right-hand side and the Jacobi preconditioner D = diag(M + dM) on the solved dofs, and the first guess.
// The held dofs' accelerations a_h act on the others through dM: b = F - dM a_h. The matrix changes as the
// elements' steps do: the update keeps the momentum (M + dM) v through the change, so b also takes
// - (dM^n - dM^(n-1)) v^(n-1/2) / dt^n (eq. SM-5a), and no kinetic energy comes from the mass itself.
void start_solve(const Model& m, SolverState& s, double dt_average) {
  SelectiveMassState& sm = s.selective_mass;
  const NodalState& n = s.nodes;
  std::fill(sm.q.begin(), sm.q.end(), 0.0);
  bool changed = false;
  for (const auto& list : sm.changed) changed = changed || !list.empty();
  if (changed && dt_average > 0.0) {
    for (std::size_t k = 0; k < n.size(); ++k)
      sm.velocity[3 * k] = n.vx[k], sm.velocity[3 * k + 1] = n.vy[k], sm.velocity[3 * k + 2] = n.vz[k];
    add_element_mass_product(m, sm, sm.element_change, sm.changed, sm.velocity, sm.q);
    for (double& v : sm.q) v /= dt_average;
  }
  add_element_mass_product(m, sm, sm.element_added, sm.scaled, sm.prescribed, sm.q);
  const std::size_t nodes = n.size();
  for (std::size_t k = 0; k < nodes; ++k) {
    const double f[3] = {n.fx[k], n.fy[k], n.fz[k]};  // a rigid body's: gathered at its main node
    const double lumped = lumped_mass(s, k);
    for (std::size_t d = 0; d < 3; ++d) {
      const std::size_t i = 3 * k + d;
      const bool solved = sm.solved[k] & (1u << d);
      sm.forces[i] = f[d], sm.b[i] = f[d] - sm.q[i];
      sm.lumped[i] = solved ? lumped : 0.0;
      sm.diagonal[i] = solved ? lumped + sm.node_added[k] : 0.0;
    }
  }
  // A body: the torque about its centre on its rotation; its diagonal, its mass and inertia with its nodes' added
  // mass (at their arms for the rotation).
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    const auto main = static_cast<std::size_t>(b.main_node);
    const std::size_t rotation = 3 * nodes + 3 * i;
    const double torque[3] = {n.mx[main], n.my[main], n.mz[main]};
    for (std::size_t d = 0; d < 3; ++d) {
      sm.forces[rotation + d] = in_solve(b) ? torque[d] : 0.0;
      sm.b[rotation + d] = in_solve(b) ? torque[d] - sm.q[rotation + d] : 0.0;
    }
    if (!in_solve(b)) continue;
    double mass = b.mass + sm.node_added[main];
    double inertia[3] = {sm.body_inertia[9 * i], sm.body_inertia[9 * i + 4], sm.body_inertia[9 * i + 8]};
    for (std::int32_t k : b.secondary) {
      const double added = sm.node_added[static_cast<std::size_t>(k)];
      const Vec3 r = arm(s, b, k);
      mass += added;
      for (std::size_t d = 0; d < 3; ++d) inertia[d] += added * (dot(r, r) - r[d] * r[d]);
    }
    for (std::size_t d = 0; d < 3; ++d) {
      sm.diagonal[3 * main + d] = (sm.solved[main] & (1u << d)) ? mass : 0.0;
      sm.diagonal[rotation + d] = (sm.body_rotation_solved[i] & (1u << d)) ? inertia[d] : 0.0;
    }
  }
  gather_bodies(s, sm.b);
  project_on_solved(sm, sm.b);
  // The first guess: the last cycle's answer where it has one (accelerations change little from a cycle to the
  // next), else D^-1 b.
  if (sm.warm) {
    project_on_solved(sm, sm.x);
  } else {
    for (std::size_t i = 0; i < sm.b.size(); ++i) sm.x[i] = sm.diagonal[i] > 0.0 ? sm.b[i] / sm.diagonal[i] : 0.0;
  }
}

// The reactions of the held dofs, R = (M + dM) a - F there, and their work over the step on the mid-step velocity
// v + a dt / 2 (eq. SM-4b): the energy the conditions put in or take out. A wall's reaction is along its normal; a
// rigid body's nodes have none (the body's motion is internal).
double reaction_work(const Model& m, SolverState& s, double dt_average) {
  SelectiveMassState& sm = s.selective_mass;
  const NodalState& n = s.nodes;
  std::fill(sm.q.begin(), sm.q.end(), 0.0);
  for (std::size_t k = 0; k < n.size(); ++k)
    sm.velocity[3 * k] = sm.ax[k], sm.velocity[3 * k + 1] = sm.ay[k], sm.velocity[3 * k + 2] = sm.az[k];
  add_element_mass_product(m, sm, sm.element_added, sm.scaled, sm.velocity, sm.q);
  const std::vector<double>* v[3] = {&n.vx, &n.vy, &n.vz};
  double work = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    if (s.rigid_owner[k] >= 0) continue;
    const double* normal = &sm.wall_normal[3 * k];
    double reaction[3], middle[3];
    for (std::size_t d = 0; d < 3; ++d) {
      const std::size_t i = 3 * k + d;
      reaction[d] = n.mass[k] * sm.velocity[i] + sm.q[i] - sm.forces[i];
      middle[d] = (*v[d])[k] + 0.5 * sm.velocity[i] * dt_average;
    }
    const double along = reaction[0] * normal[0] + reaction[1] * normal[1] + reaction[2] * normal[2];
    const bool on_wall = normal[0] != 0.0 || normal[1] != 0.0 || normal[2] != 0.0;
    for (std::size_t d = 0; d < 3; ++d) {
      const double held = (sm.solved[k] & (1u << d)) ? along * normal[d] : reaction[d];
      work += held * middle[d] * dt_average;
      sm.wall_reaction[3 * k + d] = on_wall ? held : 0.0;  // a wall's force, for its outputs (SM-4c)
    }
  }
  return work;
}

void precondition(SelectiveMassState& sm) {
  for (std::size_t i = 0; i < sm.r.size(); ++i) sm.z[i] = sm.diagonal[i] > 0.0 ? sm.r[i] / sm.diagonal[i] : 0.0;
}

}  // namespace

SelectiveSolve solve_selective_mass(const Model& m, SolverState& s, double dt_average, double dt_next) {
  SelectiveMassState& sm = s.selective_mass;
  const SelectiveMassControl& ams = m.run.dt_ams;
  hold_constrained_dofs(m, s, dt_average, dt_next);
  start_solve(m, s, dt_average);
  // Conjugate gradients on (M + dM) x = F, preconditioned by D (eq. SM-5); converged when the residual's D^-1 norm
  // is Tol_AMS times the right-hand side's.
  apply_mass(m, s, sm.x, sm.q);
  double reference = 0.0;
  for (std::size_t i = 0; i < sm.r.size(); ++i) {
    sm.r[i] = sm.b[i] - sm.q[i];
    if (sm.diagonal[i] > 0.0) reference += sm.b[i] * sm.b[i] / sm.diagonal[i];
  }
  precondition(sm);
  sm.p = sm.z;
  double rz = inner(sm.r, sm.z);
  const double tolerance = ams.tolerance_or_default();
  const double target = tolerance * tolerance * reference;
  const long long limit = ams.max_iterations_or_default();
  long long it = 0;
  while (rz > target && it < limit) {
    apply_mass(m, s, sm.p, sm.q);
    const double pq = inner(sm.p, sm.q);
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    for (std::size_t i = 0; i < sm.x.size(); ++i) sm.x[i] += alpha * sm.p[i], sm.r[i] -= alpha * sm.q[i];
    precondition(sm);
    const double rz_next = inner(sm.r, sm.z);
    const double beta = rz_next / rz;
    for (std::size_t i = 0; i < sm.p.size(); ++i) sm.p[i] = sm.z[i] + beta * sm.p[i];
    rz = rz_next;
    ++it;
  }
  // The accelerations: the solved ones and the held ones (SM-4).
  const NodalState& n = s.nodes;
  for (std::size_t k = 0; k < n.size(); ++k) {
    double* a[3] = {&sm.ax[k], &sm.ay[k], &sm.az[k]};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::size_t i = 3 * k + d;
      const bool body_node = s.rigid_owner[k] >= 0;
      *a[d] = body_node ? (n.mass[k] > 0.0 ? sm.forces[i] / n.mass[k] : 0.0)
                        : (sm.solved[k] & (1u << d)) ? sm.x[i] + sm.prescribed[i] : sm.prescribed[i];
    }
  }
  sm.reaction_work = reaction_work(m, s, dt_average);
  // A body moves by the force and torque that give it the solved motion (M a, I alpha): the element and contact
  // forces less its nodes' share of the scaled mass's reaction (SM-4a).
  NodalState& nodal = s.nodes;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    if (!in_solve(b)) continue;
    const auto main = static_cast<std::size_t>(b.main_node);
    const double* alpha = &sm.x[3 * n.size() + 3 * i];
    const double* inertia = &sm.body_inertia[9 * i];
    double* force[3] = {&nodal.fx[main], &nodal.fy[main], &nodal.fz[main]};
    double* torque[3] = {&nodal.mx[main], &nodal.my[main], &nodal.mz[main]};
    for (std::size_t d = 0; d < 3; ++d) {
      if (sm.solved[main] & (1u << d)) *force[d] = b.mass * sm.x[3 * main + d];
      if (sm.body_rotation_solved[i] & (1u << d))
        *torque[d] = inertia[3 * d] * alpha[0] + inertia[3 * d + 1] * alpha[1] + inertia[3 * d + 2] * alpha[2];
    }
  }
  sm.solved_cycle = s.cycle;
  sm.warm = true;
  ++sm.solves, sm.iterations += it, sm.max_iterations = std::max(sm.max_iterations, it);
  return {it, rz <= target, reference > 0.0 ? std::sqrt(rz / reference) : 0.0};
}

// Over this domain's elements (whose nodes' velocities it holds), exact sums combined over the domains: the same
// at any number of them.
double selective_mass_kinetic_energy(const Model& m, SolverState& s) {
  const SelectiveMassState& sm = s.selective_mass;
  if (sm.node_added.empty()) return 0.0;
  const NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(1, ExactSum{});
  for (ElementKind kind : kAllElementKinds) {
    const ElementTable& table = m.elements[static_cast<int>(kind)];
    const std::vector<double>& added = sm.element_added[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(kind);
    for (std::int32_t e : sm.scaled[static_cast<std::size_t>(kind)]) {
      const auto ue = static_cast<std::size_t>(e);
      if (s.domain.several() && !s.domain.mine(kind, ue)) continue;
      const std::int32_t* corner = table.nodes_of(ue);
      double mean[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < count; ++a) {
        const auto k = static_cast<std::size_t>(corner[a]);
        const double f = corner_share(sm, kind, ue, a, count);
        mean[0] += f * n.vx[k], mean[1] += f * n.vy[k], mean[2] += f * n.vz[k];
      }
      for (int a = 0; a < count; ++a) {  // eq. SM-6: (1/2) c sum_a f_a A_e |v_a - v_mean|^2
        const auto k = static_cast<std::size_t>(corner[a]);
        const double dx = n.vx[k] - mean[0], dy = n.vy[k] - mean[1], dz = n.vz[k] - mean[2];
        sums[0].add(0.5 * coupling_factor(kind) * corner_share(sm, kind, ue, a, count) * added[ue] *
                    (dx * dx + dy * dy + dz * dz));
      }
    }
  }
  s.reducer.sum(sums);  // one domain: as it is
  return sums[0].value();
}

}  // namespace crumple::solver
