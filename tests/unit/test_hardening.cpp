// Yield stress laws and the strain-rate filter (docs/theory/materials.md, eqs. JC and RF) against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "crumple/materials/hardening.hpp"
#include "crumple/materials/plane_stress.hpp"

namespace crumple::materials::test_hardening {
namespace {

Material johnson_cook(int fsmooth, double f_cut) {
  Material m;
  m.law = MaterialLaw::JohnsonCook;
  m.johnson_cook.a = 2e8, m.johnson_cook.b = 5e8, m.johnson_cook.n = 0.4;
  m.johnson_cook.c = 0.05, m.johnson_cook.eps_dot_0 = 1e-3;
  m.johnson_cook.fsmooth = fsmooth, m.johnson_cook.f_cut = f_cut;
  return m;
}

TEST(Hardening, JohnsonCookWithRateFactor) {
  const std::vector<Function> none;
  const Material m = johnson_cook(0, 0.0);
  const Hardening h = Hardening::of(m, none);
  // (a + b 0.1^0.4) (1 + 0.05 ln(10 / 1e-3)) by hand: (2e8 + 5e8 * 0.3981072) * 1.4605170 = 5.828246e8
  EXPECT_NEAR(h.yield(0.1, 10.0), 5.828246e8, 1e2);
  // Below the reference rate the factor is 1.
  EXPECT_NEAR(h.yield(0.1, 1e-4), 2e8 + 5e8 * std::pow(0.1, 0.4), 1e-6);
}

TEST(Hardening, RateFilterIsAFirstOrderLowPass) {
  const std::vector<Function> none;
  const double dt = 1e-6, f_cut = 1e4;
  const double a = 2.0 * std::numbers::pi * f_cut * dt;  // 0.0628
  const Material filtered = johnson_cook(1, f_cut);
  const Hardening h = Hardening::of(filtered, none);
  EXPECT_DOUBLE_EQ(h.filtered_rate(100.0, 0.0, dt), a * 100.0);
  EXPECT_DOUBLE_EQ(h.filtered_rate(100.0, 50.0, dt), a * 100.0 + (1.0 - a) * 50.0);
  // A step beyond 1 / (2 pi Fcut) passes the rate through (a is capped at 1).
  EXPECT_DOUBLE_EQ(h.filtered_rate(100.0, 50.0, 1.0), 100.0);
  // A unit step input after N cycles: 1 - (1 - a)^N, i.e. about 1 - 1/e after the time constant 1/(2 pi Fcut).
  double r = 0.0;
  const int steps = 16;
  for (int k = 0; k < steps; ++k) r = h.filtered_rate(1.0, r, dt);
  EXPECT_NEAR(r, 1.0 - std::pow(1.0 - a, steps), 1e-12);
  EXPECT_NEAR(r, 1.0 - std::exp(-steps * a), 0.02);
  // Fsmooth = 0, or Fcut = 0 (the manual's 1e30), leave the rate unfiltered.
  const Material off = johnson_cook(0, f_cut), infinite = johnson_cook(1, 0.0);
  EXPECT_DOUBLE_EQ(Hardening::of(off, none).filtered_rate(100.0, 50.0, dt), 100.0);
  EXPECT_DOUBLE_EQ(Hardening::of(infinite, none).filtered_rate(100.0, 50.0, dt), 100.0);
}

// The kept term follows b eps_p^n of the current strain: in double by the series (eq. JC-2), whose round-off walks
// about an ulp a plastic cycle, so 1e-13 bounds it over these few thousand cycles with a margin of 10; in the
// mixed build, stored in single, to a float's rounding (eq. PR-2).
constexpr double kKeptTermTolerance = kMixedPrecision ? 1e-7 : 1e-13;
// Stresses and strains from the series' terms against the powers': the Newton iteration stops at a residual of
// 1e-12 of the yield stress, and both follow the same path to within the terms' round-off.
constexpr double kReturnTolerance = 1e-12;

// |a - b| within `relative` of `scale` (a stress component against the initial yield stress, a strain against
// itself).
void expect_close(double a, double b, double relative, int step, double scale = 0.0) {
  const double size = std::max(std::abs(b), scale);
  ASSERT_LE(std::abs(a - b), relative * size) << "step " << step << ": " << a << " vs " << b;
}


TEST(Hardening, KeptTermGivesTheSameReturn) {
  // A plane-stress point driven through loading, unloading and reloading at a varying rate, once with the kept
  // Johnson-Cook term b eps_p^n (no power in the elastic check nor in the return) and once without: the same
  // stresses and plastic strains to the return's own tolerance, and the kept term b eps_p^n of the current strain
  // throughout.
  Material m = johnson_cook(0, 0.0);
  m.johnson_cook.sig_max0 = 6e8;  // the cap on the way as well
  m.young = 2.1e11, m.poisson = 0.3;
  const std::vector<Function> none;
  const auto h = Hardening::of(m, none);
  const PlaneStressElastic el{m.young, m.poisson};
  double a[3] = {0, 0, 0}, b[3] = {0, 0, 0}, eps_a = 0.0, eps_b = 0.0;
  double kept = std::numeric_limits<double>::quiet_NaN();
  for (int step = 0; step < 4000; ++step) {
    const double phase = std::sin(step * 0.004), de = 2e-5 * (phase > 0.0 ? 1.0 : -0.7);
    const double rate = 1.0 + 100.0 * std::abs(phase);
    const auto ra = plane_stress_update(el, h, de, -0.3 * de, 0.5 * de, rate, eps_a, a[0], a[1], a[2], &kept);
    const auto rb = plane_stress_update(el, h, de, -0.3 * de, 0.5 * de, rate, eps_b, b[0], b[1], b[2]);
    eps_a += ra.plastic_strain_increment, eps_b += rb.plastic_strain_increment;
    for (int k = 0; k < 3; ++k) expect_close(a[k], b[k], kReturnTolerance, step, m.johnson_cook.a);
    expect_close(eps_a, eps_b, kReturnTolerance, step);
    expect_close(kept, h.hardening_term(eps_a), kKeptTermTolerance, step);
  }
  EXPECT_GT(eps_a, 0.01);  // it did yield, several times
}

TEST(Hardening, KeptTermGivesTheSameRadialReturn) {
  // The same with the radial return (Iplas 2), whose Newton steps take the kept term's series instead of a power,
  // from a start below eps_p = 1e-6 (where the slope is evaluated at 1e-6, not at eps_p) to strains well above it.
  Material m = johnson_cook(0, 0.0);
  m.young = 2.1e11, m.poisson = 0.3;
  const std::vector<Function> none;
  const auto h = Hardening::of(m, none);
  const PlaneStressElastic el{m.young, m.poisson};
  double a[3] = {0, 0, 0}, b[3] = {0, 0, 0}, eps_a = 0.0, eps_b = 0.0;
  double kept = std::numeric_limits<double>::quiet_NaN();
  int plastic_steps = 0;
  for (int step = 0; step < 4000; ++step) {
    const double phase = std::sin(step * 0.004), de = 2e-5 * (phase > 0.0 ? 1.0 : -0.7);
    const double rate = 1.0 + 100.0 * std::abs(phase);
    const auto ra = plane_stress_radial_return(el, h, de, -0.3 * de, 0.5 * de, rate, eps_a, a[0], a[1], a[2], &kept);
    const auto rb = plane_stress_radial_return(el, h, de, -0.3 * de, 0.5 * de, rate, eps_b, b[0], b[1], b[2]);
    plastic_steps += ra.plastic_strain_increment > 0.0 ? 1 : 0;
    eps_a += ra.plastic_strain_increment, eps_b += rb.plastic_strain_increment;
    for (int k = 0; k < 3; ++k) expect_close(a[k], b[k], kReturnTolerance, step, m.johnson_cook.a);
    expect_close(eps_a, eps_b, kReturnTolerance, step);
    expect_close(kept, h.hardening_term(eps_a), kKeptTermTolerance, step);
  }
  EXPECT_GT(eps_a, 0.01);
  EXPECT_GT(plastic_steps, 100);
}

TEST(Hardening, SeriesTermMatchesThePower) {
  // b (e0 (1 + u))^n by the series (eq. JC-2) against std::pow across the series' reach, for exponents below and
  // above 1: within 4 ulps of the term (the remainder is below 1e-17; the rest is the round-off of the sum, of
  // e0 (1 + u) and of the power itself).
  const std::vector<Function> none;
  for (const double n : {0.1, 0.4, 0.75, 1.3}) {
    Material m = johnson_cook(0, 0.0);
    m.johnson_cook.n = n;
    const auto h = Hardening::of(m, none);
    for (const double e0 : {1e-5, 3e-3, 0.2, 1.7}) {
      const Hardening::KeptTerm kept{e0, h.hardening_term(e0), 1.0 / e0};
      for (double u = -Hardening::kSeriesReach; u <= Hardening::kSeriesReach; u += Hardening::kSeriesReach / 50.0) {
        const double eps = e0 * (1.0 + u), exact = h.hardening_term(eps);
        EXPECT_LE(std::abs(h.term_near(kept, eps) - exact), 4.0 * std::numeric_limits<double>::epsilon() * exact)
            << "n " << n << " e0 " << e0 << " u " << u;
      }
      // Beyond the reach the power itself: the same value to the last bit.
      EXPECT_EQ(h.term_near(kept, 1.5 * e0), h.hardening_term(1.5 * e0));
      EXPECT_EQ(h.term_near(kept, e0), kept.term);
    }
  }
}

TEST(Hardening, SeriesCarriedOverManyCyclesStaysOnThePower) {
  // A term carried from cycle to cycle by the series only, 10^5 plastic increments of up to 1 % of the strain:
  // its round-off walks, but stays within 1e-13 of b eps^n (measured: 1.6e-14, a random walk of about an ulp a cycle).
  const std::vector<Function> none;
  const Material m = johnson_cook(0, 0.0);  // Hardening keeps a pointer to its parameters
  const auto h = Hardening::of(m, none);
  double eps = 1e-4, term = h.hardening_term(eps);
  double worst = 0.0;
  for (int cycle = 0; cycle < 100000; ++cycle) {
    const double d = eps * 0.01 * (0.5 + 0.5 * std::sin(cycle * 0.37));
    term = h.term_near({eps, term, 1.0 / eps}, eps + d);
    eps += d;
    worst = std::max(worst, std::abs(term - h.hardening_term(eps)) / h.hardening_term(eps));
  }
  EXPECT_GT(eps, 1.0);  // well past the strains a crash reaches
  EXPECT_LE(worst, 1e-13);
}

TEST(Hardening, SlopeFromTermIsTheSlope) {
  // n b eps^(n-1) from the term n (b eps^n) / eps, with the rate factor and the cap: the slope's value.
  const std::vector<Function> none;
  Material m = johnson_cook(0, 0.0);
  for (const double cap : {0.0, 6e8}) {
    m.johnson_cook.sig_max0 = cap;
    const auto h = Hardening::of(m, none);
    for (const double eps : {1e-6, 1e-3, 0.05, 0.4})
      for (const double rate : {1e-4, 10.0}) {
        const double slope = h.slope(eps, rate), from_term = h.slope_from_term(eps, h.hardening_term(eps), rate);
        EXPECT_NEAR(from_term, slope, 1e-14 * std::abs(slope) + 1e-300) << eps << " " << rate << " " << cap;
      }
  }
}

}  // namespace
}  // namespace crumple::materials::test_hardening
