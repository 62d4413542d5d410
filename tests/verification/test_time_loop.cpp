// Edge cases of the time loop (docs/theory/time-step.md, "No stable step"; docs/theory/time-loop.md, outputs).
#include <cmath>
#include <fstream>
#include <sstream>

#include "solver/internal.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_time_loop {
namespace {

// Point masses alone: nothing has stiffness, so no step is stable or unstable; the run refuses to start instead
// of jumping to the end time in one step (it used to, which silently skipped every load and output).
TEST(TimeLoop, ModelWithoutElementsIsRefused) {
  const std::string starter = node_cards({{1, 0.0, 0.0, 0.0}, {2, 1.0, 0.0, 0.0}}) + node_group(1, {1, 2}) +
                              added_mass(1, 2.0, 1) + initial_velocity(1, 1.0, 0.0, 0.0, 1);
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 1.0, 0.1);
  EXPECT_EQ(run.summary.status, RunStatus::Error);
  EXPECT_EQ(run.summary.cycles, 0);
  EXPECT_NE(run.summary.message.find("no element limits the time step"), std::string::npos) << run.summary.message;
}

// Output times: the first start + k interval after t, in O(1), with the loop's 1e-12 relative tolerance.
TEST(TimeLoop, NextOutputTimeJumpsOverManyIntervals) {
  using solver::next_output_time;
  EXPECT_DOUBLE_EQ(next_output_time(0.0, 0.0, 0.1), 0.1);
  EXPECT_NEAR(next_output_time(0.35, 0.0, 0.1), 0.4, 1e-15);
  // Exactly on an output time (to the tolerance): the next one.
  EXPECT_NEAR(next_output_time(0.3 * (1.0 - 1e-13), 0.0, 0.1), 0.4, 1e-15);
  // /ANIM/DT with a start time: outputs at start + k interval.
  EXPECT_NEAR(next_output_time(1.234, 1.0, 0.05), 1.25, 1e-15);
  // An interval 1e9 times below t: one evaluation, not 1e9 additions, and the result just after t.
  const double t = 1e-3, tiny = 1e-12;
  const double next = next_output_time(t, 0.0, tiny);
  EXPECT_GT(next, t * (1.0 + 1e-12));
  EXPECT_LE(next, t + 2.0 * tiny + 2e-15);
}

// Two steel shells in a row, flying at 1 m/s along x.
std::string moving_strip() {
  Strip strip;
  strip.nx = 2;
  return node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() + shell_property(0.01, 1) +
         elastic_material(7800.0, 2.1e11, 0.3) + node_group(1, strip.all()) + initial_velocity(1, 1.0, 0.0, 0.0, 1);
}

// A /TFILE interval far below the step: one history call per cycle, and the run takes no longer for it.
TEST(TimeLoop, TinyHistoryIntervalGivesOneSamplePerCycle) {
  const std::string starter = moving_strip();
  long long calls = 0;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 1e-3, 1e-15, [&](const Model&, const SolverState&) { ++calls; });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_EQ(calls, run.summary.cycles);
}

// A deck without /INTER/TYPE7 pays nothing for contact: no contact state is allocated, and the time loop's only
// contact code is the test of an empty interface list (docs/performance.md, "Contact").
TEST(TimeLoop, ContactFreeDeckCarriesNoContactState) {
  const std::string starter = moving_strip();
  bool checked = false;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 1e-4, 1e-5, [&](const Model&, const SolverState& s) {
    EXPECT_TRUE(s.contact.interfaces.empty());
    EXPECT_TRUE(s.contact.fx.empty() && s.contact.fy.empty() && s.contact.fz.empty());
    EXPECT_EQ(s.energy.contact, 0.0);
    checked = true;
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_TRUE(checked);
}

// The listing warns when the hourglass energy passes 10 % of the internal energy (docs/theory/energy.md): one
// square Belytschko-Tsay shell started in its membrane hourglass mode (x velocities +v -v +v -v around it, which
// the one-point strain does not see) stores most of its energy in the hourglass stiffness (the large-rotation
// terms of the mode give the rest); the same shell stretched uniformly has none, and its listing says nothing.
std::string listing_of(const test::TempDir& dir) {
  std::ifstream in(dir.path() / "VERIF.out");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TimeLoop, HourglassShareAboveTenPercentIsWarned) {
  Strip strip;
  const std::string shell = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                            shell_property(0.01, 1) + elastic_material(7800.0, 2.1e11, 0.3);
  const double v = 1.0;
  const std::string hourglass = shell + node_group(1, {1, 4}) + node_group(2, {2, 3}) +
                                initial_velocity(1, v, 0.0, 0.0, 1) + initial_velocity(2, -v, 0.0, 0.0, 2);
  const std::string stretch = shell + node_group(1, {2, 4}) + initial_velocity(1, v, 0.0, 0.0, 1);
  test::TempDir a, b;
  // A lone element needs /DT 0.8 (time-step.md, "Isolated elements").
  const RunResult mode = run_deck(a, hourglass, 5e-3, 1e-3, {}, "/DT\n0.8 0\n");
  ASSERT_EQ(mode.summary.status, RunStatus::Normal) << mode.summary.message;
  ASSERT_GT(mode.summary.energy.hourglass, 0.1 * std::abs(mode.summary.energy.internal));
  EXPECT_NE(listing_of(a).find("WARNING: hourglass energy is"), std::string::npos);
  EXPECT_NE(listing_of(a).find("HOURGLASS ENERGY AT THE END"), std::string::npos);
  const RunResult uniform = run_deck(b, stretch, 5e-3, 1e-3, {}, "/DT\n0.8 0\n");
  ASSERT_EQ(uniform.summary.status, RunStatus::Normal) << uniform.summary.message;
  EXPECT_LT(uniform.summary.energy.hourglass, 1e-6 * uniform.summary.energy.internal);
  EXPECT_EQ(listing_of(b).find("hourglass energy is"), std::string::npos);
}

// /DT/SHELL/CST against /DT/SHELL/DEL (docs/theory/time-step.md, "Element minimum"): a strip of 4 shells, one end
// held, the other pushed in at 300 m/s for 0.6 ms, shortens its elements and with them their step. With CST the elements
// that reach the minimum switch to small strain, which freezes their step: none is deleted, the listing names
// them, and the step never falls below 0.9 of the minimum (an element switches at the first cycle its step is below
// the minimum; at this crushing speed its length shrinks 5 % a cycle). With DEL the same elements are deleted. (The
// energy balance of this violent 4-element crush rings by +-1.5 % whether elements switch or not: the half-step
// kinetic energy against the whole-step strain energy; it is not what this test measures.)
struct StepControlRun {
  RunResult run;
  double smallest_dt = 1e300;
  std::size_t deleted = 0;
  std::string listing;
};

StepControlRun crushed_strip(const std::string& keyword3, double minimum) {
  Strip strip;
  strip.nx = 4, strip.ny = 1, strip.length = 0.4, strip.width = 0.1;
  const std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                              shell_property(0.01, 3) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, strip.column(0)) + boundary_condition(1, "111 111", 1) +
                              node_group(2, strip.column(4)) + unit_function(1) +
                              imposed_velocity(1, 1, "X", 2, -300.0);
  StepControlRun out;
  test::TempDir dir;
  std::ostringstream engine;
  engine << "/DT/SHELL/" << keyword3 << "\n0.9 " << minimum << "\n";
  constexpr double end = 6e-4;
  out.run = run_deck(dir, starter, end, 1e-9, [&](const Model&, const SolverState& s) {
    if (s.time < end * (1.0 - 1e-12)) out.smallest_dt = std::min(out.smallest_dt, s.dt);  // not the cut last step
    out.deleted = 0;
    for (std::uint8_t d : s.shells.deleted) out.deleted += d != 0;
  }, engine.str());
  out.listing = listing_of(dir);
  return out;
}

TEST(TimeLoop, ShellsAtTheirMinimumStepSwitchToSmallStrainOrAreDeleted) {
  // The undeformed strip's step: 0.9 x 0.1 / c_plate = 1.63e-5 s; the minimum is 70 % of it (the strip ends
  // 45 % shorter).
  const double c = std::sqrt(2.1e11 / (7800.0 * (1.0 - 0.09)));
  const double minimum = 0.7 * 0.9 * 0.1 / c;
  const StepControlRun cst = crushed_strip("CST", minimum), del = crushed_strip("DEL", minimum);
  ASSERT_EQ(cst.run.summary.status, RunStatus::Normal) << cst.run.summary.message;
  EXPECT_EQ(cst.deleted, 0u);
  EXPECT_NE(cst.listing.find("SWITCHED TO SMALL STRAIN"), std::string::npos);
  EXPECT_GT(cst.smallest_dt, 0.9 * minimum);
  EXPECT_GT(del.deleted, 0u);
  EXPECT_NE(del.listing.find("DELETED"), std::string::npos);
  std::printf("[dt shell cst] minimum %.4e  smallest step CST %.4e  deleted CST %zu DEL %zu  energy error CST %.3f %% "
              "DEL %.3f %%\n", minimum, cst.smallest_dt, cst.deleted, del.deleted, cst.run.summary.energy.error_percent,
              del.run.summary.energy.error_percent);
}

// /DT/BRICK/CST on Ismstr 2 bricks (brick8.md B-14): the same crush on a bar of 4 one-point bricks. With Ismstr 2
// the bricks at the minimum switch and the step stays above 0.9 of it; with Ismstr 4 (the default) CST has no
// effect, as the manual says, and the step goes on falling with the bricks' length.
double smallest_brick_step(int ismstr, double minimum) {
  constexpr double h = 0.1, end = 6e-4;
  std::vector<NodeRow> nodes;
  auto id = [](int i, int j, int k) { return 1 + 4 * i + j + 2 * k; };
  for (int i = 0; i <= 4; ++i)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j) nodes.push_back({id(i, j, k), h * i, h * j, h * k});
  std::string bricks = "/BRICK/1\n";
  for (int i = 0; i < 4; ++i)
    bricks += I(1 + i) + I(id(i, 0, 0)) + I(id(i, 1, 0)) + I(id(i, 1, 1)) + I(id(i, 0, 1)) + I(id(i + 1, 0, 0)) +
              I(id(i + 1, 1, 0)) + I(id(i + 1, 1, 1)) + I(id(i + 1, 0, 1)) + "\n";
  const std::string starter = node_cards(nodes) + bricks + part_card() + "/PROP/SOLID/1\nsolid\n" + I(1) + I(ismstr) +
                              "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, {1, 2, 3, 4}) + boundary_condition(1, "111 000", 1) +
                              node_group(2, {17, 18, 19, 20}) + unit_function(1) + imposed_velocity(1, 1, "X", 2, -300.0);
  std::ostringstream engine;
  engine << "/DT/BRICK/CST\n0.9 " << minimum << "\n";
  test::TempDir dir;
  double smallest = 1e300;
  const RunResult run = run_deck(dir, starter, end, 1e-9, [&](const Model&, const SolverState& s) {
    if (s.time < end * (1.0 - 1e-12)) smallest = std::min(smallest, s.dt);
  }, engine.str());
  EXPECT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  return smallest;
}

TEST(TimeLoop, BricksAtTheirMinimumStepSwitchWhenTheirFormulationCan) {
  const double crushed = smallest_brick_step(4, 1e-12);  // no switch: the crushed bar's smallest step
  const double minimum = 1.3 * crushed;                   // reached during the crush
  const double switched = smallest_brick_step(2, minimum), unswitched = smallest_brick_step(4, minimum);
  EXPECT_GT(switched, 0.9 * minimum);
  EXPECT_LT(unswitched, 0.8 * minimum);
  std::printf("[dt brick cst] minimum %.4e  smallest step Ismstr 2 %.4e, Ismstr 4 %.4e\n", minimum, switched, unswitched);
}

}  // namespace
}  // namespace crumple::verification::test_time_loop
