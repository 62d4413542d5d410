// Resultant (global) shell plasticity, N = 0 (docs/theory/materials.md, "Resultant plasticity").
#include "crumple/materials/resultant_plasticity.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::materials {

double resultant_equivalent_stress(const double sm[3], const double sb[3]) {
  const double m = von_mises_plane_stress(sm[0], sm[1], sm[2]), b = von_mises_plane_stress(sb[0], sb[1], sb[2]);
  return std::sqrt(m * m + 4.0 / 9.0 * b * b);  // eq. RP-1
}

PlaneStressResult resultant_update(const PlaneStressElastic& elastic, const Hardening& hardening,
                                   const ResultantIncrement& d, double rate, double eps_p, double sm[3], double sb[3]) {
  const double E = elastic.young, nu = elastic.poisson, c = E / (1.0 - nu * nu);
  const double old_trace = sm[0] + sm[1];
  auto add_elastic = [&](double* s, const double* e) {
    s[0] += c * (e[0] + nu * e[1]);
    s[1] += c * (e[1] + nu * e[0]);
    s[2] += c * 0.5 * (1.0 - nu) * e[2];
  };
  add_elastic(sm, d.membrane);
  add_elastic(sb, d.bending);
  PlaneStressResult result{0.0, 0.0};
  const double trial = resultant_equivalent_stress(sm, sb);
  if (hardening.plastic() && trial > hardening.yield(eps_p, rate)) {
    // RP-2: S_trial - sigma_y(eps_p + de_p) - E de_p = 0, the uniaxial return (exact for uniaxial membrane
    // tension), solved by Newton; then (sm, sb) scaled radially onto S = sigma_y.
    double increment = 0.0, sigma_y = 0.0;
    for (int iteration = 0; iteration < 30; ++iteration) {
      double slope = 0.0;
      sigma_y = hardening.yield_and_slope(eps_p + increment, rate, slope);
      const double residual = trial - sigma_y - E * increment;
      if (std::abs(residual) <= 1e-13 * trial) break;
      increment = std::max(0.0, increment + residual / (E + std::max(slope, 0.0)));
    }
    const double scale = sigma_y / trial;
    for (int k = 0; k < 3; ++k) sm[k] *= scale, sb[k] *= scale;
    result.plastic_strain_increment = increment;
  }
  // RP-3: elastic thickness strain -nu/E (dsxx + dsyy) plus the plastic one, -(trace of the plastic membrane
  // strain), the plastic strain being the total minus the elastic (1/E)(ds - nu ds_other).
  const double stress_trace = sm[0] + sm[1] - old_trace;
  result.thickness_strain = (1.0 - 2.0 * nu) / E * stress_trace - (d.membrane[0] + d.membrane[1]);
  return result;
}

}  // namespace crumple::materials
