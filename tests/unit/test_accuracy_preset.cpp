// --accuracy draft|standard|fine (src/app/accuracy.hpp): what each preset moves in a read deck, and that it says
// every change in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/accuracy.hpp"
#include "crumple/elements/critical_step.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_accuracy_preset {

using namespace crumple;
using test::I;
using test::R;

namespace {

bool any_contains(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// A strip of `n` square shells of side 10 mm (property 1, N points) and, with `tiny`, one more shell of side
// 0.1 mm beside it (element step 100 times smaller).
std::string strip(int n, int points, bool tiny) {
  std::string s = "/NODE\n";
  for (int i = 0; i <= n; ++i) s += I(2 * i + 1) + R(0.01 * i) + R(0.0) + R(0.0) + "\n" + I(2 * i + 2) + R(0.01 * i) + R(0.01) + R(0.0) + "\n";
  const long long t = 2 * n + 3;
  if (tiny)
    s += I(t) + R(-1.0) + R(0.0) + R(0.0) + "\n" + I(t + 1) + R(-0.9999) + R(0.0) + R(0.0) + "\n" + I(t + 2) +
         R(-0.9999) + R(0.0001) + R(0.0) + "\n" + I(t + 3) + R(-1.0) + R(0.0001) + R(0.0) + "\n";
  s += "/SHELL/1\n";
  for (int i = 0; i < n; ++i) s += I(i + 1) + I(2 * i + 1) + I(2 * i + 3) + I(2 * i + 4) + I(2 * i + 2) + "\n";
  if (tiny) s += I(n + 1) + I(t) + I(t + 1) + I(t + 2) + I(t + 3) + "\n";
  s += "/PART/1\nstrip\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(points) + I(0) + R(0.001) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  return s;
}

struct Read {
  test::TempDir dir;
  Deck deck;
  Read(const std::string& starter_cards, const std::string& engine) {
    dir.write("TEST_0001.rad", engine);
    deck = read_deck(dir.write("TEST_0000.rad", test::begin_card() + starter_cards + "/END\n"));
  }
  std::vector<std::string> apply(app::AccuracyPreset preset) {
    return app::apply_accuracy_preset(preset, deck.model, {&deck.model.run});
  }
};

const std::string kEngine = test::engine_cards();

TEST(AccuracyPreset, StandardChangesNothing) {
  Read r(strip(4, 3, false), kEngine + "/DT/NODA/CST\n0.8 1e-7\n");
  EXPECT_TRUE(r.apply(app::AccuracyPreset::Standard).empty());
  EXPECT_EQ(r.deck.model.formulations[0].n_points, 3);
  EXPECT_TRUE(r.deck.model.run.dt_nodal_cst.given);
}

TEST(AccuracyPreset, FineCapsTheStepScalesRemovesAddedMassAndTakesFivePoints) {
  Read r(strip(4, 3, false), kEngine + "/DT\n0.8 0\n/DT/SHELL\n0.7 0\n/DT/NODA/CST\n0.8 1e-7\n/DT/INTER/CST\n0.9 1e-8\n");
  const auto changes = r.apply(app::AccuracyPreset::Fine);
  const RunControl& run = r.deck.model.run;
  EXPECT_DOUBLE_EQ(run.dt.scale, app::kFineStepScale);
  EXPECT_DOUBLE_EQ(run.dt_shell.scale, app::kFineStepScale);
  EXPECT_FALSE(run.dt_nodal_cst.given);
  EXPECT_FALSE(run.dt_inter_cst.given);
  EXPECT_EQ(r.deck.model.formulations[0].n_points, 5);
  ASSERT_EQ(changes.size(), 5u);
  EXPECT_TRUE(any_contains(changes, "--accuracy fine: /DT scale 0.8 -> 0.6"));
  EXPECT_TRUE(any_contains(changes, "--accuracy fine: /DT/SHELL scale 0.7 -> 0.6"));
  EXPECT_TRUE(any_contains(changes, "--accuracy fine: /DT/NODA/CST 0.8 1e-07 removed"));
  EXPECT_TRUE(any_contains(changes, "--accuracy fine: /DT/INTER/CST 0.9 1e-08 removed"));
  EXPECT_TRUE(any_contains(changes, "--accuracy fine: /PROP/SHELL/1 N 3 -> 5 points"));
}

TEST(AccuracyPreset, FineKeepsWhatIsAlreadyFinerAndTheSectionsThatAreNotIntegrationChoices) {
  Read r(strip(4, 1, false), kEngine + "/DT\n0.5 0\n");  // N = 1: a membrane, not a coarse integration
  EXPECT_TRUE(r.apply(app::AccuracyPreset::Fine).empty());
  EXPECT_DOUBLE_EQ(r.deck.model.run.dt.scale, 0.5);
  EXPECT_EQ(r.deck.model.formulations[0].n_points, 1);
}

TEST(AccuracyPreset, DraftKeepsThePointsAndHoldsAUniformMeshAtSixTenthsOfItsFirstStep) {
  Read r(strip(200, 5, false), kEngine);
  const auto changes = r.apply(app::AccuracyPreset::Draft);
  EXPECT_EQ(r.deck.model.formulations[0].n_points, 5);
  // Every element has the same step: the target is 0.63 times the nodal step the run starts with (/DT 0.9), for
  // QEPH sqrt(1 - nu^2) of the element's (T-2), so 0.6 times the element's; at the nodal scale 0.67, and the run
  // warns beyond 5 % of energy error.
  const RunControl& run = r.deck.model.run;
  const TimeStepControl& cst = run.dt_nodal_cst;
  ASSERT_TRUE(cst.given);
  const double step = initial_element_time_step(r.deck.model, ElementKind::Shell4, 0);
  const double nodal = initial_element_nodal_step(r.deck.model, ElementKind::Shell4, 0);
  EXPECT_NEAR(nodal, std::sqrt(1.0 - 0.3 * 0.3) * step, 1e-12 * step);
  EXPECT_DOUBLE_EQ(cst.scale, 0.67);
  EXPECT_NEAR(cst.minimum, 0.63 * 0.9 * nodal, 1e-9 * step);
  EXPECT_NEAR(cst.minimum, 0.6 * 0.9 * step, 0.002 * step);
  EXPECT_DOUBLE_EQ(run.energy_error_warning, 5.0);
  EXPECT_TRUE(run.nodal_step_at_least_as_written) << "the deck's own step where larger (T-3c)";
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(any_contains(changes, "--accuracy draft: /DT/NODA/CST 0.67"));
}

TEST(AccuracyPreset, DraftMassScalesTheSmallestPercentOfTheElements) {
  Read r(strip(200, 3, true), kEngine + "/DT\n0.5 0\n");  // 200 shells of 10 mm and one of 0.1 mm (1/100 the step)
  const auto changes = r.apply(app::AccuracyPreset::Draft);
  const TimeStepControl& cst = r.deck.model.run.dt_nodal_cst;
  ASSERT_TRUE(cst.given);
  const double big = initial_element_nodal_step(r.deck.model, ElementKind::Shell4, 0);
  EXPECT_DOUBLE_EQ(cst.scale, 0.67);
  EXPECT_NEAR(cst.minimum, 0.63 * 0.5 * big, 1e-9 * big);  // the 1st percentile is a 10 mm shell's, at /DT 0.5
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(any_contains(changes, "--accuracy draft: /DT/NODA/CST 0.67"));
}

TEST(AccuracyPreset, StandardKeepsTheTenPercentEnergyWarning) {
  Read r(strip(4, 3, false), kEngine);
  EXPECT_TRUE(r.apply(app::AccuracyPreset::Standard).empty());
  EXPECT_DOUBLE_EQ(r.deck.model.run.energy_error_warning, 10.0);
}

TEST(AccuracyPreset, DraftKeepsADeckThatMassScalesFurther) {
  Read r(strip(200, 3, true), kEngine + "/DT/NODA/CST\n0.9 1\n");
  EXPECT_TRUE(r.apply(app::AccuracyPreset::Draft).empty());
  EXPECT_DOUBLE_EQ(r.deck.model.run.dt_nodal_cst.minimum, 1.0);
}

// fine also counts K0 in the TYPE7 steps three steps before a node enters the gap (docs/theory/contact.md, C-11);
// a deck without contact is not told about it, and the deck as written keeps the reference's rule.
TEST(AccuracyPreset, FineAnticipatesContactEntryWhenThereIsContact) {
  Read plain(strip(4, 3, false), kEngine);
  EXPECT_FALSE(any_contains(plain.apply(app::AccuracyPreset::Fine), "TYPE7"));
  EXPECT_EQ(plain.deck.model.run.contact_entry_window, 0);
  const std::string contact = "/GRNOD/NODE/10\nnodes\n" + I(1) + I(2) + "\n/SURF/PART/20\nsurface\n" + I(1) +
                              "\n/INTER/TYPE7/5\ncontact\n" + I(10) + I(20) + "\n\n\n\n       000\n\n";
  Read standard(strip(4, 3, false) + contact, kEngine);
  EXPECT_TRUE(standard.apply(app::AccuracyPreset::Standard).empty());
  EXPECT_EQ(standard.deck.model.run.contact_entry_window, 0);
  Read draft(strip(4, 3, false) + contact, kEngine);
  draft.apply(app::AccuracyPreset::Draft);
  EXPECT_TRUE(draft.deck.model.run.nodal_step_at_least_as_written) << "with its contacts' steps (T-3c)";
  Read fine(strip(4, 3, false) + contact, kEngine);
  EXPECT_TRUE(any_contains(fine.apply(app::AccuracyPreset::Fine), "TYPE7 contact steps count K0 from 3 steps"));
  EXPECT_EQ(fine.deck.model.run.contact_entry_window, app::kFineContactEntryWindow);
}

TEST(AccuracyPreset, NamesAreTheThreePresets) {
  EXPECT_EQ(app::accuracy_preset("draft"), app::AccuracyPreset::Draft);
  EXPECT_EQ(app::accuracy_preset("fine"), app::AccuracyPreset::Fine);
  EXPECT_THROW(app::accuracy_preset("coarse"), std::invalid_argument);
}

}  // namespace

}  // namespace test_accuracy_preset
