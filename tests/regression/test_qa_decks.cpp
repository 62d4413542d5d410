// The shared QA decks (../shared/qa) against the reference solver at the reference's time (docs/validation.md).
//
// ref.extract is the reference listing's last printed row, which can come before the run's end: Crumple's values
// are taken at the TIME of ref.extract, interpolating linearly between the rows of the results file's histories
// (energies) and between the rows of the listing's last energy table (cycles). Tolerances (issue 10): internal
// energy within 10 % of the larger of its reference value and 0.1 % of the energy scale; kinetic energy
// (translational plus rotational) within 5 % of the scale; cycle count within 15 %.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "app/run.hpp"
#include "h5_reader.hpp"
#include "qa_reference.hpp"

namespace crumple::test {
namespace {

const std::filesystem::path kQa = CRUMPLE_QA_DIR;

// y(t) on a table of increasing times, linear between rows (the last value past the end).
double at_time(const std::vector<double>& t, const std::vector<double>& y, double time) {
  if (t.empty()) return std::nan("");
  if (time <= t.front()) return y.front();
  for (std::size_t k = 1; k < t.size(); ++k)
    if (time <= t[k]) {
      const double w = t[k] > t[k - 1] ? (time - t[k - 1]) / (t[k] - t[k - 1]) : 1.0;
      return y[k - 1] + w * (y[k] - y[k - 1]);
    }
  return y.back();
}

// Cycle and time of the rows of the listing's last energy table (a continued run's tables start again from 0).
void listing_cycles(const std::filesystem::path& listing, std::vector<double>& times, std::vector<double>& cycles) {
  std::ifstream in(listing);
  const std::regex row(R"(^\s*(\d+)\s+([-+0-9.eE]+)\s)");
  std::smatch m;
  for (std::string line; std::getline(in, line);) {
    if (!std::regex_search(line, m, row)) continue;
    const double cycle = std::stod(m[1]), time = std::stod(m[2]);
    if (!cycles.empty() && cycle < cycles.back()) times.clear(), cycles.clear();
    if (times.empty() || time > times.back()) times.push_back(time), cycles.push_back(cycle);
  }
}

struct QaCase {
  const char* folder;
  const char* deck;  // NAME of NAME_0000.rad
  // A known, measured deviation of the kinetic energy (docs/validation.md): the test still checks the internal
  // energy and the cycles, reports the kinetic energy as skipped while it is outside its tolerance, and fails once
  // it is inside, so that the case is closed.
  const char* open_kinetic = nullptr;
};

class QaDeck : public ::testing::TestWithParam<QaCase> {};

TEST_P(QaDeck, MatchesTheReferenceAtItsTime) {
  const QaCase& c = GetParam();
  const auto folder = kQa / c.folder;
  const auto ref = read_reference(folder / "ref.extract");
  Deck deck = read_deck(folder / (std::string(c.deck) + "_0000.rad"));
  TempDir dir;
  SolverOptions options;
  options.name = c.deck;
  options.output_directory = dir.path();
  std::ostringstream console;
  const RunSummary run = app::run_engine_decks(deck, options, console);
  ASSERT_EQ(run.status, RunStatus::Normal) << run.message;

  const double time = ref.at("TIME").value, scale = ref.at("IENERGY").scale;
  const H5Reader h5(dir.path() / (std::string(c.deck) + ".h5"));
  const std::vector<double> t = h5.doubles("/history/time");
  ASSERT_FALSE(t.empty());
  ASSERT_GE(t.back(), 0.98 * time) << "the histories end before the reference's time";
  std::vector<double> kinetic = h5.doubles("/history/kinetic_translational");
  const std::vector<double> rotational = h5.doubles("/history/kinetic_rotational");
  for (std::size_t k = 0; k < kinetic.size(); ++k) kinetic[k] += rotational[k];
  const double internal = at_time(t, h5.doubles("/history/internal"), time);
  const double kinetic_at = at_time(t, kinetic, time);
  std::vector<double> listing_t, listing_c;
  listing_cycles(dir.path() / (std::string(c.deck) + ".out"), listing_t, listing_c);
  const double cycles = at_time(listing_t, listing_c, time);

  const double internal_ref = ref.at("IENERGY").value;
  const double kinetic_ref = ref.at("KENERGYT").value + ref.at("KENERGYR").value;
  const double cycles_ref = ref.at("CYCLE").value;
  EXPECT_NEAR(internal, internal_ref, 0.10 * std::max(std::abs(internal_ref), 1e-3 * scale));
  const bool kinetic_matches = std::abs(kinetic_at - kinetic_ref) <= 0.05 * scale;
  if (c.open_kinetic == nullptr) EXPECT_NEAR(kinetic_at, kinetic_ref, 0.05 * scale);
  else EXPECT_FALSE(kinetic_matches) << c.folder << "'s kinetic energy now matches: remove its open_kinetic note";
  EXPECT_NEAR(cycles, cycles_ref, 0.15 * cycles_ref);
  std::printf("[qa %s] t %.4e  IE %.5g (ref %.5g, %+.1f %%)  KE %.5g (ref %.5g, %.1f %% of scale)  cycles %.0f "
              "(ref %.0f, %+.1f %%)  energy error %.3f %%\n",
              c.folder, time, internal, internal_ref, internal_ref != 0.0 ? 100.0 * (internal / internal_ref - 1.0) : 0.0,
              kinetic_at, kinetic_ref,
              100.0 * std::abs(kinetic_at - kinetic_ref) / scale, cycles, cycles_ref,
              100.0 * (cycles / cycles_ref - 1.0), run.energy.error_percent);
  if (c.open_kinetic != nullptr && !kinetic_matches && !HasFailure())
    GTEST_SKIP() << "known open: kinetic energy " << kinetic_at << " against " << kinetic_ref << " ("
                 << 100.0 * std::abs(kinetic_at - kinetic_ref) / scale << " % of the scale, tolerance 5 %): "
                 << c.open_kinetic;
}

INSTANTIATE_TEST_SUITE_P(
    Shared, QaDeck,
    ::testing::Values(QaCase{"ball_on_wall", "BOULE1V4"}, QaCase{"ball_two_runs", "BOULE1V4"},
                      QaCase{"box_crush", "BOX1BL"}, QaCase{"brick_bending_isolid1", "CONV_ELS"},
                      QaCase{"brick_bending_isolid24", "CONV_ELS"}, QaCase{"contact_idel", "IDEL8",
                             "within 1.6 of the reference from t = 0.015 to 0.046, -5.1 at 0.011, +3.1 at its last row (docs/validation.md)"},
                      QaCase{"crash_triangles", "TRITUBV4"}, QaCase{"friction", "FRICT41"},
                      QaCase{"rbody_rotation", "BLOCK"}, QaCase{"twisted_beam", "TWISBEAM"}),
    [](const auto& p) { return std::string(p.param.folder); });

}  // namespace
}  // namespace crumple::test
