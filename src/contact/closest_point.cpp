// Closest point of a segment to a node (docs/theory/contact.md, eq. C-1).
#include <cmath>

#include "crumple/contact/kernels.hpp"

namespace crumple::contact {
namespace {

// Closest point of triangle (a, b, c) to p, as barycentric weights (wa, wb, wc): the Voronoi regions of the
// corners, the edges and the face, in that order.
void closest_on_triangle(const double p[3], const double a[3], const double b[3], const double c[3], double w[3]) {
  double ab[3], ac[3], ap[3];
  for (int k = 0; k < 3; ++k) ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = p[k] - a[k];
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) { w[0] = 1, w[1] = 0, w[2] = 0; return; }  // corner a
  double bp[3];
  for (int k = 0; k < 3; ++k) bp[k] = p[k] - b[k];
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) { w[0] = 0, w[1] = 1, w[2] = 0; return; }  // corner b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
    const double v = d1 / (d1 - d3);
    w[0] = 1.0 - v, w[1] = v, w[2] = 0.0;
    return;
  }
  double cp[3];
  for (int k = 0; k < 3; ++k) cp[k] = p[k] - c[k];
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) { w[0] = 0, w[1] = 0, w[2] = 1; return; }  // corner c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
    const double v = d2 / (d2 - d6);
    w[0] = 1.0 - v, w[1] = 0.0, w[2] = v;
    return;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge bc
    const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    w[0] = 0.0, w[1] = 1.0 - v, w[2] = v;
    return;
  }
  const double denominator = 1.0 / (va + vb + vc);  // face
  w[1] = vb * denominator, w[2] = vc * denominator, w[0] = 1.0 - w[1] - w[2];
}

}  // namespace

SegmentPoint closest_point_on_segment(const double node[3], const double x[4][3], bool triangle) {
  SegmentPoint best{{0, 0, 0}, {0, 0, 0, 0}, std::numeric_limits<double>::infinity()};
  auto consider = [&](const double* a, const double* b, const double* c, const double wa[4], const double wb[4],
                      const double wc[4]) {
    double w[3];
    closest_on_triangle(node, a, b, c, w);
    double q[3], d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      q[k] = w[0] * a[k] + w[1] * b[k] + w[2] * c[k];
      d2 += (node[k] - q[k]) * (node[k] - q[k]);
    }
    const double d = std::sqrt(d2);
    if (d < best.distance) {
      best.distance = d;
      for (int k = 0; k < 3; ++k) best.point[k] = q[k];
      for (int n = 0; n < 4; ++n) best.weight[n] = w[0] * wa[n] + w[1] * wb[n] + w[2] * wc[n];
    }
  };
  static constexpr double unit[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  if (triangle) {
    consider(x[0], x[1], x[2], unit[0], unit[1], unit[2]);
    return best;
  }
  // Four triangles (corner a, corner a+1, centroid); the centroid carries a quarter to each node.
  static constexpr double quarter[4] = {0.25, 0.25, 0.25, 0.25};
  double centre[3];
  for (int k = 0; k < 3; ++k) centre[k] = 0.25 * (x[0][k] + x[1][k] + x[2][k] + x[3][k]);
  for (int a = 0; a < 4; ++a) consider(x[a], x[(a + 1) % 4], centre, unit[a], unit[(a + 1) % 4], quarter);
  return best;
}

}  // namespace crumple::contact
