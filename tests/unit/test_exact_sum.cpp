// ExactSum (core/exact_sum.hpp): the sum does not depend on the order of the terms and is the exact sum rounded
// once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "crumple/core/exact_sum.hpp"

namespace crumple::test_exact_sum {
namespace {

double exact(const std::vector<double>& terms) {
  ExactSum s;
  for (double t : terms) s.add(t);
  return s.value();
}

TEST(ExactSum, SmallIntegersAndPowersOfTwoAreExact) {
  EXPECT_EQ(exact({}), 0.0);
  EXPECT_EQ(exact({1.0, 2.0, 3.0}), 6.0);
  EXPECT_EQ(exact({-1.5, 0.25}), -1.25);
  EXPECT_EQ(exact({1e308, 1e308, -1e308}), 1e308);  // no overflow in between
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(exact({tiny, tiny, tiny}), 3.0 * tiny);
  EXPECT_EQ(exact({std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()}), 0.0);
}

TEST(ExactSum, CancellationKeepsTheSmallTerm) {
  // Left to right in doubles: (1e16 + 1) - 1e16 = 0 (the 1 is lost); the exact sum is 1.
  EXPECT_EQ(exact({1e16, 1.0, -1e16}), 1.0);
  EXPECT_EQ(exact({1.0, 1e100, 1.0, -1e100}), 2.0);
  // The three doubles nearest 0.1, 0.2 and 0.3 sum exactly to 2^-55; left to right in doubles gives 2^-54.
  EXPECT_EQ(exact({0.1, 0.2, -0.3}), std::ldexp(1.0, -55));
  EXPECT_EQ(0.1 + 0.2 - 0.3, std::ldexp(1.0, -54));
}

TEST(ExactSum, RoundsTheExactSumToNearestEven) {
  const double u = std::ldexp(1.0, -53);  // half an ulp of 1
  EXPECT_EQ(exact({1.0, u}), 1.0);                        // a tie: to even
  EXPECT_EQ(exact({1.0, u, std::ldexp(1.0, -200)}), 1.0 + 2 * u);  // just above the tie: up
  EXPECT_EQ(exact({1.0 + 2 * u, u}), 1.0 + 4 * u);        // a tie from an odd mantissa: up to even
  EXPECT_EQ(exact({-1.0, -u, -std::ldexp(1.0, -300)}), -(1.0 + 2 * u));
}

TEST(ExactSum, OrderDoesNotMatter) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<double> terms(5000);
  for (double& t : terms) t = std::ldexp(mantissa(random), exponent(random));
  const double reference = exact(terms);
  double naive_first = 0.0;
  for (double t : terms) naive_first += t;
  bool naive_changed = false;
  for (int trial = 0; trial < 20; ++trial) {
    std::shuffle(terms.begin(), terms.end(), random);
    EXPECT_EQ(exact(terms), reference);
    double naive = 0.0;
    for (double t : terms) naive += t;
    naive_changed = naive_changed || naive != naive_first;
  }
  EXPECT_TRUE(naive_changed) << "the terms should be ones whose plain sum depends on the order";
  // Split among "domains" and combined.
  ExactSum a, b, c;
  for (std::size_t i = 0; i < terms.size(); ++i) (i % 3 == 0 ? a : i % 3 == 1 ? b : c).add(terms[i]);
  c.add(a), c.add(b);
  EXPECT_EQ(c.value(), reference);
  // Close to the plain sum (which carries rounding errors of about n ulps of the largest partial sums).
  EXPECT_NEAR(reference, naive_first, 5000 * std::ldexp(1.0, 60 - 52));  // n ulps of the largest term
}

TEST(ExactSum, DigitsCombineAsIntegers) {
  ExactSum a, b;
  a.add(3.25), a.add(-1e-20);
  b.add(1e-20), b.add(-0.25);
  ExactSum c = a;
  for (std::size_t i = 0; i < c.digits().size(); ++i) c.digits()[i] += b.digits()[i];
  EXPECT_EQ(c.value(), 3.0);
}

TEST(ExactSum, NonFiniteTermsGiveTheIeeeResult) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(exact({1.0, inf}), inf);
  EXPECT_TRUE(std::isnan(exact({1.0, inf, -inf})));
  EXPECT_TRUE(std::isnan(exact({std::nan(""), 2.0})));
}

}  // namespace
}  // namespace crumple::test_exact_sum
