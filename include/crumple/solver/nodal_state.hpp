#pragma once
// The nodal state the solver advances every cycle, as structure of arrays indexed by dense node index.
#include <cstddef>
#include <vector>

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

}  // namespace crumple
