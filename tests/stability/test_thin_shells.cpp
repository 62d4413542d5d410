// Thin shells at the default step scale (docs/theory/shell4.md, S-8; docs/theory/time-step.md, T-1a): a clamped
// strip of 5 square elements swinging at 1 m/s, elastic steel, for thickness / side from 1/5 to 1/200 and every
// 4-node formulation. The step is the element's (bar speed over its side, x 0.9); the transverse shear couples
// each node's rotation with the deflection of its neighbours, and the mode's frequency depends on the nodal
// rotational inertia: with (m/4)(t^2 + A)/12 the 20 x 20 x 1 mm strip diverged at cycle 200 (energy error 1e6 %,
// an element inverted at cycle 325); with the reference solver's (m/4)(t^2/12 + A/9) it runs. A stable run keeps its
// energy balance: the test asks for |error| < 5 % at 2 ms (about 600 cycles) and a finite, non-inverted end. With
// nu = 0 even that inertia leaves the shear mode faster than the step (0.86 of the element step for a thin square
// element, eq. S-8a): the strips diverged until the inertia took the mode's bound too.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "verification_support.hpp"

namespace crumple::verification {
namespace {

struct ThinCase {
  int ishell;
  double thickness;  // [m], on 20 mm elements
  double poisson = 0.3;
};

void PrintTo(const ThinCase& c, std::ostream* os) {
  *os << "Ishell " << c.ishell << ", t = " << c.thickness << ", nu = " << c.poisson;
}

class ThinShell : public ::testing::TestWithParam<ThinCase> {};

TEST_P(ThinShell, ClampedStripStaysStableAtTheDefaultStepScale) {
  const ThinCase& c = GetParam();
  Strip strip;
  strip.nx = 5, strip.ny = 1, strip.length = 0.1, strip.width = 0.02;
  std::vector<long long> free;
  for (int i = 1; i <= strip.nx; ++i)
    for (long long id : strip.column(i)) free.push_back(id);
  const std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                              shell_property(c.thickness, 3, 0.0, c.ishell) + elastic_material(7800.0, 2.1e11, c.poisson) +
                              node_group(1, strip.column(0)) + boundary_condition(1, "111 111", 1) +
                              node_group(2, free) + initial_velocity(1, 0.0, 0.0, 1.0, 2);
  test::TempDir dir;
  const RunResult r = run_deck(dir, starter, 2e-3, 1e-4);
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  EXPECT_GT(r.summary.cycles, 500);
  EXPECT_TRUE(std::isfinite(r.summary.energy.error_percent));
  EXPECT_LT(std::abs(r.summary.energy.error_percent), 5.0);
  std::printf("[thin] Ishell %d t %.4f nu %.1f: %lld cycles, energy error %.3f %%\n", c.ishell, c.thickness, c.poisson,
              r.summary.cycles, r.summary.energy.error_percent);
}

INSTANTIATE_TEST_SUITE_P(
    Formulations, ThinShell,
    ::testing::Values(ThinCase{1, 0.004}, ThinCase{1, 0.001}, ThinCase{1, 0.0001}, ThinCase{2, 0.001},
                      ThinCase{3, 0.001}, ThinCase{3, 0.0001}, ThinCase{24, 0.001}, ThinCase{24, 0.0001},
                      ThinCase{12, 0.001},
                      // nu = 0: the shear mode is faster than the step with the reference's inertia alone (S-8a).
                      ThinCase{1, 0.001, 0.0}, ThinCase{24, 0.001, 0.0}, ThinCase{24, 0.0001, 0.0},
                      ThinCase{12, 0.001, 0.0}),
    [](const auto& p) {
      return "Ishell" + std::to_string(p.param.ishell) + "_t" + std::to_string(static_cast<int>(p.param.thickness * 1e5)) +
             (p.param.poisson == 0.0 ? "_nu0" : "");
    });

}  // namespace
}  // namespace crumple::verification
