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
// A line element's local y at rest (a beam's, BM-0; a beam-type spring's, SP-15): `reference` made normal to the
// element's unit direction `along`, and unit; global X made normal to it where the two are parallel.
inline Vec3 rest_frame_y(const Vec3& along, const Vec3& reference) {
  Vec3 y = reference - scaled(along, dot(along, reference));
  if (norm(y) < 1e-6) y = Vec3{1.0, 0.0, 0.0} - scaled(along, along.x);
  return scaled(y, 1.0 / norm(y));
}

inline double quad_area(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  return 0.5 * norm(cross(p3 - p1, p4 - p2));
}
inline double triangle_area(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return 0.5 * norm(cross(p2 - p1, p3 - p1));
}

// The share of a triangle's mass and rotational inertia each corner takes: its interior angle over pi (the
// reference solver's lumping of the 3-node shell, docs/theory/shell4.md, eq. S-9c); the three add up to 1. A
// degenerate triangle (a side of zero length) shares equally.
inline std::array<double, 3> triangle_corner_fractions(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 p[3] = {p1, p2, p3};
  std::array<double, 3> f{};
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const Vec3 u = p[(a + 1) % 3] - p[a], v = p[(a + 2) % 3] - p[a];
    f[static_cast<std::size_t>(a)] = std::atan2(norm(cross(u, v)), dot(u, v));
    sum += f[static_cast<std::size_t>(a)];
  }
  if (!(sum > 0.0)) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  for (double& x : f) x /= sum;
  return f;
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

// det J of the trilinear map at the natural point (r, s, t) of the cube [-1, 1]^3 (8 det J(0) is the one-point
// volume estimate; the 2x2x2 points sit at +-1/sqrt(3)).
double brick_jacobian(const double* x, const double* y, const double* z, double r, double s, double t);
// The one-point volume estimate 8 det J(0): the exact volume for a parallelepiped and a prism, 3/4 of it for a
// tetrahedron or a pyramid written as a brick (docs/theory/brick8.md, "Degenerate bricks").
inline double one_point_volume(const double* x, const double* y, const double* z) {
  return 8.0 * brick_jacobian(x, y, z, 0.0, 0.0, 0.0);
}
// Whether an 8-node connectivity repeats a node (a degenerate brick).
inline bool repeats_a_node(const std::int32_t* nodes) {
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      if (nodes[a] == nodes[b]) return true;
  return false;
}
// The smallest det J over the 2x2x2 Gauss points.
double smallest_point_jacobian(const double* x, const double* y, const double* z);
// The characteristic length of a fully integrated (2x2x2) brick (docs/theory/brick8.md, eq. B-12a): 8 times the
// smallest point's det J over the largest |m_a x m_b|, m_a the three vectors between the centroids of opposite
// faces. V / (largest face area) for a parallelepiped; far shorter for a degenerate brick, whose smallest point
// volume is small (the reference's rule, measured on prisms of several shapes).
double full_integration_length(const double* x, const double* y, const double* z, double smallest_point_det);

// Characteristic length of a 4-node shell for the critical time step: L = A / longest side (eq. T-1,
// docs/theory/time-step.md); for a square it is the side.
inline double quad_characteristic_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const double area = quad_area(p1, p2, p3, p4);
  const double longest_side = std::max(std::max(norm(p2 - p1), norm(p3 - p2)),
                                       std::max(norm(p4 - p3), norm(p1 - p4)));
  return area / longest_side;
}
// The Belytschko-Tsay quadrilateral's length (eq. T-1b): the reference's max(shortest side, A / longest diagonal),
// the sides in the element's plane (normal to the diagonals' cross product), A half that product's norm [L].
// Equal to T-1 on rectangles; below it on trapezoids with one short side, where the reference's steps are
// A / longest diagonal; on a folded (warped) element its sides' projections are short and A / longest diagonal
// holds (measured on the reference's deformed shells, docs/theory/time-step.md).
inline double belytschko_tsay_length(double area, double shortest_side, double longest_diagonal) {
  return std::max(shortest_side, area / longest_diagonal);
}
inline double belytschko_tsay_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 normal = cross(p3 - p1, p4 - p2);
  const Vec3 n = scaled(normal, 1.0 / norm(normal));
  const Vec3 corners[4] = {p1, p2, p3, p4};
  double shortest = 1e300;
  for (int a = 0; a < 4; ++a) {
    const Vec3 side = corners[(a + 1) % 4] - corners[a];
    shortest = std::min(shortest, norm(side - scaled(n, dot(side, n))));
  }
  return belytschko_tsay_length(0.5 * norm(normal), shortest, std::max(norm(p3 - p1), norm(p4 - p2)));
}
// The Belytschko-Tsay quadrilateral's length under /DT/NODA/CST (eq. T-2a): sqrt(2) A / longest diagonal [L]; a
// square's side, a 10 x 2 rectangle's 2.77 (T-1b: 2).
inline double belytschko_tsay_nodal_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  return std::sqrt(2.0) * quad_area(p1, p2, p3, p4) / std::max(norm(p3 - p1), norm(p4 - p2));
}
// Triangle: twice the area over the longest side, the smallest height.
inline double triangle_characteristic_length(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const double area = triangle_area(p1, p2, p3);
  const double longest_side = std::max(std::max(norm(p2 - p1), norm(p3 - p2)), norm(p1 - p3));
  return 2.0 * area / longest_side;
}
// The QEPH shell's (Ishell 24) characteristic length [L] (docs/theory/time-step.md, eq. T-1d): the reference's
// A / sqrt(2 f_ar f_sk (5/4 + w) D^2 / 4), D the longest diagonal, f_ar = 1 + min(1/2, (c_max / c_min - 1) / 4) on
// the two mid-line lengths c, f_sk = 0.78 + 0.22 (3.413 max(0, s - 0.7071))^3 on the sine s = 4 A / (c_1 c_2) of
// their angle, w = max(|x2 x y4|, |x1 x y3|) / A the taper (0 for a parallelogram). lx, ly from the centroid.
inline double qeph_length(const double* lx, const double* ly, double area) {
  const double d13 = (lx[0] - lx[2]) * (lx[0] - lx[2]) + (ly[0] - ly[2]) * (ly[0] - ly[2]);
  const double d24 = (lx[1] - lx[3]) * (lx[1] - lx[3]) + (ly[1] - ly[3]) * (ly[1] - ly[3]);
  const double half_diagonal2 = 0.25 * std::max(d13, d24);
  const double c1 = std::hypot(lx[1] + lx[2] - lx[3] - lx[0], ly[1] + ly[2] - ly[3] - ly[0]);
  const double c2 = std::hypot(lx[2] + lx[3] - lx[1] - lx[0], ly[2] + ly[3] - ly[1] - ly[0]);
  const double aspect = 1.0 + std::min(0.5, (std::max(c1, c2) / std::min(c1, c2) - 1.0) / 4.0);
  const double skew_term = 3.413 * std::max(0.0, 4.0 * area / (c1 * c2) - 0.7071);
  const double skew = 0.78 + 0.22 * skew_term * skew_term * skew_term;
  const double taper = std::max(std::abs(lx[1] * ly[3] - ly[1] * lx[3]), std::abs(lx[0] * ly[2] - ly[0] * lx[2])) / area;
  return area / std::sqrt(2.0 * aspect * skew * (1.25 + taper) * half_diagonal2);
}

// The same from the corners: the plane of the diagonals, coordinates from the centroid.
inline double qeph_length(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 normal = cross(p3 - p1, p4 - p2);
  const double n = norm(normal);
  if (!(n > 0.0)) return 0.0;
  const Vec3 e3 = scaled(normal, 1.0 / n), side = p2 - p1;
  const Vec3 e1 = unit(side - scaled(e3, dot(side, e3))), e2 = cross(e3, e1);
  const Vec3 centre = scaled(p1 + p2 + p3 + p4, 0.25);
  const Vec3 p[4] = {p1, p2, p3, p4};
  double lx[4], ly[4];
  for (int a = 0; a < 4; ++a) lx[a] = dot(p[a] - centre, e1), ly[a] = dot(p[a] - centre, e2);
  return qeph_length(lx, ly, 0.5 * n);
}

// Brick: volume over the largest face area.
inline double brick_characteristic_length(const std::array<Vec3, 8>& p) {
  constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double largest = 0.0;
  for (const auto& f : faces) largest = std::max(largest, quad_area(p[f[0]], p[f[1]], p[f[2]], p[f[3]]));
  return largest > 0.0 ? brick_volume(p) / largest : 0.0;
}

}  // namespace crumple::geometry
