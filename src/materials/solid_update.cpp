// Three-dimensional Cauchy stress update (docs/theory/materials.md, "Solids", eq. SU-1 to SU-4).
#include "crumple/materials/solid_update.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::materials {

double von_mises(const double* s) {
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - p, b = s[1] - p, c = s[2] - p;
  const double j2 = 0.5 * (a * a + b * b + c * c) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  return std::sqrt(3.0 * j2);
}

double equivalent_strain(const double* de) {
  const double v = (de[0] + de[1] + de[2]) / 3.0;
  const double a = de[0] - v, b = de[1] - v, c = de[2] - v;
  const double ee = a * a + b * b + c * c + 0.5 * (de[3] * de[3] + de[4] * de[4] + de[5] * de[5]);
  return std::sqrt(2.0 / 3.0 * ee);
}

void rotate_stress(double* s, double wx, double wy, double wz) {
  // Cayley transform of A = W dt / 2 (axial vector a = w / 2): Q = I + 2 (A + A^2) / (1 + |a|^2) (eq. SU-2).
  const double ax = 0.5 * wx, ay = 0.5 * wy, az = 0.5 * wz;
  const double aa = ax * ax + ay * ay + az * az;
  // A = [[0, -az, ay], [az, 0, -ax], [-ay, ax, 0]]; A^2 = a a^T - |a|^2 I.
  const double A[3][3] = {{0.0, -az, ay}, {az, 0.0, -ax}, {-ay, ax, 0.0}};
  const double av[3] = {ax, ay, az};
  const double f = 2.0 / (1.0 + aa);
  double Q[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Q[i][j] = (i == j ? 1.0 : 0.0) + f * (A[i][j] + av[i] * av[j] - (i == j ? aa : 0.0));
  const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double QS[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) QS[i][j] = Q[i][0] * S[0][j] + Q[i][1] * S[1][j] + Q[i][2] * S[2][j];
  auto qsqt = [&](int i, int j) { return QS[i][0] * Q[j][0] + QS[i][1] * Q[j][1] + QS[i][2] * Q[j][2]; };
  s[0] = qsqt(0, 0), s[1] = qsqt(1, 1), s[2] = qsqt(2, 2);
  s[3] = qsqt(0, 1), s[4] = qsqt(1, 2), s[5] = qsqt(2, 0);
}

SolidUpdateResult solid_update(const SolidElastic& elastic, const Hardening& hardening, const double* de, double rate,
                               double eps_p, double* s) {
  const double G = elastic.shear(), K = elastic.bulk();
  // Elastic predictor (eq. SU-1): s += K tr(de) I + 2 G dev(de).
  const double tr = de[0] + de[1] + de[2];
  const double lame = K - 2.0 / 3.0 * G;
  s[0] += lame * tr + 2.0 * G * de[0];
  s[1] += lame * tr + 2.0 * G * de[1];
  s[2] += lame * tr + 2.0 * G * de[2];
  s[3] += G * de[3];
  s[4] += G * de[4];
  s[5] += G * de[5];
  SolidUpdateResult result;
  if (!hardening.plastic()) return result;

  const double trial = von_mises(s);
  const double yield0 = hardening.yield(eps_p, rate);
  if (!(trial > yield0)) return result;

  // Radial return (eq. SU-3): the deviator shrinks by 1 - 3 G dg / trial, the pressure is unchanged, and the
  // multiplier dg solves f(dg) = trial - 3 G dg - sigma_y(eps_p + dg) = 0. f(0) > 0 and f(trial / 3G) =
  // -sigma_y < 0: Newton with the slope -3G - H, kept inside the bracket, bisection when it leaves it.
  auto residual = [&](double g) { return trial - 3.0 * G * g - hardening.yield(eps_p + g, rate); };
  double lo = 0.0, hi = trial / (3.0 * G);
  double g = (trial - yield0) / (3.0 * G + std::max(hardening.slope(eps_p, rate), 0.0));
  if (!(g > lo && g < hi)) g = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double f = residual(g);
    if (f > 0.0) lo = g; else hi = g;
    if (std::abs(f) <= 1e-15 * trial) break;
    const double slope = -3.0 * G - hardening.slope(eps_p + g, rate);
    double next = slope < 0.0 ? g - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool converged = std::abs(next - g) <= 1e-15 * g || hi - lo <= 1e-16 * hi;
    g = next;
    if (converged) break;
  }
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  const double factor = std::max(1.0 - 3.0 * G * g / trial, 0.0);
  for (int k = 0; k < 3; ++k) s[k] = p + factor * (s[k] - p);
  for (int k = 3; k < 6; ++k) s[k] *= factor;
  result.plastic_strain_increment = g;  // eq. SU-4: the equivalent plastic strain grows by the multiplier
  return result;
}

}  // namespace crumple::materials
