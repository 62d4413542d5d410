// Rigid walls (/RWALL): kinematic, impenetrable surfaces for their secondary nodes (docs/theory/rigid-walls.md).
#include <algorithm>
#include <cmath>

#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

using V3 = std::array<double, 3>;
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 scaled(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// Signed distance of p from the wall and the outward normal there; false when p is beside a finite wall.
// The model build gives the unit normal or axis (RigidWall::direction).
bool distance(const RigidWall& w, const V3& origin, const V3& p, double& d, V3& normal) {
  const V3 r = sub(p, origin);
  switch (w.shape) {
    case RigidWallShape::Plane:
      normal = w.direction;
      d = dot(r, normal);
      return true;
    case RigidWallShape::Cylinder: {
      const V3 radial = sub(r, scaled(w.direction, dot(r, w.direction)));
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
      const V3 a = sub(w.point1, w.point), b = sub(w.point2, w.point);
      const double u = dot(r, a) / dot(a, a), v = dot(r, b) / dot(b, b);
      if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return false;
      normal = w.direction;
      d = dot(r, normal);
      return true;
    }
  }
  return false;
}

}  // namespace

void setup_rigid_walls(const Model& m, SolverState& s) {
  for (const RigidWall& w : m.rigid_walls) {
    RigidWallState state;
    state.nodes = w.secondary_nodes;
    state.tied.assign(state.nodes.size(), 0);
    state.origin = w.point;
    state.velocity = w.velocity0;
    s.walls.push_back(std::move(state));
  }
}

void apply_rigid_walls(const Model& m, SolverState& s, double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  for (std::size_t iw = 0; iw < m.rigid_walls.size(); ++iw) {
    const RigidWall& w = m.rigid_walls[iw];
    RigidWallState& st = s.walls[iw];
    if (w.node >= 0) {
      // A wall driven by its node moves with it (the node's velocity is already final for this step).
      const auto k = static_cast<std::size_t>(w.node);
      st.velocity = {n.vx[k], n.vy[k], n.vz[k]};
      st.origin = {n.x[k], n.y[k], n.z[k]};
    }
    V3 impulse{};
    for (std::size_t i = 0; i < st.nodes.size(); ++i) {
      const auto k = static_cast<std::size_t>(st.nodes[i]);
      V3 v{n.vx[k], n.vy[k], n.vz[k]};
      const V3 before = v;
      V3 rel = sub(v, st.velocity);
      if (st.tied[i]) {
        v = st.velocity;
      } else {
        double d = 0.0;
        V3 normal{};
        if (!distance(w, st.origin, {n.x[k], n.y[k], n.z[k]}, d, normal)) continue;
        const double vn = dot(rel, normal);
        // Impenetrability at the end of the step (eq. RW-1): d + vn dt >= 0, without pulling a node that
        // starts inside the wall back out in one step.
        if (d + vn * dt_next >= 0.0) continue;
        const double vn_new = d > 0.0 ? -d / dt_next : std::max(vn, 0.0);
        const double dvn = vn_new - vn;
        V3 tangential = sub(rel, scaled(normal, vn));
        if (w.slide == WallSliding::Tied) {
          st.tied[i] = 1;
          tangential = {0.0, 0.0, 0.0};
        } else if (w.slide == WallSliding::Friction && w.friction > 0.0) {
          // Coulomb: the tangential impulse is at most mu times the normal impulse.
          const double vt = std::sqrt(dot(tangential, tangential));
          if (vt > 0.0) tangential = scaled(tangential, std::max(0.0, 1.0 - w.friction * dvn / vt));
        }
        for (int d3 = 0; d3 < 3; ++d3) {
          const auto c = static_cast<std::size_t>(d3);
          v[c] = st.velocity[c] + tangential[c] + normal[c] * vn_new;
        }
      }
      n.vx[k] = v[0], n.vy[k] = v[1], n.vz[k] = v[2];
      for (int d3 = 0; d3 < 3; ++d3) {
        const auto c = static_cast<std::size_t>(d3);
        impulse[c] += n.mass[k] * (v[c] - before[c]);
      }
    }
    // A moving wall with a mass takes the opposite impulse (momentum is exchanged, not created).
    if (w.node >= 0 && w.mass > 0.0) {
      const auto k = static_cast<std::size_t>(w.node);
      n.vx[k] -= impulse[0] / n.mass[k], n.vy[k] -= impulse[1] / n.mass[k], n.vz[k] -= impulse[2] / n.mass[k];
    }
    // Force of the wall on its nodes during the cycle (the listing reports it; the wall takes the opposite).
    for (int d3 = 0; d3 < 3; ++d3)
      st.force[static_cast<std::size_t>(d3)] = dt_average > 0.0 ? impulse[static_cast<std::size_t>(d3)] / dt_average : 0.0;
  }
}

}  // namespace crumple::solver
