// Continued runs (docs/theory/time-loop.md, "Continued runs"): NAME_0002.rad carries on the time and the whole
// state NAME_0001.rad left, with its own run controls.
//
// A run stopped at T/2 and carried on to T by a second engine deck takes exactly the steps of one run to T when the
// step is the same and T/2 falls on a step: /DTIX holds the step at dt = 2^-20 s (below the bar's stable step), so
// that every time t = k dt is exact in floating point. The positions, velocities and energies at T must then be
// bitwise those of the single run: nothing of the state is lost or re-initialised between the decks. The second
// deck's cycle count and energy error start again from 0.
#include <cmath>
#include <cstring>
#include <sstream>

#include "app/run.hpp"
#include "crumple/solver/solver_state.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_continued_run {
namespace {

constexpr double kStep = 1.0 / 1048576.0;  // 2^-20 s
constexpr int kHalf = 200;                  // steps to T/2

// An elastic bar of 40 shells, its left half moving at 3 m/s: waves run both ways through the whole run. Node
// 1000 is a rigid body's main node holding the right end column (body 1).
std::string bar_starter() {
  Strip strip;
  strip.nx = 40, strip.ny = 1, strip.length = 1.0, strip.width = 0.025;
  std::vector<long long> left;
  for (int i = 0; i <= 20; ++i)
    for (long long id : strip.column(i)) left.push_back(id);
  return node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() + shell_property(0.001, 3) +
         elastic_material(7800.0, 2.1e11, 0.3) + node_group(1, left) + initial_velocity(1, 3.0, 0.0, 1.0, 1) +
         node_cards({{1000, 1.0, 0.0125, 0.0}}) + node_group(2, strip.column(40)) +
         "/RBODY/1\nend\n" + I(1000) + I(0) + I(0) + I(0) + R(0.0) + I(2) + I(0) + I(0) + I(0) + "\n" + R(0.0) +
         "\n" + R(0.0) + "\n" + I(0) + I(0) + "\n";
}

std::string engine(int number, double end_time, const std::string& extra = "") {
  std::ostringstream s;
  s.precision(17);
  s << "/RUN/VERIF/" << number << "\n" << end_time << "\n/TFILE\n" << 50 * kStep << "\n/DTIX\n0 " << kStep
    << "\n/PRINT/-100000\n" << extra;
  return s.str();
}

struct Final {
  RunSummary summary;
  SolverState state;
};

Final run(const test::TempDir& dir) {
  Deck deck = read_deck(dir.write("VERIF_0000.rad", test::begin_card("VERIF") + bar_starter() + "/END\n"));
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  options.write_results = false;
  Final f;
  options.on_history_row = [&f](const SolverState& s) { f.state = s; };
  std::ostringstream console;
  f.summary = app::run_engine_decks(deck, options, console);
  return f;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(ContinuedRun, TwoEngineDecksGiveTheStateOfOne) {
  const double half = kHalf * kStep, end = 2 * kHalf * kStep;
  test::TempDir one, two;
  one.write("VERIF_0001.rad", engine(1, end));
  two.write("VERIF_0001.rad", engine(1, half));
  two.write("VERIF_0002.rad", engine(2, end));
  const Final a = run(one), b = run(two);
  ASSERT_EQ(a.summary.status, RunStatus::Normal) << a.summary.message;
  ASSERT_EQ(b.summary.status, RunStatus::Normal) << b.summary.message;
  EXPECT_EQ(b.summary.engine_decks, 2);
  EXPECT_EQ(a.summary.cycles, 2 * kHalf);
  EXPECT_EQ(b.summary.cycles, kHalf);  // the second deck counts from 0
  EXPECT_EQ(b.summary.cycles_total, 2 * kHalf);
  EXPECT_EQ(b.summary.time, a.summary.time);
  for (auto member : {&NodalState::x, &NodalState::y, &NodalState::z, &NodalState::vx, &NodalState::vy,
                      &NodalState::vz, &NodalState::wx, &NodalState::wy, &NodalState::wz})
    EXPECT_TRUE(same(a.state.nodes.*member, b.state.nodes.*member));
  EXPECT_EQ(a.summary.energy.internal, b.summary.energy.internal);
  EXPECT_EQ(a.summary.energy.kinetic_translational, b.summary.energy.kinetic_translational);
  EXPECT_EQ(a.summary.energy.external_work, b.summary.energy.external_work);
  // The second deck's balance starts from its own initial energy: its error is that of the second half alone.
  EXPECT_LT(std::abs(b.summary.energy.error_percent), 0.5);
}

// /RBODY/OFF in the second deck releases the body's nodes: the end column then moves on its own (the rigid body
// kept it straight), and the first deck's state is carried on unchanged up to the switch.
TEST(ContinuedRun, RigidBodyOffInTheSecondDeckReleasesItsNodes) {
  const double half = kHalf * kStep, end = 2 * kHalf * kStep;
  test::TempDir on, off;
  on.write("VERIF_0001.rad", engine(1, half));
  on.write("VERIF_0002.rad", engine(2, end));
  off.write("VERIF_0001.rad", engine(1, half));
  off.write("VERIF_0002.rad", engine(2, end, "/RBODY/OFF\n1000\n"));
  const Final kept = run(on), released = run(off);
  ASSERT_EQ(released.summary.status, RunStatus::Normal) << released.summary.message;
  ASSERT_EQ(released.state.bodies.size(), 1u);
  EXPECT_TRUE(kept.state.bodies[0].active);
  EXPECT_FALSE(released.state.bodies[0].active);
  EXPECT_FALSE(same(kept.state.nodes.vx, released.state.nodes.vx));
}

// /DTIX: the first step of the deck is DTini, every later one at most DTmax; in between the step grows by a tenth a
// cycle (time-step.md, T-5), as the reference's does (a 5 mm shell with DTini 2e-4 ms: its listing's steps are
// 2.0e-4, 2.2e-4, 2.42e-4, 2.662e-4, ... up to the shell's).
TEST(ContinuedRun, DtixSetsTheFirstAndTheLargestStep) {
  test::TempDir dir;
  std::ostringstream e;
  e.precision(17);
  e << "/RUN/VERIF/1\n" << 20 * kStep << "\n/TFILE\n" << 1e-12 << "\n/DTIX\n" << 0.25 * kStep << " " << kStep
    << "\n/PRINT/-100000\n";
  dir.write("VERIF_0001.rad", e.str());
  std::vector<double> steps;
  Deck deck = read_deck(dir.write("VERIF_0000.rad", test::begin_card("VERIF") + bar_starter() + "/END\n"));
  SimulationOptions options;
  options.output_directory = dir.path();
  options.write_results = false;
  options.on_history_row = [&steps](const SolverState& s) { steps.push_back(s.dt); };
  std::ostringstream console;
  const RunSummary r = app::run_engine_decks(deck, options, console);
  ASSERT_EQ(r.status, RunStatus::Normal) << r.message;
  ASSERT_GT(steps.size(), 3u);
  EXPECT_EQ(steps[0], 0.25 * kStep);
  for (std::size_t k = 1; k < steps.size(); ++k) {
    EXPECT_LE(steps[k], kStep);
    EXPECT_DOUBLE_EQ(steps[k], std::min(1.1 * steps[k - 1], kStep)) << "step " << k;
  }
  EXPECT_DOUBLE_EQ(steps[1], 1.1 * 0.25 * kStep);
}

}  // namespace
}  // namespace crumple::verification::test_continued_run
