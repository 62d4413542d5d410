// Bar impact on a rigid wall (docs/verification.md, "Rigid wall").
//
// Physics: an elastic bar of length L moving at -v0 touches a fixed rigid plane with its end at t = 0. The end
// stops, a compression wave (stress rho c v0, particle velocity 0 behind it) runs to the free end in L / c,
// reflects as an unloading wave that leaves the particles at +v0, and reaches the wall at t = 2 L / c: at that
// moment the whole bar moves at +v0 with no stress, and it leaves the wall. The impact is perfectly elastic:
// contact time 2 L / c, rebound velocity +v0. The strip is a membrane with nu = 0 (exact bar, c = sqrt(E/rho)).
// The discrete bar loses the kinetic energy of the end node at the first contact (the wall stops that node in
// one step: m_end v0^2 / 2, i.e. 1/(2 nx) = 0.125 % of the energy here); the balance counts it as the (negative)
// work of the wall, and the rebound velocity falls by about half that fraction.
// Energy: the balance adds the kinetic energy of the half-step velocities to the strain energy at whole steps.
// While the waves run, energy flows between the two at the rate E0 c / L, so the balance is off by
// (dt / 2) E0 c / L = 0.9 / (2 nx) of E0 (sign changing with the flow); after the rebound the ringing that
// the impact leaves behind (frequencies with omega dt ~ 1, where 1/2 m v^2 at half steps overstates the energy
// the central difference conserves) holds a residual of the same 1/nx order. Both are artifacts of the
// measure, halved by each mesh refinement (0.3 % at nx = 100, 0.07 % at nx = 400 after the rebound): the test
// uses nx = 400 so that the 0.1 % bound applies.
#include <algorithm>
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_rigid_wall {
namespace {

// /RWALL/PLANE fixed at M = (0, 0, 0), normal towards M1 = (1, 0, 0), secondary nodes: group; Slide 0
// frictionless, 1 tied.
std::string plane_wall(long long id, long long group, int slide = 0) {
  return "/RWALL/PLANE/" + std::to_string(id) + "\nwall\n" + I(0) + I(slide) + I(group) + I(0) + "\n" + R(0.0) +
         R(0.0) + R(0.0) + R(0.0) + I(0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(1.0) + R(0.0) + R(0.0) + "\n";
}

// A node that would cross the wall within the step stops where it is (eq. RW-1): the bar's end, 0.3 of a step's
// travel from the wall, ends its first cycle at that distance with no normal velocity, and stays off the wall by
// it while the wall holds it. The reference's nodes do so: the 5 mm benchmark tube's bottom corner node ends
// 6.12e-3 mm off the wall in both solvers (docs/theory/rigid-walls.md); landed on the wall it was at 0.
TEST(RigidWall, ANodeThatWouldCrossStopsWhereItIs) {
  constexpr double E = 2.1e11, rho = 7800.0, L = 1.0, v0 = 5.0;
  const double c = std::sqrt(E / rho);
  Strip strip;
  strip.nx = 40, strip.ny = 1, strip.length = L, strip.width = L / 40;
  const double step = 0.9 * strip.width / c, gap = 0.3 * v0 * step;
  const std::string starter = node_cards(strip.nodes(gap)) + shell_cards(1, strip.shells()) + part_card() +
                              shell_property(0.001, 1) + elastic_material(rho, E, 0.0) +
                              node_group(1, strip.column(0)) + node_group(2, strip.all()) +
                              initial_velocity(1, -v0, 0.0, 0.0, 2) + plane_wall(1, 1);
  std::vector<double> x_end, v_end;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 20.0 * step, 0.5 * step, [&](const Model&, const SolverState& s) {
    x_end.push_back(s.nodes.x[0]), v_end.push_back(s.nodes.vx[0]);
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_GT(x_end.size(), 5u);
  for (std::size_t k = 1; k < 5; ++k) {  // the rows after the first cycle: held at the gap, at rest
    EXPECT_NEAR(x_end[k], gap, 1e-12 * L) << "cycle " << k;
    EXPECT_EQ(v_end[k], 0.0) << "cycle " << k;
  }
}

void bar_rebounds_after_two_transits(int slide) {
  constexpr double E = 2.1e11, rho = 7800.0, L = 1.0, v0 = 5.0;
  const double c = std::sqrt(E / rho);
  Strip strip;
  strip.nx = 400, strip.ny = 1, strip.length = L, strip.width = L / 400;
  std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                        shell_property(0.001, 1) + elastic_material(rho, E, 0.0) + node_group(1, strip.column(0)) +
                        node_group(2, strip.all()) + initial_velocity(1, -v0, 0.0, 0.0, 2) + plane_wall(1, 1, slide);

  std::vector<double> t, force, velocity;
  test::TempDir dir;
  const double end_time = 3.0 * L / c;
  const double step = 0.9 * strip.width / c;  // square elements: dt = 0.9 h / c, one sample per cycle
  const RunResult run = run_deck(dir, starter, end_time, 0.5 * step, [&](const Model&, const SolverState& s) {
    double momentum = 0.0, mass = 0.0;
    for (std::size_t k = 0; k < s.nodes.size(); ++k) momentum += s.nodes.mass[k] * s.nodes.vx[k], mass += s.nodes.mass[k];
    t.push_back(s.time - s.dt);  // the wall acted at t^n, in the velocity update of this cycle
    force.push_back(s.walls.at(0).force[0]);
    velocity.push_back(momentum / mass);
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;

  // Contact: from the first to the last cycle in which the wall pushed the bar.
  std::size_t first = t.size(), last = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (force[k] != 0.0) first = std::min(first, k), last = k;
  ASSERT_LT(first, t.size()) << "the bar never touched the wall";
  const double contact = t[last] - t[first];
  // Rebound velocity: the mean velocity (momentum over mass) once the bar has left the wall.
  double v_sum = 0.0;
  int samples = 0;
  for (std::size_t k = last + 1; k < t.size(); ++k) v_sum += velocity[k], ++samples;
  ASSERT_GT(samples, 20) << "the bar did not leave the wall before the end of the run";
  const double rebound = v_sum / samples;
  const double contact_error = contact / (2.0 * L / c) - 1.0;
  const double rebound_error = rebound / v0 - 1.0;
  // Tolerances of issue 4: contact time and rebound velocity 2 %, energy 0.1 %.
  EXPECT_LT(std::abs(contact_error), 0.02);
  EXPECT_LT(std::abs(rebound_error), 0.02);
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[rigid wall, Slide %d] cycles %lld  contact %.6e s (2L/c %.6e, %+.3f %%)  rebound %.5f m/s (%+.3f %%)  "
              "wall work %.3e (%.3f %% of E_kin0)  energy error %.4f %%\n",
              slide, run.summary.cycles, contact, 2.0 * L / c, 100 * contact_error, rebound, 100 * rebound_error,
              run.summary.energy.external_work,
              100 * run.summary.energy.external_work / (0.5 * rho * 0.001 * L * strip.width * v0 * v0),
              run.summary.energy.error_percent);
}

TEST(RigidWall, ElasticBarReboundsAfterTwoTransits) { bar_rebounds_after_two_transits(0); }

// A tied wall (Slide 1) holds a node while it presses on the wall, and lets it go when it pulls away (eq. RW-1a):
// the bar rebounds as from the frictionless wall. The reference does so: a plate pressed onto a tied floor, then
// pulled up and sideways, leaves it (its lifted node 1.1585 mm up and 0.5418 mm aside at 0.45 ms in both solvers,
// 2026-12-07); welded, as Crumple's tied nodes were before, the bar never leaves.
TEST(RigidWall, TiedBarLeavesTheWallWhenItPullsAway) { bar_rebounds_after_two_transits(1); }

}  // namespace
}  // namespace crumple::verification::test_rigid_wall
