#include "crumple/materials/plane_stress.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::materials {

PlaneStressResult plane_stress_update(const PlaneStressElastic& el, const Hardening& hardening, double dexx,
                                      double deyy, double dgxy, double rate, double eps_p, double& sxx, double& syy,
                                      double& sxy) {
  const double E = el.young;
  const double nu = el.poisson;
  const double G = E / (2.0 * (1.0 + nu));
  const double c = E / (1.0 - nu * nu);
  // Elastic predictor (docs/theory/materials.md, eq. PS-1).
  const double txx = sxx + c * (dexx + nu * deyy);
  const double tyy = syy + c * (deyy + nu * dexx);
  const double txy = sxy + G * dgxy;
  const double old_sum = sxx + syy;
  sxx = txx, syy = tyy, sxy = txy;
  PlaneStressResult result{0.0, -nu / E * ((txx + tyy) - old_sum)};
  if (!hardening.plastic()) return result;

  const double yield0 = hardening.yield(eps_p, rate);
  const double trial = von_mises_plane_stress(txx, tyy, txy);
  if (trial <= yield0) return result;

  // Return mapping in the eigen-basis of the plane-stress projection (eq. PS-3): with p = sxx + syy,
  // q = syy - sxx, r = sxy the corrected stress is p/(1 + E g/(3(1-nu))), q/(1 + 2 G g), r/(1 + 2 G g) for the
  // plastic multiplier g, and the equivalent plastic strain grows by (2/3) g sigma_vm(g).
  const double p = txx + tyy, q = tyy - txx, r = txy;
  auto vm = [&](double g) {
    const double a = p / (1.0 + E * g / (3.0 * (1.0 - nu)));
    const double b = 1.0 / (1.0 + 2.0 * G * g);
    return std::sqrt(0.25 * a * a + (0.75 * q * q + 3.0 * r * r) * b * b);
  };
  auto residual = [&](double g) {
    const double s = vm(g);
    return s - hardening.yield(eps_p + 2.0 / 3.0 * g * s, rate);
  };
  // Bracket: residual(0) > 0; grow the upper bound until the residual changes sign.
  double lo = 0.0, hi = (trial - yield0) / (3.0 * G * trial) * 3.0 + 1e-300;
  for (int k = 0; k < 60 && residual(hi) > 0.0; ++k) hi *= 2.0;
  double g = 0.5 * (lo + hi);
  for (int it = 0; it < 60; ++it) {
    const double f = residual(g);
    if (f > 0.0) lo = g; else hi = g;
    // Newton step with a finite-difference slope, kept inside the bracket.
    const double h = 1e-7 * std::max(g, 1e-30);
    const double slope = (residual(g + h) - f) / h;
    double next = slope < 0.0 ? g - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - g) <= 1e-14 * std::max(g, 1e-300) || hi - lo <= 1e-15 * hi) {
      g = next;
      break;
    }
    g = next;
  }
  const double a = 1.0 / (1.0 + E * g / (3.0 * (1.0 - nu)));
  const double b = 1.0 / (1.0 + 2.0 * G * g);
  const double new_p = p * a, new_q = q * b;
  sxx = 0.5 * (new_p - new_q);
  syy = 0.5 * (new_p + new_q);
  sxy = r * b;
  result.plastic_strain_increment = 2.0 / 3.0 * g * von_mises_plane_stress(sxx, syy, sxy);
  // Through-thickness strain: elastic part from the stress change, plastic part from incompressibility
  // (d eps_p_zz = -(d eps_p_xx + d eps_p_yy) = -g (sxx + syy) / 3).
  result.thickness_strain = -nu / E * ((sxx + syy) - old_sum) - g * (sxx + syy) / 3.0;
  return result;
}

}  // namespace crumple::materials
