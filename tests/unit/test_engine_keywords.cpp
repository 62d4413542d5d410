// Engine deck (run control): free-format data lines, every card of docs/cards/loads-output-engine.md §7,
// conversion of times from the starter's input units (also when the engine part comes before /BEGIN), and the
// errors for malformed cards.
#include <gtest/gtest.h>

#include <array>
#include <map>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_engine_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

std::string gram_mm_ms_begin() {
  return "/BEGIN\nTEST\n      2019         0\n" + R("g") + R("mm") + R("ms") + "\n" + R("kg") + R("m") + R("s") + "\n";
}

// The engine deck of the QA deck box_crush, with this test's run name.
const char* const kQaEngine =
    "#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|\n"
    "/ANIM/DT\n"
    "#   TSTART     TFREQ\n"
    "0.000000 0.010000\n"
    "/ANIM/GZIP\n"
    "/DT\n"
    "0.100000 0.000000\n"
    "/MON/ON\n"
    "/PARITH/ON\n"
    "/PRINT/-1/55\n"
    "/RUN/TEST/1\n"
    "             0.10001\n"
    "/TFILE/4\n"
    "#            dT_HIS\n"
    "0.001000\n"
    "/VERS/2019\n";

RunControl run_of(const std::string& engine, const std::string& extra = "") {
  test::TempDir dir;
  return read_deck(test::write_deck(dir, extra, engine)).model.run;
}

std::string error_of(const std::string& engine, const std::string& extra = "") {
  test::TempDir dir;
  return test::first_error(test::write_deck(dir, extra, engine));
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kRun = "/RUN/TEST/1\n1e-3\n";

// A rigid body 7 (free node 7, secondary nodes 3 and 6) for /RBODY/ON and /RBODY/OFF.
std::string rigid_body() {
  return "/NODE\n" + I(7) + R(0.05) + R(0.0) + R(0.1) + "\n/GRNOD/NODE/14\nedge\n" + I(3) + I(6) + "\n" +
         "/RBODY/7\nbody\n" + I(7) + I(0) + I(0) + I(0) + R(3.0) + I(14) + I(0) + I(0) + I(0) + "\n" + R(0.0) + "\n" +
         R(0.0) + "\n" + I(0) + I(0) + "\n";
}

}  // namespace

// /TH/VERS/n of old engine decks (the reference QA deck LOIS/LOI27 has /TH/VERS/41): the version of a file Crumple
// does not write, a named output-only warning; a version that is no positive integer is an error.
TEST(EngineKeywords, TimeHistoryVersionIsOutputOnly) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "", kRun + "/TH/VERS/41\n"));
  std::string warnings;
  for (const auto& w : d.report.warnings) warnings += w.message + "\n";
  EXPECT_TRUE(contains(warnings, "time-history file's version")) << warnings;
  EXPECT_TRUE(contains(error_of(kRun + "/TH/VERS/x\n"), "/TH/VERS"));
}

TEST(EngineKeywords, QaEngineDeckReads) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "", kQaEngine));
  const RunControl& run = d.model.run;
  EXPECT_TRUE(run.present);
  EXPECT_TRUE(contains(run.where.file, "TEST_0001.rad")) << run.where.file;
  EXPECT_EQ(run.where.line, 11);
  EXPECT_EQ(run.run_name, "TEST");
  EXPECT_EQ(run.run_number, 1);
  EXPECT_DOUBLE_EQ(run.end_time, 0.10001);
  EXPECT_DOUBLE_EQ(run.history_interval, 0.001);
  EXPECT_EQ(run.history_format, 4);
  EXPECT_DOUBLE_EQ(run.anim_start, 0.0);
  EXPECT_DOUBLE_EQ(run.anim_interval, 0.01);
  EXPECT_TRUE(run.anim_gzip);
  EXPECT_TRUE(run.dt.given);
  EXPECT_DOUBLE_EQ(run.dt.scale, 0.1);
  EXPECT_DOUBLE_EQ(run.dt.minimum, 0.0);
  EXPECT_TRUE(run.monitor);
  EXPECT_TRUE(run.parith);
  EXPECT_EQ(run.print_every, -1);
  EXPECT_EQ(run.print_header_lines, 55);
  EXPECT_EQ(run.engine_version, 2019);
  const auto& ignored = d.report.accepted_without_effect;
  EXPECT_NE(std::find(ignored.begin(), ignored.end(), "/VERS"), ignored.end());
}

TEST(EngineKeywords, AbsentCardsLeaveDefaults) {
  const RunControl run = run_of(kRun);
  EXPECT_TRUE(run.present);
  EXPECT_DOUBLE_EQ(run.end_time, 1e-3);
  EXPECT_EQ(run.history_interval, 0.0);
  EXPECT_EQ(run.history_format, 0);
  EXPECT_EQ(run.anim_interval, 0.0);
  EXPECT_FALSE(run.dt.given);
  EXPECT_FALSE(run.dt_inter_del.given);
  EXPECT_TRUE(run.parith);
  EXPECT_FALSE(run.monitor);
  EXPECT_EQ(run.print_every, 0);
  EXPECT_EQ(run.restart_every, 0);
  // /TFILE without a type writes the default IEEE binary format.
  EXPECT_EQ(run_of(kRun + "/TFILE\n1e-4\n").history_format, 4);
  EXPECT_FALSE(run_of(kRun + "/TFILE\n1e-4\n").history_every_cycle());
  // dT_his 0: a row every cycle, as the reference writes its T01 file (one record a cycle, measured); no /TFILE:
  // no rows.
  EXPECT_TRUE(run_of(kRun + "/TFILE\n0\n").history_every_cycle());
  EXPECT_FALSE(run.history_every_cycle());
}

// Engine values are in the starter's input units: a g-mm-ms deck gives times in ms.
TEST(EngineKeywords, TimesConvertedFromStarterUnits) {
  test::TempDir dir;
  dir.write("TEST_0001.rad", "/RUN/TEST/1\n100\n/TFILE\n0.5\n/ANIM/DT\n1 2\n/DT\n0.9 1e-3\n/DT/INTER/DEL\n0.5 1e-4\n");
  const auto path = dir.write("TEST_0000.rad", gram_mm_ms_begin() + test::plate_cards() + "/END\n");
  const RunControl run = read_deck(path).model.run;
  EXPECT_NEAR(run.end_time, 0.1, 1e-15);
  EXPECT_NEAR(run.history_interval, 5e-4, 1e-18);
  EXPECT_NEAR(run.anim_start, 1e-3, 1e-18);
  EXPECT_NEAR(run.anim_interval, 2e-3, 1e-18);
  EXPECT_DOUBLE_EQ(run.dt.scale, 0.9);  // a ratio: not converted
  EXPECT_NEAR(run.dt.minimum, 1e-6, 1e-20);
  EXPECT_NEAR(run.dt_inter_del.minimum, 1e-7, 1e-21);
}

// Radioss single-file form: engine cards first, closed by /END/ENGINE, then /BEGIN: the units come later but
// the times are still converted with them.
TEST(EngineKeywords, EngineBeforeBeginIsConvertedWithTheStarterUnits) {
  test::TempDir dir;
  const auto path = dir.write("ONE_0000.rad", "/RUN/ONE/1\n100\n/TFILE\n0.5\n/END/ENGINE\n" + gram_mm_ms_begin() +
                                                  test::plate_cards() + "/END\n");
  const RunControl run = read_deck(path).model.run;
  EXPECT_TRUE(run.present);
  EXPECT_NEAR(run.end_time, 0.1, 1e-15);
  EXPECT_NEAR(run.history_interval, 5e-4, 1e-18);
}

TEST(EngineKeywords, EveryRunControlCardReads) {
  const std::string engine = kRun +
                             "/DT/NODA/CST\n0.67 1e-7\n"
                             "/DT/SHELL/DEL\n0.8, 1e-8\n"
                             "/DT/BRICK/STOP\n0.7\n"
                             "/DT/SH_3N\n\n0.6 2e-8\n"  // a blank line inside an engine card is skipped
                             "/DT/INTER/DEL\n0.5 1e-6\n"
                             "/DT/INTER/CST\n0.4 2e-6\n"
                             "/PARITH/OFF\n/MON/OFF\n"
                             "/STOP\n0.1, 0.05, 0 1 1 0\n"
                             "/RFILE/5\n1000\n"
                             "/ANIM/ELEM/EPSP\n/ANIM/ELEM/vonm\n/ANIM/ELEM/EPSP\n/ANIM/VECT/VEL\n/ANIM/VECT/CONT\n"
                             "/ANIM/NODA/DMAS\n/ANIM/VERS/44\n"
                             "/TITLE\nrun 1/2 of the study\n";
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "", engine));
  const RunControl& run = d.model.run;
  EXPECT_DOUBLE_EQ(run.dt_nodal_cst.scale, 0.67);
  EXPECT_DOUBLE_EQ(run.dt_nodal_cst.minimum, 1e-7);
  EXPECT_EQ(run.dt_shell.action, TimeStepAction::Delete);
  EXPECT_DOUBLE_EQ(run.dt_shell.minimum, 1e-8);
  EXPECT_EQ(run.dt_brick.action, TimeStepAction::Stop);
  EXPECT_DOUBLE_EQ(run.dt_brick.scale, 0.7);
  EXPECT_DOUBLE_EQ(run.dt_brick.minimum, 0.0);
  EXPECT_EQ(run.dt_sh3n.action, TimeStepAction::Default);
  EXPECT_DOUBLE_EQ(run.dt_sh3n.minimum, 2e-8);
  EXPECT_DOUBLE_EQ(run.dt_inter_del.minimum, 1e-6);
  EXPECT_DOUBLE_EQ(run.dt_inter_cst.scale, 0.4);
  EXPECT_DOUBLE_EQ(run.dt_inter_cst.minimum, 2e-6);
  EXPECT_FALSE(run.dt.given);
  EXPECT_FALSE(run.parith);
  EXPECT_FALSE(run.monitor);
  EXPECT_DOUBLE_EQ(run.stop_energy_error, 0.1);
  EXPECT_DOUBLE_EQ(run.stop_mass_error, 0.05);
  EXPECT_DOUBLE_EQ(run.stop_node_mass_error, 0.0);
  EXPECT_TRUE(run.stop_write_history && run.stop_write_animation);
  EXPECT_FALSE(run.stop_positive_error_only);
  EXPECT_EQ(run.restart_every, 1000);
  EXPECT_EQ(run.restart_sets, 5);
  EXPECT_EQ(run.anim_version, 44);
  const auto& ignored = d.report.accepted_without_effect;
  EXPECT_NE(std::find(ignored.begin(), ignored.end(), "/TITLE"), ignored.end());
  // Output-only requests Crumple does not write and performance hints are named warnings, one per card or field.
  auto noted = [&](std::string_view keyword, SkipKind kind) {
    return std::count_if(d.report.skipped_options.begin(), d.report.skipped_options.end(),
                         [&](const SkippedOption& o) { return o.keyword == keyword && o.kind == kind; });
  };
  EXPECT_EQ(noted("/ANIM/ELEM/vonm", SkipKind::OutputOnly), 0);  // von Mises stress is written on request
  EXPECT_EQ(noted("/ANIM/ELEM/EPSP", SkipKind::OutputOnly), 0);  // plastic strain is in every frame
  EXPECT_EQ(noted("/ANIM/NODA/DMAS", SkipKind::OutputOnly), 0);
  EXPECT_TRUE(run.anim.added_mass && run.anim.contact_force);
  EXPECT_FALSE(run.anim.pressure || run.anim.acceleration);
  EXPECT_EQ(noted("/RFILE/5", SkipKind::OutputOnly), 1);
  EXPECT_EQ(noted("/STOP", SkipKind::OutputOnly), 1);  // NTH, NANIM: no extra output at a stop
  EXPECT_EQ(noted("/PARITH/OFF", SkipKind::PerformanceHint), 1);
  EXPECT_EQ(d.report.skipped_options.size(), d.report.warnings.size());
}

// Each /ANIM request either sets the frame field it asks for (docs/output-format.md) or is a named warning saying
// what is not written; a field of every frame needs no flag and no warning.
TEST(EngineKeywords, AnimRequestsSetTheirFrameFieldsOrNameWhatIsNotWritten) {
  const std::string engine = kRun +
                             "/ANIM/ELEM/P\n/ANIM/SHELL/VONM\n/ANIM/BRICK/ENER\n/ANIM/ELEM/HOURG\n/ANIM/ELEM/DT\n"
                             "/ANIM/SHELL/TENS/STRESS/BEND\n/ANIM/TENS/STRESS/UPPER\n/ANIM/TENS/STRESS/MEMB\n"
                             "/ANIM/BRICK/TENS/STRESS\n/ANIM/VECT/ACC\n/ANIM/VECT/FINT\n/ANIM/VECT/FEXT\n"
                             "/ANIM/VECT/VROT\n/ANIM/MASS\n/ANIM/NODA/DMAS\n/ANIM/ELEM/THIC\n/ANIM/BRICK/SIGZ\n"
                             // not written:
                             "/ANIM/ELEM/DENS\n/ANIM/BRICK/THIC\n/ANIM/SHELL/SIGZ\n/ANIM/BRICK/TENS/STRESS/BEND\n"
                             "/ANIM/SHELL/TENS/STRESS/3\n/ANIM/BRICK/TENS/STRESS/111\n/ANIM/TENS/STRAIN\n"
                             "/ANIM/SHELL/TENS/STRESS/1/UPPER\n/ANIM/SHELL/EPSP/UPPER\n/ANIM/VECT/FREAC\n"
                             "/ANIM/NODA/DT\n/ANIM/BEAM/EPSP\n";
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "", engine));
  const FrameRequests& a = d.model.run.anim;
  EXPECT_TRUE(a.pressure && a.energy_density && a.hourglass_energy && a.time_step);
  EXPECT_TRUE(a.bending_stress && a.surface_stress);
  EXPECT_TRUE(a.acceleration && a.internal_force && a.external_force && a.angular_velocity);
  EXPECT_TRUE(a.nodal_mass && a.added_mass);
  EXPECT_FALSE(a.contact_force);
  std::map<std::string, std::string> warned;
  for (const SkippedOption& o : d.report.skipped_options)
    if (o.kind == SkipKind::OutputOnly) warned[o.keyword] = o.text();
  for (const char* written : {"/ANIM/ELEM/P", "/ANIM/SHELL/VONM", "/ANIM/BRICK/ENER", "/ANIM/SHELL/TENS/STRESS/BEND",
                              "/ANIM/TENS/STRESS/UPPER", "/ANIM/TENS/STRESS/MEMB", "/ANIM/BRICK/TENS/STRESS",
                              "/ANIM/VECT/FINT", "/ANIM/MASS", "/ANIM/NODA/DMAS", "/ANIM/ELEM/THIC", "/ANIM/BRICK/SIGZ"})
    EXPECT_EQ(warned.count(written), 0u) << written << ": " << warned[written];
  const std::pair<const char*, const char*> missing[] = {
      {"/ANIM/ELEM/DENS", "result DENS is not written by Crumple (its frames hold EPSP OFF SIGX"},
      {"/ANIM/BRICK/THIC", "result THIC is written for shells only"},
      {"/ANIM/SHELL/SIGZ", "result SIGZ is written for bricks only"},
      {"/ANIM/BRICK/TENS/STRESS/BEND", "stress BEND is written for shells only"},
      {"/ANIM/SHELL/TENS/STRESS/3", "stress at integration point 3 is not written"},
      {"/ANIM/BRICK/TENS/STRESS/111", "stress at integration point 111 is not written"},
      {"/ANIM/TENS/STRAIN", "tensor STRAIN is not written"},
      {"/ANIM/SHELL/TENS/STRESS/1/UPPER", "composite layer"},
      {"/ANIM/SHELL/EPSP/UPPER", "result EPSP per layer or point is not written"},
      {"/ANIM/VECT/FREAC", "result FREAC is not written by Crumple (its frames hold VEL DISP CONT ACC FINT FEXT VROT)"},
      {"/ANIM/NODA/DT", "result DT is not written by Crumple (its frames hold DMAS)"},
      {"/ANIM/BEAM/EPSP", "output-only card (/ANIM/BEAM): not written by Crumple"}};
  for (const auto& [keyword, text] : missing)
    EXPECT_TRUE(contains(warned[keyword], text)) << keyword << ": " << warned[keyword];
  EXPECT_EQ(warned.size(), std::size(missing));
  // A tensor card needs its tensor's name; /ANIM/MASS takes nothing after it.
  EXPECT_TRUE(contains(error_of(kRun + "/ANIM/SHELL/TENS\n"), "field restype"));
  EXPECT_TRUE(contains(error_of(kRun + "/ANIM/MASS/2\n"), "nothing after /ANIM/MASS"));
}

// A typo in an /ANIM request is an error naming the nearest option, one test per class: the request (/ANIM/TD), an
// element, shell, vector or nodal result, a result per point, a tensor; a real option Crumple does not write stays
// a named warning (above); --skip-unknown runs anyway.
TEST(EngineKeywords, AnimTyposAreErrorsWithTheNearestOption) {
  const std::pair<const char*, const char*> typos[] = {
      {"/ANIM/TD\n0 1e-3\n", "unknown keyword '/ANIM/TD'"},
      {"/ANIM/ELEM/VONMM\n", "'VONMM', which is no result of /ANIM/ELEM"},
      {"/ANIM/SHELL/EPSPP\n", "(nearest: EPSP)"},
      {"/ANIM/BRICK/HOURGG\n", "(nearest: HOURG)"},
      {"/ANIM/VECT/DIPS\n", "(nearest: DISP)"},
      {"/ANIM/NODA/DMASS\n", "(nearest: DMAS)"},
      {"/ANIM/SHELL/EPPS/UPPER\n", "(nearest: EPSP)"},
      {"/ANIM/BRICK/TENS/STRES\n", "(nearest: STRESS)"},
  };
  for (const auto& [card, text] : typos) {
    const std::string error = error_of(kRun + card);
    EXPECT_TRUE(contains(error, text)) << card << ": " << error;
  }
  EXPECT_TRUE(contains(error_of(kRun + "/ANIM/TD\n0 1e-3\n"), "/ANIM/DT")) << "the nearest keyword";
  // --skip-unknown: the run goes on without it, with a warning that names it.
  test::TempDir dir;
  ReadOptions skip;
  skip.skip_unknown = true;
  const Deck d = read_deck(test::write_deck(dir, "", kRun + "/ANIM/ELEM/HOURGG\n"), skip);
  EXPECT_FALSE(d.model.run.anim.hourglass_energy);
  bool named = false;
  for (const SkippedOption& o : d.report.skipped_options) named = named || contains(o.text(), "HOURGG");
  EXPECT_TRUE(named);
}

// Physics limits of /STOP that the solver does not implement are errors naming the value.
TEST(EngineKeywords, StopLimitsCrumpleLacksAreErrors) {
  EXPECT_TRUE(contains(error_of(kRun + "/STOP\n0 0 2\n"), "field Nmax (value 3): expected 0 or blank"));
  EXPECT_TRUE(contains(error_of(kRun + "/STOP\n0.1 0 0 0 0 1\n"), "NERR_POSIT (value 6)"));
  EXPECT_TRUE(contains(error_of(kRun + "/STOP\n0.1 0 0 0 0 1\n"), "not supported by Crumple"));
  // Without an energy limit NERR_POSIT changes nothing.
  EXPECT_TRUE(run_of(kRun + "/STOP\n0 0 0 0 0 1\n").stop_positive_error_only);
}

TEST(EngineKeywords, StopAndRestartShortForms) {
  const RunControl stop = run_of(kRun + "/STOP\n0.2 0.1 0\n");
  EXPECT_DOUBLE_EQ(stop.stop_energy_error, 0.2);
  EXPECT_FALSE(stop.stop_write_history);
  EXPECT_EQ(run_of(kRun + "/RFILE\n").restart_every, 1000000);
  EXPECT_EQ(run_of(kRun + "/RFILE/OFF\n").restart_every, 0);
}

TEST(EngineKeywords, RigidBodiesSwitchedOnAndOff) {
  const RunControl run = run_of(kRun + "/RBODY/OFF\n7\n/RBODY/ON\n7 7\n", rigid_body());
  EXPECT_EQ(run.rbody_off, (std::vector<std::int64_t>{7}));
  EXPECT_EQ(run.rbody_on, (std::vector<std::int64_t>{7, 7}));
  EXPECT_EQ(run.rbody_on_where.size(), 2u);
  // The engine names bodies by their main node; 0 names none (the QA deck rbody_rotation has "/RBODY/ON 0").
  EXPECT_TRUE(run_of(kRun + "/RBODY/ON\n0\n", rigid_body()).rbody_on.empty());
  const std::string e = error_of(kRun + "/RBODY/ON\n7\n99\n", rigid_body());
  EXPECT_TRUE(contains(e, "node 99, which is the main node of no /RBODY")) << e;
  EXPECT_TRUE(contains(e, "TEST_0001.rad:5")) << e;  // the line that holds the id
}

// /VEL/TRA/dirs[/skew_ID] with its node list (docs/cards/loads-output-engine.md §7.2; docs/theory/loads.md, L-8).
TEST(EngineKeywords, VelocityLinkAlongAxes) {
  const RunControl run = run_of(kRun + "/VEL/TRA/XZ\n1 2 3\n4\n");
  ASSERT_EQ(run.velocity_links.size(), 1u);
  const auto& link = run.velocity_links[0];
  EXPECT_EQ(link.along, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(link.skew, -1);
  EXPECT_EQ(link.node_ids, (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(link.nodes, (std::vector<std::int32_t>{0, 1, 2, 3}));
  const std::string skew = "/SKEW/FIX/5\nskew\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(0.0) + R(1.0) + R(0.0) +
                           "\n" + R(0.0) + R(0.0) + R(1.0) + "\n";
  EXPECT_EQ(run_of(kRun + "/VEL/TRA/YX/5\n1 2\n", skew).velocity_links[0].skew, 0);
}

TEST(EngineKeywords, VelocityLinkErrorsNameTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {"/VEL/TRA/XQ\n1 2\n", "Keyword3"},
      {"/VEL/TRA/XX\n1 2\n", "Keyword3"},
      {"/VEL/TRA\n1 2\n", "Keyword3"},
      {"/VEL/TRA/X\n1\n", "at least two node ids"},
      {"/VEL/TRA/X\n1 -2\n", "node_ID"},
      {"/VEL/TRA/X\n1 99\n", "node 99 not defined"},
      {"/VEL/TRA/X/8\n1 2\n", "skew 8 not defined"},
      {"/VEL/ROT/X\n1 2\n", "TRA in /VEL/TRA"},
      {"/VEL/TRA/X\n3 7\n", "/RBODY/7"},
  };
  for (const auto& [card, expected] : cases) {
    const std::string e = error_of(kRun + card, rigid_body());
    EXPECT_TRUE(contains(e, expected)) << card << ": " << e;
  }
}

// /RUN/name without its run number (the reference QA deck INTERF/INT_7/fpenmax) is this engine deck's run.
TEST(EngineKeywords, RunWithoutItsNumberIsThisDecksRun) {
  const RunControl run = run_of("/RUN/TEST\n1e-3\n");
  EXPECT_TRUE(run.present);
  EXPECT_EQ(run.run_number, 1);
  EXPECT_DOUBLE_EQ(run.end_time, 1e-3);
}

TEST(EngineKeywords, RunNameDifferentFromBeginIsAWarning) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "", "/RUN/OTHER/1\n1e-3\n"));
  ASSERT_FALSE(d.report.warnings.empty());
  EXPECT_TRUE(contains(d.report.warnings.back().text(), "differs")) << d.report.warnings.back().text();
}

TEST(EngineKeywords, MalformedCardsAreErrorsNamingTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {"/TFILE\n1e-4\n", "an engine deck without /RUN"},
      {"/RUN/TEST/1\n0\n", "field Tstop"},
      {"/RUN/TEST/1\n-1e-3\n", "field Tstop"},
      {"/RUN/TEST/1\n", "field Tstop"},
      {"/RUN/TEST/1\n1e-3 2e-3\n", "at most 1 value"},
      {"/RUN/TEST/2\n1e-3\n", "field run_number"},
      {"/RUN/TEST/1/J\n1e-3\n", "restart letter"},
      {kRun + kRun, "a single /RUN"},
      {kRun + "/DT\n1.5\n", "field DTsca"},
      {kRun + "/DT\n-0.5\n", "field DTsca"},
      {kRun + "/DT\nabc\n", "field DTsca"},
      {kRun + "/DT\n0.5 -1\n", "field DTmin"},
      {kRun + "/DT\n0.5/0.1\n", "'/'"},
      {kRun + "/DT\n0.9\n/DT\n0.8\n", "a single /DT"},
      {kRun + "/DT\n", "field DTsca, DTmin"},
      {kRun + "/DT/NODA/CST\n0.5 0\n", "field DTmin"},
      {kRun + "/DT/INTER/DEL\n0.5\n", "field DTmin"},
      {kRun + "/DT/INTER/STOP\n0.5 1e-6\n", "field Keyword3"},
      {kRun + "/DT/QUAD\n0.5\n", "field Eltyp"},
      {kRun + "/DT/NODA/SET\n0.5 1e-6\n", "field Keyword3"},
      {kRun + "/DT/NODA/CST/1\n0.5 1e-6\n", "field Iflag"},
      {kRun + "/DT/SH_3N/FOO\n0.5\n", "field Keyword3"},
      {kRun + "/DT/BRICK/CST/1\n0.5\n", "field Iflag"},
      {kRun + "/TFILE\n-1\n", "field dT_his"},
      {kRun + "/TFILE/7\n1e-4\n", "field type"},
      {kRun + "/ANIM/DT\n0\n", "field Tfreq"},
      {kRun + "/ANIM/DT\n0 -1\n", "field Tfreq"},
      {kRun + "/ANIM/DT\n-1 1e-4\n", "field Tstart"},
      {kRun + "/ANIM/ELEM\n", "field restype"},
      {kRun + "/ANIM/GZIP\n1\n", "no more data lines"},
      {kRun + "/ANIM/VERS\n", "field n"},
      {kRun + "/PRINT/0\n", "field Nprint"},
      {kRun + "/PRINT\n", "field Nprint"},
      {kRun + "/PRINT/-100/-5\n", "field Nline"},
      {kRun + "/STOP\n0 0 0 2\n", "field NTH"},
      {kRun + "/STOP\n-1\n", "field Emax"},
      {kRun + "/STOP\n0 0 0 0 0 0 0\n", "at most 6 values"},
      {kRun + "/STOP/LSENSOR\n1\n", "field keyword"},
      {kRun + "/PARITH/MAYBE\n", "/PARITH/ON or /PARITH/OFF"},
      {kRun + "/MON\n", "/MON/ON or /MON/OFF"},
      {kRun + "/RFILE/30\n", "field n"},
      {kRun + "/RFILE\n-5\n", "field Ncycle"},
      {kRun + "/RBODY/ON\n", "field node_ID"},
      {kRun + "/RBODY/OFF\n-3\n", "field node_ID"},
      {kRun + "/VERS\n", "field version"},
      {kRun + "/NODE\n", "belongs to the starter"},
  };
  for (const auto& [engine, expected] : cases) {
    const std::string e = error_of(engine);
    EXPECT_TRUE(contains(e, expected)) << engine << "-> " << e;
  }
}

// A malformed /RUN is reported once, for what is wrong with it, not also as a missing /RUN.
TEST(EngineKeywords, MalformedRunIsNotAlsoAMissingRun) {
  test::TempDir dir;
  try {
    read_deck(test::write_deck(dir, "", "/RUN/TEST/1\n0\n"));
    FAIL() << "the deck should not read";
  } catch (const DeckErrors& e) {
    ASSERT_EQ(e.errors().size(), 1u) << e.what();
    EXPECT_EQ(e.errors()[0].field(), "Tstop (value 1)");
  }
}

// /DT/AMS/Iflag (selective mass scaling; docs/cards/loads-output-engine.md §7.2): the values of each line, the
// reference's defaults when blank (0 here; the solver reads 0.9, 1e-3, 1000), Nprint output-only, and /AMS
// without /DT/AMS said to do nothing.
TEST(EngineKeywords, SelectiveMassScalingCards) {
  const std::string ams = "/AMS\n" + I(0) + "\n";
  const RunControl plain = run_of(kRun + "/DT/AMS\n0.67 2e-3\n", ams);
  EXPECT_TRUE(plain.dt_ams.given);
  EXPECT_DOUBLE_EQ(plain.dt_ams.scale, 0.67);
  EXPECT_DOUBLE_EQ(plain.dt_ams.minimum, 2e-3);
  EXPECT_DOUBLE_EQ(plain.dt_ams.tolerance_or_default(), 1e-3);
  EXPECT_EQ(plain.dt_ams.max_iterations_or_default(), 1000);
  EXPECT_DOUBLE_EQ(run_of(kRun + "/DT/AMS\n0 2e-3\n", ams).dt_ams.scale_or_default(), 0.9);
  const RunControl full = run_of(kRun + "/DT/AMS/2\n0.67 2e-3\n1e-4\n50 0\n", ams);
  EXPECT_DOUBLE_EQ(full.dt_ams.tolerance, 1e-4);
  EXPECT_EQ(full.dt_ams.max_iterations, 50);
  EXPECT_DOUBLE_EQ(run_of(kRun + "/DT/AMS/1\n0.67 2e-3\n1e-2\n", ams).dt_ams.tolerance, 1e-2);
  EXPECT_TRUE(contains(error_of(kRun + "/DT/AMS/2\n0.67 2e-3\n1e-4\n-5 0\n", ams), "Niter"));
  EXPECT_TRUE(contains(error_of(kRun + "/DT/AMS\n1.5 2e-3\n", ams), "DTsca"));

  test::TempDir dir;
  Deck with_print = read_deck(test::write_deck(dir, ams, kRun + "/DT/AMS/2\n0.67 2e-3\n0\n0 10\n"));
  bool named = false;
  for (const auto& o : with_print.report.skipped_options) named = named || contains(o.text(), "Nprint");
  EXPECT_TRUE(named) << "a non-default Nprint is a named output-only warning";

  test::TempDir alone;
  std::string warnings;
  for (const auto& w : read_deck(test::write_deck(alone, ams, kRun)).report.warnings) warnings += w.text();
  EXPECT_TRUE(contains(warnings, "/AMS: no effect")) << warnings;
}

}  // namespace test_engine_keywords
