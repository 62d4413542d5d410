#pragma once
// Plane-stress J2 plasticity with isotropic hardening for shells (docs/theory/materials.md, "Plane stress").
#include "crumple/core/precision.hpp"
#include "crumple/materials/hardening.hpp"

namespace crumple::materials {

struct PlaneStressElastic {
  double young;    // E
  double poisson;  // nu
  double shear_modulus() const { return young / (2.0 * (1.0 + poisson)); }  // G
};

struct PlaneStressResult {
  double plastic_strain_increment;  // equivalent plastic strain increment
  double thickness_strain;          // through-thickness strain increment (elastic + plastic)
};

// Updates the stress (sxx, syy, sxy) at one point for the strain increment (dexx, deyy, dgxy = 2 dexy) by an
// elastic predictor and, when the trial stress is outside the von Mises cylinder, the exact plane-stress
// return of Simo and Taylor (one scalar equation in the plastic multiplier, solved by safeguarded Newton).
// eps_p is the point's equivalent plastic strain; rate the equivalent strain rate used by the hardening law.
// kept_term, when given, is the point's kept Johnson-Cook term b eps_p^n (NaN: not yet computed): read for the
// elastic check and the return's first step, renewed after a plastic step (Hardening::hardening_term).
PlaneStressResult plane_stress_update(const PlaneStressElastic& elastic, const Hardening& hardening, double dexx,
                                      double deyy, double dgxy, double rate, double eps_p, double& sxx, double& syy,
                                      double& sxy, point_real* kept_term = nullptr);

// The same elastic predictor with the radial return of Iplas 2, the reference's default for explicit decks
// (docs/theory/materials.md, PS-5): the plastic strain increment solves sigma_vm_trial - 3 G d_eps_p =
// sigma_y(eps_p + d_eps_p) and the trial stress is scaled back onto the yield surface along itself, which keeps
// it plane but is not the exact plane-stress projection of plane_stress_update.
PlaneStressResult plane_stress_radial_return(const PlaneStressElastic& elastic, const Hardening& hardening,
                                             double dexx, double deyy, double dgxy, double rate, double eps_p,
                                             double& sxx, double& syy, double& sxy, point_real* kept_term = nullptr);

inline double von_mises_plane_stress(double sxx, double syy, double sxy) {
  const double v = sxx * sxx - sxx * syy + syy * syy + 3.0 * sxy * sxy;
  return v > 0.0 ? __builtin_sqrt(v) : 0.0;
}

}  // namespace crumple::materials
