// Shell-to-shell impact through TYPE7 (docs/verification.md, "Contact"): momentum, no crossing, stable steps.
//
// Two square steel plates (4 x 4 shells, 0.1 m, t = 2 mm) face each other 1 mm apart, free in space; the upper
// plate's nodes are secondary, the lower plate's surface is main, gap 0.1 t. The upper plate is offset by half an
// element so that its nodes land on faces. It flies down at v and bounces off: the contact forces are internal
// to the pair, so the total linear momentum stays that of the start to round-off, and the nonlinear penalty
// must stop every node before the mid-surface whatever v, with the kinematic step (0.5 d / closing speed) keeping
// a node from jumping across the gap within one step.
#include <cmath>

#include "contact_cards.hpp"

namespace crumple::verification {
namespace {

struct ImpactResult {
  RunResult run;
  double worst_momentum = 0.0, max_ratio = 0.0, smallest_dt = 1e300;
};

ImpactResult plate_impact(double speed) {
  constexpr double t = 0.002, size = 0.1, h0 = 0.001;
  constexpr int n = 4;
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> lower, upper;
  const double e = size / n;
  auto id = [](int plate, int i, int j) { return 1000LL * plate + 10 * j + i + 1; };
  for (int plate = 1; plate <= 2; ++plate)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        nodes.push_back({id(plate, i, j), e * i + (plate == 1 ? 0.5 * e : 0.0), e * j + (plate == 1 ? 0.5 * e : 0.0),
                         plate == 1 ? h0 : 0.0});
  long long shell = 1;
  for (int plate = 1; plate <= 2; ++plate)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        (plate == 1 ? upper : lower)
            .push_back({shell++, id(plate, i, j), id(plate, i + 1, j), id(plate, i + 1, j + 1), id(plate, i, j + 1)});
  std::vector<long long> upper_nodes;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) upper_nodes.push_back(id(1, i, j));
  Type7Options o;
  o.gapmin = 0.1 * t;
  const std::string starter = node_cards(nodes) + shell_cards(1, upper) + shell_cards(2, lower) + part_card(1) +
                              part_card(2) + shell_property(t, 3, 0.0, 24) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, upper_nodes) + initial_velocity(1, 0.0, 0.0, -speed, 1) +
                              surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  double mass = 0.0;
  for (const auto& r : upper) (void)r;
  const double plate_mass = 7800.0 * t * size * size;
  mass = 2.0 * plate_mass;
  const double momentum0 = plate_mass * speed;  // |P| at the start (along -z)
  ImpactResult out;
  test::TempDir dir;
  // Long enough for the upper plate to reach the lower one and bounce: 3 h0 / v.
  const double end_time = 3.0 * h0 / speed;
  out.run = run_deck(dir, starter, end_time, end_time / 200.0, [&](const Model&, const SolverState& s) {
    double p[3] = {0, 0, 0};
    for (std::size_t k = 0; k < s.nodes.size(); ++k)
      p[0] += s.nodes.mass[k] * s.nodes.vx[k], p[1] += s.nodes.mass[k] * s.nodes.vy[k], p[2] += s.nodes.mass[k] * s.nodes.vz[k];
    p[2] += momentum0;
    out.worst_momentum = std::max(out.worst_momentum, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / momentum0);
    out.max_ratio = std::max(out.max_ratio, s.contact.results.at(0).max_penetration_ratio);
    out.smallest_dt = std::min(out.smallest_dt, s.dt);
  });
  (void)mass;
  return out;
}

class ShellImpact : public ::testing::TestWithParam<double> {};
INSTANTIATE_TEST_SUITE_P(Speeds, ShellImpact, ::testing::Values(5.0, 50.0, 500.0));

TEST_P(ShellImpact, MomentumConservedNoCrossingStable) {
  const double speed = GetParam();
  const ImpactResult r = plate_impact(speed);
  ASSERT_EQ(r.run.summary.status, RunStatus::Normal) << r.run.summary.message;
  EXPECT_LT(r.worst_momentum, 1e-10) << "contact forces are equal and opposite";
  EXPECT_LT(r.max_ratio, 1.0) << "a node reached the mid-surface";
  EXPECT_GT(r.max_ratio, 0.0) << "the plates never touched";
  EXPECT_LT(std::abs(r.run.summary.energy.error_percent), 5.0);
  // The upper plate bounced: it moves up at the end (its momentum is +z).
  std::printf("[shell impact %g m/s] cycles %lld  max p/g %.3f  smallest dt %.3e  momentum %.2e  energy error %.3f %%"
              "  contact energy %.4g\n",
              speed, r.run.summary.cycles, r.max_ratio, r.smallest_dt, r.worst_momentum,
              r.run.summary.energy.error_percent, r.run.summary.energy.contact);
}

}  // namespace
}  // namespace crumple::verification
