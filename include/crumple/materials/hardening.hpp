#pragma once
// Yield stress of the elasto-plastic laws as a function of equivalent plastic strain and strain rate
// (docs/theory/materials.md, "Hardening"): law 2 Johnson-Cook, law 36 tabulated; law 1 never yields.
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
  // Both at once (one power evaluation for Johnson-Cook, none when `term_in` gives b eps_p^n at this eps_p):
  // returns sigma_y, writes the slope and, when asked for, Johnson-Cook's term at eps_p (hardening_term's value,
  // to the last bit).
  double yield_and_slope(double eps_p, double eps_rate, double& slope, double* term_out = nullptr,
                         const double* term_in = nullptr) const;
  // Strain rate the yield stress sees (docs/theory/materials.md, eq. RF): with Fsmooth on and a cut-off Fcut, the
  // first-order low-pass rate_f = a rate + (1 - a) previous with a = min(1, 2 pi Fcut dt); otherwise `rate`.
  double filtered_rate(double rate, double previous, double dt) const;
  // Plastic strain at which the element fails and is deleted (0: never).
  double failure_strain() const;
};

}  // namespace crumple::materials
