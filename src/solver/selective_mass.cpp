// Selective (advanced) mass scaling, /AMS with /DT/AMS (docs/theory/time-step.md, "Selective mass scaling",
// SM-1 to SM-6): the elements whose scaled step is below dt_min give their deformation modes mass, in a matrix that
// leaves rigid translation alone; the accelerations solve (M + dM) a = F by preconditioned conjugate gradients.
#include <algorithm>
#include <cmath>

#include "crumple/model/mass.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

using PerKind = std::array<std::vector<double>, kElementKinds>;
using ElementLists = std::array<std::vector<std::int32_t>, kElementKinds>;

constexpr ElementKind kKinds[] = {ElementKind::Shell4, ElementKind::Shell3, ElementKind::Brick8};

const std::vector<double>& critical_steps(const SolverState& s, ElementKind kind) {
  return kind == ElementKind::Shell4 ? s.shells.critical_dt : kind == ElementKind::Shell3 ? s.shells3.critical_dt
                                                                                           : s.bricks.critical_dt;
}
const std::vector<double>& element_masses(const SolverState& s, ElementKind kind) {
  return kind == ElementKind::Shell4 ? s.shells.mass : kind == ElementKind::Shell3 ? s.shells3.mass : s.bricks.mass;
}
const std::vector<std::uint8_t>& element_status(const SolverState& s, ElementKind kind) {
  return kind == ElementKind::Shell4 ? s.shells.deleted : kind == ElementKind::Shell3 ? s.shells3.deleted
                                                                                       : s.bricks.deleted;
}

// The share f_a of corner a of element e in its mass (eq. SM-1): the 3-node shell's by its corner angles, the
// others' even.
double corner_share(const SelectiveMassState& sm, ElementKind kind, std::size_t e, int a, int n) {
  return kind == ElementKind::Shell3 ? sm.shell3_fraction[3 * e + static_cast<std::size_t>(a)] : 1.0 / n;
}

// n / (n - 1): the factor that makes dM's diagonal at an even element's node the mass nodal scaling would add
// there (eq. SM-2, measured on the reference solver).
double coupling_factor(int n) { return static_cast<double>(n) / (n - 1); }

// Whether a rigid body moves in the solve (eq. SM-4a): an active one with mass.
bool in_solve(const RigidBodyState& b) { return b.active && b.mass > 0.0; }

// Translation dofs held by a condition the velocity update sets afterwards: fixed or imposed. They are left out of
// the solve (eq. SM-4): their acceleration is the diagonal one, F / m. A rigid body's nodes move with its centre:
// its main node carries the body's translation in the solve, its secondary nodes none of their own (SM-4a).
void hold_constrained_dofs(const Model& m, SolverState& s) {
  SelectiveMassState& sm = s.selective_mass;
  const std::size_t nodes = s.nodes.size();
  sm.solved.assign(nodes, 7);
  for (std::size_t k = 0; k < nodes; ++k) {
    sm.solved[k] &= static_cast<std::uint8_t>(~s.fixed[k] & 7);
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
  // A node a rigid wall held last cycle moves in the wall's plane (eq. SM-4): its normal is held, or all three
  // translations on a tied wall.
  std::fill(sm.wall_normal.begin(), sm.wall_normal.end(), 0.0);
  for (const RigidWallState& w : s.walls)
    for (std::size_t i = 0; i < w.nodes.size(); ++i) {
      if (!w.active[i]) continue;
      const auto k = static_cast<std::size_t>(w.nodes[i]);
      if (w.held_tied[i]) sm.solved[k] = 0;
      for (std::size_t d = 0; d < 3; ++d) sm.wall_normal[3 * k + d] = w.held_normal[i][d];
    }
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind == ImposedKind::Force || im.node_group < 0) continue;
    const auto d = static_cast<int>(im.dof);
    for (std::int32_t k : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes)
      sm.solved[static_cast<std::size_t>(k)] &= static_cast<std::uint8_t>(d < 3 ? ~(1u << d) : 7u);
  }
}

void size_state(const Model& m, SolverState& s) {
  SelectiveMassState& sm = s.selective_mass;
  const std::size_t nodes = s.nodes.size();
  if (sm.node_added.size() == nodes) return;
  for (ElementKind kind : kKinds) {
    const std::size_t count = m.elements[static_cast<int>(kind)].size();
    for (PerKind* v : {&sm.element_added, &sm.element_added_before, &sm.element_change})
      (*v)[static_cast<std::size_t>(kind)].assign(count, 0.0);
  }
  sm.started = false;
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
  sm.node_added.assign(nodes, 0.0);
  sm.node_added_before.assign(nodes, 0.0);
  for (auto* v : {&sm.ax, &sm.ay, &sm.az}) v->assign(nodes, 0.0);
  const std::size_t unknowns = 3 * nodes + 3 * s.bodies.size();  // the nodes' translations, then the bodies' rotations
  for (auto* v : {&sm.x, &sm.b, &sm.diagonal, &sm.r, &sm.z, &sm.p, &sm.q, &sm.velocity, &sm.spread}) v->assign(unknowns, 0.0);
  sm.wall_normal.assign(3 * nodes, 0.0);
  sm.body_inertia.assign(9 * s.bodies.size(), 0.0);
  sm.body_rotation_solved.assign(s.bodies.size(), 0);
  sm.diagonal_mass.assign(nodes, 0.0);
}

// y += dM x (eq. SM-2) for the element matrices of weights `added` over the listed elements: each gives its
// corners c f_a A_e (x_a - sum_b f_b x_b).
void add_element_mass_product(const Model& m, const SelectiveMassState& sm, const PerKind& weights,
                              const ElementLists& elements, const std::vector<double>& x, std::vector<double>& y) {
  for (ElementKind kind : kKinds) {
    const ElementTable& table = m.elements[static_cast<int>(kind)];
    const std::vector<double>& added = weights[static_cast<std::size_t>(kind)];
    const int n = nodes_per_element(kind);
    const double c = coupling_factor(n);
    for (std::int32_t e : elements[static_cast<std::size_t>(kind)]) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int32_t* corner = table.nodes_of(ue);
      double mean[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < n; ++a)
        for (std::size_t d = 0; d < 3; ++d)
          mean[d] += corner_share(sm, kind, ue, a, n) * x[3 * static_cast<std::size_t>(corner[a]) + d];
      for (int a = 0; a < n; ++a) {
        const double weight = c * corner_share(sm, kind, ue, a, n) * added[ue];
        const std::size_t i = 3 * static_cast<std::size_t>(corner[a]);
        for (std::size_t d = 0; d < 3; ++d) y[i + d] += weight * (x[i + d] - mean[d]);
      }
    }
  }
}

// The held parts of a solve vector set to 0: the held dofs, a wall's normal (eq. SM-4), a body's held rotations.
void project_on_solved(const SelectiveMassState& sm, std::vector<double>& v) {
  for (std::size_t i = 0; i < sm.body_rotation_solved.size(); ++i)
    for (std::size_t d = 0; d < 3; ++d)
      if (!(sm.body_rotation_solved[i] & (1u << d))) v[3 * sm.solved.size() + 3 * i + d] = 0.0;
  for (std::size_t k = 0; k < sm.solved.size(); ++k) {
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
  sm.spread = p;
  spread_bodies(s, sm.spread);
  for (std::size_t k = 0; k < nodes; ++k)
    for (std::size_t d = 0; d < 3; ++d) q[3 * k + d] = sm.solved[k] & (1u << d) ? lumped_mass(s, k) * p[3 * k + d] : 0.0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {  // the body's inertia tensor (global axes) on its rotation
    const double* inertia = &sm.body_inertia[9 * i];
    const double* theta = &p[3 * nodes + 3 * i];
    for (std::size_t r = 0; r < 3; ++r)
      q[3 * nodes + 3 * i + r] = inertia[3 * r] * theta[0] + inertia[3 * r + 1] * theta[1] + inertia[3 * r + 2] * theta[2];
  }
  add_element_mass_product(m, sm, sm.element_added, sm.scaled, sm.spread, q);
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
  size_state(m, s);
  SelectiveMassState& sm = s.selective_mass;
  const SelectiveMassControl& ams = m.run.dt_ams;
  const double scale = ams.scale_or_default();
  sm.node_added_before.swap(sm.node_added);
  sm.node_added.assign(s.nodes.size(), 0.0);
  for (ElementKind kind : kKinds) {
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
      const double c = coupling_factor(n);
      for (int a = 0; a < n; ++a) {
        const double f = corner_share(sm, kind, e, a, n);
        sm.node_added[static_cast<std::size_t>(table.nodes_of(e)[a])] += c * f * (1.0 - f) * added[e];  // eq. SM-3
      }
    }
  }
  // What each element's matrix changed by since the last cycle (eq. SM-5a); none at the first, whose velocities
  // are taken as moving with the scaled mass already.
  for (ElementKind kind : kKinds) {
    const auto k = static_cast<std::size_t>(kind);
    if (!sm.started) sm.element_added_before[k] = sm.element_added[k], sm.node_added_before = sm.node_added;
    sm.changed[k].clear();
    for (std::size_t e = 0; e < sm.element_added[k].size(); ++e) {
      sm.element_change[k][e] = sm.element_added[k][e] - sm.element_added_before[k][e];
      if (sm.element_change[k][e] != 0.0) sm.changed[k].push_back(static_cast<std::int32_t>(e));
    }
  }
  sm.started = true;
}

double velocity_change_mass(const SolverState& s, std::size_t k, std::size_t d) {
  const SelectiveMassState& sm = s.selective_mass;
  if (sm.solved_cycle != s.cycle || !(sm.solved[k] & (1u << d))) return s.nodes.mass[k];
  return sm.diagonal_mass[k];  // eq. SM-4b
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

// The right-hand side and the Jacobi preconditioner D = diag(M + dM) on the solved dofs; the first guess D^-1 b.
// The matrix changes as the elements' steps do: the update keeps the momentum (M + dM) v through the change, so
// b = F - (dM^n - dM^(n-1)) v^(n-1/2) / dt^n (eq. SM-5a), and no kinetic energy comes from the mass itself.
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
  const std::size_t nodes = n.size();
  for (std::size_t k = 0; k < nodes; ++k) {
    const double f[3] = {n.fx[k], n.fy[k], n.fz[k]};  // a rigid body's: gathered at its main node
    for (std::size_t d = 0; d < 3; ++d) sm.b[3 * k + d] = f[d] - sm.q[3 * k + d];
    sm.diagonal_mass[k] = lumped_mass(s, k) + sm.node_added[k];
  }
  for (std::size_t k = 0; k < nodes; ++k)
    for (std::size_t d = 0; d < 3; ++d) sm.diagonal[3 * k + d] = (sm.solved[k] & (1u << d)) ? sm.diagonal_mass[k] : 0.0;
  // A body: the torque about its centre on its rotation; its diagonal, its mass and inertia with its nodes' added
  // mass (at their arms for the rotation).
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    const auto main = static_cast<std::size_t>(b.main_node);
    const std::size_t rotation = 3 * nodes + 3 * i;
    const double torque[3] = {n.mx[main], n.my[main], n.mz[main]};
    for (std::size_t d = 0; d < 3; ++d) sm.b[rotation + d] = in_solve(b) ? torque[d] - sm.q[rotation + d] : 0.0;
    if (!in_solve(b)) continue;
    double inertia[3] = {sm.body_inertia[9 * i], sm.body_inertia[9 * i + 4], sm.body_inertia[9 * i + 8]};
    for (std::int32_t k : b.secondary) {
      const double added = sm.node_added[static_cast<std::size_t>(k)];
      const Vec3 r = arm(s, b, k);
      sm.diagonal_mass[main] += added;
      for (std::size_t d = 0; d < 3; ++d) inertia[d] += added * (dot(r, r) - r[d] * r[d]);
    }
    for (std::size_t d = 0; d < 3; ++d) {
      sm.diagonal[3 * main + d] = (sm.solved[main] & (1u << d)) ? sm.diagonal_mass[main] : 0.0;
      sm.diagonal[rotation + d] = (sm.body_rotation_solved[i] & (1u << d)) ? inertia[d] : 0.0;
    }
  }
  gather_bodies(s, sm.b);
  project_on_solved(sm, sm.b);
  for (std::size_t i = 0; i < sm.b.size(); ++i) sm.x[i] = sm.diagonal[i] > 0.0 ? sm.b[i] / sm.diagonal[i] : 0.0;
}

void precondition(SelectiveMassState& sm) {
  for (std::size_t i = 0; i < sm.r.size(); ++i) sm.z[i] = sm.diagonal[i] > 0.0 ? sm.r[i] / sm.diagonal[i] : 0.0;
}

SelectiveSolve solve_selective_mass(const Model& m, SolverState& s, double dt_average) {
  SelectiveMassState& sm = s.selective_mass;
  const SelectiveMassControl& ams = m.run.dt_ams;
  hold_constrained_dofs(m, s);
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
  // The held dofs take the diagonal answer F / m: their conditions set the velocity after the update. Along a
  // wall's normal, on the scaled diagonal, in case the node leaves the wall this step.
  const NodalState& n = s.nodes;
  for (std::size_t k = 0; k < n.size(); ++k) {
    const double f[3] = {n.fx[k], n.fy[k], n.fz[k]};
    const double* normal = &sm.wall_normal[3 * k];
    const double f_normal = f[0] * normal[0] + f[1] * normal[1] + f[2] * normal[2];
    const double scaled_mass = sm.diagonal_mass[k];
    double* a[3] = {&sm.ax[k], &sm.ay[k], &sm.az[k]};
    for (std::size_t d = 0; d < 3; ++d)
      *a[d] = (sm.solved[k] & (1u << d)) ? sm.x[3 * k + d] + (scaled_mass > 0.0 ? normal[d] * f_normal / scaled_mass : 0.0)
              : n.mass[k] > 0.0           ? f[d] / n.mass[k]
                                          : 0.0;
  }
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
  ++sm.solves, sm.iterations += it, sm.max_iterations = std::max(sm.max_iterations, it);
  return {it, rz <= target, reference > 0.0 ? std::sqrt(rz / reference) : 0.0};
}

double selective_mass_kinetic_energy(const Model& m, const SolverState& s) {
  const SelectiveMassState& sm = s.selective_mass;
  if (sm.node_added.empty()) return 0.0;
  const NodalState& n = s.nodes;
  double sum = 0.0;
  for (ElementKind kind : kKinds) {
    const ElementTable& table = m.elements[static_cast<int>(kind)];
    const std::vector<double>& added = sm.element_added[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(kind);
    for (std::int32_t e : sm.scaled[static_cast<std::size_t>(kind)]) {
      const auto ue = static_cast<std::size_t>(e);
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
        sum += 0.5 * coupling_factor(count) * corner_share(sm, kind, ue, a, count) * added[ue] *
               (dx * dx + dy * dy + dz * dz);
      }
    }
  }
  return sum;
}

}  // namespace crumple::solver
