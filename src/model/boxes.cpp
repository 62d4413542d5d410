// Box membership (docs/deck-format.md, "Boxes"): the measured rules of the reference, surfaces inside.
#include "crumple/model/boxes.hpp"

#include <algorithm>

namespace crumple {
namespace {

// Between the two corners along each axis of the box's frame (global, or the skew's: both corners and the point are
// projected on its axes, so the skew's origin plays no part).
bool in_rectangle(const Box& b, Vec3 p) {
  const Vec3 c1 = to_skew(b.axes, b.points[0]), c2 = to_skew(b.axes, b.points[1]), q = to_skew(b.axes, p);
  for (std::size_t k = 0; k < 3; ++k)
    if (q[k] < std::min(c1[k], c2[k]) || q[k] > std::max(c1[k], c2[k])) return false;
  return true;
}

// Within D/2 of the axis and between the planes through its two ends normal to it.
bool in_cylinder(const Box& b, Vec3 p) {
  const Vec3 axis = b.points[1] - b.points[0], d = p - b.points[0];
  const double length2 = dot(axis, axis), along = dot(d, axis);
  if (along < 0.0 || along > length2) return false;
  const double radius = 0.5 * b.diameter;
  return dot(d, d) - along * along / length2 <= radius * radius;
}

bool in_sphere(const Box& b, Vec3 p) {
  const Vec3 d = p - b.points[0];
  const double radius = 0.5 * b.diameter;
  return dot(d, d) <= radius * radius;
}

}  // namespace

bool box_contains(const std::vector<Box>& boxes, std::size_t box, Vec3 p) {
  const Box& b = boxes[box];
  switch (b.shape) {
    case BoxShape::Rectangle: return in_rectangle(b, p);
    case BoxShape::Cylinder: return in_cylinder(b, p);
    case BoxShape::Sphere: return in_sphere(b, p);
    case BoxShape::Combination: break;
  }
  const auto contains = [&](std::int32_t k) { return box_contains(boxes, static_cast<std::size_t>(k), p); };
  return std::any_of(b.added.begin(), b.added.end(), contains) &&
         std::none_of(b.removed.begin(), b.removed.end(), contains);
}

}  // namespace crumple
