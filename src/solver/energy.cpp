// Energy balance (docs/theory/energy.md).
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

std::pair<double, double> kinetic_energy(const SolverState& s) {
  const NodalState& n = s.nodes;
  double translational = 0.0, rotational = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    translational += 0.5 * n.mass[k] * (n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]);
    rotational += 0.5 * n.inertia[k] * (n.wx[k] * n.wx[k] + n.wy[k] * n.wy[k] + n.wz[k] * n.wz[k]);
  }
  // Rigid bodies: their nodes' translation holds the rotation of the nodal masses; the inertia the card adds
  // (Jxx..Jxz, in the body frame) spins with the body: 1/2 w . R J R^T w.
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
