// Characteristic lengths of the shell time step (docs/theory/time-step.md, eqs. T-1, T-1b, T-1d) and the
// triangle's mass shares (docs/theory/shell4.md, eq. S-9c).
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/core/geometry.hpp"

namespace crumple::geometry::test_geometry {
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

// A rhombus at 30 degrees: its shortest side a, as the reference takes it (its height a / 2 is not the length:
// measured on the reference's deformed shells, the welded rail of docs/theory/time-step.md).
TEST(Geometry, BelytschkoTsayLengthOfASkewedElementIsItsShortestSide) {
  const double a = 1.0, s = std::sin(M_PI / 6.0), c = std::cos(M_PI / 6.0);
  const Vec3 p1{0, 0, 0}, p2{a, 0, 0}, p3{a + a * c, a * s, 0}, p4{a * c, a * s, 0};
  EXPECT_NEAR(belytschko_tsay_length(p1, p2, p3, p4), a, 1e-14);
}

// SHELL 2666 of the welded rail (docs/theory/time-step.md, T-1b), folded: its corners as the reference's /TH/NODE
// gave them at 2 ms; the reference's step there is 1.4955 mm over sqrt(E / rho) / 0.9, its A / longest diagonal
// (the sides in its plane are shorter: 1.39 mm).
TEST(Geometry, BelytschkoTsayLengthOfAFoldedElementIsTheReferences) {
  const Vec3 p1{-25.26, -11.62, 1.66}, p2{-20.22, -6.39, 1.38}, p3{-20.04, -8.97, 3.81}, p4{-24.95, -7.39, 2.56};
  const double area = 0.5 * norm(cross(p3 - p1, p4 - p2));
  EXPECT_NEAR(belytschko_tsay_length(p1, p2, p3, p4), area / std::max(norm(p3 - p1), norm(p4 - p2)), 1e-12);
  EXPECT_NEAR(belytschko_tsay_length(p1, p2, p3, p4), 1.4955, 0.003);
}

// The QEPH length (eq. T-1d) on eight single elements, against the steps the reference solver's starter printed
// for them (generate_probe.py mode --corners ..., /MAT/ELAST steel E 210, rho 7.85e-6, dn 0.015: its step is
// L (sqrt(1 + dn^2) - dn) / sqrt(E / rho), eq. T-1c). Squares 2:1 and 4:1, two parallelograms, a trapezoid,
// two warped squares and a rectangle with one short side: aspect, skew, taper and warp, to 6 digits.
TEST(Geometry, QephLengthIsTheReferences) {
  struct Case {
    Vec3 p[4];
    double step;
  };
  const Case cases[] = {
      {{{0, 0, 0}, {10, 0, 0}, {10, 5, 0}, {0, 5, 0}}, 9.6378151793608e-04},
      {{{0, 0, 0}, {20, 0, 0}, {20, 5, 0}, {0, 5, 0}}, 9.5428590195074e-04},
      {{{0, 0, 0}, {5, 0, 0}, {7, 5, 0}, {2, 5, 0}}, 7.4143986959001e-04},
      {{{0, 0, 0}, {5, 0, 0}, {9, 5, 0}, {4, 5, 0}}, 6.3886912782992e-04},
      {{{0, 0, 0}, {6, 0, 0}, {4, 5, 0}, {2, 5, 0}}, 6.6650218474819e-04},
      {{{0, 0, 0}, {5, 0, 0}, {5, 5, 0.5}, {0, 5, 0}}, 8.5102716832952e-04},
      {{{0, 0, 0}, {5, 0, 0}, {5, 5, 1.5}, {0, 5, 0}}, 8.4485745916379e-04},
      {{{0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {0, 8, 0}}, 8.0460255509106e-04},
  };
  const double c = std::sqrt(210.0 / 7.85e-6), damping = std::sqrt(1.0 + 0.015 * 0.015) - 0.015;
  for (const Case& k : cases) {
    const double step = qeph_length(k.p[0], k.p[1], k.p[2], k.p[3]) * damping / c;
    EXPECT_NEAR(step, k.step, 2e-6 * k.step);
  }
  // A square of side a: 0.894 a (the 5/4 of T-1d; f_sk is 0.9998 there, not 1, with the reference's rounded
  // constants 3.413 and 0.7071), whatever its frame.
  EXPECT_NEAR(qeph_length({0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {0, 5, 0}), 5.0 / std::sqrt(1.25), 2e-4 * 5.0);
}

// The corner-angle shares of a triangle's mass (docs/theory/shell4.md, eq. S-9c): a right isosceles triangle gives
// its right-angled corner a half and each other corner a quarter.
TEST(Geometry, TriangleCornerFractionsAreTheAnglesOverPi) {
  const auto f = triangle_corner_fractions({0, 0, 0}, {5, 0, 0}, {0, 5, 0});
  EXPECT_NEAR(f[0], 0.5, 1e-14);
  EXPECT_NEAR(f[1], 0.25, 1e-14);
  EXPECT_NEAR(f[2], 0.25, 1e-14);
}

}  // namespace
}  // namespace crumple::geometry::test_geometry
