// /GRAV with its optional fields blank (docs/cards/loads-output-engine.md): no funct_IDT is a constant
// acceleration, no grnod_ID is every node. A free strip falls at g: v_z(t) = -g t and z(t) = -g t^2 / 2 at the
// nodes, exactly in central differences for a constant acceleration (to round-off), and the work of gravity is
// the kinetic energy (energy error 0). It crashed before (the missing function and group were indexed).
#include <gtest/gtest.h>

#include <cmath>

#include "verification_support.hpp"

namespace crumple::verification::test_gravity {
namespace {

TEST(Gravity, BlankFunctionAndGroupAreAConstantAccelerationOnEveryNode) {
  constexpr double g = 9.81, end = 1e-3;
  Strip strip;
  strip.nx = 2, strip.ny = 1, strip.length = 0.2, strip.width = 0.1;
  const std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                              shell_property(0.002, 3) + elastic_material(7800.0, 2.1e11, 0.3) + "/GRAV/1\ngravity\n" +
                              I(0) + "         Z" + I(0) + I(0) + I(0) + I(0) + R(0.0) + R(-g) + "\n";
  test::TempDir dir;
  double vz_min = 0.0, vz_max = -1e30, time = 0.0, step = 0.0, full_step = 0.0, loop_error = 0.0, row_error = 0.0;
  const RunResult r = run_deck(dir, starter, end, 1e-5, [&](const Model&, const SolverState& s) {
    loop_error = std::max(loop_error, row_error);  // every row's but the last
    row_error = std::abs(s.energy.error_percent());
    full_step = step, time = s.time, step = s.dt;
    vz_min = *std::min_element(s.nodes.vz.begin(), s.nodes.vz.end());
    vz_max = *std::max_element(s.nodes.vz.begin(), s.nodes.vz.end());
  });
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  EXPECT_GT(r.summary.cycles, 10);
  // At the last history row, t^(n+1) = t^n + dt and the velocities are v^(n+1/2) = -g (t^(n+1) - dt / 2) (the first
  // cycle's half step from rest, then whole steps).
  EXPECT_GT(time, 0.9 * end);
  EXPECT_NEAR(vz_min, vz_max, 1e-12 * g * end) << "every node falls alike";
  EXPECT_NEAR(vz_min, -g * (time - 0.5 * step), 1e-6 * g * end);
  // The loop's balance closes to round-off at every row before the last. The last row is the end state (energy.md,
  // E-3): its kinetic energy is exactly m (g t)^2 / 2, its work the linear share of the next cycle's, above the
  // quadratic work by m g^2 (dt_last / 2) (dt / 2) / 2: an error of -dt_last dt / (4 t^2).
  EXPECT_LT(loop_error, 1e-6);
  const double expected = -100.0 * step * full_step / (4.0 * time * time);
  EXPECT_NEAR(r.summary.energy.error_percent, expected, 1e-3 * std::abs(expected));
  EXPECT_GT(r.summary.energy.external_work, 0.0);
}

}  // namespace
}  // namespace crumple::verification::test_gravity
