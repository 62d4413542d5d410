// Where each node of a tied interface sits on the main surface (docs/theory/tied-interfaces.md, TI-1, TI-2).
#include "crumple/model/ties.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/core/vec3.hpp"
#include "crumple/model/model.hpp"

namespace crumple {
namespace {

bool is_triangle(const Segment& seg) { return seg.nodes[3] == seg.nodes[2]; }


// Bilinear shape functions of the 4-node segment at (s, t), nodes at (-1,-1), (1,-1), (1,1), (-1,1) (eq. TI-1).
std::array<double, 4> quad_weights(double s, double t) {
  return {0.25 * (1 - s) * (1 - t), 0.25 * (1 + s) * (1 - t), 0.25 * (1 + s) * (1 + t), 0.25 * (1 - s) * (1 + t)};
}

Vec3 at(const std::array<Vec3, 4>& x, const std::array<double, 4>& w) {
  return scaled(x[0], w[0]) + scaled(x[1], w[1]) + scaled(x[2], w[2]) + scaled(x[3], w[3]);
}

// The point of the quadrilateral nearest to p: Gauss-Newton on |x(s, t) - p|^2 from the centre, (s, t) kept in
// [-1, 1]^2 (a point off the segment's edge is tied to its edge).
Tie project_on_quad(const std::array<Vec3, 4>& x, Vec3 p) {
  double s = 0.0, t = 0.0;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec3 xs = scaled(scaled(x[1] - x[0], 1 - t) + scaled(x[2] - x[3], 1 + t), 0.25);
    const Vec3 xt = scaled(scaled(x[3] - x[0], 1 - s) + scaled(x[2] - x[1], 1 + s), 0.25);
    const Vec3 r = p - at(x, quad_weights(s, t));
    const double a = dot(xs, xs), b = dot(xs, xt), c = dot(xt, xt), det = a * c - b * b;
    if (!(det > 0.0)) break;
    const double ds = (c * dot(xs, r) - b * dot(xt, r)) / det, dt = (a * dot(xt, r) - b * dot(xs, r)) / det;
    const double s_next = std::clamp(s + ds, -1.0, 1.0), t_next = std::clamp(t + dt, -1.0, 1.0);
    const bool settled = std::abs(s_next - s) < 1e-13 && std::abs(t_next - t) < 1e-13;
    s = s_next, t = t_next;
    if (settled) break;
  }
  Tie tie;
  tie.s = s, tie.t = t, tie.weight = quad_weights(s, t);
  tie.distance = norm(p - at(x, tie.weight));
  return tie;
}

// The triangle's point nearest to p, by its area coordinates kept non-negative; (s, t) are the second and third.
Tie project_on_triangle(const std::array<Vec3, 4>& x, Vec3 p) {
  const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0], r = p - x[0];
  const double a = dot(e1, e1), b = dot(e1, e2), c = dot(e2, e2), det = a * c - b * b;
  double l1 = det > 0.0 ? (c * dot(e1, r) - b * dot(e2, r)) / det : 0.0;
  double l2 = det > 0.0 ? (a * dot(e2, r) - b * dot(e1, r)) / det : 0.0;
  l1 = std::max(l1, 0.0), l2 = std::max(l2, 0.0);
  if (l1 + l2 > 1.0) l1 /= l1 + l2, l2 = 1.0 - l1;
  Tie tie;
  tie.s = l1, tie.t = l2, tie.weight = {1.0 - l1 - l2, l1, l2, 0.0};
  tie.distance = norm(p - at(x, tie.weight));
  return tie;
}

std::array<Vec3, 4> corners(const Model& m, const Segment& seg) {
  std::array<Vec3, 4> x;
  for (std::size_t a = 0; a < 4; ++a) x[a] = m.nodes.position(seg.nodes[a]);
  return x;
}

// The default search distance (eq. TI-2): the root mean square of the main segments' edges, four per segment (a
// triangle's fourth, from its third node to itself, is 0). Measured on the reference; its manual says "the mean size".
double mean_segment_size(const Model& m, const std::vector<Segment>& segments) {
  if (segments.empty()) return 0.0;
  double sum = 0.0;
  for (const Segment& seg : segments) {
    const std::array<Vec3, 4> x = corners(m, seg);
    for (std::size_t a = 0; a < 4; ++a) {
      const Vec3 edge = x[(a + 1) % 4] - x[a];
      sum += dot(edge, edge);
    }
  }
  return std::sqrt(sum / (4.0 * static_cast<double>(segments.size())));
}

}  // namespace

TieSearch find_ties(const Model& m, const Type2Interface& in) {
  TieSearch out;
  if (in.secondary_group < 0 || in.main_surface < 0) return out;
  const std::vector<Segment>& segments = m.surfaces[static_cast<std::size_t>(in.main_surface)].segments;
  out.search_distance = in.dsearch > 0.0 ? in.dsearch : mean_segment_size(m, segments);
  for (std::int32_t node : m.node_groups[static_cast<std::size_t>(in.secondary_group)].nodes) {
    const Vec3 p = m.nodes.position(node);
    Tie best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const Segment& seg = segments[k];
      if (std::find(seg.nodes.begin(), seg.nodes.end(), node) != seg.nodes.end()) continue;  // not to itself
      const std::array<Vec3, 4> x = corners(m, seg);
      const Tie tie = is_triangle(seg) ? project_on_triangle(x, p) : project_on_quad(x, p);
      if (tie.distance < best.distance) best = tie, best.segment = static_cast<std::int32_t>(k), best.main = seg.nodes;
    }
    if (best.segment < 0 || best.distance > out.search_distance) {
      out.unmatched.push_back(node);
      continue;
    }
    best.node = node;
    out.ties.push_back(best);
  }
  return out;
}

std::vector<const Tie*> ties_by_node(const Model& m) {
  std::vector<const Tie*> by_node(m.nodes.size(), nullptr);
  for (const Type2Interface& in : m.type2_interfaces)
    for (const Tie& tie : in.ties) by_node[static_cast<std::size_t>(tie.node)] = &tie;
  return by_node;
}

}  // namespace crumple
