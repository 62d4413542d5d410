// Free vibration of a cantilever plate strip (docs/verification.md, "Cantilever").
//
// Physics: a thin strip clamped at x = 0 vibrates in its first bending mode at the Kirchhoff frequency
//     f1 = (beta1 L)^2 / (2 pi L^2) sqrt(D / (rho t)),   beta1 L = 1.87510,
// with D the bending stiffness per unit width. For a wide plate bent cylindrically D = E t^3 / (12 (1 - nu^2));
// a narrow strip is free to take the anticlastic curvature and behaves as a beam, D = E t^3 / 12. The strip
// here (b = L / 10) is narrow, and the test takes nu = 0 so that both values coincide: the 2 % tolerance then
// measures the element (16 one-point shells along the length, Mindlin shear, lumped rotational inertia) and
// the time integration, not the choice of 1-D idealisation. The neglected effects are small: transverse
// shear and rotary inertia (t / L = 0.01) shift f1 by O((t/L)^2); the rotational inertia that Crumple lumps
// at the nodes, m/4 (t^2 + A)/12 (shell4.md S-8), is inflated by the A term but enters the first mode through
// the slope only, about (t^2 + A)/12 (beta1)^2 ~ 1e-3 relative; the central difference error is
// (omega dt)^2 / 24 ~ 1e-8.
// The strip starts straight with the velocity field of the first mode (one /INIVEL/TRA per node column), so
// the higher modes carry little energy and the tip displacement crosses zero every half period. A Mindlin shell
// also needs the matching rotation rates, theta_y = -dw/dx (u_x = z theta_y, shell4.md S-3): without them the
// initial shear strain rate excites the shear-rotation mode of the nodes (omega dt ~ 0.8 on this mesh), whose
// energy the balance measures badly because it adds kinetic energy at half steps to strain energy at whole
// steps; that mode would show as a +-0.5 % "energy error" that has nothing to do with the first mode. There is
// no /INIVEL/ROT, so rotational /IMPVEL cards impose those rates for the first step only (Tstop = one step);
// their impulse is counted as external work.
#include <algorithm>
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_cantilever {
namespace {

// First cantilever mode shape, phi(0) = phi'(0) = 0, phi(L) = 2, and its slope.
constexpr double kBeta1L = 1.875104068711961;
double mode_sigma() {
  return (std::cosh(kBeta1L) + std::cos(kBeta1L)) / (std::sinh(kBeta1L) + std::sin(kBeta1L));
}
double mode_shape(double x, double L) {
  const double bx = kBeta1L * x / L;
  return std::cosh(bx) - std::cos(bx) - mode_sigma() * (std::sinh(bx) - std::sin(bx));
}
double mode_slope(double x, double L) {
  const double bx = kBeta1L * x / L;
  return kBeta1L / L * (std::sinh(bx) + std::sin(bx) - mode_sigma() * (std::cosh(bx) - std::cos(bx)));
}

// Both 4-node formulations: Belytschko-Tsay (Ishell 1) and the physically stabilised element (Ishell 24).
class Cantilever : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Ishell, Cantilever, ::testing::Values(1, 12, 24));

TEST_P(Cantilever, FirstBendingFrequency) {
  constexpr double E = 2.1e11, rho = 7800.0, L = 1.0, b = 0.1, t = 0.01, v_tip = 0.01;
  Strip strip;
  strip.nx = 16, strip.ny = 1, strip.length = L, strip.width = b;
  std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                        shell_property(t, 5, 0.0, GetParam()) + elastic_material(rho, E, 0.0) + node_group(1, strip.column(0)) +
                        boundary_condition(1, "111 111", 1);
  // First step: dt = 0.9 (area / longest side) / c = 0.9 (L / nx) / c; the rotations are imposed at the first
  // half step t = dt / 2 only.
  const double first_step = 0.9 * (L / strip.nx) / std::sqrt(E / rho);
  starter += unit_function(1);
  for (int i = 1; i <= strip.nx; ++i) {
    const double x = L * i / strip.nx;
    starter += node_group(100 + i, strip.column(i)) +
               initial_velocity(i, 0.0, 0.0, v_tip * mode_shape(x, L) / mode_shape(L, L), 100 + i) +
               imposed_velocity(i, 1, "YY", 100 + i, -v_tip * mode_slope(x, L) / mode_shape(L, L), first_step);
  }
  const double D = E * t * t * t / 12.0;
  const double f_kirchhoff = kBeta1L * kBeta1L / (2.0 * kPi * L * L) * std::sqrt(D / (rho * t));
  const double end_time = 3.6 / f_kirchhoff;

  std::vector<double> time, tip;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, end_time, 0.5 * first_step, [&](const Model& m, const SolverState& s) {
    double w = 0.0;
    for (long long id : strip.column(strip.nx)) w += s.nodes.z[node_index(m, id)];
    time.push_back(s.time);
    tip.push_back(w / (strip.ny + 1));
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;

  // Zero crossings of the tip displacement after the start (one every half period).
  std::vector<double> crossings;
  for (std::size_t k = 1; k < tip.size(); ++k) {
    const double c = first_crossing(time, tip, 0.0, k);
    if (c < 0.0) break;
    if (c > 0.1 / f_kirchhoff) crossings.push_back(c);
    while (k < time.size() && time[k] < c) ++k;
  }
  ASSERT_GE(crossings.size(), 6u) << "too few zero crossings of the tip displacement";
  const double period = 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double frequency = 1.0 / period;
  const double error = frequency / f_kirchhoff - 1.0;
  EXPECT_LT(std::abs(error), 0.02);
  // Free vibration: no external work, the balance is the exchange between kinetic and strain energy.
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[cantilever Ishell %d] cycles %lld  crossings %zu  f %.5f Hz  Kirchhoff %.5f Hz (%+.3f %%)  energy error "
              "%.4f %%  hourglass/internal %.2e\n",
              GetParam(), run.summary.cycles, crossings.size(), frequency, f_kirchhoff, 100 * error,
              run.summary.energy.error_percent, run.summary.energy.hourglass / std::max(run.summary.energy.internal, 1e-300));
}

}  // namespace
}  // namespace crumple::verification::test_cantilever
