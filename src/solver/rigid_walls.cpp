// Rigid walls (/RWALL): kinematic, impenetrable surfaces for their secondary nodes (docs/theory/rigid-walls.md).
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "crumple/core/geometry.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {



// Signed distance of p from the wall and the outward normal there; false when p is beside a finite wall.
// The model build gives the unit normal or axis (RigidWall::direction).
bool distance(const RigidWall& w, const Vec3& origin, const Vec3& p, double& d, Vec3& normal) {
  const Vec3 r = p - origin;
  switch (w.shape) {
    case RigidWallShape::Plane:
      normal = w.direction;
      d = dot(r, normal);
      return true;
    case RigidWallShape::Cylinder: {
      const Vec3 radial = r - scaled(w.direction, dot(r, w.direction));
      const double rho = std::sqrt(dot(radial, radial));
      if (rho <= 0.0) return false;
      normal = scaled(radial, 1.0 / rho);
      d = rho - 0.5 * w.diameter;
      return true;
    }
    case RigidWallShape::Sphere: {
      const double rho = std::sqrt(dot(r, r));
      if (rho <= 0.0) return false;
      normal = scaled(r, 1.0 / rho);
      d = rho - 0.5 * w.diameter;
      return true;
    }
    case RigidWallShape::Parallelogram: {
      const Vec3 a = w.point1 - w.point, b = w.point2 - w.point;
      const double u = dot(r, a) / dot(a, a), v = dot(r, b) / dot(b, b);
      if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return false;
      normal = w.direction;
      d = dot(r, normal);
      return true;
    }
  }
  return false;
}


// Translation dofs of node k (bit 0 x, 1 y, 2 z) that neither /BCS nor an imposed velocity or displacement hold.
std::uint8_t free_translation_dofs(const Model& m, const SolverState& s, std::int32_t k) {
  std::uint8_t free = static_cast<std::uint8_t>(~s.fixed[static_cast<std::size_t>(k)] & 7u);
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind == ImposedKind::Force || is_rotation(im.dof)) continue;
    const auto& nodes = m.node_groups[static_cast<std::size_t>(im.node_group)].nodes;
    if (std::find(nodes.begin(), nodes.end(), k) != nodes.end())
      free = static_cast<std::uint8_t>(free & ~(1u << dof_axis(im.dof)));
  }
  return free;
}


// The rigid body whose main node k is (its centre of mass, eq. RB-0), or null: a wall that holds it holds the body,
// whose mass takes the impulse (eq. RW-3).
RigidBodyState* body_of_main_node(SolverState& s, std::size_t k) {
  const std::int32_t owner = s.rigid_owner[k];
  if (owner < 0) return nullptr;
  RigidBodyState& b = s.bodies[static_cast<std::size_t>(owner)];
  return b.active && static_cast<std::size_t>(b.main_node) == k ? &b : nullptr;
}

// The mass a wall's held node brings to the impulse: its own, or its body's.
double held_mass(SolverState& s, std::size_t k) {
  const RigidBodyState* body = body_of_main_node(s, k);
  return body != nullptr ? body->mass : s.nodes.mass[k];
}

// The body of a held main node moves with it: its translation changes by the node's, its secondary nodes with it
// (their spin about the centre is the body's own, untouched by a force through the centre).
void move_body_with_main_node(SolverState& s, RigidBodyState& b, const Vec3& change) {
  NodalState& n = s.nodes;
  for (std::size_t d = 0; d < 3; ++d) b.velocity[d] += change[d];
  for (std::int32_t node : b.secondary) {
    const auto k = static_cast<std::size_t>(node);
    n.vx[k] += change[0], n.vy[k] += change[1], n.vz[k] += change[2];
  }
}

// Whether the wall moving at `wall_velocity` holds node k moving at `velocity` over the step (eq. RW-1): it would
// cross the wall, or it is tied to it and does not pull away. Gives the normal and the normal velocity relative to
// the wall it ends with.
bool holds_at(const RigidWall& w, const RigidWallState& st, std::size_t i, const NodalState& n, const Vec3& velocity,
              const Vec3& wall_velocity, double dt_next, Vec3& normal, double& vn_new) {
  const auto k = static_cast<std::size_t>(st.nodes[i]);
  double d = 0.0;
  if (!distance(w, st.origin, {n.x[k], n.y[k], n.z[k]}, d, normal)) return st.tied[i] != 0;
  const double vn = dot(velocity - wall_velocity, normal);
  // Impenetrability at the end of the step: a node that would cross the wall stops where it is (it ends the step
  // at its distance d >= 0, as the reference's nodes do), without pulling a node that starts inside the wall back
  // out in one step.
  vn_new = d > 0.0 ? 0.0 : std::max(vn, 0.0);
  // A tied node stays while it presses on the wall or slides along it, and leaves when it pulls away (eq. RW-1a).
  if (st.tied[i] != 0) return vn <= 0.0;
  // A node inside the wall that moves out of it is left alone: held, it would only carry the wall's velocity, and a
  // light moving wall's exchange would then pull it along (eq. RW-1).
  if (d <= 0.0 && vn >= 0.0) return false;
  return d + vn * dt_next < 0.0;
}

bool holds(const RigidWall& w, const RigidWallState& st, std::size_t i, const NodalState& n, const Vec3& wall_velocity,
           double dt_next, Vec3& normal, double& vn_new) {
  const auto k = static_cast<std::size_t>(st.nodes[i]);
  return holds_at(w, st, i, n, node_velocity(n, k), wall_velocity, dt_next, normal, vn_new);
}

// Velocity of a moving wall after it takes the reaction of the nodes it holds (eq. RW-2): with M the wall node's
// mass, (M I + sum m_i n_i n_i^T) V' = M V + sum m_i (v_i . n_i - vn_i') n_i over the held nodes (m_i I and
// m_i v_i for tied ones), which conserves momentum and leaves every held node on the wall. Dofs in which the
// wall node is driven keep V. The set of held nodes depends on V': a few passes settle it.
// The sums run over the held nodes each domain owns, exactly, combined over the domains (docs/parallel.md), and
// whether the held set changed is combined too, so that every domain takes the same passes and the same V'.
Vec3 exchanged_velocity(const RigidWall& w, RigidWallState& st, SolverState& s, double dt_next) {
  const NodalState& n = s.nodes;
  const double wall_mass = n.mass[static_cast<std::size_t>(w.node)];
  Vec3 velocity = st.velocity;
  std::fill(st.active.begin(), st.active.end(), 0);
  std::vector<ExactSum>& sums = s.reducer.sums;
  std::vector<std::int32_t>& changed = s.reducer.flags;
  for (int pass = 0; pass < 4; ++pass) {
    sums.assign(12, ExactSum{});  // a (row by row), then b
    changed.assign(1, 0);
    for (std::size_t i = 0; i < st.nodes.size(); ++i) {
      const auto k = static_cast<std::size_t>(st.nodes[i]);
      if (!s.domain.owns(k)) continue;
      Vec3 normal{};
      double vn_new = 0.0;
      const bool held = holds(w, st, i, n, velocity, dt_next, normal, vn_new);
      if (held != (st.active[i] != 0)) changed[0] = 1;
      st.active[i] = held;
      if (!held) continue;
      const Eigen::Vector3d v(n.vx[k], n.vy[k], n.vz[k]), nn(normal[0], normal[1], normal[2]);
      const double mass = held_mass(s, k);
      Eigen::Matrix3d a_node;
      Eigen::Vector3d b_node;
      if (st.tied[i] != 0 || w.slide == WallSliding::Tied) {
        a_node = mass * Eigen::Matrix3d::Identity(), b_node = mass * v;
      } else {
        a_node = mass * nn * nn.transpose(), b_node = mass * (v.dot(nn) - vn_new) * nn;
      }
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) sums[static_cast<std::size_t>(3 * r + c)].add(a_node(r, c));
        sums[static_cast<std::size_t>(9 + r)].add(b_node(r));
      }
    }
    s.reducer.sum(sums);
    s.reducer.max(changed);
    Eigen::Matrix3d a = wall_mass * Eigen::Matrix3d::Identity();
    Eigen::Vector3d b = wall_mass * Eigen::Vector3d(st.velocity[0], st.velocity[1], st.velocity[2]);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) a(r, c) += sums[static_cast<std::size_t>(3 * r + c)].value();
      b(r) += sums[static_cast<std::size_t>(9 + r)].value();
    }
    for (int d = 0; d < 3; ++d)
      if (!(st.free_dofs & (1u << d))) a.row(d) = Eigen::RowVector3d::Unit(d), b(d) = st.velocity[static_cast<std::size_t>(d)];
    const Eigen::Vector3d solved = a.partialPivLu().solve(b);
    velocity = {solved(0), solved(1), solved(2)};
    if (changed[0] == 0 && pass > 0) break;
  }
  return velocity;
}

}  // namespace

void setup_rigid_walls(const Model& m, SolverState& s) {
  NodalState& n = s.nodes;
  // A node tied by an /INTER/TYPE2 moves with its segment and has no mass to hold: walls leave it out, as the
  // reference does (its starter: "secondary nodes of interfaces type 2 suppressed from rigid walls"); its segment's
  // nodes are held instead (TI-14).
  const std::vector<const Tie*> tie_of = ties_by_node(m);
  for (const RigidWall& w : m.rigid_walls) {
    RigidWallState state;
    for (std::int32_t node : w.secondary_nodes)
      if (tie_of[static_cast<std::size_t>(node)] == nullptr) state.nodes.push_back(node);
    state.tied.assign(state.nodes.size(), 0);
    state.active.assign(state.nodes.size(), 0);
    state.held_normal.assign(3 * state.nodes.size(), 0.0);
    state.held_tied.assign(state.nodes.size(), 0);
    state.held_speed.assign(state.nodes.size(), 0.0);
    state.origin = w.point;
    state.velocity = w.velocity0;
    if (w.node >= 0) {
      // A moving wall is its node: the wall's initial velocity is the node's (it replaces an /INIVEL there).
      const auto k = static_cast<std::size_t>(w.node);
      if (w.velocity0 != Vec3{}) n.vx[k] = w.velocity0[0], n.vy[k] = w.velocity0[1], n.vz[k] = w.velocity0[2];
      state.velocity = node_velocity(n, k);
      state.free_dofs = free_translation_dofs(m, s, w.node);
    }
    s.walls.push_back(std::move(state));
  }
}

void predict_wall_holds(const Model& m, SolverState& s, double dt_average, double dt_next) {
  const NodalState& n = s.nodes;
  const std::vector<double>& added = s.selective_mass.node_added;
  for (std::size_t iw = 0; iw < m.rigid_walls.size(); ++iw) {
    const RigidWall& w = m.rigid_walls[iw];
    RigidWallState& st = s.walls[iw];
    for (std::size_t i = 0; i < st.nodes.size(); ++i) {
      // The node's velocity after the update on its scaled diagonal: a trial that tells which nodes the wall will
      // hold, and the normal velocity it will leave them.
      const auto k = static_cast<std::size_t>(st.nodes[i]);
      const double mass = n.mass[k] + (added.empty() ? 0.0 : added[k]);
      const double rate = mass > 0.0 ? dt_average / mass : 0.0;
      const Vec3 trial{n.vx[k] + rate * n.fx[k], n.vy[k] + rate * n.fy[k], n.vz[k] + rate * n.fz[k]};
      Vec3 normal{};
      double vn_new = 0.0;
      st.active[i] = holds_at(w, st, i, n, trial, st.velocity, dt_next, normal, vn_new);
      if (!st.active[i]) continue;
      for (std::size_t d = 0; d < 3; ++d) st.held_normal[3 * i + d] = normal[d];
      st.held_tied[i] = st.tied[i] != 0 || w.slide == WallSliding::Tied;
      st.held_speed[i] = dot(st.velocity, normal) + vn_new;  // the normal velocity the wall leaves it [L/T]
    }
  }
}

namespace {

// Under selective mass scaling the solve has held the wall's nodes already (SM-4): their impulses are the
// reactions it found (SM-4c), each taken once, by the first wall that holds the node.
void add_solved_reactions(SolverState& s, const RigidWallState& st, double dt_average, std::vector<ExactSum>& sums) {
  SelectiveMassState& sm = s.selective_mass;
  for (std::int32_t node : st.nodes) {
    const auto k = static_cast<std::size_t>(node);
    if (!s.domain.owns(k)) continue;
    double* reaction = &sm.wall_reaction[3 * k];
    const double* normal = &sm.wall_normal[3 * k];
    const double along = (reaction[0] * normal[0] + reaction[1] * normal[1] + reaction[2] * normal[2]) * dt_average;
    for (std::size_t c = 0; c < 3; ++c) {
      sums[c].add(reaction[c] * dt_average), sums[3 + c].add(along * normal[c]);
      reaction[c] = 0.0;
    }
  }
}

}  // namespace

void apply_rigid_walls(const Model& m, SolverState& s, double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  for (std::size_t iw = 0; iw < m.rigid_walls.size(); ++iw) {
    const RigidWall& w = m.rigid_walls[iw];
    RigidWallState& st = s.walls[iw];
    const bool moving = w.node >= 0;
    if (moving) {  // the wall moves with its node, whose velocity is the free update's (or its imposed one)
      const auto k = static_cast<std::size_t>(w.node);
      st.velocity = node_velocity(n, k);
      st.origin = {n.x[k], n.y[k], n.z[k]};
    }
    const bool exchange = moving && st.free_dofs != 0 && n.mass[static_cast<std::size_t>(w.node)] > 0.0;
    const Vec3 wall_velocity = exchange ? exchanged_velocity(w, st, s, dt_next) : st.velocity;
    // The held local nodes take the wall's velocity; the impulses are exact sums over the owned ones.
    std::vector<ExactSum>& sums = s.reducer.sums;
    sums.assign(6, ExactSum{});  // impulse x y z, its normal part x y z
    for (std::size_t i = 0; i < st.nodes.size(); ++i) {
      const auto k = static_cast<std::size_t>(st.nodes[i]);
      if (!s.domain.is_local(k)) continue;
      Vec3 normal{};
      double vn_new = 0.0;
      if (!holds(w, st, i, n, wall_velocity, dt_next, normal, vn_new)) {
        st.tied[i] = 0;  // a tied node that pulls away is free until it touches again (eq. RW-1a)
        continue;
      }
      const Vec3 before = node_velocity(n, k);
      const Vec3 rel = before - wall_velocity;
      Vec3 v = wall_velocity;  // tied
      if (st.tied[i] == 0) {
        const double vn = dot(rel, normal);
        const double dvn = vn_new - vn;
        Vec3 tangential = rel - scaled(normal, vn);
        if (w.slide == WallSliding::Tied) {
          st.tied[i] = 1;
          tangential = {0.0, 0.0, 0.0};
        } else if (w.slide == WallSliding::Friction && w.friction > 0.0) {
          // Coulomb: the tangential impulse is at most mu times the normal one.
          const double vt = std::sqrt(dot(tangential, tangential));
          if (vt > 0.0) tangential = scaled(tangential, std::max(0.0, 1.0 - w.friction * dvn / vt));
        }
        for (std::size_t c = 0; c < 3; ++c) v[c] = wall_velocity[c] + tangential[c] + normal[c] * vn_new;
      }
      n.vx[k] = v[0], n.vy[k] = v[1], n.vz[k] = v[2];
      // A body's main node: every domain advances it alike, and moves the body with it.
      if (RigidBodyState* body = body_of_main_node(s, k)) move_body_with_main_node(s, *body, v - before);
      if (!s.domain.owns(k)) continue;
      const double mass = held_mass(s, k);
      for (std::size_t c = 0; c < 3; ++c) sums[c].add(mass * (v[c] - before[c]));
      // Its part along the wall's normal at the node, for the normal and tangential wall forces of the outputs.
      const double along_normal = mass * dot(v - before, normal);
      for (std::size_t c = 0; c < 3; ++c) sums[3 + c].add(along_normal * normal[c]);
    }
    if (s.selective_mass.solved_cycle == s.cycle) add_solved_reactions(s, st, dt_average, sums);
    s.reducer.sum(sums);
    const Vec3 impulse{sums[0].value(), sums[1].value(), sums[2].value()};
    const Vec3 normal_impulse{sums[3].value(), sums[4].value(), sums[5].value()};
    // A moving wall takes the opposite impulse in its free dofs (momentum is exchanged, not created).
    if (exchange) {
      const auto k = static_cast<std::size_t>(w.node);
      const double mass = n.mass[k];
      std::vector<double>* v[3] = {&n.vx, &n.vy, &n.vz};
      for (std::size_t c = 0; c < 3; ++c)
        if (st.free_dofs & (1u << c)) (*v[c])[k] = st.velocity[c] - impulse[c] / mass;
      st.velocity = node_velocity(n, k);
    }
    // Force of the wall on its nodes during the cycle (the listing reports it; the wall takes the opposite).
    for (std::size_t c = 0; c < 3; ++c) {
      st.force[c] = dt_average > 0.0 ? impulse[c] / dt_average : 0.0;
      st.normal_force[c] = dt_average > 0.0 ? normal_impulse[c] / dt_average : 0.0;
    }
  }
}

}  // namespace crumple::solver
