// The accelerometers' 4-pole Butterworth low-pass and their update after a cycle's velocity update
// (include/crumple/solver/accelerometers.hpp, docs/output-format.md "ACCEL", eqs. ACC-1 to ACC-3).
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/solver/accelerometers.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_accelerometers {

using namespace crumple;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Steady-state amplitude of the filter's response to sin(2 pi f t) sampled every h: the response over whole
// periods after `settle` samples, projected on sin and cos (exact for a sinusoid over whole periods).
double steady_gain(double cutoff, double f, double h, int samples_per_period, int settle_periods) {
  const auto filter = butterworth4(cutoff, h);
  double memory[6] = {};
  double a = 0.0, b = 0.0;
  const int periods = 10, n_settle = settle_periods * samples_per_period, n = periods * samples_per_period;
  for (int k = 0; k < n_settle + n; ++k) {
    const double phase = 2.0 * kPi * f * h * k;
    const double y = filter_sample(filter, std::sin(phase), memory);
    if (k >= n_settle) a += y * std::sin(phase), b += y * std::cos(phase);
  }
  return 2.0 / n * std::sqrt(a * a + b * b);
}

}  // namespace

// With fc h = 1/4, K = tan(pi/4) = 1: a1 = 0 and b0 = 1 / (2 + 2 zeta) in each section (eq. ACC-2). A unit step from
// rest: the first output is b0 b0' = 0.0939808514..., the second 5 b0 b0' (section 1 gives b0 then 3 b0; section 2
// b0' (3 b0) + 2 b0' b0).
TEST(Accelerometers, FirstSamplesOfAStepAreTheHandComputedOnes) {
  const auto filter = butterworth4(250.0, 1e-3);
  const double b0 = 1.0 / (2.0 + 2.0 * std::sin(kPi / 8.0)), c0 = 1.0 / (2.0 + 2.0 * std::sin(3.0 * kPi / 8.0));
  EXPECT_NEAR(b0, 0.36161567304292236, 1e-15);
  EXPECT_NEAR(c0, 0.25989153247414504, 1e-15);
  EXPECT_NEAR(filter[0].b0, b0, 1e-15);
  EXPECT_NEAR(filter[0].a1, 0.0, 1e-15);
  EXPECT_NEAR(filter[1].a2, (2.0 - 2.0 * std::sin(3.0 * kPi / 8.0)) * c0, 1e-15);
  double memory[6] = {};
  EXPECT_NEAR(filter_sample(filter, 1.0, memory), 0.09398085143379448, 1e-15);
  EXPECT_NEAR(filter_sample(filter, 1.0, memory), 5.0 * 0.09398085143379448, 1e-15);
}

// Gain 1 at zero frequency: a constant comes through unchanged once the transient is over.
TEST(Accelerometers, AConstantComesThrough) {
  const auto filter = butterworth4(1000.0, 1e-5);
  double memory[6] = {};
  double y = 0.0;
  for (int k = 0; k < 20000; ++k) y = filter_sample(filter, 3.5, memory);
  EXPECT_NEAR(y, 3.5, 1e-12);
}

// The prewarped bilinear filter's gain is 1 / sqrt(1 + (tan(pi f h) / tan(pi fc h))^8): 1/sqrt(2) at fc exactly.
TEST(Accelerometers, GainOfAButterworthOfFourPoles) {
  const double fc = 1000.0, h = 1e-5;
  for (double f : {250.0, 500.0, 1000.0, 2000.0, 4000.0}) {
    const double ratio = std::tan(kPi * f * h) / std::tan(kPi * fc * h);
    const double expected = 1.0 / std::sqrt(1.0 + std::pow(ratio, 8));
    EXPECT_NEAR(steady_gain(fc, f, h, static_cast<int>(std::lround(1.0 / (f * h))), 40), expected, 1e-6) << f;
  }
  EXPECT_NEAR(steady_gain(fc, fc, h, 100, 40), 1.0 / std::sqrt(2.0), 1e-6);
}

// A corner frequency at or above the Nyquist frequency 0.5 / h is capped at 0.4 / h: finite coefficients.
TEST(Accelerometers, CornerFrequencyCappedBelowNyquist) {
  const auto capped = butterworth4(1e9, 1e-3), at_cap = butterworth4(400.0, 1e-3);
  for (int s = 0; s < 2; ++s) {
    EXPECT_TRUE(std::isfinite(capped[s].b0) && std::isfinite(capped[s].a1) && std::isfinite(capped[s].a2));
    EXPECT_EQ(capped[s].b0, at_cap[s].b0);
    EXPECT_EQ(capped[s].a2, at_cap[s].a2);
  }
}

// After a velocity update: the raw acceleration (v - before) / dt, its integral W (eq. ACC-3), and the filter for
// Fcut > 0 (Fcut 0: the raw value).
TEST(Accelerometers, UpdateAfterTheVelocityUpdate) {
  NodalState n;
  n.resize(3);
  std::vector<double> bx{0.0, 1.0, 2.0}, by{0.0, 0.0, 0.0}, bz{0.0, -1.0, 0.0};
  n.vx = {0.0, 1.5, 2.0}, n.vy = {0.0, 0.25, 0.0}, n.vz = {0.0, -1.0, 4.0};
  std::vector<Accelerometer> meters(2);
  meters[0].node = 1, meters[0].cutoff = 0.0;
  meters[1].node = 2, meters[1].cutoff = 250.0;
  HistoryIntegrals h;
  setup_accelerometers(meters.size(), h);
  const double dt = 1e-3;
  update_accelerometers(meters, n, {&bx, &by, &bz}, dt, {}, h);
  EXPECT_DOUBLE_EQ(h.accel_filtered[0], 0.5 / dt);  // raw: (1.5 - 1) / dt
  EXPECT_DOUBLE_EQ(h.accel_filtered[1], 0.25 / dt);
  EXPECT_EQ(h.accel_filtered[2], 0.0);
  EXPECT_DOUBLE_EQ(h.accel_velocity[0], 0.5);
  EXPECT_EQ(h.accel_filtered[3], 0.0);  // no change along x at node 2
  // fc h = 1/4: the first filtered sample is b0 b0' times the raw 4 / dt.
  EXPECT_NEAR(h.accel_filtered[5], 0.09398085143379448 * 4.0 / dt, 1e-12 * 4.0 / dt);
  EXPECT_DOUBLE_EQ(h.accel_velocity[5], 4.0);
  // The same change again: W sums, the step's second sample is 5 b0 b0'.
  for (auto* v : {&bx, &by, &bz}) v->assign(3, 0.0);
  bx = {0.0, 1.0, 2.0}, bz = {0.0, -1.0, 0.0};
  update_accelerometers(meters, n, {&bx, &by, &bz}, dt, {}, h);
  EXPECT_DOUBLE_EQ(h.accel_velocity[0], 1.0);
  EXPECT_DOUBLE_EQ(h.accel_velocity[5], 8.0);
  EXPECT_NEAR(h.accel_filtered[5], 5.0 * 0.09398085143379448 * 4.0 / dt, 1e-12 * 4.0 / dt);
  // No accelerometer, or no step (the state before the first cycle): nothing changes.
  update_accelerometers(meters, n, {&bx, &by, &bz}, 0.0, {}, h);
  EXPECT_DOUBLE_EQ(h.accel_velocity[0], 1.0);
}

}  // namespace test_accelerometers
