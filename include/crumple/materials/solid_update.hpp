#pragma once
// Three-dimensional stress update for the solid elements (docs/theory/materials.md, "Solids"): objective rotation
// of the stored Cauchy stress by the spin increment (Hughes-Winget integration of the Jaumann rate), Hooke's law,
// and the J2 radial return with isotropic hardening.
//
// Voigt order everywhere: xx, yy, zz, xy, yz, zx. Stresses are tensor components; strain increments carry the
// engineering shears (gxy = 2 exy, ...), like the plane-stress update of the shells.
#include "crumple/materials/hardening.hpp"

namespace crumple::materials {

struct SolidElastic {
  double young;    // E
  double poisson;  // nu
  double shear() const { return young / (2.0 * (1.0 + poisson)); }
  double bulk() const { return young / (3.0 * (1.0 - 2.0 * poisson)); }
};

struct SolidUpdateResult {
  double plastic_strain_increment = 0.0;  // equivalent plastic strain increment (the plastic multiplier)
};

// Updates the stress s[6] at one point for the strain increment de[6] (eq. SU-1 to SU-4): elastic predictor, then,
// when the von Mises stress of the trial state exceeds sigma_y(eps_p, rate), the radial return whose plastic
// multiplier solves sigma_trial - 3 G dg = sigma_y(eps_p + dg) by Newton's method (consistent slope from the
// hardening law, safeguarded by bisection). `rate` is the equivalent strain rate seen by the hardening law.
SolidUpdateResult solid_update(const SolidElastic& elastic, const Hardening& hardening, const double* de, double rate,
                               double eps_p, double* s);

// Rotates the stress s[6] by the spin increment whose axial vector is (wx, wy, wz) = W dt, i.e. wz = (dvy/dx -
// dvx/dy) dt / 2 and cyclically (eq. SU-2): s <- Q s Q^T with Q = (I - W dt/2)^-1 (I + W dt/2), an exact rotation.
void rotate_stress(double* s, double wx, double wy, double wz);

// von Mises equivalent stress sqrt(3/2 dev(s) : dev(s)).
double von_mises(const double* s);

// Equivalent strain of an increment, sqrt(2/3 dev(de) : dev(de)) (engineering shears halved).
double equivalent_strain(const double* de);

}  // namespace crumple::materials
