#pragma once
// Yield stress of the elasto-plastic laws as a function of equivalent plastic strain and strain rate
// (docs/theory/materials.md, "Hardening"): law 2 Johnson-Cook, law 36 tabulated; law 1 never yields.
#include <array>
#include <vector>

#include "crumple/model/functions.hpp"
#include "crumple/model/materials.hpp"

namespace crumple::materials {

struct Hardening {
  MaterialLaw law = MaterialLaw::Elastic;
  const JohnsonCookParameters* johnson_cook = nullptr;
  const TabulatedHardening* tabulated = nullptr;
  const std::vector<Function>* functions = nullptr;

  static Hardening of(const Material& material, const std::vector<Function>& functions);

  bool plastic() const { return law != MaterialLaw::Elastic; }
  // The modulus that turns a shell point's excess of trial stress into plastic strain in the radial return (eq.
  // PS-5): Young's modulus for law 2, whose plastic strain is then the inelastic strain of a uniaxial test, 3 G for
  // law 36, the three-dimensional return's. The reference does so (measured on one element, materials.md).
  bool uniaxial_radial_return() const { return law == MaterialLaw::JohnsonCook; }
  // Flow stress sigma_y(eps_p, eps_rate) [stress]; eps_rate is the equivalent strain rate [1/T] (>= 0).
  double yield(double eps_p, double eps_rate) const;
  // d sigma_y / d eps_p at fixed rate (for the return mapping's Newton iteration).
  double slope(double eps_p, double eps_rate) const;
  // Johnson-Cook's strain-hardening term b eps_p^n changes only with eps_p: a point keeps it with its plastic
  // strain. With it the elastic check (yield_from_term) and the first step of a return (yield_and_slope at the
  // kept strain) cost no power, and give the values of yield and yield_and_slope to the last bit. Other laws have
  // no such term.
  bool has_kept_term() const { return law == MaterialLaw::JohnsonCook; }
  double hardening_term(double eps_p) const;  // b eps_p^n, 0 for eps_p <= 0 [stress]
  double yield_from_term(double term, double eps_rate) const;
  // Johnson-Cook's term near a kept one (docs/theory/materials.md, eq. JC-2): b (e0 + d)^n from term0 = b e0^n,
  // as term0 (1 + u)^n with u = d / e0 summed by its binomial series when |u| <= kSeriesReach (its remainder is
  // below 1e-17 of the term), else by a power. A return's Newton iterates and its result are all within a
  // plastic increment of the kept strain, so the return takes no power.
  struct KeptTerm {
    double eps_p;          // e0 > 0
    double term;           // b e0^n [stress]
    double inverse_eps_p;  // 1 / e0
  };
  static constexpr int kSeriesTerms = 8;
  static constexpr double kSeriesReach = 0.02;
  double term_near(const KeptTerm& kept, double eps_p) const;
  // Both at once (one power evaluation for Johnson-Cook, none when `kept` is given and eps_p is within the series'
  // reach of it): returns sigma_y, writes the slope and, when asked for, Johnson-Cook's term at eps_p (at
  // kept.eps_p itself, kept.term to the last bit).
  double yield_and_slope(double eps_p, double eps_rate, double& slope, double* term_out = nullptr,
                         const KeptTerm* kept = nullptr) const;
  // The slope from Johnson-Cook's term at eps_p (slope's value, from n term / eps_p: no power).
  double slope_from_term(double eps_p, double term, double eps_rate) const;
  // Strain rate the yield stress sees (docs/theory/materials.md, eq. RF): with Fsmooth on and a cut-off Fcut, the
  // first-order low-pass rate_f = a rate + (1 - a) previous with a = min(1, 2 pi Fcut dt); otherwise `rate`.
  double filtered_rate(double rate, double previous, double dt) const;
  // Plastic strain at which the element fails and is deleted (0: never).
  double failure_strain() const;

  // The binomial coefficients C(n, k), k = 1..kSeriesTerms, of Johnson-Cook's exponent (set by of()).
  std::array<double, kSeriesTerms> binomial{};
  // Johnson-Cook's slope is taken no lower than this strain, where b eps^n is kept too (set by of()).
  static constexpr double kSlopeFloor = 1e-6;
  double floor_term = 0.0;  // b kSlopeFloor^n [stress]
};

}  // namespace crumple::materials
