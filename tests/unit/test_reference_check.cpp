// The comparison with a reference (crumple/output/reference_check.hpp, docs/regression.md): ref.extract, the
// interpolation at the reference's time, the listing's cycles, the tolerance file and the verdicts.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/run.hpp"
#include "crumple/output/reference_check.hpp"
#include "crumple/output/results_reader.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_reference_check {

using namespace crumple;

namespace {

// box_crush's ref.extract, tab-separated as the reference writes it.
const char* const kRefExtract =
    "    1 Start                    0\n"
    "    2 CYCLE\t      1102\n"
    "    3 TIME\t 1.0010e-01\n"
    "    7 ERROR\t -0.0\n"
    "    8 IENERGY\t 3.4970e+01 7.6460e+03\n"
    "    9 KENERGYT\t 7.6460e+03 7.6460e+03\n"
    "   10 KENERGYR\t 6.7880e-03 7.6460e+03\n"
    "   13 Stop                    0\n";

// The error ReferenceFileError `read` throws, or a default one when it throws none.
template <class Read>
ReferenceFileError error_of(Read&& read) {
  try {
    read();
  } catch (const ReferenceFileError& e) {
    return e;
  }
  return ReferenceFileError("none", -1, "none", "no error");
}

TEST(ReferenceExtract, EveryLineIsReadWithItsScale) {
  test::TempDir dir;
  const auto values = read_reference_values(dir.write("ref.extract", kRefExtract));
  EXPECT_EQ(values.size(), 8u);
  EXPECT_EQ(values.at("CYCLE").value, 1102.0);
  EXPECT_EQ(values.at("CYCLE").scale, 0.0);
  EXPECT_EQ(values.at("IENERGY").value, 34.97);
  EXPECT_EQ(values.at("IENERGY").scale, 7646.0);
  EXPECT_EQ(values.at("Start").value, 0.0);
}

TEST(ReferenceExtract, ThePointSumsTheKineticEnergyAndTakesTheInternalEnergysScale) {
  test::TempDir dir;
  const ReferencePoint p = read_reference(dir.write("ref.extract", kRefExtract));
  EXPECT_EQ(p.time, 0.1001);
  EXPECT_EQ(p.cycles, 1102.0);
  EXPECT_EQ(p.internal, 34.97);
  EXPECT_EQ(p.kinetic, 7646.0 + 6.788e-3);
  EXPECT_EQ(p.scale, 7646.0);
}

TEST(ReferenceExtract, AMalformedLineNamesTheFileTheLineAndTheKey) {
  test::TempDir dir;
  const auto file = dir.write("ref.extract", "    2 CYCLE\t 1102\n\n    4 TIME\t 1.0e-01 x\n");
  const ReferenceFileError e = error_of([&] { read_reference_values(file); });
  EXPECT_EQ(e.file(), file);
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "TIME");
  EXPECT_EQ(std::string(e.what()), file.string() + ":3: TIME: expected '<line> KEY value [scale]', found "
                                                    "'    4 TIME\t 1.0e-01 x'");
}

TEST(ReferenceExtract, AMissingKeyOrFileIsNamed) {
  test::TempDir dir;
  const auto file = dir.write("ref.extract", "    2 CYCLE\t 1102\n    3 TIME\t 0.1\n    8 IENERGY\t 1 2\n");
  EXPECT_EQ(std::string(error_of([&] { read_reference(file); }).what()),
            file.string() + ": KENERGYT: missing (needed for the comparison)");
  const auto none = dir.path() / "none.extract";
  EXPECT_EQ(std::string(error_of([&] { read_reference(none); }).what()),
            none.string() + ": cannot read the reference values");
}

TEST(ValueAtTime, LinearBetweenRowsAndHeldOutsideTheTable) {
  const std::vector<double> t{0.0, 1.0, 3.0}, y{0.0, 10.0, 50.0};
  EXPECT_EQ(value_at_time(t, y, 0.5), 5.0);
  EXPECT_EQ(value_at_time(t, y, 1.0), 10.0);
  EXPECT_EQ(value_at_time(t, y, 2.0), 30.0);
  EXPECT_EQ(value_at_time(t, y, -1.0), 0.0);
  EXPECT_EQ(value_at_time(t, y, 4.0), 50.0);
  EXPECT_TRUE(std::isnan(value_at_time({}, {}, 1.0)));
  // Two rows at one time (a continued run's first row): the later one.
  EXPECT_EQ(value_at_time({0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 7.0, 9.0}, 1.0), 1.0);
  EXPECT_EQ(value_at_time({0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 7.0, 9.0}, 1.5), 8.0);
}

TEST(ListingCycles, TheLastEnergyTableCounts) {
  test::TempDir dir;
  const auto listing = dir.write("R.out",
                                 "Crumple explicit run R\n"
                                 "    CYCLE        TIME   TIME-STEP ELEMENT\n"
                                 "      100  1.0000e-04  1.0e-06 SHELL 1\n"
                                 "      200  2.0000e-04  1.0e-06 SHELL 1\n"
                                 "        0  2.0000e-04  1.0e-06 SHELL 1\n"  // the continued run's table
                                 "       50  2.5000e-04  1.0e-06 SHELL 1\n"
                                 "       50  2.5000e-04  1.0e-06 SHELL 1\n"  // the last row printed twice
                                 "TOTAL NUMBER OF CYCLES 50\n");
  const ListingCycles rows = read_listing_cycles(listing);
  EXPECT_EQ(rows.time, (std::vector<double>{2e-4, 2.5e-4}));
  EXPECT_EQ(rows.cycle, (std::vector<double>{0.0, 50.0}));
}

TEST(Tolerances, AFileTightensTheFieldsItNamesInPercent) {
  test::TempDir dir;
  const Tolerances t = read_tolerances(dir.write(kToleranceFile, "# tighter\n\ninternal 5   # was 10\ncycles 15\n"
                                                                 "internal_floor 0.05\n"));
  EXPECT_EQ(t.internal, 0.05);
  EXPECT_EQ(t.internal_floor, 0.05 / 100.0);
  EXPECT_EQ(t.kinetic, Tolerances{}.kinetic);  // not named: the default
  EXPECT_EQ(t.cycles, 0.15);                   // equal to the default: accepted
}

TEST(Tolerances, AWiderValueIsRefusedNamingTheFileLineAndField) {
  test::TempDir dir;
  const auto file = dir.write(kToleranceFile, "internal 5\nkinetic 7\n");
  const ReferenceFileError e = error_of([&] { read_tolerances(file); });
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.field(), "kinetic");
  EXPECT_EQ(std::string(e.what()), file.string() + ":2: kinetic: 7 % is larger than the default 5 %: a tolerance "
                                                    "file may only tighten the tolerances");
}

TEST(Tolerances, UnknownFieldsAndValuesThatAreNoPercentAreRefused) {
  test::TempDir dir;
  const auto message = [&](const std::string& text) {
    return std::string(error_of([&] { read_tolerances(dir.write(kToleranceFile, text)); }).what());
  };
  const std::string file = (dir.path() / kToleranceFile).string();
  EXPECT_EQ(message("energy 5\n"), file + ":1: energy: unknown field (internal, internal_floor, kinetic or cycles)");
  EXPECT_EQ(message("cycles five\n"), file + ":1: cycles: expected one number (percent), found 'cycles five'");
  EXPECT_EQ(message("cycles 5 %\n"), file + ":1: cycles: expected one number (percent), found 'cycles 5 %'");
  EXPECT_EQ(message("\ncycles -1\n"), file + ":2: cycles: -1 % is negative");
}

ReferencePoint reference_point() {
  ReferencePoint r;
  r.time = 0.1, r.cycles = 1000.0, r.internal = 50.0, r.kinetic = 900.0, r.scale = 1000.0;
  return r;
}

RunPoint run_point(double internal, double kinetic, double cycles) { return {0.1, internal, kinetic, cycles}; }

TEST(Compare, EachBandIsClosedAndTheInternalEnergyHasAFloor) {
  const ReferencePoint r = reference_point();
  // On the edges: internal 10 % of 50, kinetic 5 % of the scale, cycles 15 %.
  const Comparison edge = compare(r, run_point(55.0, 850.0, 1150.0));
  EXPECT_TRUE(edge.passed()) << edge.failures();
  EXPECT_EQ(edge.failures(), "");
  const Comparison out = compare(r, run_point(55.01, 950.01, 849.0));
  EXPECT_FALSE(out.internal.passed());
  EXPECT_FALSE(out.kinetic.passed());
  EXPECT_FALSE(out.cycles.passed());
  // A reference internal energy near zero is judged against 0.1 % of the scale: a band of 0.1.
  ReferencePoint zero = r;
  zero.internal = 0.0;
  EXPECT_EQ(compare(zero, run_point(0.1, 900.0, 1000.0)).internal.tolerance, 0.1 * (1e-3 * 1000.0));
  EXPECT_TRUE(compare(zero, run_point(0.1, 900.0, 1000.0)).internal.passed());
  EXPECT_FALSE(compare(zero, run_point(0.1001, 900.0, 1000.0)).internal.passed());
}

TEST(Compare, TighterTolerancesNaNAndShortHistoriesFail) {
  const ReferencePoint r = reference_point();
  Tolerances tight;
  tight.kinetic = 0.02;
  EXPECT_TRUE(compare(r, run_point(50.0, 930.0, 1000.0)).passed());
  EXPECT_FALSE(compare(r, run_point(50.0, 930.0, 1000.0), tight).passed());
  EXPECT_FALSE(compare(r, run_point(std::nan(""), 900.0, 1000.0)).passed());
  RunPoint short_run = run_point(50.0, 900.0, 1000.0);
  short_run.history_end = 0.097;
  const Comparison c = compare(r, short_run);
  EXPECT_FALSE(c.reaches_time);
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(c.failures(), "the histories end at 0.097, before the reference's time 0.1");
}

TEST(Compare, TheFailuresCarryTheNumbers) {
  const Comparison c = compare(reference_point(), run_point(60.0, 800.0, 1200.0));
  EXPECT_EQ(c.failures(),
            "internal energy 60 against 50: difference 10, tolerance 5; "
            "kinetic energy 800 against 900: 10.00 % of the scale 1000, tolerance 5 %; "
            "cycles 1200 against 1000: +20.0 %, tolerance 15 %");
}

// A run of the plate deck: the values at its end are the listing's last row's, the end state's (docs/theory/
// energy.md, E-3; the summary's, to the row's 5 digits), not the last history row's, which are the loop's (the
// elements' energies a cycle behind); a step before its end they are the histories'.
TEST(RunPoint, ReadsTheHistoriesAndTheListingOfARun) {
  test::TempDir dir;
  using test::I, test::R;
  const std::string end = "/GRNOD/NODE/1\nfree end\n" + I(3) + I(6) + "\n";  // pulled: the plate stretches
  Deck deck = read_deck(test::write_deck(dir, end + "/INIVEL/TRA/1\npull\n" + R(1.0) + R(0.0) + R(0.0) + I(1) + "\n"));
  SimulationOptions options;
  options.name = "TEST";
  options.output_directory = dir.path();
  std::ostringstream console;
  const RunSummary summary = app::run_engine_decks(deck, options, console);
  ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
  const RunPoint p = read_run_point(dir.path(), "TEST", summary.time);
  EXPECT_DOUBLE_EQ(p.history_end, summary.time);
  EXPECT_NEAR(p.internal, summary.energy.internal, 5e-5 * summary.energy.internal);
  const double kinetic = summary.energy.kinetic_translational + summary.energy.kinetic_rotational;
  EXPECT_NEAR(p.kinetic, kinetic, 5e-5 * kinetic);
  EXPECT_EQ(p.cycles, static_cast<double>(summary.cycles));
  const ResultsReader h5(dir.path() / "TEST.h5");
  const std::vector<double> t = h5.doubles("/history/time"), internal = h5.doubles("/history/internal");
  ASSERT_GE(t.size(), 2u);
  EXPECT_NE(internal.back(), p.internal);  // the loop's, at x^(N-1)
  const double before = t.back() - summary.dt;  // a step before the end: between the last two history rows
  ASSERT_GT(before, t[t.size() - 2]);
  const RunPoint q = read_run_point(dir.path(), "TEST", before);
  EXPECT_EQ(q.internal, value_at_time(t, internal, before));
}

}  // namespace

}  // namespace test_reference_check
