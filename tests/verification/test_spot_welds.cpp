// A spot-welded hat section peeled off its closing plate (issue 28, docs/verification.md): the welds are beam-type
// springs (/PROP/TYPE13, docs/theory/spring.md) whose tension law breaks at delta_max (SP-5a, Ifail 0), so each weld's
// rupture law is F_break = K delta_max. The hat (0.12 m long, 60 mm wide, 30 mm high, 15 mm flanges, elastic steel
// shells of 1.5 mm) is welded at six stations along each flange to a plate 1 mm below it, which is held. Its end
// section is lifted at 2 m/s: the welds open one station after the other from the lifted end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "crumple/state/element_status.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_spot_welds {
namespace {

constexpr int kStations = 13;                 // hat sections along x, 10 mm apart
constexpr double kPitch = 0.01;               // [m]
constexpr double kWeldStiffness = 2e6;        // K of the weld's tension law [N/m]
constexpr double kBreakElongation = 1e-3;     // delta_max [m]: F_break = 2000 N
constexpr double kLift = 2.0;                 // the end section's velocity [m/s]
// The hat's section, flange to flange: (y, z) [m].
constexpr double kSection[11][2] = {{-0.045, 0.0}, {-0.03, 0.0},  {-0.03, 0.015}, {-0.03, 0.03}, {-0.015, 0.03}, {0.0, 0.03},
                                    {0.015, 0.03}, {0.03, 0.03}, {0.03, 0.015},  {0.03, 0.0},   {0.045, 0.0}};
constexpr double kPlateY[7] = {-0.045, -0.03, -0.015, 0.0, 0.015, 0.03, 0.045};

long long hat_node(int i, int j) { return 1 + 11 * i + j; }
long long plate_node(int i, int j) { return 1001 + 7 * i + j; }
// The welded stations: x = 10, 30, ..., 110 mm, on each flange's outer edge.
constexpr int kWeldStations[6] = {1, 3, 5, 7, 9, 11};

// One law of the beam-type spring (three lines): stiffness k, failing in tension beyond delta_max (0: never).
std::string weld_law(double k, double delta_max = 0.0) {
  return R(k) + R(0.0) + R(1.0) + R(0.0) + R(1.0) + "\n" + I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') +
         R(0.0) + R(delta_max) + "\n" + R(0.0) + R(0.0) + R(1.0) + R(0.0) + "\n";
}

std::string hat_deck() {
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> shells;
  for (int i = 0; i < kStations; ++i) {
    for (int j = 0; j < 11; ++j) nodes.push_back({hat_node(i, j), kPitch * i, kSection[j][0], kSection[j][1]});
    for (int j = 0; j < 7; ++j) nodes.push_back({plate_node(i, j), kPitch * i, kPlateY[j], -0.001});
  }
  for (int i = 0; i + 1 < kStations; ++i) {
    for (int j = 0; j < 10; ++j)
      shells.push_back({static_cast<long long>(shells.size() + 1), hat_node(i, j), hat_node(i + 1, j), hat_node(i + 1, j + 1), hat_node(i, j + 1)});
    for (int j = 0; j < 6; ++j)
      shells.push_back({static_cast<long long>(shells.size() + 1), plate_node(i, j), plate_node(i + 1, j),
                        plate_node(i + 1, j + 1), plate_node(i, j + 1)});
  }
  std::string d = node_cards(nodes) + shell_cards(1, shells) + part_card() + shell_property(0.0015, 5) +
                  elastic_material(7800.0, 2.1e11, 0.3);
  // Welds 1-6 on the flange at y = -45 mm, 7-12 on the one at +45 mm, each from the hat to the plate.
  d += "/SPRING/2\n";
  int weld = 0;
  for (int side = 0; side < 2; ++side)
    for (int i : kWeldStations)
      d += I(++weld) + I(hat_node(i, side == 0 ? 0 : 10)) + I(plate_node(i, side == 0 ? 0 : 6)) + "\n";
  d += "/PART/2\nwelds\n" + I(2) + I(0) + "\n/PROP/TYPE13/2\nweld\n" + R(1e-6) + R(1e-12) + "\n";
  d += weld_law(kWeldStiffness, kBreakElongation) + weld_law(kWeldStiffness) + weld_law(kWeldStiffness);
  for (int k = 0; k < 3; ++k) d += weld_law(100.0);
  std::vector<long long> plate, end;
  for (int i = 0; i < kStations; ++i)
    for (int j = 0; j < 7; ++j) plate.push_back(plate_node(i, j));
  for (int j = 0; j < 11; ++j) end.push_back(hat_node(0, j));
  d += node_group(1, plate) + boundary_condition(1, "111 111", 1) + node_group(2, end) + unit_function(9);
  d += imposed_velocity(1, 9, "Z", 2, kLift);
  return d;
}

}  // namespace

// Each weld follows its law, F = K delta in tension, to round-off until it breaks, and breaks in the first cycle
// whose elongation reaches delta_max: its largest tension is K delta_max plus at most that last cycle's opening (up
// to 0.94 % of delta_max here, where a station lets go and its neighbour takes the load within a few cycles). All
// twelve go, one station after the other from the lifted end, the two flanges' welds of a station in the same cycle
// (the deck is symmetric in y).
TEST(SpotWelds, PeeledHatWeldsBreakAtTheirRuptureForceInTurn) {
  test::TempDir dir;
  constexpr std::size_t kWelds = 12;
  std::vector<double> before_break(kWelds, 0.0), at_break(kWelds, 0.0), force_at_break(kWelds, 0.0),
      broken_at(kWelds, -1.0);
  double worst_law = 0.0;
  const RunResult r = run_deck(dir, hat_deck(), 0.03, 1e-9, [&](const Model&, const SolverState& s) {
    for (std::size_t w = 0; w < kWelds; ++w) {
      if (broken_at[w] >= 0.0) continue;
      const double delta = s.springs.elongation[6 * w], force = s.springs.force[6 * w];
      worst_law = std::max(worst_law, std::abs(force - kWeldStiffness * delta));
      if (element_condition(s.springs.deleted[w]) == kElementDeleted) {
        broken_at[w] = s.time, at_break[w] = delta, force_at_break[w] = force;
      } else {
        before_break[w] = delta;
      }
    }
  });
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  const double rupture = kWeldStiffness * kBreakElongation;
  EXPECT_LT(worst_law, 1e-9 * rupture);
  for (std::size_t w = 0; w < kWelds; ++w) {
    std::printf("weld %2zu at x = %3.0f mm: broken at %.3f ms, tension %.1f N (rupture law %.0f N), last opening "
                "%.2f %% of delta_max\n", w + 1, 1e3 * kPitch * kWeldStations[w % 6], 1e3 * broken_at[w],
                force_at_break[w], rupture, 100.0 * (at_break[w] - before_break[w]) / kBreakElongation);
    ASSERT_GT(broken_at[w], 0.0) << "weld " << w + 1 << " never broke";
    EXPECT_LT(before_break[w], kBreakElongation) << "weld " << w + 1;
    EXPECT_GE(at_break[w], kBreakElongation) << "weld " << w + 1;
    EXPECT_NEAR(force_at_break[w], rupture, 0.01 * rupture) << "weld " << w + 1;
  }
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(broken_at[k], broken_at[k + 6]) << "station " << k + 1;
    if (k > 0) {
      EXPECT_GT(broken_at[k], broken_at[k - 1]) << "station " << k + 1;
    }
  }
}

}  // namespace crumple::verification::test_spot_welds
