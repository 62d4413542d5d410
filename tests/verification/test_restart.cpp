// Restart (docs/theory/time-loop.md, "Restart"): a run stopped after k cycles with its snapshot written
// (NAME.rst), then resumed with `--restart`, must end bitwise where the uninterrupted run ends: every field of
// the snapshot (positions, velocities, stresses, plastic strains, hourglass stresses, contact pairs and their
// friction history, rigid bodies, walls, energies, cycle count) and every history row written after the restart,
// the /TH datasets' included.
// The decks cover shells with a rigid body and a rigid wall (the example tube), TYPE7 contact with friction and a
// rigid body of bricks (contact_idel), a continued run (ball_two_runs, stopped in its first engine deck),
// accelerometers, whose filters and integrals carry over (accel_strip), cut sections, whose work integrals
// carry over and whose loads the first cycle after the restart records again (section_strip), springs under
// the mass damping of an engine /DAMP (damping_springs), general springs beside axial ones and trusses
// (springs_mixed_damped), beam-type springs (beam_spring_cantilever), a spot weld tied to two plates
// (tied_spot_weld), trusses letting go over their last cycles (truss_tower_fails), a frame of beams past yield
// (beam_frame_plastic), a bolt on an /RBE2 (rbe2_bolt_beam), a mass on an /RBE3 (rbe3_mass_dependent) and an
// axisymmetric spring's radial law (spring_axi_swinging_mass), pretensioners, one locked (spring_pretension_locks), and
// a hardening spring's rate effects (spring_rate_hardening), sensor-switched springs (spring_sensor_switches) and
// joints (joint_free_bodies).
#include <gtest/gtest.h>
#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "app/run.hpp"
#include "crumple/core/precision.hpp"
#include "crumple/output/restart_file.hpp"
#include "crumple/solver/snapshot.hpp"
#include "crumple/solver/solver_state.hpp"
#include "deck_files.hpp"
#include "crumple/output/history_reader.hpp"
#include "crumple/output/results_reader.hpp"

namespace crumple::test::test_restart {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every field of a snapshot as bytes, by name.
struct Collector {
  std::map<std::string, std::string> fields;
  template <class T>
  void operator()(const std::string& name, std::vector<T>& v) {
    fields[name].assign(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  template <class T, std::size_t N>
  void operator()(const std::string& name, std::array<T, N>& v) {
    fields[name].assign(reinterpret_cast<const char*>(v.data()), N * sizeof(T));
  }
  template <class T>
  void operator()(const std::string& name, T& v) {
    fields[name].assign(reinterpret_cast<const char*>(&v), sizeof(T));
  }
};

std::map<std::string, std::string> snapshot_fields(const Model& model, const std::filesystem::path& file) {
  std::vector<std::string> notes;
  SolverState state = initial_state(model, notes);
  ResumeMarks marks = read_restart(file, model, state);
  Collector c;
  visit_state(c, state, marks);
  return c.fields;
}

// Runs the deck into `dir` with a snapshot at its end; `max_cycles` >= 0 stops it there in its first engine deck.
RunSummary run(const std::filesystem::path& starter, const TempDir& dir, long long max_cycles,
               const std::filesystem::path& restart = {}, bool overwrite = false) {
  Deck deck = read_deck(starter);
  deck.model.run.restart_every = 1LL << 60;  // no snapshot on the way: only the one at the end
  for (RunControl& r : deck.continued_runs) r.restart_every = 1LL << 60;
  if (max_cycles >= 0) deck.continued_runs.clear();
  SimulationOptions options;
  options.name = "RUN";
  options.output_directory = dir.path();
  options.max_cycles = max_cycles;
  options.overwrite_results = overwrite;
  std::ostringstream console;
  return app::run_engine_decks(deck, options, console, restart);
}

struct RestartCase {
  const char* name;
  std::filesystem::path starter;
  long long stop_cycle;
};

void PrintTo(const RestartCase& c, std::ostream* os) { *os << c.name << " stopped at cycle " << c.stop_cycle; }

class Restart : public ::testing::TestWithParam<RestartCase> {};

void expect_bitwise_resume(const RestartCase& c) {
  TempDir whole, first, second;
  const RunSummary uninterrupted = run(c.starter, whole, -1);
  ASSERT_EQ(uninterrupted.status, RunStatus::Normal) << uninterrupted.message;
  const RunSummary stopped = run(c.starter, first, c.stop_cycle);
  ASSERT_EQ(stopped.cycles, c.stop_cycle);
  ASSERT_LT(stopped.time, uninterrupted.time);
  const RunSummary resumed = run(c.starter, second, -1, first.path() / "RUN.rst");
  ASSERT_EQ(resumed.status, RunStatus::Normal) << resumed.message;
  EXPECT_EQ(resumed.cycles_total, uninterrupted.cycles_total);

  const Deck deck = read_deck(c.starter);
  const auto expected = snapshot_fields(deck.model, whole.path() / "RUN.rst");
  const auto found = snapshot_fields(deck.model, second.path() / "RUN.rst");
  ASSERT_EQ(expected.size(), found.size());
  for (const auto& [name, bytes] : expected) EXPECT_TRUE(found.at(name) == bytes) << "field " << name << " differs";

  // The histories written after the restart are the uninterrupted run's rows from the same time on.
  const ResultsReader a(whole.path() / "RUN.h5"), b(second.path() / "RUN.h5");
  const std::vector<double> ta = a.doubles("/history/time"), tb = b.doubles("/history/time");
  ASSERT_FALSE(tb.empty());
  std::size_t offset = 0;
  while (offset < ta.size() && ta[offset] != tb[0]) ++offset;
  ASSERT_LT(offset, ta.size()) << "the resumed run's first history time " << tb[0] << " is not one of the run's";
  ASSERT_EQ(ta.size() - offset, tb.size());
  for (const char* series : {"time", "internal", "kinetic_translational", "kinetic_rotational", "hourglass", "contact",
                             "external_work"}) {
    const std::vector<double> ya = a.doubles(std::string("/history/") + series), yb = b.doubles(std::string("/history/") + series);
    EXPECT_EQ(0, std::memcmp(ya.data() + offset, yb.data(), yb.size() * sizeof(double))) << series;
  }
  // So are the /TH datasets' rows: what the cycle integrates for them (accelerometers, nodal rotations) carries over.
  const HistoryFile listing(whole.path() / "RUN.h5");
  for (const HistorySeries& th : listing.series()) {
    if (th.path.rfind("/history/th/", 0) != 0) continue;
    const std::size_t width = th.columns.size();
    const std::vector<double> ya = a.doubles(th.path), yb = b.doubles(th.path);
    ASSERT_EQ(yb.size(), (ta.size() - offset) * width) << th.path;
    EXPECT_EQ(0, std::memcmp(ya.data() + offset * width, yb.data(), yb.size() * sizeof(double))) << th.path;
  }
}

TEST_P(Restart, ResumedRunEndsBitwiseWhereTheUninterruptedRunEnds) { expect_bitwise_resume(GetParam()); }

const std::filesystem::path kQa = CRUMPLE_QA_DIR;
const std::filesystem::path kDecks = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "decks";
const std::filesystem::path kTestDecks = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "tests" / "regression" / "decks";
const std::filesystem::path kPeerDecks = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "tests" / "regression" / "peer_decks";

// Selective mass scaling (/AMS, /DT/AMS; docs/theory/time-step.md, SM-5a): the example tube (a rigid body, a rigid
// wall) held at 4 times its step, whose mass matrix each cycle changes from the last: what the last cycle left
// (the elements' added mass, the walls' held nodes) carries over.
TEST(Restart, SelectiveMassScaledTubeResumesBitwise) {
  TempDir deck;
  const std::filesystem::path source = kDecks / "tube_impact";
  std::string starter = read_text(source / "TUBE_0000.rad");
  const auto end = starter.rfind("/END");
  ASSERT_NE(end, std::string::npos);
  starter.insert(end, "/AMS\n         0\n");
  deck.write("TUBE_0000.rad", starter);
  deck.write("TUBE_0001.rad", "/RUN/TUBE/1\n0.6\n/TFILE\n0.01\n/ANIM/DT\n0.0 0.5\n/DT/AMS\n0.67 2e-3\n");
  expect_bitwise_resume({"tube_ams", deck.path() / "TUBE_0000.rad", 150});
}

INSTANTIATE_TEST_SUITE_P(
    Decks, Restart,
    ::testing::Values(RestartCase{"tube", kDecks / "tube_impact" / "TUBE_0000.rad", 3000},
                      RestartCase{"contact_idel", kQa / "contact_idel" / "IDEL8_0000.rad", 333},
                      RestartCase{"ball_two_runs", kQa / "ball_two_runs" / "BOULE1V4_0000.rad", 777},
                      RestartCase{"accel_strip", kTestDecks / "accel_strip" / "ACCEL_0000.rad", 300},
                      RestartCase{"section_strip", kTestDecks / "section_strip" / "SECT_0000.rad", 600},
                      // springs, /DAMP changed by the engine deck, /TH/SPRING (issue 28)
                      RestartCase{"damping_springs", kQa / "damping_springs" / "DAMPC_0000.rad", 150},
                      // general springs (their rotations and hardening 5) beside axial ones and trusses, under /DAMP
                      RestartCase{"springs_mixed_damped", kPeerDecks / "springs_mixed_damped" / "SPRMIX_0000.rad", 250},
                      // beam-type springs: their frames carry over
                      RestartCase{"beam_spring_cantilever", kPeerDecks / "beam_spring_cantilever" / "BSPR_0000.rad", 120},
                      // tied interfaces: the rigid-segment ties' added mass and the tied nodes' velocities
                      RestartCase{"tied_spot_weld", kPeerDecks / "tied_spot_weld_spotflag1" / "TIEDSW1_0000.rad", 700},
                      // trusses: plastic strain, area, and the members that are letting go (TR-7)
                      RestartCase{"truss_tower_fails", kPeerDecks / "truss_tower_fails" / "TOWERF_0000.rad", 105},
                      // beams past yield: their frames, resultants and plastic strains
                      RestartCase{"beam_frame_plastic", kPeerDecks / "beam_frame_plastic" / "BFRAME_0000.rad", 150},
                      // /RBE2: a bolt's main node and the shell nodes it carries, from their positions and velocities
                      RestartCase{"rbe2_bolt_beam", kPeerDecks / "rbe2_bolt_beam" / "RBEBOLT_0000.rad", 600},
                      // /RBE3: the dependent node's mass spread, its motion from the independent nodes
                      RestartCase{"rbe3_mass_dependent", kPeerDecks / "rbe3_mass_dependent" / "RBE3MD_0000.rad", 400},
                      // /PROP/TYPE25: the radial shear law's own history (SP-20)
                      RestartCase{"spring_axi_swinging_mass", kPeerDecks / "spring_axi_swinging_mass" / "AXISWING_0000.rad", 2000},
                      // /PROP/TYPE32: the pretensioners' shortening and phase, one locked before the restart (SP-22)
                      RestartCase{"spring_pretension_locks", kPeerDecks / "spring_pretension_locks" / "SPRELOCK_0000.rad", 1500},
                      // SP-23: the rate of the first cycle after the restart, from the elongations it kept
                      RestartCase{"spring_rate_hardening", kPeerDecks / "spring_rate_hardening" / "SPRRATE_0000.rad", 700},
                      // SP-24: springs switched on, off and taken at rest anew by sensors, between two switches
                      RestartCase{"spring_sensor_switches", kPeerDecks / "spring_sensor_switches" / "SPRSENS_0000.rad", 2000},
                      // SP-25: the joint's turned frame and its rotations so far; its stiffness taken anew at the
                      // resumed run's first step, the same /DTIX step
                      RestartCase{"joint_free_bodies", kPeerDecks / "joint_free_bodies" / "JFREE_0000.rad", 3000}),
    [](const auto& p) { return std::string(p.param.name); });

TEST(Restart, FileOfAnotherModelIsRefusedWithItsCounts) {
  TempDir dir;
  run(kDecks / "tube_impact" / "TUBE_0000.rad", dir, 10);
  const Deck other = read_deck(kQa / "contact_idel" / "IDEL8_0000.rad");
  std::vector<std::string> notes;
  SolverState state = initial_state(other.model, notes);
  try {
    read_restart(dir.path() / "RUN.rst", other.model, state);
    FAIL() << "a restart file of another model was read";
  } catch (const RestartError& e) {
    EXPECT_NE(std::string(e.what()).find("written for another model"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_restart(dir.path() / "none.rst", other.model, state), RestartError);
  EXPECT_THROW(read_restart(dir.path() / "RUN.out", other.model, state), RestartError);
}

// A run goes on in the precision it started in (docs/theory/precision.md): a restart file records the bytes of
// the integration points' state, and the build of the other precision refuses it, naming both builds.
TEST(Restart, FileOfTheOtherPrecisionIsRefused) {
  TempDir dir;
  run(kDecks / "tube_impact" / "TUBE_0000.rad", dir, 10);
  const Deck deck = read_deck(kDecks / "tube_impact" / "TUBE_0000.rad");
  std::vector<std::string> notes;
  SolverState state = initial_state(deck.model, notes);
  ASSERT_NO_THROW(read_restart(dir.path() / "RUN.rst", deck.model, state));
  {  // the file as the other build writes it
    const hid_t file = H5Fopen((dir.path() / "RUN.rst").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t attribute = H5Aopen(file, "point_bytes", H5P_DEFAULT);
    ASSERT_GE(attribute, 0);
    const long long other = sizeof(point_real) == 8 ? 4 : 8;
    EXPECT_GE(H5Awrite(attribute, H5T_NATIVE_LLONG, &other), 0);
    H5Aclose(attribute);
    H5Fclose(file);
  }
  try {
    read_restart(dir.path() / "RUN.rst", deck.model, state);
    FAIL() << "a restart file of the other precision was read";
  } catch (const RestartError& e) {
    const std::string expected = std::string("written by the ") + (sizeof(point_real) == 8 ? "mixed" : "double") +
                                 " build of Crumple, and this is the " + kPrecision + " build";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}


// A run resumed into the folder of the run it continues appends to that run's results (docs/output-format.md,
// "Restart"), which the first run's frames and rows end at or before the restart: the shell strip of th_strip with
// a frame every 1e-5 (its /TH of every kind), stopped at cycle 35 and resumed into its folder, against the same
// deck run whole.
std::filesystem::path strip_with_frames(const TempDir& deck) {
  deck.write("THSTRIP_0000.rad", read_text(kTestDecks / "th_strip" / "THSTRIP_0000.rad"));
  deck.write("THSTRIP_0001.rad", "/RUN/THSTRIP/1\n1e-4\n/TFILE\n1e-5\n/ANIM/DT\n0 1e-5\n");
  return deck.path() / "THSTRIP_0000.rad";
}

std::vector<double> frame_times(const std::filesystem::path& h5) {
  std::vector<double> times;
  const ResultsReader r(h5);
  for (int f = 0; r.exists(fmt::format("/frames/{:04}", f)); ++f)
    times.push_back(r.attribute<double>(fmt::format("/frames/{:04}", f), "time"));
  return times;
}

TEST(RestartResults, AResumedRunContinuesTheResultsOfItsFolder) {
  TempDir deck, whole, folder;
  const std::filesystem::path starter = strip_with_frames(deck);
  ASSERT_EQ(run(starter, whole, -1).status, RunStatus::Normal);
  const RunSummary stopped = run(starter, folder, 35);
  ASSERT_EQ(stopped.cycles, 35);
  const std::vector<double> first_frames = frame_times(folder.path() / "RUN.h5");
  const std::size_t first_rows = ResultsReader(folder.path() / "RUN.h5").doubles("/history/time").size();
  const RunSummary resumed = run(starter, folder, -1, folder.path() / "RUN.rst");
  ASSERT_EQ(resumed.status, RunStatus::Normal) << resumed.message;

  // Every row of the whole run is in the continued file, bit for bit, every series and /TH dataset; the only other
  // row is the stopped run's last, at its last cycle.
  const ResultsReader a(whole.path() / "RUN.h5"), b(folder.path() / "RUN.h5");
  const std::vector<double> ta = a.doubles("/history/time"), tb = b.doubles("/history/time");
  ASSERT_GT(tb.size(), first_rows);
  EXPECT_TRUE(std::is_sorted(tb.begin(), tb.end()));
  EXPECT_EQ(std::adjacent_find(tb.begin(), tb.end()), tb.end()) << "a time written twice";
  std::vector<std::size_t> row_of(ta.size());
  for (std::size_t i = 0; i < ta.size(); ++i) {
    const auto at = std::find(tb.begin(), tb.end(), ta[i]);
    ASSERT_NE(at, tb.end()) << "the whole run's row at t = " << ta[i] << " is not in the continued file";
    row_of[i] = static_cast<std::size_t>(at - tb.begin());
  }
  EXPECT_LE(tb.size(), ta.size() + 1);
  const HistoryFile listing(whole.path() / "RUN.h5");
  for (const HistorySeries& s : listing.series()) {
    const std::size_t width = s.columns.size();
    const std::vector<double> ya = a.doubles(s.path), yb = b.doubles(s.path);
    ASSERT_EQ(yb.size(), tb.size() * width) << s.path;
    for (std::size_t i = 0; i < ta.size(); ++i)
      EXPECT_EQ(0, std::memcmp(&ya[i * width], &yb[row_of[i] * width], width * sizeof(double)))
          << s.path << " at t = " << ta[i];
  }
  // The frames: the first run's, then the resumed run's, every frame time of the whole run among them.
  const std::vector<double> fa = frame_times(whole.path() / "RUN.h5"), fb = frame_times(folder.path() / "RUN.h5");
  ASSERT_GT(first_frames.size(), 2u);
  EXPECT_TRUE(std::equal(first_frames.begin(), first_frames.end(), fb.begin()));
  for (double f : fa) EXPECT_NE(std::find(fb.begin(), fb.end(), f), fb.end()) << "frame at t = " << f;
  EXPECT_TRUE(std::is_sorted(fb.begin(), fb.end()));
  EXPECT_LE(fb.size(), fa.size() + 1);
  // NAME.xdmf shows every frame; the listing holds both runs.
  const std::string xdmf = read_text(folder.path() / "RUN.xdmf");
  for (std::size_t f = 0; f < fb.size(); ++f)
    EXPECT_NE(xdmf.find(fmt::format("RUN.h5:/frames/{:04}/coordinates", f)), std::string::npos) << f;
  const std::string out = read_text(folder.path() / "RUN.out");
  EXPECT_EQ(out.rfind("Crumple ", 0), 0u) << "the first run's header is kept";
  EXPECT_NE(out.find("RESUMED at t = "), std::string::npos);
  EXPECT_LT(out.find("ENGINE DECK 1"), out.find("RESUMED at t = "));
  EXPECT_LT(out.find("RESUMED at t = "), out.rfind("NORMAL TERMINATION"));
  EXPECT_NE(out.rfind("NORMAL TERMINATION"), std::string::npos);
}

// Continuing results past the restart would leave them out of order: refused, naming the file, the times and the
// way out, with the file untouched; --overwrite replaces them by the resumed run's.
TEST(RestartResults, ResultsPastTheRestartAreNotOverwrittenUnlessAsked) {
  TempDir deck, whole, stopped;
  const std::filesystem::path starter = strip_with_frames(deck);
  ASSERT_EQ(run(starter, whole, -1).status, RunStatus::Normal);
  ASSERT_EQ(run(starter, stopped, 35).cycles, 35);
  const std::size_t rows = ResultsReader(whole.path() / "RUN.h5").doubles("/history/time").size();
  const std::size_t frames = frame_times(whole.path() / "RUN.h5").size();
  try {
    run(starter, whole, -1, stopped.path() / "RUN.rst");
    FAIL() << "a resumed run continued results past its restart";
  } catch (const RestartError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((whole.path() / "RUN.h5").string()), std::string::npos) << what;
    EXPECT_NE(what.find("past the restart's t = "), std::string::npos) << what;
    EXPECT_NE(what.find("--overwrite"), std::string::npos) << what;
  }
  EXPECT_EQ(ResultsReader(whole.path() / "RUN.h5").doubles("/history/time").size(), rows);
  EXPECT_EQ(frame_times(whole.path() / "RUN.h5").size(), frames);

  ASSERT_EQ(run(starter, whole, -1, stopped.path() / "RUN.rst", true).status, RunStatus::Normal);
  const std::vector<double> t = ResultsReader(whole.path() / "RUN.h5").doubles("/history/time");
  ASSERT_FALSE(t.empty());
  EXPECT_LT(t.size(), rows);  // the resumed run's rows alone
}

// The snapshot of a run's own end (T-0 decided it there) leaves nothing to run: resumed into the same folder, no
// cycle past the end time, no row or frame written twice, and the end's energies (it took a cycle past the end time
// before, and on the example tube a step of 0).
TEST(RestartResults, ResumingFromTheEndOfARunRunsNoCycle) {
  TempDir deck, folder;
  const std::filesystem::path starter = strip_with_frames(deck);
  const RunSummary whole = run(starter, folder, -1);
  ASSERT_EQ(whole.status, RunStatus::Normal);
  const std::size_t rows = ResultsReader(folder.path() / "RUN.h5").doubles("/history/time").size();
  const std::size_t frames = frame_times(folder.path() / "RUN.h5").size();
  const RunSummary again = run(starter, folder, -1, folder.path() / "RUN.rst");
  ASSERT_EQ(again.status, RunStatus::Normal) << again.message;
  EXPECT_EQ(again.cycles_total, whole.cycles_total);
  EXPECT_EQ(again.time, whole.time);
  EXPECT_EQ(again.energy.error_percent, whole.energy.error_percent);
  EXPECT_EQ(ResultsReader(folder.path() / "RUN.h5").doubles("/history/time").size(), rows);
  EXPECT_EQ(frame_times(folder.path() / "RUN.h5").size(), frames);
}

}  // namespace
}  // namespace crumple::test::test_restart
