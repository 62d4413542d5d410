#include "crumple/materials/hardening.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>

namespace crumple::materials {
namespace {

// Johnson-Cook without temperature (docs/theory/materials.md, eq. JC):
//   sigma_y = (a + b eps_p^n) (1 + c ln(max(eps_rate / eps_dot_0, 1))), capped by sig_max0 when given.
double jc_rate_factor(const JohnsonCookParameters& p, double rate) {
  if (p.c <= 0.0 || p.eps_dot_0 <= 0.0 || rate <= p.eps_dot_0) return 1.0;
  return 1.0 + p.c * std::log(rate / p.eps_dot_0);
}

double jc_term(const JohnsonCookParameters& p, double eps_p) { return eps_p > 0.0 ? p.b * std::pow(eps_p, p.n) : 0.0; }
double jc_static(const JohnsonCookParameters& p, double eps_p) { return p.a + jc_term(p, eps_p); }

// The cap follows the strain rate too unless ICC = 2 (ICC 0 is 1): sigma_max = sig_max0 (1 + c ln(...)).
double cap(const JohnsonCookParameters& p, double rate_factor) {
  return p.icc == 2 ? p.sig_max0 : p.sig_max0 * rate_factor;
}
double capped(const JohnsonCookParameters& p, double sigma, double rate_factor) {
  return p.sig_max0 > 0.0 ? std::min(sigma, cap(p, rate_factor)) : sigma;
}

// Law 36: curve k gives sigma_y(eps_p) at strain rate rate_k; linear interpolation between the two curves that
// bracket the current rate, the first or last curve outside their range.
template <class Eval>
double interpolate_rates(const TabulatedHardening& t, double rate, Eval eval) {
  const std::size_t n = t.function.size();
  if (n == 1 || rate <= t.strain_rate.front()) return eval(0);
  if (rate >= t.strain_rate.back()) return eval(n - 1);
  std::size_t k = 1;
  while (k < n - 1 && t.strain_rate[k] < rate) ++k;
  const double w = (rate - t.strain_rate[k - 1]) / (t.strain_rate[k] - t.strain_rate[k - 1]);
  return (1.0 - w) * eval(k - 1) + w * eval(k);
}

}  // namespace

Hardening Hardening::of(const Material& material, const std::vector<Function>& functions_of_model) {
  Hardening h;
  h.law = material.law;
  h.johnson_cook = &material.johnson_cook;
  h.tabulated = &material.tabulated;
  h.functions = &functions_of_model;
  double c = 1.0;  // C(n, k) = C(n, k - 1) (n - k + 1) / k
  for (int k = 1; k <= kSeriesTerms; ++k) c *= (material.johnson_cook.n - (k - 1)) / k, h.binomial[k - 1] = c;
  h.floor_term = material.johnson_cook.b * std::pow(kSlopeFloor, material.johnson_cook.n);
  return h;
}

double Hardening::yield(double eps_p, double eps_rate) const {
  switch (law) {
    case MaterialLaw::Elastic: return std::numeric_limits<double>::infinity();
    case MaterialLaw::JohnsonCook: {
      const auto& p = *johnson_cook;
      const double factor = jc_rate_factor(p, eps_rate);
      return capped(p, jc_static(p, eps_p) * factor, factor);
    }
    case MaterialLaw::Tabulated: {
      const auto& t = *tabulated;
      return interpolate_rates(t, eps_rate, [&](std::size_t k) {
        const Function& f = (*functions)[static_cast<std::size_t>(t.function[k])];
        return t.scale[k] * f(eps_p);
      });
    }
  }
  return std::numeric_limits<double>::infinity();
}

double Hardening::hardening_term(double eps_p) const { return jc_term(*johnson_cook, eps_p); }

double Hardening::yield_from_term(double term, double eps_rate) const {
  const auto& p = *johnson_cook;
  const double factor = jc_rate_factor(p, eps_rate);
  return capped(p, (p.a + term) * factor, factor);  // the expression of yield, from the kept term
}

double Hardening::slope(double eps_p, double eps_rate) const {
  switch (law) {
    case MaterialLaw::Elastic: return 0.0;
    case MaterialLaw::JohnsonCook: {
      const auto& p = *johnson_cook;
      const double factor = jc_rate_factor(p, eps_rate);
      if (p.sig_max0 > 0.0 && jc_static(p, eps_p) * factor >= cap(p, factor)) return 0.0;
      // d/d eps (b eps^n) = b n eps^(n-1), unbounded at 0 for n < 1: evaluate a little above zero.
      const double e = std::max(eps_p, kSlopeFloor);
      return p.b * p.n * std::pow(e, p.n - 1.0) * factor;
    }
    case MaterialLaw::Tabulated: {
      const auto& t = *tabulated;
      return interpolate_rates(t, eps_rate, [&](std::size_t k) {
        const Function& f = (*functions)[static_cast<std::size_t>(t.function[k])];
        // Slope of the segment that holds eps_p: the last one beyond the last point (linear extrapolation, as
        // Function's value).
        const auto& x = f.x;
        if (x.size() < 2) return 0.0;
        std::size_t i = 1;
        while (i < x.size() - 1 && x[i] <= eps_p) ++i;
        return t.scale[k] * (f.y[i] - f.y[i - 1]) / (x[i] - x[i - 1]);
      });
    }
  }
  return 0.0;
}

double Hardening::term_near(const KeptTerm& kept, double eps_p) const {
  if (eps_p == kept.eps_p) return kept.term;
  const double u = (eps_p - kept.eps_p) * kept.inverse_eps_p;
  if (!(kept.eps_p > 0.0) || !(std::abs(u) <= kSeriesReach)) return jc_term(*johnson_cook, eps_p);
  // 1 + u (C1 + u C2 + ... + u^7 C8) (eq. JC-2), in Estrin's order: four products deep instead of eight.
  const auto& c = binomial;
  const double u2 = u * u, u4 = u2 * u2;
  const double low = (c[0] + u * c[1]) + u2 * (c[2] + u * c[3]);
  const double high = (c[4] + u * c[5]) + u2 * (c[6] + u * c[7]);
  return kept.term * (1.0 + u * (low + u4 * high));
}

double Hardening::slope_from_term(double eps_p, double term, double eps_rate) const {
  if (law != MaterialLaw::JohnsonCook || !(eps_p >= kSlopeFloor)) return slope(eps_p, eps_rate);
  const auto& p = *johnson_cook;
  const double factor = jc_rate_factor(p, eps_rate);
  if (p.sig_max0 > 0.0 && (p.a + term) * factor >= cap(p, factor)) return 0.0;
  return p.n * term / eps_p * factor;
}

double Hardening::yield_and_slope(double eps_p, double eps_rate, double& slope_out, double* term_out,
                                  const KeptTerm* kept) const {
  if (law != MaterialLaw::JohnsonCook) {
    slope_out = slope(eps_p, eps_rate);
    return yield(eps_p, eps_rate);
  }
  const auto& p = *johnson_cook;
  const double factor = jc_rate_factor(p, eps_rate);
  // b eps^n and its derivative b n eps^(n-1) = n (b eps^n) / eps from one power (slope evaluated a little above 0),
  // or none when the caller keeps b eps_p^n and eps_p is where the slope is evaluated.
  const double e = std::max(eps_p, kSlopeFloor);
  const bool known = kept != nullptr && eps_p == e;
  const double power = known ? term_near(*kept, e) : e == kSlopeFloor ? floor_term : p.b * std::pow(e, p.n);
  const double hardening = eps_p > 0.0 ? (eps_p == e ? power : p.b * std::pow(eps_p, p.n)) : 0.0;
  const double static_value = p.a + hardening;  // jc_static's expression, term for term
  if (term_out != nullptr) *term_out = hardening;
  const double sigma = static_value * factor;
  if (p.sig_max0 > 0.0 && sigma >= cap(p, factor)) {
    slope_out = 0.0;
    return cap(p, factor);
  }
  slope_out = p.n * power / e * factor;
  return sigma;
}

double Hardening::filtered_rate(double rate, double previous, double dt) const {
  int smoothing = 0;
  double cut_off = 0.0;
  if (law == MaterialLaw::JohnsonCook) smoothing = johnson_cook->fsmooth, cut_off = johnson_cook->f_cut;
  if (law == MaterialLaw::Tabulated) smoothing = tabulated->fsmooth, cut_off = tabulated->f_cut;
  // Fcut = 0 is the manual's 1e30: an infinite cut-off, i.e. no filtering.
  if (smoothing == 0 || !(cut_off > 0.0)) return rate;
  const double a = std::min(1.0, 2.0 * std::numbers::pi * cut_off * dt);  // eq. RF
  return a * rate + (1.0 - a) * previous;
}

double Hardening::failure_strain() const {
  switch (law) {
    case MaterialLaw::Elastic: return 0.0;
    case MaterialLaw::JohnsonCook: return johnson_cook->eps_p_max;
    case MaterialLaw::Tabulated: return tabulated->eps_p_max;
  }
  return 0.0;
}

}  // namespace crumple::materials
