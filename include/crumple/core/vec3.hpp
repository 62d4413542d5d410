#pragma once
// The one 3-vector of Crumple: a position, a velocity, a force, an axis of a frame. Plain values with inline
// operations, so that kernels keep them in registers. Hot data is never stored as Vec3 but as structures of
// arrays (x[], y[], z[]); a Vec3 is what a kernel gathers from them.
#include <cmath>
#include <cstddef>

namespace crumple {

struct Vec3 {
  double x, y, z;

  // Component k (0 x, 1 y, 2 z), for loops over the three directions.
  double& operator[](std::size_t k) { return k == 0 ? x : k == 1 ? y : z; }
  double operator[](std::size_t k) const { return k == 0 ? x : k == 1 ? y : z; }
  bool operator==(const Vec3&) const = default;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 scaled(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 unit(Vec3 a) { return scaled(a, 1.0 / norm(a)); }
// `a` turned by the rotation vector phi (Rodrigues): a cos t + (k x a) sin t + k (k . a)(1 - cos t), t = |phi|, k = phi / t.
inline Vec3 rotated(Vec3 a, Vec3 phi) {
  const double t = norm(phi);
  if (t < 1e-300) return a;
  const Vec3 k = scaled(phi, 1.0 / t);
  return scaled(a, std::cos(t)) + scaled(cross(k, a), std::sin(t)) + scaled(k, dot(k, a) * (1.0 - std::cos(t)));
}

}  // namespace crumple
