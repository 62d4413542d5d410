#include "crumple/materials/plane_stress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::materials {

namespace {

// Johnson-Cook's term kept for the next cycle at eps_new (eq. JC-2). In double, the series from this cycle's kept
// term carries it (or the value the return already evaluated there): its round-off walks about 1e-16 of the term a
// plastic cycle, 1e-14 over 10^4 cycles. Stored in single, each rounding would walk 3e-8 a cycle and never come
// back, so the mixed build takes a fresh power (eq. PR-2).
double term_to_keep(const Hardening& hardening, const Hardening::KeptTerm* near, double eps_new,
                    const double* evaluated) {
  if constexpr (kMixedPrecision) return hardening.hardening_term(eps_new);
  if (evaluated != nullptr) return *evaluated;
  return near != nullptr ? hardening.term_near(*near, eps_new) : hardening.hardening_term(eps_new);
}

// The elastic predictor (docs/theory/materials.md, eq. PS-1) and the yield check that both returns start with: the
// stress becomes the trial stress; `plastic` says whether its von Mises stress `trial` is above the yield stress.
struct Predictor {
  PlaneStressResult elastic;  // the step's result if it is elastic
  double old_sum = 0.0;       // sxx + syy before the step
  double trial = 0.0;         // von Mises stress of the trial stress
  bool kept = false;          // Johnson-Cook's b eps_p^n is kept in *kept_term
  bool plastic = false;
};

Predictor predict(const PlaneStressElastic& el, const Hardening& hardening, double dexx, double deyy, double dgxy,
                  double rate, double eps_p, double& sxx, double& syy, double& sxy, point_real* kept_term) {
  const double E = el.young, nu = el.poisson, G = el.shear_modulus();
  const double c = E / (1.0 - nu * nu);
  const double txx = sxx + c * (dexx + nu * deyy);
  const double tyy = syy + c * (deyy + nu * dexx);
  const double txy = sxy + G * dgxy;
  Predictor pr;
  pr.old_sum = sxx + syy;
  sxx = txx, syy = tyy, sxy = txy;
  pr.elastic = {0.0, -nu / E * ((txx + tyy) - pr.old_sum)};
  if (!hardening.plastic()) return pr;
  pr.kept = kept_term != nullptr && hardening.has_kept_term();
  if (pr.kept && std::isnan(*kept_term)) *kept_term = stored(hardening.hardening_term(eps_p));
  const double yield0 = pr.kept ? hardening.yield_from_term(*kept_term, rate) : hardening.yield(eps_p, rate);
  pr.trial = von_mises_plane_stress(txx, tyy, txy);
  pr.plastic = !(pr.trial <= yield0);
  return pr;
}

}  // namespace

PlaneStressResult plane_stress_update(const PlaneStressElastic& el, const Hardening& hardening, double dexx,
                                      double deyy, double dgxy, double rate, double eps_p, double& sxx, double& syy,
                                      double& sxy, point_real* kept_term) {
  const double E = el.young, nu = el.poisson, G = el.shear_modulus();
  const Predictor pr = predict(el, hardening, dexx, deyy, dgxy, rate, eps_p, sxx, syy, sxy, kept_term);
  PlaneStressResult result = pr.elastic;
  if (!pr.plastic) return result;
  const double txx = sxx, tyy = syy, txy = sxy, old_sum = pr.old_sum;
  const bool kept = pr.kept;

  // Return mapping in the eigen-basis of the plane-stress projection (eq. PS-3): with p = sxx + syy,
  // q = syy - sxx, r = sxy the corrected stress is p/(1 + E g/(3(1-nu))), q/(1 + 2 G g), r/(1 + 2 G g) for the
  // plastic multiplier g, and the equivalent plastic strain grows by (2/3) g sigma_vm(g).
  const double p = txx + tyy, q = tyy - txx, r = txy;
  const double alpha = E / (3.0 * (1.0 - nu));
  const double deviatoric = 0.75 * q * q + 3.0 * r * r;
  // sigma_vm(g) and its derivative (eq. PS-4).
  auto vm = [&](double g, double& derivative) {
    const double a = p / (1.0 + alpha * g), b = 1.0 / (1.0 + 2.0 * G * g);
    const double value = std::sqrt(0.25 * a * a + deviatoric * b * b);
    const double da = -alpha * a / (1.0 + alpha * g), db = -2.0 * G * b * b;
    derivative = value > 0.0 ? (0.25 * a * da + deviatoric * b * db) / value : 0.0;
    return value;
  };
  // Newton from g = 0 with the exact slope, kept inside a bracket [lo, hi] of the sign change. The residual
  // decreases with g, so the iteration needs a handful of steps; bisection guards the rare overshoot.
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double g = 0.0;
  // The stored term, widened: every iterate's term comes from it without a power (eq. JC-2).
  const Hardening::KeptTerm base{eps_p, kept ? static_cast<double>(*kept_term) : 0.0, eps_p > 0.0 ? 1.0 / eps_p : 0.0};
  const Hardening::KeptTerm* near = kept && eps_p > 0.0 ? &base : nullptr;
  for (int it = 0; it < 50; ++it) {
    double dvm = 0.0;
    const double s_vm = vm(g, dvm);
    const double eps = eps_p + 2.0 / 3.0 * g * s_vm;
    double hardening_slope = 0.0;
    const double yield = hardening.yield_and_slope(eps, rate, hardening_slope, nullptr, near);
    const double f = s_vm - yield;
    if (std::abs(f) <= 1e-12 * yield) break;
    if (f > 0.0) lo = g; else hi = g;
    const double slope = dvm - hardening_slope * 2.0 / 3.0 * (s_vm + g * dvm);
    double next = slope < 0.0 ? g - f / slope : lo * 2.0 + 1e-30;
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : std::max(2.0 * lo, 1e-30);
    if (std::abs(next - g) <= 1e-13 * next) {
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
  const double eps_new = eps_p + result.plastic_strain_increment;
  if (kept) *kept_term = stored(term_to_keep(hardening, near, eps_new, nullptr));
  // Through-thickness strain: elastic part from the stress change, plastic part from incompressibility
  // (d eps_p_zz = -(d eps_p_xx + d eps_p_yy) = -g (sxx + syy) / 3).
  result.thickness_strain = -nu / E * ((sxx + syy) - old_sum) - g * (sxx + syy) / 3.0;
  return result;
}

PlaneStressResult plane_stress_radial_return(const PlaneStressElastic& el, const Hardening& hardening, double dexx,
                                             double deyy, double dgxy, double rate, double eps_p, double& sxx,
                                             double& syy, double& sxy, point_real* kept_term) {
  const double E = el.young, nu = el.poisson;
  const Predictor pr = predict(el, hardening, dexx, deyy, dgxy, rate, eps_p, sxx, syy, sxy, kept_term);
  PlaneStressResult result = pr.elastic;
  if (!pr.plastic) return result;
  const double txx = sxx, tyy = syy, txy = sxy, old_sum = pr.old_sum, trial = pr.trial;
  const bool kept = pr.kept;
  // PS-5: f(d) = trial - H_r d - sigma_y(eps_p + d) = 0, decreasing in d; Newton from d = 0, safeguarded. H_r is E
  // (law 2: in uniaxial stress d is the inelastic strain) or the three-dimensional return's 3 G (law 36).
  const double modulus = hardening.uniaxial_radial_return() ? E : 3.0 * el.shear_modulus();
  double d = 0.0, lo = 0.0, hi = trial / modulus;
  // The last strain the hardening was evaluated at and its term: when the iteration ends on the residual there,
  // the kept term needs no second power. The first step, at eps_p itself, takes the kept term: no power at all.
  double evaluated = -1.0, evaluated_term = 0.0;
  // The stored term, widened: every iterate's term comes from it without a power (eq. JC-2). A point that yields
  // for the first time has none: its first power becomes the base, and is replaced only when an iterate goes out of
  // the series' reach of it.
  Hardening::KeptTerm base{eps_p, kept ? static_cast<double>(*kept_term) : 0.0, eps_p > 0.0 ? 1.0 / eps_p : 0.0};
  bool based = kept && eps_p > 0.0;
  for (int it = 0; it < 50; ++it) {
    double slope = 0.0;
    evaluated = eps_p + d;
    const double yield = hardening.yield_and_slope(evaluated, rate, slope, kept ? &evaluated_term : nullptr,
                                                   based ? &base : nullptr);
    if (kept && evaluated >= Hardening::kSlopeFloor &&
        !(based && std::abs(evaluated - base.eps_p) <= Hardening::kSeriesReach * base.eps_p))
      base = {evaluated, evaluated_term, 1.0 / evaluated}, based = true;
    const double f = trial - modulus * d - yield;
    if (std::abs(f) <= 1e-12 * yield) break;
    if (f > 0.0) lo = d; else hi = d;
    double next = d + f / (modulus + std::max(slope, 0.0));
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - d) <= 1e-14 * next) {
      d = next;
      break;
    }
    d = next;
  }
  const double scale = (trial - modulus * d) / trial;
  sxx = txx * scale, syy = tyy * scale, sxy = txy * scale;
  result.plastic_strain_increment = d;
  if (kept)
    *kept_term = stored(term_to_keep(hardening, based ? &base : nullptr, eps_p + d,
                                     eps_p + d == evaluated ? &evaluated_term : nullptr));
  // Plastic flow along the normal (3/2) s / sigma_vm: through the thickness -d (sxx + syy) / (2 sigma_vm).
  const double vm = von_mises_plane_stress(sxx, syy, sxy);
  result.thickness_strain = -nu / E * ((sxx + syy) - old_sum) - (vm > 0.0 ? d * (sxx + syy) / (2.0 * vm) : 0.0);
  return result;
}

}  // namespace crumple::materials
