// Energy balance (docs/theory/energy.md).
#include <algorithm>
#include <cmath>

#include "solver/internal.hpp"

namespace crumple {

double EnergyBalanceState::error_percent() const {
  const double work = external_work - external_work_at_start;
  const double reference = initial_kinetic + work;
  const double balance = internal + kinetic_translational + kinetic_rotational + hourglass + contact - initial_kinetic -
                         work;
  if (std::abs(reference) <= 0.0) return 0.0;
  return 100.0 * balance / std::abs(reference);
}

namespace solver {
namespace {

// Kinetic energy of a body's nodes (main and secondary) relative to their centre of mass,
// sum 1/2 m_i |v_i - v_c|^2 [E]: the centre's velocity first, then the sum, without the cancellation of
// "total minus 1/2 M v_c^2" on a body that mostly translates.
double relative_kinetic_energy(const NodalState& n, const RigidBodyState& b) {
  double mass = n.mass[static_cast<std::size_t>(b.main_node)], vc[3] = {0.0, 0.0, 0.0};
  auto add_momentum = [&](std::size_t k, double m) { vc[0] += m * n.vx[k], vc[1] += m * n.vy[k], vc[2] += m * n.vz[k]; };
  add_momentum(static_cast<std::size_t>(b.main_node), mass);
  for (std::int32_t k : b.secondary) {
    const auto uk = static_cast<std::size_t>(k);
    mass += n.mass[uk];
    add_momentum(uk, n.mass[uk]);
  }
  if (!(mass > 0.0)) return 0.0;
  for (double& v : vc) v /= mass;
  auto relative = [&](std::size_t k) {
    const double dx = n.vx[k] - vc[0], dy = n.vy[k] - vc[1], dz = n.vz[k] - vc[2];
    return 0.5 * n.mass[k] * (dx * dx + dy * dy + dz * dz);
  };
  double spin = relative(static_cast<std::size_t>(b.main_node));
  for (std::int32_t k : b.secondary) spin += relative(static_cast<std::size_t>(k));
  return spin;
}

}  // namespace

std::pair<double, double> kinetic_energy(const SolverState& s) {
  const NodalState& n = s.nodes;
  double translational = 0.0, rotational = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    translational += 0.5 * n.mass[k] * (n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]);
    rotational += 0.5 * n.inertia[k] * (n.wx[k] * n.wx[k] + n.wy[k] * n.wy[k] + n.wz[k] * n.wz[k]);
  }
  // Rigid bodies, as the reference's listing splits them: translational 1/2 M v_c^2 of the centre of mass,
  // rotational the rest of the nodes' kinetic energy, sum 1/2 m_i |v_i - v_c|^2, which for a rigid motion is
  // 1/2 w . I w of the nodal masses about the centre (docs/theory/rigid-bodies.md, RB-7). The total is unchanged.
  // The inertia the card adds (Jxx..Jxz, in the body frame) spins with the body: 1/2 w . R J R^T w.
  for (const RigidBodyState& b : s.bodies) {
    if (b.active) {
      const double spin = relative_kinetic_energy(n, b);
      translational -= spin, rotational += spin;
    }
    const auto& R = b.rotation;
    const auto& J = b.inertia_added;
    double local[3];
    for (int i = 0; i < 3; ++i)  // w in the body frame: R^T w
      local[i] = R[static_cast<std::size_t>(i)] * b.omega[0] + R[static_cast<std::size_t>(3 + i)] * b.omega[1] +
                 R[static_cast<std::size_t>(6 + i)] * b.omega[2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        rotational += 0.5 * local[i] * J[static_cast<std::size_t>(3 * i + j)] * local[j];
  }
  return {translational, rotational};
}

}  // namespace solver
}  // namespace crumple
