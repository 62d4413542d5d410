#pragma once
// A free rigid body tumbling (docs/verification.md, "Rigid body"), shared by verification.RigidBody (20 rad/s over
// 20 rad) and stability.SpinningRigidBody (10^4 rad/s).
//
// Physics: without external forces a rigid body keeps its linear momentum and its angular momentum L about the
// centre of mass, and its kinetic energy 1/2 M V^2 + 1/2 w . L. The body is eight point masses at the corners of a
// box, all different, so that the inertia tensor is fully populated with three distinct principal moments, and
// the initial spin is along none of the principal axes: the body tumbles (w moves in the body and in space) while
// L stays fixed. Crumple stores L as the body's state and changes it only by the gathered torque
// (rigid-bodies.md, RB-2), so without torque it must stay constant to round-off. The body has no elements; a
// separate shell at rest, not connected to it, sets the time step (9.9e-6 s).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification {

using V3 = std::array<double, 3>;
inline V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const V3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

struct PointMass {
  long long id;
  V3 x;
  double mass;
};

// /RBODY: main node, secondary node group, no added mass or inertia, Ioptoff line.
inline std::string rigid_body(long long id, long long main_node, long long group) {
  return "/RBODY/" + std::to_string(id) + "\nbody\n" + I(main_node) + I(0) + I(0) + I(0) + R(0.0) + I(group) + "\n" +
         R(0.0) + R(0.0) + R(0.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + I(0) + I(0) + "\n";
}

// What a tumbling run measured: the largest relative deviations over the samples, |w| dt, the angle w turned
// through, and the body's exact initial kinetic energy and its translational part.
struct TumblingRun {
  RunSummary summary;
  double worst_state = 0.0, worst_nodal = 0.0, worst_energy = 0.0, worst_momentum = 0.0;
  double omega_dt = 0.0, turn = 0.0, energy0 = 0.0, translation = 0.0;
  int samples = 0;
};

// The body launched with spin omega0 [1/T] and velocity V0 [L/T], run to end_time with a sample every `sample`.
inline TumblingRun run_tumbling_body(const V3& omega0, const V3& V0, double end_time, double sample) {
  const std::vector<PointMass> body{
      {1, {-0.30, -0.20, -0.10}, 1.0}, {2, {0.35, -0.20, -0.10}, 2.0}, {3, {0.35, 0.25, -0.10}, 3.0},
      {4, {-0.30, 0.25, -0.10}, 4.0},  {5, {-0.30, -0.20, 0.12}, 1.5}, {6, {0.35, -0.20, 0.12}, 2.5},
      {7, {0.35, 0.25, 0.12}, 3.5},    {8, {-0.30, 0.25, 0.12}, 0.5}};
  double M = 0.0;
  V3 centre{};
  for (const PointMass& p : body) {
    M += p.mass;
    for (int d = 0; d < 3; ++d) centre[d] += p.mass * p.x[d];
  }
  for (double& c : centre) c /= M;
  // Initial velocities of the rigid field v = V + w x (x - c), one /INIVEL/TRA per node; the exact L and energy.
  std::vector<NodeRow> rows;
  std::string cards;
  V3 L0{};
  double energy0 = 0.0;
  for (const PointMass& p : body) {
    rows.push_back({p.id, p.x[0], p.x[1], p.x[2]});
    const V3 r{p.x[0] - centre[0], p.x[1] - centre[1], p.x[2] - centre[2]};
    const V3 spin = cross(omega0, r);
    const V3 v{V0[0] + spin[0], V0[1] + spin[1], V0[2] + spin[2]};
    const V3 h = cross(r, v);
    for (int d = 0; d < 3; ++d) L0[d] += p.mass * h[d];
    energy0 += 0.5 * p.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    cards += node_group(10 + p.id, {p.id}) + added_mass(p.id, p.mass, 10 + p.id) +
             initial_velocity(p.id, v[0], v[1], v[2], 10 + p.id);
  }
  rows.push_back({100, 0.0, 0.0, 0.0});  // main node, moved to the centre of mass
  // Time-step shell: steel, 0.06 m square at x = 10, at rest: dt = 0.9 * 0.06 / 5439 m/s = 9.9e-6 s, so that
  // |w| dt = 2e-4 rad per cycle.
  const double h = 0.06;
  for (long long k = 0; k < 4; ++k)
    rows.push_back({201 + k, 10.0 + (k == 1 || k == 2 ? h : 0.0), k >= 2 ? h : 0.0, 0.0});
  const std::string starter = node_cards(rows) + shell_cards(1, {{1, 201, 202, 203, 204}}) + part_card() +
                              shell_property(0.001, 1) + elastic_material(7800.0, 2.1e11, 0.3) + cards +
                              node_group(1, {1, 2, 3, 4, 5, 6, 7, 8}) + rigid_body(1, 100, 1);

  TumblingRun out;
  double &worst_state = out.worst_state, &worst_nodal = out.worst_nodal;
  double &worst_energy = out.worst_energy, &worst_momentum = out.worst_momentum, &omega_dt = out.omega_dt;
  int& samples = out.samples;
  V3 omega_first{}, omega_last{};
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, end_time, sample, [&](const Model& m, const SolverState& s) {
    ASSERT_EQ(s.bodies.size(), 1u);
    const RigidBodyState& b = s.bodies[0];
    // (1) The body's angular momentum state.
    const V3 L{b.momentum_angular[0], b.momentum_angular[1], b.momentum_angular[2]};
    worst_state = std::max(worst_state, norm({L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]}) / norm(L0));
    // (2) The same from the nodal masses and velocities. The nodes move on chords: v^(n+1/2) carries each node
    // from R^n r to R^(n+1) r. With w taken at the mid-step attitude (RB-2b) the chord velocities give
    // sum m r^n x v^(n+1/2) = L + O((w dt)^2) L; a scheme with w from the attitude at t^n would leave a
    // first-order term (dt/2) w x L, which this bound catches (at 20 rad/s it is 1e-4, (w dt)^2 is 4e-8).
    V3 Ln{}, P{}, cg{};
    double mass = 0.0;
    for (const PointMass& p : body) {
      const std::size_t k = node_index(m, p.id);
      mass += s.nodes.mass[k];
      for (int d = 0; d < 3; ++d)
        cg[d] += s.nodes.mass[k] * (d == 0 ? s.nodes.x[k] : d == 1 ? s.nodes.y[k] : s.nodes.z[k]);
    }
    for (double& c : cg) c /= mass;
    for (const PointMass& p : body) {
      const std::size_t k = node_index(m, p.id);
      const V3 v{s.nodes.vx[k], s.nodes.vy[k], s.nodes.vz[k]};
      // Positions at t^n: the observer sees x^(n+1) = x^n + dt v^(n+1/2) (the centre moves the same way).
      const V3 r{s.nodes.x[k] - s.dt * v[0] - (cg[0] - s.dt * V0[0]), s.nodes.y[k] - s.dt * v[1] - (cg[1] - s.dt * V0[1]),
                 s.nodes.z[k] - s.dt * v[2] - (cg[2] - s.dt * V0[2])};
      const V3 hm = cross(r, v);
      for (int d = 0; d < 3; ++d) Ln[d] += s.nodes.mass[k] * hm[d], P[d] += s.nodes.mass[k] * v[d];
    }
    const V3 w{b.omega[0], b.omega[1], b.omega[2]};
    worst_nodal = std::max(worst_nodal, norm({Ln[0] - L0[0], Ln[1] - L0[1], Ln[2] - L0[2]}) / norm(L0));
    worst_momentum = std::max(worst_momentum, norm({P[0] - M * V0[0], P[1] - M * V0[1], P[2] - M * V0[2]}) / (M * norm(V0)));
    // (3) Kinetic energy of the body: 1/2 M V^2 + 1/2 w . L.
    const double energy = 0.5 * M * (b.velocity[0] * b.velocity[0] + b.velocity[1] * b.velocity[1] +
                                     b.velocity[2] * b.velocity[2]) + 0.5 * (w[0] * L[0] + w[1] * L[1] + w[2] * L[2]);
    worst_energy = std::max(worst_energy, std::abs(energy / energy0 - 1.0));
    omega_dt = std::max(omega_dt, norm(w) * s.dt);
    if (samples++ == 0) omega_first = w;
    omega_last = w;
  });
  // The body tumbles: w turns by a large angle in space while L stays put.
  out.turn = std::acos(std::clamp(
      (omega_first[0] * omega_last[0] + omega_first[1] * omega_last[1] + omega_first[2] * omega_last[2]) /
          (norm(omega_first) * norm(omega_last)), -1.0, 1.0));
  out.summary = run.summary;
  out.energy0 = energy0;
  out.translation = 0.5 * M * (V0[0] * V0[0] + V0[1] * V0[1] + V0[2] * V0[2]);
  return out;
}

}  // namespace crumple::verification
