// The shared QA decks (../shared/qa) against the reference solver at the reference's time (docs/validation.md).
//
// The comparison is the library's (crumple/output/reference_check.hpp, docs/regression.md), the one `crumple
// regress` makes: Crumple's values at the TIME of ref.extract, internal energy within 10 % of the larger of its
// reference value and 0.1 % of the energy scale, kinetic energy (translational plus rotational) within 5 % of the
// scale, cycle count within 15 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/run.hpp"
#include "crumple/output/reference_check.hpp"
#include "deck_files.hpp"

namespace crumple::test {
namespace {

const std::filesystem::path kQa = CRUMPLE_QA_DIR;

struct QaCase {
  const char* folder;
  const char* deck;  // NAME of NAME_0000.rad
};

class QaDeck : public ::testing::TestWithParam<QaCase> {};

TEST_P(QaDeck, MatchesTheReferenceAtItsTime) {
  const QaCase& c = GetParam();
  const auto folder = kQa / c.folder;
  const ReferencePoint ref = read_reference(folder / "ref.extract");
  Deck deck = read_deck(folder / (std::string(c.deck) + "_0000.rad"));
  TempDir dir;
  SimulationOptions options;
  options.name = c.deck;
  options.output_directory = dir.path();
  std::ostringstream console;
  const RunSummary run = app::run_engine_decks(deck, options, console);
  ASSERT_EQ(run.status, RunStatus::Normal) << run.message;

  const Comparison result = compare(ref, read_run_point(dir.path(), c.deck, ref.time));
  ASSERT_TRUE(result.reaches_time) << "the histories end before the reference's time";
  const QuantityCheck& internal = result.internal;
  const QuantityCheck& kinetic = result.kinetic;
  const QuantityCheck& cycles = result.cycles;
  EXPECT_TRUE(internal.passed()) << result.failures();
  EXPECT_TRUE(kinetic.passed()) << result.failures();
  EXPECT_TRUE(cycles.passed()) << result.failures();
  std::printf("[qa %s] t %.4e  IE %.5g (ref %.5g, %+.1f %%)  KE %.5g (ref %.5g, %.1f %% of scale)  cycles %.0f "
              "(ref %.0f, %+.1f %%)  energy error %.3f %%\n",
              c.folder, result.time, internal.run, internal.reference,
              internal.reference != 0.0 ? 100.0 * (internal.run / internal.reference - 1.0) : 0.0, kinetic.run,
              kinetic.reference, 100.0 * std::abs(kinetic.difference()) / result.scale, cycles.run, cycles.reference,
              100.0 * (cycles.run / cycles.reference - 1.0), run.energy.error_percent);
}

INSTANTIATE_TEST_SUITE_P(
    Shared, QaDeck,
    ::testing::Values(QaCase{"ball_on_wall", "BOULE1V4"}, QaCase{"ball_two_runs", "BOULE1V4"},
                      QaCase{"box_crush", "BOX1BL"}, QaCase{"brick_bending_isolid1", "CONV_ELS"},
                      QaCase{"brick_bending_isolid24", "CONV_ELS"}, QaCase{"contact_idel", "IDEL8"},
                      QaCase{"crash_triangles", "TRITUBV4"}, QaCase{"friction", "FRICT41"},
                      QaCase{"rbody_rotation", "BLOCK"}, QaCase{"twisted_beam", "TWISBEAM"}),
    [](const auto& p) { return std::string(p.param.folder); });

}  // namespace
}  // namespace crumple::test
