#pragma once
// The /RBE3 system (docs/theory/rigid-bodies.md, RI-1 to RI-3): the dependent node's rigid motion q = (u, theta)
// that fits its independent nodes' motion in the weighted least-squares sense, A q = sum X_i^T W_i y_i, with
// X_i q = (u + theta x r_i, theta) the motion q gives node i at r_i = x_i - x_d, W_i its dof weights.
#include <array>

#include "crumple/core/vec3.hpp"

namespace crumple {

using Matrix6 = std::array<double, 36>;  // row-major
using Vector6 = std::array<double, 6>;   // x y z rx ry rz

// A += X_i^T W_i X_i for a node at r from the dependent node, with weights w (the rotational ones already scaled by
// the characteristic length squared, RI-2).
void add_interpolation_node(const Vec3& r, const Vector6& w, Matrix6& a);
// W_i X_i q: the force and moment node i takes from the dependent node's load solve q = A^-1 (F, M) (RI-3).
Vector6 interpolation_node_load(const Vec3& r, const Vector6& w, const Vector6& q);
// X_i^T W_i y: node i's share of the right-hand side of the dependent node's motion, y = (v_i, w_i) (RI-4).
Vector6 interpolation_node_motion(const Vec3& r, const Vector6& w, const Vector6& y);

// A^-1 of a symmetric positive semi-definite A; `constrained` is false when A has a direction of (relatively) zero
// weight, a motion of the dependent node that its independent nodes do not hold. The inverse then leaves it out
// (pseudo-inverse).
struct InterpolationInverse {
  Matrix6 inverse{};
  bool constrained = true;
};
InterpolationInverse invert_interpolation(const Matrix6& a);
Vector6 multiply(const Matrix6& a, const Vector6& v);

}  // namespace crumple
