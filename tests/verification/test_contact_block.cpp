// A block on a plate through TYPE7 (docs/verification.md, "Contact"): the rebound of a block dropped on the plate.
//
// The block is one shell (0.05 m square, 2 mm steel, node mass M = 9.75e-3 kg), its four nodes the secondary
// nodes; the main surface is a fixed plate of 10 x 2 shells. The block's nodes move together, so that each is a
// mass on the contact spring K0 = E t / 2 = 2.1e8 N/m (its element stays unstrained).
//
// Rebound: dropped at v0 = 1 m/s onto the plate with VisS = 0.2, each node meets the spring-dashpot K0, C = VisS
// sqrt(2 K0 M), zeta = C / (2 sqrt(K0 M)) = VisS / sqrt 2, and leaves when the normal force K0 p + C dp/dt
// reaches zero (it never pulls, eq. C-8). Penetration p = (v0 / w_d) e^(-zeta w t) sin(w_d t), w = sqrt(K0 / M),
// w_d = w sqrt(1 - zeta^2); the force is zero again at w_d t* = pi - atan(2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2)),
// and the block leaves at e v0 with e = e^(-zeta w t*) |cos(w_d t*) - zeta / sqrt(1 - zeta^2) sin(w_d t*)|.
// Damping on the way in only would give e = e^(-zeta w t1), w_d t1 = atan(sqrt(1 - zeta^2) / zeta): 0.815 instead of
// 0.665. The gap is 1 mm and p stays below 7e-6 m, so the penalty is linear to 1.4 %.
//
// Time step: /DT 0.05 (the lone element's breathing mode needs below 0.877, docs/theory/time-step.md), so that a
// contact of 22 us takes about 80 steps (the damping acts on the half-step velocity, an O(dt) lag: e is +0.94 %
// off at /DT 0.1, +0.15 % at 0.02).
#include <cmath>
#include <string>

#include "contact_cards.hpp"

namespace crumple::verification {
namespace {

constexpr double kT = 0.002, kBlock = 0.05, kRho = 7800.0, kYoung = 2.1e11, kGap = 0.001;
constexpr double kNodeMass = kRho * kT * kBlock * kBlock / 4.0, kK0 = 0.5 * kYoung * kT;
constexpr double kX0 = 0.125;

// The plate (nodes 1..33, fixed, part 2) and the block (nodes 101..104 at height z, part 1, group 1), with `extra`
// cards; the observer gets the block's mean x, vx, vz.
struct BlockTrace {
  std::vector<double> time, x, vx, vz;
  RunResult run;
};

BlockTrace run_block(double z, const Type7Options& o, const std::string& extra, double end_time, double dt_scale) {
  std::vector<NodeRow> nodes;
  const std::vector<ShellRow> plate = shell_grid(10, 2, 0.1, 0.1, 0.0, 0.0, 0.0, 1, 1, nodes);
  const double y0 = 0.02;
  nodes.push_back({101, kX0, y0, z});
  nodes.push_back({102, kX0 + kBlock, y0, z});
  nodes.push_back({103, kX0 + kBlock, y0 + kBlock, z});
  nodes.push_back({104, kX0, y0 + kBlock, z});
  std::vector<long long> plate_nodes;
  for (long long k = 1; k <= 33; ++k) plate_nodes.push_back(k);
  const std::string starter =
      node_cards(nodes) + shell_cards(1, {{100, 101, 102, 103, 104}}) + shell_cards(2, plate) + part_card(1) +
      part_card(2) + shell_property(kT, 3, 0.0, 24) + elastic_material(kRho, kYoung, 0.3) +
      node_group(1, {101, 102, 103, 104}) + node_group(2, plate_nodes) + boundary_condition(1, "111 111", 2) +
      surface_of_part(2, 2) + type7_card(1, 1, 2, o) + extra;
  BlockTrace out;
  test::TempDir dir;
  out.run = run_deck(dir, starter, end_time, 1e-9, [&](const Model& m, const SolverState& s) {
    double x = 0.0, vx = 0.0, vz = 0.0;
    for (long long n : {101, 102, 103, 104}) {
      const std::size_t k = node_index(m, n);
      x += 0.25 * s.nodes.x[k], vx += 0.25 * s.nodes.vx[k], vz += 0.25 * s.nodes.vz[k];
    }
    out.time.push_back(s.time), out.x.push_back(x), out.vx.push_back(vx), out.vz.push_back(vz);
  }, "/DT\n" + std::to_string(dt_scale) + " 0\n");
  return out;
}

// Coefficient of restitution of the spring-dashpot that leaves when its force is zero, and of the one damped on
// the way in only, for the damping fraction zeta (see the head of the file).
double restitution_both_ways(double zeta) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double phase = kPi - std::atan(2.0 * zeta * root / (1.0 - 2.0 * zeta * zeta));  // w_d t*
  return std::exp(-zeta * phase / root) * std::abs(std::cos(phase) - zeta / root * std::sin(phase));
}
double restitution_inward_only(double zeta) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  return std::exp(-zeta * std::atan(root / zeta) / root);
}

TEST(ContactRebound, DampedBothWaysAndLeavesWhenTheForceIsZero) {
  constexpr double kVisS = 0.2, kV0 = 1.0;
  Type7Options o;
  o.gapmin = kGap, o.viss = kVisS;
  // Starts just outside the gap (a hundredth of a step of travel above it), falling at v0.
  const BlockTrace b = run_block(kGap + 1e-9, o, initial_velocity(1, 0.0, 0.0, -kV0, 1), 60e-6, 0.05);
  ASSERT_EQ(b.run.summary.status, RunStatus::Normal) << b.run.summary.message;
  const double zeta = kVisS / std::sqrt(2.0), e = restitution_both_ways(zeta);
  const double measured = b.vz.back() / kV0;
  const double w = std::sqrt(kK0 / kNodeMass), duration = kPi / (w * std::sqrt(1.0 - zeta * zeta));
  std::printf("[rebound VisS %.2f] cycles %lld  e %.4f (both ways %.4f, %+.2f %%; inward only %.4f)  contact %.1f us"
              "  energy error %.3f %%\n",
              kVisS, b.run.summary.cycles, measured, e, 100.0 * (measured / e - 1.0), restitution_inward_only(zeta),
              1e6 * duration, b.run.summary.energy.error_percent);
  EXPECT_NEAR(measured, e, 0.01 * e);
  EXPECT_LT(std::abs(b.run.summary.energy.error_percent), 1.0);
}

}  // namespace
}  // namespace crumple::verification
