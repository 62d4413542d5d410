#pragma once
// Shell plasticity on stress resultants, property N = 0 (docs/theory/materials.md, "Resultant plasticity",
// eqs. RP-1 to RP-3): Ilyushin's yield function without the coupling term, radial return in resultant space.
#include "crumple/materials/hardening.hpp"
#include "crumple/materials/plane_stress.hpp"

namespace crumple::materials {

// The resultants are carried as stresses: membrane stress sm = N / t and outer-fibre bending stress
// sb = 6 M / t^2 (xx, yy, xy each) [stress].
struct ResultantIncrement {
  double membrane[3];  // membrane strain increment (dexx, deyy, dgxy = 2 dexy) [-]
  double bending[3];   // (t / 2) times the curvature increment, the outer fibre's bending strain [-]
};

// Elastic predictor on (sm, sb); when (sm, sb) leaves the yield surface (RP-1) it is scaled back onto it, with
// the equivalent plastic strain from the uniaxial relation of RP-2. `rate` is the strain rate seen by the law.
// Returns the plastic strain increment and the thickness strain increment (RP-3).
PlaneStressResult resultant_update(const PlaneStressElastic& elastic, const Hardening& hardening,
                                   const ResultantIncrement& d, double rate, double eps_p, double sm[3], double sb[3]);

// Generalised equivalent stress S = sqrt(vm(sm)^2 + (4/9) vm(sb)^2): S = sigma_y is Ilyushin's surface (RP-1).
double resultant_equivalent_stress(const double sm[3], const double sb[3]);

}  // namespace crumple::materials
