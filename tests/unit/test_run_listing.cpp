// While a run goes (README, "Watching and stopping a run"): the console progress line, the listing written row by
// row with a header, a cycle-0 row and each cycle's row once, and a stop asked from outside the solver.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <sstream>

#include "crumple/output/progress.hpp"
#include "crumple/output/run.hpp"
#include "crumple/output/run_summary.hpp"
#include "crumple/solver/solver_state.hpp"
#include "deck_files.hpp"
#include "crumple/output/results_reader.hpp"

namespace crumple::test_run_listing {
namespace {

TEST(Progress, DurationsAreMinutesAndSecondsThenHours) {
  EXPECT_EQ(format_duration(0.0), "0:00");
  EXPECT_EQ(format_duration(4.9), "0:04");  // whole seconds gone: the clock does not run ahead
  EXPECT_EQ(format_duration(59.99), "0:59");
  EXPECT_EQ(format_duration(60.0), "1:00");
  EXPECT_EQ(format_duration(725.0), "12:05");
  EXPECT_EQ(format_duration(3599.5), "59:59");
  EXPECT_EQ(format_duration(3600.0), "1:00:00");
  EXPECT_EQ(format_duration(11222.0), "3:07:02");
  EXPECT_EQ(format_duration(-1.0), "?");  // no estimate yet
  EXPECT_EQ(format_duration(std::numeric_limits<double>::quiet_NaN()), "?");
  EXPECT_EQ(format_duration(std::numeric_limits<double>::infinity()), "?");
}

TEST(Progress, RemainingTimeFollowsTheRateSinceTheStart) {
  EXPECT_DOUBLE_EQ(remaining_seconds(0.0, 1.0, 3.0, 2.0), 4.0);  // 1 of 3 time units in 2 s: 2 more take 4 s
  EXPECT_DOUBLE_EQ(remaining_seconds(1.0, 2.0, 3.0, 5.0), 5.0);  // a continued run counts from its own start
  EXPECT_EQ(remaining_seconds(0.0, 3.0, 3.0, 7.0), 0.0);
  EXPECT_EQ(remaining_seconds(0.0, 3.5, 3.0, 7.0), 0.0);          // past the end (the last step lands on it)
  EXPECT_LT(remaining_seconds(0.5, 0.5, 3.0, 1.0), 0.0);          // no simulation time gone: unknown
}

TEST(Progress, LineSaysCycleTimeShareStepControlErrorAndWallTimes) {
  ProgressValues v;
  v.cycle = 4000, v.time = 1.6841, v.end_time = 3.0, v.dt = 2.8291e-4, v.control = "SHELL 10";
  v.error_percent = -0.0234, v.elapsed_seconds = 4.3, v.remaining_seconds = 3.4;
  EXPECT_EQ(progress_line(v), "cycle 4000  t 1.684e+00 56.1%  dt 2.829e-04 SHELL 10  err -0.02%  elapsed 0:04  left 0:03");
  v.remaining_seconds = -1.0, v.end_time = 0.0, v.elapsed_seconds = 3725.0;
  EXPECT_EQ(progress_line(v), "cycle 4000  t 1.684e+00 0.0%  dt 2.829e-04 SHELL 10  err -0.02%  elapsed 1:02:05  left ?");
}

TEST(Progress, ClockIsDueOncePerIntervalAndNeverWhenOff) {
  ProgressClock off(ProgressOptions{ProgressOptions::Mode::Off, 0.0, 0});
  EXPECT_FALSE(off.due());
  ProgressClock every(ProgressOptions{ProgressOptions::Mode::Lines, 0.0, 0});
  EXPECT_TRUE(every.due());
  EXPECT_TRUE(every.due());
  ProgressClock hourly(ProgressOptions{ProgressOptions::Mode::Terminal, 3600.0, 80});
  EXPECT_FALSE(hourly.due());  // the first update one interval after the start
}

// ---------------------------------------------------------------------------------------------------------------
// The listing and the stop, on the test plate (deck_files.hpp): 2 elastic shells, the left edge moving at 1 m/s.

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Row {
  long long cycle;
  double time;
};

std::vector<Row> table_rows(const std::string& listing) {
  std::vector<Row> rows;
  const std::regex row(R"(^\s*(\d+)\s+([-+0-9.eE]+)\s+[-+0-9.eE]+\s)");
  std::istringstream in(listing);
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, row)) rows.push_back({std::stoll(m[1]), std::stod(m[2])});
  return rows;
}

std::string moving_plate() {
  return "/INIVEL/TRA/1\nleft edge\n" + test::R(1.0) + test::R(0.0) + test::R(0.0) + test::I(1) + "\n" +
         "/GRNOD/NODE/1\nleft\n" + test::I(1) + test::I(4) + "\n";
}

struct PlateRun {
  RunSummary summary;
  std::string listing;
};

PlateRun run_plate(const test::TempDir& dir, const std::string& engine, const std::function<void(const SolverState&)>&
              observer = {}, const std::atomic<int>* stop = nullptr) {
  const Model model = read_deck(test::write_deck(dir, moving_plate(), engine)).model;
  SimulationOptions options;
  options.name = "TEST";
  options.output_directory = dir.path();
  options.deck = dir.path() / "TEST_0000.rad";
  options.on_history_row = observer;
  options.stop_request = stop;
  std::ostringstream console;
  const RunSummary summary = run_simulation(model, options, console);
  return {summary, read_text(dir.path() / "TEST.out")};
}

TEST(RunListing, HeaderNamesTheVersionDeckUnitsAndModel) {
  test::TempDir dir;
  const PlateRun run = run_plate(dir, test::engine_cards(1e-4));
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  const std::string& l = run.listing;
  // The version and the commit it was built from (build_info.hpp).
  EXPECT_TRUE(std::regex_search(
      l, std::regex(R"(^Crumple \d+\.\d+\.\d+ \(([0-9a-f]{12}(-modified)?|unknown)\) explicit run TEST)")))
      << l;
  EXPECT_TRUE(std::regex_search(l, std::regex(R"(\nSTARTED \d{4}-\d\d-\d\d \d\d:\d\d:\d\d\n)"))) << l;
  EXPECT_NE(l.find("\nDECK " + (dir.path() / "TEST_0000.rad").string() + "\n"), std::string::npos) << l;
  EXPECT_NE(l.find("\nWORKING UNITS (SI size of one unit): mass 1 kg  length 1 m  time 1 s\n"), std::string::npos) << l;
  EXPECT_NE(l.find("\nUNITS mass kg, length m, time s, force N, energy J, stress Pa\n"), std::string::npos) << l;
  EXPECT_NE(l.find("\nnodes 6  4-node shells 2  3-node shells 0  8-node bricks 0  springs 0  trusses 0  beams 0  "
                   "element groups 1  parts 1  interfaces 0  rigid bodies 0  rigid walls 0\n"),
            std::string::npos)
      << l;
  EXPECT_NE(l.find("\nENGINE DECK 1: end time 0.0001\n"), std::string::npos) << l;
}

// The first row is cycle 0, before any step; the last is the run's last cycle, printed once although it is both a
// /PRINT cycle (every cycle here) and the end of the run.
TEST(RunListing, RowsRunFromCycleZeroToTheLastCycleEachOnce) {
  test::TempDir dir;
  const PlateRun run = run_plate(dir, test::engine_cards(1e-4) + "/PRINT/-1\n");
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  const std::vector<Row> rows = table_rows(run.listing);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(run.summary.cycles) + 1) << run.listing;
  for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(rows[k].cycle, static_cast<long long>(k)) << run.listing;
  EXPECT_EQ(rows.front().time, 0.0);
  EXPECT_NE(run.listing.find("\nNORMAL TERMINATION\n"), std::string::npos) << run.listing;
}

TEST(RunListing, LastCycleOffThePrintIntervalGetsItsOwnRow) {
  test::TempDir dir;
  const PlateRun run = run_plate(dir, test::engine_cards(1e-4) + "/PRINT/-7\n");
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_NE(run.summary.cycles % 7, 0) << "pick another /PRINT interval";
  const std::vector<Row> rows = table_rows(run.listing);
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows.back().cycle, run.summary.cycles);
  EXPECT_EQ(rows[rows.size() - 2].cycle, run.summary.cycles / 7 * 7);
}

// A stop request seen at the end of a cycle ends the run there: status stopped, the listing's stop message after
// the cycle's row, and the results file's last frame at that cycle, once, even when a frame was due there anyway.
TEST(RunListing, StopRequestEndsTheRunAtTheEndOfTheCycle) {
  test::TempDir dir;
  std::atomic<int> stop{0};
  long long asked_at = -1;
  const std::string engine = "/RUN/TEST/1\n1e-4\n/TFILE\n1e-5\n/ANIM/DT\n0 1e-5\n";
  const PlateRun run = run_plate(dir, engine, [&](const SolverState& s) {
    if (s.time > 3e-5 && asked_at < 0) asked_at = s.cycle, stop.store(SIGTERM);  // at a frame and history time
  }, &stop);
  ASSERT_GT(asked_at, 0);
  EXPECT_EQ(run.summary.status, RunStatus::Stopped);
  EXPECT_TRUE(run.summary.stopped_on_request);
  EXPECT_EQ(run.summary.cycles, asked_at);
  EXPECT_LT(run.summary.time, 1e-4);
  const std::string expected = "stopped by SIGTERM at the end of cycle " + std::to_string(asked_at);
  EXPECT_EQ(run.summary.message.rfind(expected, 0), 0u) << run.summary.message;
  const std::vector<Row> rows = table_rows(run.listing);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back().cycle, asked_at);
  const auto stop_line = run.listing.find("\nRUN STOPPED ON REQUEST: " + expected);
  EXPECT_NE(stop_line, std::string::npos) << run.listing;
  EXPECT_GT(stop_line, run.listing.rfind("\n" + fmt::format("{:>9}", asked_at) + " ")) << run.listing;

  const ResultsReader h5(dir.path() / "TEST.h5");
  int frames = 0;
  while (h5.exists(fmt::format("/frames/{:04}", frames))) ++frames;
  ASSERT_GE(frames, 2);
  const std::string last = fmt::format("/frames/{:04}", frames - 1);
  EXPECT_EQ(h5.attribute<std::int64_t>(last, "cycle"), asked_at);
  EXPECT_EQ(h5.attribute<double>(last, "time"), run.summary.time);
  EXPECT_LT(h5.attribute<std::int64_t>(fmt::format("/frames/{:04}", frames - 2), "cycle"),
            asked_at);  // not written twice
}

// A stop asked while the run writes its end state (its last history row, T-0) leaves it a normal run.
TEST(RunListing, StopRequestAtTheEndStateLeavesANormalRun) {
  test::TempDir dir;
  std::atomic<int> stop{0};
  // A history row every cycle; the end state is the one whose next step would pass the end time (T-0).
  const PlateRun run = run_plate(dir, "/RUN/TEST/1\n1e-4\n/TFILE\n1e-12\n", [&](const SolverState& s) {
    if (s.time + s.dt > 1e-4) stop.store(SIGINT);
  }, &stop);
  ASSERT_NE(stop.load(), 0);
  EXPECT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_FALSE(run.summary.stopped_on_request);
}

}  // namespace
}  // namespace crumple::test_run_listing

namespace test_run_listing_parts {

using namespace crumple;

// The part table at the end of a run (listing and NAME.summary.json, issue 29): /TH/PART's values for every part,
// so its sums are the last history row's totals (the same state: the loop's, E-3), on the shell strip and the
// brick of tests/regression/decks/th_strip, two parts.
TEST(RunListing, PartTableAddsUpToTheLastHistoryRow) {
  test::TempDir dir;
  const std::filesystem::path deck = std::filesystem::path(CRUMPLE_TEST_DECKS) / "th_strip" / "THSTRIP_0000.rad";
  const Deck d = read_deck(deck);
  SimulationOptions options;
  options.name = "PARTS";
  options.output_directory = dir.path();
  std::ostringstream console;
  const RunSummary s = run_simulation(d.model, options, console);
  ASSERT_EQ(s.status, RunStatus::Normal) << s.message;
  ASSERT_EQ(s.parts.size(), 2u);
  const ResultsReader h5(dir.path() / "PARTS.h5");
  const auto last = [&](const char* series) { return h5.doubles(std::string("/history/") + series).back(); };
  double internal = 0.0, kinetic = 0.0, hourglass = 0.0;
  for (const PartResult& p : s.parts) {
    internal += p.internal, kinetic += p.kinetic, hourglass += p.hourglass;
    EXPECT_GT(p.mass, 0.0) << p.id;
    EXPECT_GT(p.internal, 0.0) << p.id;  // both parts deform
  }
  const double scale = std::abs(last("internal")) + std::abs(last("kinetic_translational"));
  EXPECT_NEAR(internal, last("internal"), 1e-12 * scale);
  EXPECT_NEAR(kinetic, last("kinetic_translational") + last("kinetic_rotational"), 1e-12 * scale);
  EXPECT_NEAR(hourglass, last("hourglass"), 1e-12 * scale);
  const std::string listing = [&] {
    std::ifstream in(dir.path() / "PARTS.out");
    std::stringstream t;
    t << in.rdbuf();
    return t.str();
  }();
  EXPECT_NE(listing.find("PARTS AT THE END (mass kg, energies J):\n"), std::string::npos) << listing;
  EXPECT_TRUE(std::regex_search(
      listing, std::regex(R"(\nPART 1 +MASS [0-9.e+-]+  INTERNAL [0-9.e+-]+  KINETIC [0-9.e+-]+  HOURGLASS [0-9.e+-]+  )")))
      << listing;
  const std::string json = to_json(s);
  EXPECT_NE(json.find("\"parts\": [\n    {\"id\": 1, \"title\": "), std::string::npos) << json;
}

}  // namespace test_run_listing_parts
