// Rigid bodies (/RBODY): mass and inertia from the nodes, 6-dof motion driven by the gathered nodal forces,
// exact rigid placement of the secondary nodes every cycle (docs/theory/rigid-bodies.md).
#include <cmath>

#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

using Mat3 = std::array<double, 9>;
using V3 = std::array<double, 3>;

V3 mul(const Mat3& a, const V3& v) {
  return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
          a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}
Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(3 * i + j)] += a[static_cast<std::size_t>(3 * i + k)] * b[static_cast<std::size_t>(3 * k + j)];
  return c;
}
Mat3 transpose(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Solves I w = L for a symmetric positive semi-definite I; directions of zero inertia get no rotation.
V3 solve(const Mat3& I, const V3& L) {
  const double det = I[0] * (I[4] * I[8] - I[5] * I[7]) - I[1] * (I[3] * I[8] - I[5] * I[6]) +
                     I[2] * (I[3] * I[7] - I[4] * I[6]);
  const double scale = std::abs(I[0]) + std::abs(I[4]) + std::abs(I[8]);
  if (!(std::abs(det) > 1e-30 * scale * scale * scale)) return {0.0, 0.0, 0.0};
  const Mat3 inv{(I[4] * I[8] - I[5] * I[7]) / det, (I[2] * I[7] - I[1] * I[8]) / det, (I[1] * I[5] - I[2] * I[4]) / det,
                 (I[5] * I[6] - I[3] * I[8]) / det, (I[0] * I[8] - I[2] * I[6]) / det, (I[2] * I[3] - I[0] * I[5]) / det,
                 (I[3] * I[7] - I[4] * I[6]) / det, (I[1] * I[6] - I[0] * I[7]) / det, (I[0] * I[4] - I[1] * I[3]) / det};
  return mul(inv, L);
}

// Rotation by the vector phi (Rodrigues): exp([phi]x).
Mat3 rotation_of(const V3& phi) {
  const double angle = std::sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]);
  if (angle < 1e-300) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const V3 k{phi[0] / angle, phi[1] / angle, phi[2] / angle};
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {t * k[0] * k[0] + c,        t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1],
          t * k[0] * k[1] + s * k[2], t * k[1] * k[1] + c,        t * k[1] * k[2] - s * k[0],
          t * k[0] * k[2] - s * k[1], t * k[1] * k[2] + s * k[0], t * k[2] * k[2] + c};
}

V3 position(const NodalState& n, std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.x[k], n.y[k], n.z[k]};
}

}  // namespace

void setup_rigid_bodies(const Model& m, SolverState& s) {
  NodalState& n = s.nodes;
  for (const RigidBody& rb : m.rigid_bodies) {
    RigidBodyState b;
    b.main_node = rb.main_node;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(rb.node_group)].nodes)
      if (node != rb.main_node) b.secondary.push_back(node);
    // Centre of mass of the secondary nodes and the main node; the main node moves there (ICOG 1).
    const auto main = static_cast<std::size_t>(rb.main_node);
    double mass = n.mass[main];
    V3 cog = position(n, rb.main_node), momentum{};
    for (int d = 0; d < 3; ++d) cog[static_cast<std::size_t>(d)] *= mass;
    momentum = {mass * n.vx[main], mass * n.vy[main], mass * n.vz[main]};
    for (std::int32_t node : b.secondary) {
      const auto k = static_cast<std::size_t>(node);
      const V3 p = position(n, node);
      for (int d = 0; d < 3; ++d) cog[static_cast<std::size_t>(d)] += n.mass[k] * p[static_cast<std::size_t>(d)];
      momentum[0] += n.mass[k] * n.vx[k], momentum[1] += n.mass[k] * n.vy[k], momentum[2] += n.mass[k] * n.vz[k];
      mass += n.mass[k];
      s.rigid_owner[k] = static_cast<std::int32_t>(s.bodies.size());
    }
    b.mass = mass;
    for (auto& c : cog) c /= mass;
    n.x[main] = cog[0], n.y[main] = cog[1], n.z[main] = cog[2];
    s.x0[main] = cog[0], s.y0[main] = cog[1], s.z0[main] = cog[2];
    // Inertia about the centre of mass: the nodes' point masses plus the card's added inertia.
    Mat3 I{rb.inertia[0], rb.inertia[3], rb.inertia[5], rb.inertia[3], rb.inertia[1], rb.inertia[4],
           rb.inertia[5], rb.inertia[4], rb.inertia[2]};
    b.inertia_added = I;
    V3 angular{};
    for (std::int32_t node : b.secondary) {
      const auto k = static_cast<std::size_t>(node);
      const V3 p = position(n, node);
      const V3 r{p[0] - cog[0], p[1] - cog[1], p[2] - cog[2]};
      b.rx.push_back(r[0]), b.ry.push_back(r[1]), b.rz.push_back(r[2]);
      const double mk = n.mass[k], rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          I[static_cast<std::size_t>(3 * i + j)] += mk * ((i == j ? rr : 0.0) - r[static_cast<std::size_t>(i)] * r[static_cast<std::size_t>(j)]);
      const V3 h = cross(r, {n.vx[k], n.vy[k], n.vz[k]});
      for (int d = 0; d < 3; ++d) angular[static_cast<std::size_t>(d)] += mk * h[static_cast<std::size_t>(d)];
    }
    b.inertia_body = I;
    b.momentum_angular = angular;
    b.omega = solve(I, angular);
    // The body starts with one velocity field: the mean translation plus the rotation.
    const V3 velocity{momentum[0] / mass, momentum[1] / mass, momentum[2] / mass};
    b.velocity = velocity;
    n.vx[main] = velocity[0], n.vy[main] = velocity[1], n.vz[main] = velocity[2];
    n.wx[main] = b.omega[0], n.wy[main] = b.omega[1], n.wz[main] = b.omega[2];
    for (std::size_t i = 0; i < b.secondary.size(); ++i) {
      const auto k = static_cast<std::size_t>(b.secondary[i]);
      const V3 spin = cross(b.omega, {b.rx[i], b.ry[i], b.rz[i]});
      n.vx[k] = velocity[0] + spin[0], n.vy[k] = velocity[1] + spin[1], n.vz[k] = velocity[2] + spin[2];
    }
    s.bodies.push_back(std::move(b));
  }
}

void gather_rigid_body_forces(SolverState& s) {
  NodalState& n = s.nodes;
  for (RigidBodyState& b : s.bodies) {
    const auto main = static_cast<std::size_t>(b.main_node);
    const V3 cog = position(n, b.main_node);
    for (std::int32_t node : b.secondary) {
      const auto k = static_cast<std::size_t>(node);
      const V3 r{n.x[k] - cog[0], n.y[k] - cog[1], n.z[k] - cog[2]};
      const V3 f{n.fx[k], n.fy[k], n.fz[k]};
      const V3 t = cross(r, f);
      n.fx[main] += f[0], n.fy[main] += f[1], n.fz[main] += f[2];
      n.mx[main] += t[0] + n.mx[k], n.my[main] += t[1] + n.my[k], n.mz[main] += t[2] + n.mz[k];
      n.fx[k] = n.fy[k] = n.fz[k] = n.mx[k] = n.my[k] = n.mz[k] = 0.0;
    }
  }
}

void update_rigid_bodies(SolverState& s, double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  for (RigidBodyState& b : s.bodies) {
    const auto main = static_cast<std::size_t>(b.main_node);
    // Newton for the whole body (eq. RB-1): the gathered force over the total mass.
    for (int d = 0; d < 3; ++d)
      b.velocity[static_cast<std::size_t>(d)] +=
          dt_average * (d == 0 ? n.fx[main] : d == 1 ? n.fy[main] : n.fz[main]) / b.mass;
    const V3 velocity = b.velocity;
    // Angular momentum about the centre of mass: dL/dt = torque (eq. RB-2); omega = I(t)^-1 L.
    for (int d = 0; d < 3; ++d)
      b.momentum_angular[static_cast<std::size_t>(d)] += dt_average * (d == 0 ? n.mx[main] : d == 1 ? n.my[main] : n.mz[main]);
    // omega belongs to the half step (eq. RB-2b): take it from the inertia at the mid-step attitude, predicted
    // with the attitude-of-t^n omega. The explicit Lie-Euler step (omega at t^n) lets the kinetic energy of a
    // tumbling body drift at first order in dt; the mid-step attitude makes the update second order.
    auto omega_at = [&](const Mat3& attitude) {
      return solve(mul(mul(attitude, b.inertia_body), transpose(attitude)), b.momentum_angular);
    };
    const V3 omega_start = omega_at(b.rotation);
    const double half = 0.5 * dt_next;
    b.omega = omega_at(mul(rotation_of({omega_start[0] * half, omega_start[1] * half, omega_start[2] * half}), b.rotation));
    n.vx[main] = velocity[0], n.vy[main] = velocity[1], n.vz[main] = velocity[2];
    n.wx[main] = b.omega[0], n.wy[main] = b.omega[1], n.wz[main] = b.omega[2];
    // Secondary nodes: velocities that land them exactly on the rigid placement at t^(n+1) (eq. RB-3).
    const Mat3 next = mul(rotation_of({b.omega[0] * dt_next, b.omega[1] * dt_next, b.omega[2] * dt_next}), b.rotation);
    const V3 cog_next{n.x[main] + velocity[0] * dt_next, n.y[main] + velocity[1] * dt_next,
                      n.z[main] + velocity[2] * dt_next};
    for (std::size_t i = 0; i < b.secondary.size(); ++i) {
      const auto k = static_cast<std::size_t>(b.secondary[i]);
      const V3 r = mul(next, V3{b.rx[i], b.ry[i], b.rz[i]});
      if (dt_next > 0.0) {
        n.vx[k] = (cog_next[0] + r[0] - n.x[k]) / dt_next;
        n.vy[k] = (cog_next[1] + r[1] - n.y[k]) / dt_next;
        n.vz[k] = (cog_next[2] + r[2] - n.z[k]) / dt_next;
      }
      n.wx[k] = b.omega[0], n.wy[k] = b.omega[1], n.wz[k] = b.omega[2];
    }
    b.rotation = next;
  }
}

}  // namespace crumple::solver
