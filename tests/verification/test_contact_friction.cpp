// Sliding block with Coulomb friction through TYPE7 (docs/verification.md, "Contact").
//
// A one-shell block (0.05 m square, 2 mm steel) rests on a fixed plate under gravity g, its four nodes the
// secondary nodes, the plate's surface the main surface, Fric = 0.3. Launched along x at v0 = 1 m/s, it slides
// under the kinetic friction force mu N = mu m g: a constant deceleration mu g until it stops after
// v0^2 / (2 mu g). With Iform 1 the trial force is viscous (C_t V_t) and with Iform 2 incremental (K_t dx_t);
// both are capped by the cone, so while sliding both give mu N.
//
// Time step: the block is a single free element, whose breathing (in-plane dilatation) mode has the critical step
// L sqrt(1 - nu) / c0 = 0.877 of the plate-wave step L / c of docs/theory/time-step.md (T-1) at nu = 0.3: at the
// default scale 0.9 it is unstable and grows from round-off (docs/theory/time-step.md, "Isolated elements"). In
// a mesh the neighbours keep the highest mode below T-1; here /DT 0.7 keeps the lone element stable.
#include <cmath>

#include "contact_cards.hpp"

namespace crumple::verification {
namespace {

constexpr double kMu = 0.3, kG = 9.81, kV0 = 1.0;

struct Sliding {
  double deceleration = 0.0, distance = 0.0;
  RunResult run;
};

Sliding slide(int iform) {
  constexpr double t = 0.002, gap = 0.001, block = 0.05;
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> plate, blocks;
  // Plate: 10 x 2 shells of 0.1 m, nodes 1..33, fixed.
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 10; ++i) nodes.push_back({1 + i + 11 * j, 0.1 * i, 0.1 * j, 0.0});
  long long id = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 10; ++i) plate.push_back({id++, 1 + i + 11 * j, 2 + i + 11 * j, 13 + i + 11 * j, 12 + i + 11 * j});
  // Block resting at its static penetration: a node's weight m g / 4 = 0.0957 N on K0 = E t / 2 = 2.1e8 N/m is
  // p = 4.6e-10 m (the penalty is linear at p << g); away from the plate's nodes.
  const double weight = 7800.0 * t * block * block / 4.0 * kG, k0 = 0.5 * 2.1e11 * t;
  const double z0 = gap - weight / k0, x0 = 0.125, y0 = 0.02;
  nodes.push_back({101, x0, y0, z0});
  nodes.push_back({102, x0 + block, y0, z0});
  nodes.push_back({103, x0 + block, y0 + block, z0});
  nodes.push_back({104, x0, y0 + block, z0});
  blocks.push_back({100, 101, 102, 103, 104});
  std::vector<long long> plate_nodes;
  for (int k = 1; k <= 33; ++k) plate_nodes.push_back(k);
  Type7Options o;
  o.gapmin = gap, o.fric = kMu, o.iform = iform;
  const std::string starter =
      node_cards(nodes) + shell_cards(1, blocks) + shell_cards(2, plate) + part_card(1) + part_card(2) +
      shell_property(t, 3, 0.0, 24) + elastic_material(7800.0, 2.1e11, 0.3) + node_group(1, {101, 102, 103, 104}) +
      node_group(2, plate_nodes) + boundary_condition(1, "111 111", 2) + initial_velocity(1, kV0, 0.0, 0.0, 1) +
      unit_function(1) + "/GRAV/1\ngravity\n" + I(1) + "         Z" + I(0) + I(0) + I(1) + I(0) + R(0.0) +
      R(-kG) + "\n" + surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  Sliding out;
  std::vector<double> time, velocity, position;
  test::TempDir dir;
  const double stop_time = kV0 / (kMu * kG);
  out.run = run_deck(dir, starter, 1.3 * stop_time, 1e-3, [&](const Model& m, const SolverState& s) {
    double v = 0.0, x = 0.0;
    for (long long n : {101, 102, 103, 104}) v += 0.25 * s.nodes.vx[node_index(m, n)], x += 0.25 * s.nodes.x[node_index(m, n)];
    time.push_back(s.time), velocity.push_back(v), position.push_back(x);
  }, "/DT\n0.7 0\n");
  // Deceleration: the slope of v between 0.8 v0 and 0.2 v0; distance: where v first reaches 0.
  const double t1 = first_crossing(time, velocity, 0.8 * kV0), t2 = first_crossing(time, velocity, 0.2 * kV0);
  out.deceleration = 0.6 * kV0 / (t2 - t1);
  for (std::size_t k = 1; k < time.size(); ++k)
    if (velocity[k] <= 1e-3 * kV0) {
      out.distance = position[k] - (x0 + 0.5 * block);
      break;
    }
  return out;
}

class SlidingBlock : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Iform, SlidingBlock, ::testing::Values(1, 2));

TEST_P(SlidingBlock, DeceleratesAtMuGAndStopsAtTheCoulombDistance) {
  const Sliding s = slide(GetParam());
  ASSERT_EQ(s.run.summary.status, RunStatus::Normal) << s.run.summary.message;
  const double a = kMu * kG, d = kV0 * kV0 / (2.0 * a);
  EXPECT_NEAR(s.deceleration, a, 0.02 * a);
  EXPECT_NEAR(s.distance, d, 0.03 * d);
  std::printf("[sliding block Iform %d] cycles %lld  deceleration %.4f (mu g %.4f, %+.2f %%)  distance %.4f (%.4f, "
              "%+.2f %%)  friction work %.4g  energy error %.3f %%\n",
              GetParam(), s.run.summary.cycles, s.deceleration, a, 100 * (s.deceleration / a - 1), s.distance, d,
              100 * (s.distance / d - 1), s.run.summary.energy.contact, s.run.summary.energy.error_percent);
}

}  // namespace
}  // namespace crumple::verification
