// Exact brick volume (docs/theory/brick8.md, eq. B-2): one definition for the reader's checks, the mass, the
// time-step estimate, the contact stiffness and the brick kernels.
#include "crumple/core/geometry.hpp"

#include <algorithm>
#include <limits>

namespace crumple::geometry {
namespace {

// Exact volume (eq. B-2): V = sum over I < J < K of c_IJK x_I . (x_J x x_K) / 12 with integer c_IJK, so that
// dV/dx_I = sum_{J<K} c_IJK (x_J x x_K) / 12. kPairs lists the 24 node pairs (J, K) that occur (every pair but the
// four body diagonals); kVolumeTerms[I] the nine (pair, c) of node I.
constexpr int kPairs[24][2] = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}, {0, 7}, {1, 2}, {1, 3},
                               {1, 4}, {1, 5}, {1, 6}, {2, 3}, {2, 5}, {2, 6}, {2, 7}, {3, 4},
                               {3, 6}, {3, 7}, {4, 5}, {4, 6}, {4, 7}, {5, 6}, {5, 7}, {6, 7}};
constexpr int kVolumeTerms[8][9][2] = {
    {{6, -1}, {7, -1}, {8, 1}, {9, 1}, {11, -1}, {15, -1}, {17, -1}, {18, -1}, {20, 1}},
    {{1, 1}, {2, 1}, {3, -1}, {4, -1}, {11, -1}, {12, 1}, {13, 1}, {18, -1}, {21, -1}},
    {{0, -1}, {2, 1}, {7, 1}, {9, -1}, {10, -1}, {16, 1}, {17, 1}, {21, -1}, {23, -1}},
    {{0, -1}, {1, -1}, {3, 1}, {5, 1}, {6, -1}, {13, -1}, {14, -1}, {20, 1}, {23, -1}},
    {{0, 1}, {2, -1}, {4, 1}, {5, -1}, {9, 1}, {17, -1}, {21, 1}, {22, 1}, {23, 1}},
    {{0, 1}, {3, -1}, {6, 1}, {8, -1}, {10, 1}, {13, 1}, {19, -1}, {20, -1}, {23, 1}},
    {{6, 1}, {9, -1}, {11, 1}, {12, -1}, {14, 1}, {17, 1}, {18, 1}, {20, -1}, {22, -1}},
    {{2, -1}, {3, 1}, {11, 1}, {13, -1}, {15, 1}, {16, -1}, {18, 1}, {19, 1}, {21, 1}}};

}  // namespace

double brick_volume_gradient(const double* x, const double* y, const double* z, double* dv_dx, double* dv_dy,
                             double* dv_dz) {
  double cx[24], cy[24], cz[24];
  for (int k = 0; k < 24; ++k) {
    const int j = kPairs[k][0], l = kPairs[k][1];
    cx[k] = y[j] * z[l] - z[j] * y[l];
    cy[k] = z[j] * x[l] - x[j] * z[l];
    cz[k] = x[j] * y[l] - y[j] * x[l];
  }
  double volume = 0.0;
  for (int i = 0; i < 8; ++i) {
    double bx = 0.0, by = 0.0, bz = 0.0;
    for (const auto& t : kVolumeTerms[i]) {
      const double c = t[1];
      bx += c * cx[t[0]], by += c * cy[t[0]], bz += c * cz[t[0]];
    }
    dv_dx[i] = bx / 12.0, dv_dy[i] = by / 12.0, dv_dz[i] = bz / 12.0;
    // V is linear in each of the x, y and z coordinate vectors: V = sum x_I dV/dx_I (= same with y, z).
    volume += x[i] * dv_dx[i] + y[i] * dv_dy[i] + z[i] * dv_dz[i];
  }
  return volume / 3.0;
}

double brick_jacobian(const double* x, const double* y, const double* z, double r, double s, double t) {
  constexpr double kR[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, kS[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                   kT[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  double j[3][3] = {};  // j[i][k] = dx_i / dxi_k
  for (int a = 0; a < 8; ++a) {
    const double d[3] = {0.125 * kR[a] * (1 + kS[a] * s) * (1 + kT[a] * t), 0.125 * kS[a] * (1 + kR[a] * r) * (1 + kT[a] * t),
                         0.125 * kT[a] * (1 + kR[a] * r) * (1 + kS[a] * s)};
    for (int k = 0; k < 3; ++k) j[0][k] += x[a] * d[k], j[1][k] += y[a] * d[k], j[2][k] += z[a] * d[k];
  }
  return j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
}

double smallest_point_jacobian(const double* x, const double* y, const double* z) {
  constexpr double g = 0.57735026918962576451;  // 1 / sqrt(3)
  double smallest = std::numeric_limits<double>::infinity();
  for (double r : {-g, g})
    for (double s : {-g, g})
      for (double t : {-g, g}) smallest = std::min(smallest, brick_jacobian(x, y, z, r, s, t));
  return smallest;
}

double full_integration_length(const double* x, const double* y, const double* z, double smallest_point_det) {
  // m_a: centroid of one face minus centroid of the opposite one (faces 1234 / 5678, 1256 / 3478, 1458 / 2367).
  constexpr int kSide[3][4] = {{0, 1, 2, 3}, {0, 1, 4, 5}, {0, 3, 4, 7}};
  constexpr int kOpposite[3][4] = {{4, 5, 6, 7}, {2, 3, 6, 7}, {1, 2, 5, 6}};
  Vec3 m[3];
  for (int a = 0; a < 3; ++a) {
    m[a] = {};
    for (int k = 0; k < 4; ++k) {
      const int i = kSide[a][k], o = kOpposite[a][k];
      m[a] = m[a] + Vec3{0.25 * (x[i] - x[o]), 0.25 * (y[i] - y[o]), 0.25 * (z[i] - z[o])};
    }
  }
  const double largest = std::max({norm(cross(m[0], m[1])), norm(cross(m[0], m[2])), norm(cross(m[2], m[1]))});
  return largest > 0.0 ? 8.0 * smallest_point_det / largest : 0.0;
}

double brick_volume(const std::array<Vec3, 8>& p) {
  double x[8], y[8], z[8], bx[8], by[8], bz[8];
  for (std::size_t a = 0; a < 8; ++a) x[a] = p[a].x, y[a] = p[a].y, z[a] = p[a].z;
  return brick_volume_gradient(x, y, z, bx, by, bz);
}

double brick_volume(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                    const std::int32_t* corners) {
  std::array<Vec3, 8> p;
  for (std::size_t a = 0; a < 8; ++a) {
    const auto k = static_cast<std::size_t>(corners[a]);
    p[a] = {x[k], y[k], z[k]};
  }
  return brick_volume(p);
}

}  // namespace crumple::geometry
