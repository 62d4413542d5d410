// Yield stress laws and the strain-rate filter (docs/theory/materials.md, eqs. JC and RF) against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "crumple/materials/hardening.hpp"
#include "crumple/materials/plane_stress.hpp"

namespace crumple::materials {
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

TEST(Hardening, KeptTermGivesTheSameReturnToTheLastBit) {
  // A plane-stress point driven through loading, unloading and reloading at a varying rate, once with the kept
  // Johnson-Cook term b eps_p^n (no power in the elastic check) and once without: identical stresses and plastic
  // strains, bit for bit, and the kept term equal to b eps_p^n of the current strain throughout.
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
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a[k], b[k]) << step;
    ASSERT_EQ(eps_a, eps_b) << step;
    ASSERT_EQ(kept, h.hardening_term(eps_a)) << step;
  }
  EXPECT_GT(eps_a, 0.01);  // it did yield, several times
}

TEST(Hardening, KeptTermGivesTheSameRadialReturnToTheLastBit) {
  // The same with the radial return (Iplas 2), whose first Newton step takes the kept term instead of a power:
  // identical stresses and plastic strains, bit for bit, from a start below eps_p = 1e-6 (where the slope is
  // evaluated at 1e-6, not at eps_p) to strains well above it.
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
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a[k], b[k]) << step;
    ASSERT_EQ(eps_a, eps_b) << step;
    ASSERT_EQ(kept, h.hardening_term(eps_a)) << step;
  }
  EXPECT_GT(eps_a, 0.01);
  EXPECT_GT(plastic_steps, 100);
}

}  // namespace
}  // namespace crumple::materials
