#pragma once
// Materials (/MAT). Values in working units; stresses and moduli [M L^-1 T^-2], density [M L^-3].
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"

namespace crumple {

enum class MaterialLaw : std::uint8_t { Elastic = 1, JohnsonCook = 2, Tabulated = 36 };

struct JohnsonCookParameters {
  // sigma_y = (a + b * eps_p^n) * (1 + c * ln(eps_dot / eps_dot_0)), capped at sig_max0 (docs/theory, law 2)
  double a = 0.0;          // initial yield stress
  double b = 0.0;          // hardening modulus
  double n = 1.0;          // hardening exponent
  double eps_p_max = 0.0;  // plastic strain at failure (0: none)
  double sig_max0 = 0.0;   // maximum flow stress (0: none)
  double c = 0.0;          // strain-rate coefficient (0: rate independent)
  double eps_dot_0 = 0.0;  // reference strain rate [T^-1]
  int icc = 0;             // strain-rate effect flag on sig_max
  int fsmooth = 0;         // strain-rate smoothing flag
  double f_cut = 0.0;      // cut-off frequency of the strain-rate filter [T^-1]
  double chard = 0.0;      // kinematic/isotropic hardening mix (0 isotropic)
  double m = 0.0;          // temperature exponent (thermal softening not supported: must be 0)
  double t_melt = 0.0;
  double rho_cp = 0.0;
  double t_r = 0.0;
};

struct TabulatedHardening {
  // Yield stress against plastic strain, one curve per strain rate (law 36).
  std::vector<std::int64_t> function_id;  // user ids of the /FUNCT curves
  std::vector<std::int32_t> function;     // dense function indices (filled by the model build)
  std::vector<double> scale;              // ordinate scale of each curve [stress]
  std::vector<double> strain_rate;        // strain rate of each curve [T^-1]
  double eps_p_max = 0.0;                 // failure plastic strain (0: none)
  double eps_t1 = 0.0, eps_t2 = 0.0;      // tensile failure strains (0: none)
  double eps_p_scale = 1.0;               // abscissa scale of the curves
  int fsmooth = 0;
  double f_cut = 0.0;                     // [T^-1]
  double chard = 0.0;
};

struct Material {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  MaterialLaw law = MaterialLaw::Elastic;
  double density = 0.0;  // initial density [M L^-3]
  double young = 0.0;    // Young's modulus E
  double poisson = 0.0;  // Poisson ratio nu, in (-1, 0.5)
  JohnsonCookParameters johnson_cook;  // law 2
  TabulatedHardening tabulated;        // law 36

  double shear_modulus() const { return young / (2.0 * (1.0 + poisson)); }
  double bulk_modulus() const { return young / (3.0 * (1.0 - 2.0 * poisson)); }
};

// Whether a shell's critical step takes the plate speed sqrt(E / (rho (1 - nu^2))) rather than the bar speed
// sqrt(E / rho) (docs/theory/time-step.md, T-1a): Ishell 12, and every shell of /MAT/PLAS_TAB (LAW36), as the
// reference times them (a LAW36 plate's step is sqrt(1 - nu^2) of the same plate's with LAW1 or LAW2, for Ishell
// 1 and 24 and for 3-node shells alike).
inline bool shell_step_at_plate_speed(MaterialLaw law, bool fully_integrated) {
  return fully_integrated || law == MaterialLaw::Tabulated;
}
// The wave speed of a shell's critical step [L/T]: the plate speed where shell_step_at_plate_speed, else the bar speed.
inline double shell_step_wave_speed(double young, double poisson, double density, bool plate) {
  return plate ? std::sqrt(young / (density * (1.0 - poisson * poisson))) : std::sqrt(young / density);
}

}  // namespace crumple
