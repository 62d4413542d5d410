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
// "total minus 1/2 M v_c^2" on a body that mostly translates. Both sums are exact, each node's terms from its owner.
double relative_kinetic_energy(SolverState& s, const RigidBodyState& b, bool whole_model) {
  const NodalState& n = s.nodes;
  auto for_body_nodes = [&](auto f) {
    auto take = [&](std::int32_t k) { return whole_model || s.domain.owns(static_cast<std::size_t>(k)); };
    if (take(b.main_node)) f(static_cast<std::size_t>(b.main_node));
    for (std::int32_t k : b.secondary)
      if (take(k)) f(static_cast<std::size_t>(k));
  };
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(4, ExactSum{});  // mass, momentum x y z
  for_body_nodes([&](std::size_t k) {
    sums[0].add(n.mass[k]), sums[1].add(n.mass[k] * n.vx[k]), sums[2].add(n.mass[k] * n.vy[k]), sums[3].add(n.mass[k] * n.vz[k]);
  });
  if (!whole_model) s.reducer.sum(sums);
  const double mass = sums[0].value();
  if (!(mass > 0.0)) return 0.0;
  const double vc[3] = {sums[1].value() / mass, sums[2].value() / mass, sums[3].value() / mass};
  sums.assign(1, ExactSum{});
  for_body_nodes([&](std::size_t k) {
    const double dx = n.vx[k] - vc[0], dy = n.vy[k] - vc[1], dz = n.vz[k] - vc[2];
    sums[0].add(0.5 * n.mass[k] * (dx * dx + dy * dy + dz * dz));
  });
  if (!whole_model) s.reducer.sum(sums);
  return sums[0].value();
}

}  // namespace

std::pair<double, double> element_energies(SolverState& s) {
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(2, ExactSum{});
  for (ElementKind kind : kAllElementKinds) {
    const ElementKindState& state = element_state(s, kind);
    for (std::size_t e = 0; e < state.internal_energy.size(); ++e)
      if (s.domain.mine(kind, e)) sums[0].add(state.internal_energy[e]), sums[1].add(state.hourglass_energy[e]);
  }
  s.reducer.sum(sums);
  return {sums[0].value(), sums[1].value()};
}

std::pair<double, double> kinetic_energy(SolverState& s, bool whole_model) {
  const NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(2, ExactSum{});
  auto add = [&](std::size_t k) {
    sums[0].add(0.5 * n.mass[k] * (n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]));
    sums[1].add(0.5 * n.inertia[k] * selective_inertia_factor(s, k) *
                (n.wx[k] * n.wx[k] + n.wy[k] * n.wy[k] + n.wz[k] * n.wz[k]));
  };
  if (whole_model) {
    for (std::size_t k = 0; k < n.size(); ++k) add(k);
  } else {
    for_each_owned_node(s.domain, n.size(), add);
    s.reducer.sum(sums);
  }
  double translational = sums[0].value(), rotational = sums[1].value();
  translational += tied_kinetic_correction(s);  // TI-10: Spotflag 2 and 4 count the tied nodes' own masses
  // Rigid bodies, as the reference's listing splits them: translational 1/2 M v_c^2 of the centre of mass,
  // rotational the rest of the nodes' kinetic energy, sum 1/2 m_i |v_i - v_c|^2, which for a rigid motion is
  // 1/2 w . I w of the nodal masses about the centre (docs/theory/rigid-bodies.md, RB-7). The total is unchanged.
  // The inertia the card adds (Jxx..Jxz, in the body frame) spins with the body: 1/2 w . R J R^T w.
  for (const RigidBodyState& b : s.bodies) {
    const auto& R = b.rotation;
    if (b.active) {
      const double spin = relative_kinetic_energy(s, b, whole_model);
      translational -= spin, rotational += spin;
      // The nodes' sum holds v . (w x R S) when the secondary nodes' mass centre is not the body's centre (ICoG
      // 1 with a main node's mass off the centre, ICoG 3): the body's energy has no such term (RB-7).
      const Vec3 S = b.first_moment;
      const Vec3 moment{R[0] * S.x + R[1] * S.y + R[2] * S.z, R[3] * S.x + R[4] * S.y + R[5] * S.z,
                        R[6] * S.x + R[7] * S.y + R[8] * S.z};
      const Vec3 turning = cross(b.omega, moment);
      translational -= dot(b.velocity, turning);
      // and the secondary nodes' mass centre turning about the body's centre, 1/2 |w x R S|^2 / M, is spin: the
      // reference's translational column is 1/2 M V^2 of the centre (RB-7; measured with ICoG 3, a body spun about
      // its main node away from its nodes' mass centre: K-ENERGY T 0).
      if (b.mass > 0.0) {
        const double centre_spin = 0.5 * dot(turning, turning) / b.mass;
        translational -= centre_spin, rotational += centre_spin;
      }
    }
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
