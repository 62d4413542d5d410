// A block pressed onto a plate through TYPE7 (docs/verification.md, "Contact"): stick then slip under a growing
// drag, and the rebound of a block dropped on the plate.
//
// The block is one shell (0.05 m square, 2 mm steel, node mass M = 9.75e-3 kg), its four nodes the secondary
// nodes; the main surface is a fixed plate of 10 x 2 shells. The block's nodes move together, so that each is a
// mass on the contact spring K0 = E t / 2 = 2.1e8 N/m (its element stays unstrained).
//
// Stick then slip: each node is pressed by N = 10 N (from its static penetration N / K0 = 4.8e-8 m, p / g =
// 5e-5) and dragged along x by F = r t. Coulomb: the block sticks until F = mu N at t_s = mu N / r, then slides
// with M dv/dt = r t - mu N: v = r (t - t_s)^2 / (2 M), x - x_s = r (t - t_s)^3 / (6 M). The viscous friction
// (Iform 1) lets the block creep at F / C_t while it sticks, C_t = VisF sqrt(2 K0 M) = 2.0e3 VisF N s/m: at most
// 1.5e-3 m/s, 3e-6 m over the stick, and it creeps one way (the drag's). With VisF = 3 the dashpot's explicit
// bound 2 M / C_t (C_t dt / M < 2) is below the spring's step: the step must hold the dashpot (eq. C-11b), or
// a deviation of the sliding velocity from the creep is amplified by C_t dt / M - 1 > 1 and flips sign every
// cycle until the force reaches the cone: the friction force then chatters instead of sticking (measured
// without eq. C-11b: C_t dt / M = 2.8, speeds up to 1.1e-3 m/s, 2.2 times the creep bound, and the acceleration
// changing sign in 129 of the about 310 cycles from 0.2 t_s to 0.9 t_s; with it, none).
//
// Rebound: dropped at v0 = 1 m/s onto the plate with VisS = 0.2, each node meets the spring-dashpot K0, C = VisS
// sqrt(2 K0 M), zeta = C / (2 sqrt(K0 M)) = VisS / sqrt 2, and leaves when the normal force K0 p + C dp/dt
// reaches zero (it never pulls, eq. C-8). Penetration p = (v0 / w_d) e^(-zeta w t) sin(w_d t), w = sqrt(K0 / M),
// w_d = w sqrt(1 - zeta^2); the force is zero again at w_d t* = pi - atan(2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2)),
// and the block leaves at e v0 with e = e^(-zeta w t*) |cos(w_d t*) - zeta / sqrt(1 - zeta^2) sin(w_d t*)|.
// Damping on the way in only would give e = e^(-zeta w t1), w_d t1 = atan(sqrt(1 - zeta^2) / zeta): 0.815 instead of
// 0.665. The gap is 1 mm and p stays below 7e-6 m, so the penalty is linear to 1.4 %.
//
// Time step: /DT 0.7 as for the sliding block (the lone element's breathing mode); 0.05 for the rebound, so that a
// contact of 22 us takes about 80 steps (the damping acts on the half-step velocity, an O(dt) lag: e is +0.94 %
// off at /DT 0.1, +0.15 % at 0.02).
#include <cmath>
#include <string>

#include "contact_cards.hpp"

namespace crumple::verification::test_contact_block {
namespace {

constexpr double kT = 0.002, kBlock = 0.05, kRho = 7800.0, kYoung = 2.1e11, kGap = 0.001;
constexpr double kNodeMass = kRho * kT * kBlock * kBlock / 4.0, kK0 = 0.5 * kYoung * kT;
constexpr double kX0 = 0.125;

// /CLOAD on node group `group` along `dir`, F = scale f(t).
std::string cload(long long id, long long function, const std::string& dir, long long group, double scale) {
  return "/CLOAD/" + std::to_string(id) + "\nload\n" + I(function) + std::string(10 - dir.size(), ' ') + dir + I(0) +
         I(0) + I(group) + std::string(10, ' ') + R(0.0) + R(scale) + "\n";
}

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

// Linear interpolation of a sampled signal at time t.
double at(const std::vector<double>& time, const std::vector<double>& y, double t) {
  for (std::size_t k = 1; k < time.size(); ++k)
    if (time[k] >= t) return y[k - 1] + (y[k] - y[k - 1]) * (t - time[k - 1]) / (time[k] - time[k - 1]);
  return y.back();
}

constexpr double kMu = 0.3, kPress = 10.0, kStick = 2e-3, kEnd = 5e-3;
constexpr double kRate = kMu * kPress / kStick;  // drag rate r [N/s]: F reaches mu N at t_s

class StickThenSlip : public ::testing::TestWithParam<double> {};
INSTANTIATE_TEST_SUITE_P(VisF, StickThenSlip, ::testing::Values(1.0, 3.0),
                         [](const ::testing::TestParamInfo<double>& p) { return "visf_" + std::to_string(int(p.param)); });

TEST_P(StickThenSlip, SticksUntilMuNThenSlidesAsCoulombSays) {
  Type7Options o;
  o.gapmin = kGap, o.fric = kMu, o.visf = GetParam();
  const std::string loads = function_card(1, {{0.0, 1.0}, {1.0, 1.0}}) + function_card(2, {{0.0, 0.0}, {1.0, 1.0}}) +
                            cload(1, 1, "Z", 1, -kPress) + cload(2, 2, "X", 1, kRate);
  const BlockTrace b = run_block(kGap - kPress / kK0, o, loads, kEnd, 0.7);
  ASSERT_EQ(b.run.summary.status, RunStatus::Normal) << b.run.summary.message;
  const double x0 = kX0 + 0.5 * kBlock, slide = kEnd - kStick;
  const double v_end = kRate * slide * slide / (2.0 * kNodeMass), x_end = kRate * std::pow(slide, 3) / (6.0 * kNodeMass);
  // Creep while sticking: the drag over the dashpot, at most mu N / C_t. Over 0.2 t_s .. 0.9 t_s (after the first
  // cycles' transient): the largest speed, and the cycles whose acceleration changed sign (chatter).
  const double creep = kMu * kPress / (GetParam() * std::sqrt(2.0 * kK0 * kNodeMass));
  double fastest = 0.0;
  int chatter = 0;
  for (std::size_t k = 1; k < b.time.size(); ++k) {
    if (b.time[k] < 0.2 * kStick || b.time[k] > 0.9 * kStick) continue;
    fastest = std::max(fastest, std::abs(b.vx[k]));
    if (k >= 2 && (b.vx[k] - b.vx[k - 1]) * (b.vx[k - 1] - b.vx[k - 2]) < 0.0) ++chatter;
  }
  const double x_stick = at(b.time, b.x, 0.9 * kStick) - x0;
  const double measured_v = at(b.time, b.vx, kEnd), measured_x = at(b.time, b.x, kEnd) - x0;
  std::printf("[stick then slip VisF %.0f] cycles %lld  sticking: x %.3e m  |v| <= %.3e m/s (creep bound %.2e), %d "
              "chatter cycles  end: v %.4f (Coulomb %.4f, %+.2f %%)  x %.4e (%.4e, %+.2f %%)\n",
              GetParam(), b.run.summary.cycles, x_stick, fastest, creep, chatter, measured_v, v_end,
              100.0 * (measured_v / v_end - 1.0), measured_x, x_end, 100.0 * (measured_x / x_end - 1.0));
  EXPECT_LT(fastest, creep);
  EXPECT_EQ(chatter, 0);
  EXPECT_LT(std::abs(x_stick), 0.01 * x_end);
  EXPECT_NEAR(measured_v, v_end, 0.01 * v_end);
  EXPECT_NEAR(measured_x, x_end, 0.02 * x_end);
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
}  // namespace crumple::verification::test_contact_block
