#pragma once
// The nodal state the solver advances every cycle, as structure of arrays indexed by dense node index.
#include <array>
#include <cstddef>
#include <vector>

#include "crumple/core/vec3.hpp"

namespace crumple {

struct NodalState {
  std::vector<double> x, y, z;     // current coordinates [L]
  std::vector<double> vx, vy, vz;  // translational velocity at the last half step t^(n-1/2) [L/T]
  std::vector<double> wx, wy, wz;  // angular velocity at t^(n-1/2) (nodes of shells) [1/T]
  std::vector<double> fx, fy, fz;  // nodal force of the cycle: external minus internal [M L T^-2]
  std::vector<double> mx, my, mz;  // nodal moment of the cycle [M L^2 T^-2]
  std::vector<double> mass;        // lumped mass, element + added + mass scaling [M]
  std::vector<double> inertia;     // isotropic lumped rotational inertia; 0 for nodes without rotation [M L^2]

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &fx, &fy, &fz, &mx, &my, &mz, &mass, &inertia})
      v->assign(n, 0.0);
  }
  void clear_forces() {
    for (auto* v : {&fx, &fy, &fz, &mx, &my, &mz}) std::fill(v->begin(), v->end(), 0.0);
  }
};

// Node k's current position.
inline Vec3 node_position(const NodalState& n, std::int32_t k) {
  const auto u = static_cast<std::size_t>(k);
  return {n.x[u], n.y[u], n.z[u]};
}

// The one place element kernels hand node k its share of the element's internal force f (and moment m): the nodal
// sums take it with a minus sign (external minus internal).
inline void subtract_internal(NodalState& n, std::size_t k, const Vec3& f) {
  n.fx[k] -= f.x, n.fy[k] -= f.y, n.fz[k] -= f.z;
}
inline void subtract_internal(NodalState& n, std::size_t k, const Vec3& f, const Vec3& m) {
  n.fx[k] -= f.x, n.fy[k] -= f.y, n.fz[k] -= f.z;
  n.mx[k] -= m.x, n.my[k] -= m.y, n.mz[k] -= m.z;
}

// The velocity update of the last cycle as the time loop leaves it, for outputs (docs/output-format.md,
// "/history/th"): the accelerations a^n = (v^(n+1/2) - before) / dt and the reactions of the kinematic conditions
// m (v^(n+1/2) - free) / dt.
struct VelocityChange {
  std::array<const std::vector<double>*, 6> before{};  // v^(n-1/2): x y z rx ry rz
  // After the free update (CD-2), before the kinematic conditions; a rigid body's nodes: after the body's motion.
  std::array<const std::vector<double>*, 6> free{};
  double dt = 0.0;  // dt^n, the step of the update [T]
  bool known() const { return dt > 0.0 && before[0] != nullptr && free[0] != nullptr; }
};

}  // namespace crumple
