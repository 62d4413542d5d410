// Characteristic lengths of the shell time step (docs/theory/time-step.md, eqs. T-1, T-1b).
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/core/geometry.hpp"

namespace crumple::geometry {
namespace {

// A square and a rectangle: the shortest side, which is also the area over the longest side.
TEST(Geometry, BelytschkoTsayLengthOfRectanglesIsTheShortestSide) {
  EXPECT_DOUBLE_EQ(belytschko_tsay_length({0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {0, 5, 0}), 5.0);
  EXPECT_DOUBLE_EQ(belytschko_tsay_length({0, 0, 0}, {19, 0, 0}, {19, 8, 0}, {0, 8, 0}), 8.0);
}

// ball_on_wall's controlling trapezoid (element 10002, its geometry here): with its short side 0.29289 the length
// is A / longest diagonal = 0.356159, the reference's printed step 7.0335676e-5 s times sqrt(E / rho); area over
// the longest side would be 0.404917, 14 % more.
TEST(Geometry, BelytschkoTsayLengthIsTheReferences) {
  // Isosceles trapezoid: parallel sides 0.29289 and 0.63638, legs 0.58057.
  const double a = 0.29289255414802967, b = 0.6363798942491131, leg = 0.5805703875893862;
  const double h = std::sqrt(leg * leg - 0.25 * (b - a) * (b - a));
  const Vec3 p1{-0.5 * b, 0, 0}, p2{0.5 * b, 0, 0}, p3{0.5 * a, h, 0}, p4{-0.5 * a, h, 0};
  const double area = 0.5 * (a + b) * h;
  const double diagonal = norm(p3 - p1);
  EXPECT_NEAR(belytschko_tsay_length(p1, p2, p3, p4), area / diagonal, 1e-14);
  EXPECT_NEAR(area / diagonal, 7.0335676261312e-05 * std::sqrt(200000.0 / 0.0078), 1e-5 * area / diagonal);
  EXPECT_LT(belytschko_tsay_length(p1, p2, p3, p4), quad_characteristic_length(p1, p2, p3, p4));
}

// A rhombus at 30 degrees: its shortest side is a, but a wave crosses its height a / 2; the length is bounded by
// the area over the longest side, which is that height.
TEST(Geometry, BelytschkoTsayLengthOfASkewedElementIsItsHeight) {
  const double a = 1.0, s = std::sin(M_PI / 6.0), c = std::cos(M_PI / 6.0);
  const Vec3 p1{0, 0, 0}, p2{a, 0, 0}, p3{a + a * c, a * s, 0}, p4{a * c, a * s, 0};
  EXPECT_NEAR(belytschko_tsay_length(p1, p2, p3, p4), 0.5 * a, 1e-14);
}

}  // namespace
}  // namespace crumple::geometry
