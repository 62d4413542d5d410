// The /RBE3 weighted least-squares system (docs/theory/rigid-bodies.md, RI-1 to RI-4).
#include "crumple/model/interpolation.hpp"

#include <Eigen/Dense>

namespace crumple {

void add_interpolation_node(const Vec3& r, const Vector6& w, Matrix6& a) {
  // X = [[1, -R], [0, 1]] with R v = r x v: X^T W X = [[Wt, -Wt R], [R Wt, -R Wt R + Wr]].
  Eigen::Matrix3d R;
  R << 0.0, -r.z, r.y, r.z, 0.0, -r.x, -r.y, r.x, 0.0;
  const Eigen::Matrix3d wt = Eigen::Vector3d(w[0], w[1], w[2]).asDiagonal();
  Eigen::Matrix<double, 6, 6> block;
  block.topLeftCorner<3, 3>() = wt;
  block.topRightCorner<3, 3>() = -wt * R;
  block.bottomLeftCorner<3, 3>() = R * wt;
  block.bottomRightCorner<3, 3>() = -R * wt * R;
  for (int d = 0; d < 3; ++d) block(3 + d, 3 + d) += w[static_cast<std::size_t>(3 + d)];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) a[static_cast<std::size_t>(6 * i + j)] += block(i, j);
}

Vector6 interpolation_node_load(const Vec3& r, const Vector6& w, const Vector6& q) {
  const Vec3 theta{q[3], q[4], q[5]};
  const Vec3 u = Vec3{q[0], q[1], q[2]} + cross(theta, r);
  return {w[0] * u.x, w[1] * u.y, w[2] * u.z, w[3] * theta.x, w[4] * theta.y, w[5] * theta.z};
}

Vector6 interpolation_node_motion(const Vec3& r, const Vector6& w, const Vector6& y) {
  const Vec3 force{w[0] * y[0], w[1] * y[1], w[2] * y[2]};
  const Vec3 moment = cross(r, force);  // X^T = [[1, 0], [R, 1]]
  return {force.x, force.y, force.z, moment.x + w[3] * y[3], moment.y + w[4] * y[4], moment.z + w[5] * y[5]};
}

InterpolationInverse invert_interpolation(const Matrix6& a) {
  Eigen::Matrix<double, 6, 6> m;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m(i, j) = a[static_cast<std::size_t>(6 * i + j)];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(0.5 * (m + m.transpose()));
  const Eigen::Matrix<double, 6, 1> values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  InterpolationInverse out;
  Eigen::Matrix<double, 6, 1> inverse_values;
  for (int k = 0; k < 6; ++k) {
    const bool held = values(k) > 1e-12 * largest;
    if (!held) out.constrained = false;
    inverse_values(k) = held ? 1.0 / values(k) : 0.0;
  }
  const Eigen::Matrix<double, 6, 6> inverse =
      eigen.eigenvectors() * inverse_values.asDiagonal() * eigen.eigenvectors().transpose();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out.inverse[static_cast<std::size_t>(6 * i + j)] = inverse(i, j);
  return out;
}

Vector6 multiply(const Matrix6& a, const Vector6& v) {
  Vector6 out{};
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) out[i] += a[6 * i + j] * v[j];
  return out;
}

}  // namespace crumple
