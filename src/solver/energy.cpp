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

// Kinetic energy of a body's nodes relative to their centre of mass, sum 1/2 m_i |v_i - v_c|^2 [E].
double relative_kinetic_energy(const NodalState& n, const RigidBodyState& b) {
  double mass = 0.0, p[3] = {0.0, 0.0, 0.0}, total = 0.0;
  auto visit = [&](std::int32_t node, auto&& f) {
    f(static_cast<std::size_t>(node));
    for (std::int32_t k : b.secondary) f(static_cast<std::size_t>(k));
  };
  visit(b.main_node, [&](std::size_t k) {
    mass += n.mass[k], p[0] += n.mass[k] * n.vx[k], p[1] += n.mass[k] * n.vy[k], p[2] += n.mass[k] * n.vz[k];
    total += 0.5 * n.mass[k] * (n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]);
  });
  if (!(mass > 0.0)) return 0.0;
  return std::max(0.0, total - 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / mass);
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
  for (const RigidBodyState& b : s.bodies) {
    if (!b.active) continue;
    const double spin = relative_kinetic_energy(n, b);
    translational -= spin, rotational += spin;
  }
  // The inertia the card adds (Jxx..Jxz, in the body frame) spins with the body: 1/2 w . R J R^T w.
  for (const RigidBodyState& b : s.bodies) {
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
