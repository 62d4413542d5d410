#pragma once
// Skew systems (/SKEW/FIX, /SKEW/MOV, /SKEW/MOV2): local axes in which a condition, a load, an initial velocity or a
// time history is written. A fixed skew keeps the axes of its card; a moving one is made again each cycle from the
// current positions of its three nodes (docs/theory/skews.md, SK-1 to SK-3). A skew has axes only: a vector is
// written in it by projection on them, a position is not taken relative to an origin (SK-4).
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/core/vec3.hpp"

namespace crumple {

enum class SkewKind : std::uint8_t { Fixed, Moving };

struct Skew {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  SkewKind kind = SkewKind::Fixed;
  // /SKEW/FIX: the origin [L] (read from input version 120 on, no effect on the axes), the direction of Y' and a
  // direction in the Y'Z' plane (eq. SK-1).
  Vec3 origin{}, y_direction{}, z_direction{};
  // /SKEW/MOV, /SKEW/MOV2: N1 (origin), N2 (N1 to N2 is the first axis), N3 (N1 to N3 lies in the plane of the
  // first and second axes); `first_axis` 0 X, 1 Y, 2 Z (Dir of /SKEW/MOV; /SKEW/MOV2 is Z) (eq. SK-2).
  std::int64_t node_ids[3] = {0, 0, 0};
  std::int32_t nodes[3] = {-1, -1, -1};  // dense indices (model build)
  int first_axis = 0;
};

// The local axes X', Y', Z' as unit vectors in global components: v_local[i] = dot(axis[i], v_global).
struct SkewAxes {
  Vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
};

// Right-handed orthonormal axes whose axis `first` points along `along` and whose next axis (first + 1 mod 3) lies in
// the plane of `along` and `in_plane` (eq. SK-2). Both directions must be non-zero and not parallel.
SkewAxes axes_from_directions(int first, Vec3 along, Vec3 in_plane);

// The axes of a skew: fixed from its card, moving from its nodes' positions (x, y, z indexed by dense node index).
SkewAxes skew_axes(const Skew& skew, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& z);

// Whether the skew's two directions span a plane (not zero, not parallel), with the positions given.
bool skew_is_defined(const Skew& skew, const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<double>& z);

inline Vec3 to_skew(const SkewAxes& a, Vec3 v) { return {dot(a.axis[0], v), dot(a.axis[1], v), dot(a.axis[2], v)}; }
inline Vec3 to_global(const SkewAxes& a, Vec3 local) {
  return scaled(a.axis[0], local.x) + scaled(a.axis[1], local.y) + scaled(a.axis[2], local.z);
}
// v with its component along the unit axis e set to `value`, the others kept (eq. SK-5).
inline Vec3 with_component(Vec3 v, Vec3 e, double value) { return v + scaled(e, value - dot(v, e)); }

}  // namespace crumple
