#pragma once
// Exact element geometry, one definition for the reader's checks, the mass, the time-step estimate, the contact
// stiffness and the kernels (docs/theory/brick8.md, time-step.md). Plain functions over coordinates, no allocation.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"

namespace crumple::geometry {


// Area of a quadrilateral from its diagonals: A = |d13 x d24| / 2 (exact for a flat quad).
inline double quad_area(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  return 0.5 * norm(cross(p3 - p1, p4 - p2));
}
inline double triangle_area(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return 0.5 * norm(cross(p2 - p1, p3 - p1));
}

// Exact signed volume of an 8-node brick, the integral of det J over the trilinear map (docs/theory/brick8.md,
// eq. B-2), Radioss numbering (1-4 one face, 5-8 the opposite one). Exact also for the degenerate shapes written
// with repeated nodes (prism, pyramid, tetrahedron). Negative for an inverted element.
double brick_volume(const std::array<Vec3, 8>& p);
// The same for the brick with corner nodes `corners` (8 indices) in the coordinate arrays x, y, z (the deck's
// nodes or the current state's).
double brick_volume(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                    const std::int32_t* corners);
// The same from coordinate arrays, with its derivatives dv_dx[I] = dV/dx_I, ... (eq. B-2); the uniform gradient
// of Flanagan and Belytschko is dV/dx_I / V. Returns V.
double brick_volume_gradient(const double* x, const double* y, const double* z, double* dv_dx, double* dv_dy,
                             double* dv_dz);

// Characteristic length of a 4-node shell for the critical time step: L = A / longest side (eq. T-1,
// docs/theory/time-step.md); for a square it is the side.
inline double quad_characteristic_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const double area = quad_area(p1, p2, p3, p4);
  const double longest_side = std::max(std::max(norm(p2 - p1), norm(p3 - p2)),
                                       std::max(norm(p4 - p3), norm(p1 - p4)));
  return area / longest_side;
}
// The Belytschko-Tsay quadrilateral's length (eq. T-1b): the reference's max(shortest side, A / longest
// diagonal), never above T-1's A / longest side [L]. Equal to T-1 on rectangles; below it on trapezoids with one
// short side, where the reference's steps are A / longest diagonal.
inline double belytschko_tsay_length(double area, double shortest_side, double longest_side, double longest_diagonal) {
  return std::min(area / longest_side, std::max(shortest_side, area / longest_diagonal));
}
inline double belytschko_tsay_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const double sides[4] = {norm(p2 - p1), norm(p3 - p2), norm(p4 - p3), norm(p1 - p4)};
  const double longest_diagonal = std::max(norm(p3 - p1), norm(p4 - p2));
  return belytschko_tsay_length(quad_area(p1, p2, p3, p4), *std::min_element(sides, sides + 4),
                                *std::max_element(sides, sides + 4), longest_diagonal);
}
// Triangle: twice the area over the longest side, the smallest height.
inline double triangle_characteristic_length(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const double area = triangle_area(p1, p2, p3);
  const double longest_side = std::max(std::max(norm(p2 - p1), norm(p3 - p2)), norm(p1 - p3));
  return 2.0 * area / longest_side;
}
// Brick: volume over the largest face area.
inline double brick_characteristic_length(const std::array<Vec3, 8>& p) {
  constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double largest = 0.0;
  for (const auto& f : faces) largest = std::max(largest, quad_area(p[f[0]], p[f[1]], p[f[2]], p[f[3]]));
  return largest > 0.0 ? brick_volume(p) / largest : 0.0;
}

}  // namespace crumple::geometry
