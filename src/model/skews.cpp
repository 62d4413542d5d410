// The axes of fixed and moving skews (docs/theory/skews.md, SK-1 and SK-2).
#include "crumple/model/skews.hpp"

#include <cstddef>

namespace crumple {
namespace {

Vec3 position(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
              std::int32_t node) {
  const auto k = static_cast<std::size_t>(node);
  return {x[k], y[k], z[k]};
}

// The two directions that define the skew: (along, in_plane) and the axis `along` gives.
struct Directions {
  Vec3 along, in_plane;
  int first;
};

Directions directions_of(const Skew& s, const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& z) {
  if (s.kind == SkewKind::Fixed) return {s.y_direction, s.z_direction, 1};  // SK-1: Y' exact, Z' in the plane
  const Vec3 n1 = position(x, y, z, s.nodes[0]);
  return {position(x, y, z, s.nodes[1]) - n1, position(x, y, z, s.nodes[2]) - n1, s.first_axis};
}

}  // namespace

SkewAxes axes_from_directions(int first, Vec3 along, Vec3 in_plane) {
  const int second = (first + 1) % 3, third = (first + 2) % 3;
  SkewAxes a;
  a.axis[first] = unit(along);
  a.axis[third] = unit(cross(a.axis[first], in_plane));
  a.axis[second] = cross(a.axis[third], a.axis[first]);
  return a;
}

SkewAxes skew_axes(const Skew& skew, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& z) {
  const Directions d = directions_of(skew, x, y, z);
  return axes_from_directions(d.first, d.along, d.in_plane);
}

bool skew_is_defined(const Skew& skew, const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<double>& z) {
  const Directions d = directions_of(skew, x, y, z);
  const double a = norm(d.along), b = norm(d.in_plane);
  // |a x b| = |a| |b| sin(angle): a zero or tiny angle leaves no plane.
  return a > 0.0 && b > 0.0 && norm(cross(d.along, d.in_plane)) > 1e-8 * a * b;
}

}  // namespace crumple
