#pragma once
// TYPE7 contact kernels (docs/theory/contact.md): penalty, damping, energy, time step, friction cone and the
// closest point of a segment. Plain functions of scalars and small arrays, inlined into the contact pass.
#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::contact {

// Penetration p = g - d of a node at distance d from a segment with gap g (0 < p < g in contact) [L].

// Nonlinear penalty (eq. C-5): F = K0 g p / (g - p); it grows without bound as p -> g.
inline double penalty_force(double k0, double g, double p) { return k0 * g * p / (g - p); }
// Secant stiffness F / p = K0 g / (g - p) and tangent stiffness dF/dp = K0 g^2 / (g - p)^2 (eq. C-6).
inline double secant_stiffness(double k0, double g, double p) { return k0 * g / (g - p); }
inline double tangent_stiffness(double k0, double g, double p) {
  const double r = g / (g - p);
  return k0 * r * r;
}
// Stored elastic energy, the integral of the penalty force from 0 to p (eq. C-7).
inline double elastic_energy(double k0, double g, double p) { return k0 * g * (-p - g * std::log((g - p) / g)); }

// Normal damping (eq. C-8): C = VisS sqrt(2 Kt M) times the penetration rate; only its pushing part acts.
inline double damping_force(double viss, double kt, double mass, double penetration_rate) {
  return std::max(0.0, viss * std::sqrt(2.0 * kt * mass) * penetration_rate);
}

// Interface steps (eq. C-11): kinematic 0.5 (g - p) / (dp/dt) while closing; stiffness sqrt(2 M / Kt) reduced by
// the damping fraction xi as for a damped oscillator, (sqrt(1 + xi^2) - xi).
inline double kinematic_step(double g, double p, double penetration_rate) {
  return penetration_rate > 0.0 ? 0.5 * (g - p) / penetration_rate : std::numeric_limits<double>::infinity();
}
inline double stiffness_step(double mass, double kt, double xi) {
  return std::sqrt(2.0 * mass / kt) * (std::sqrt(1.0 + xi * xi) - xi);
}

// Coulomb cone (eq. C-9): scales the trial tangential force to at most `limit` = mu Fn. Returns true if it slid.
inline bool friction_cone(double trial[3], double limit) {
  const double norm = std::sqrt(trial[0] * trial[0] + trial[1] * trial[1] + trial[2] * trial[2]);
  if (norm <= limit) return false;
  const double s = norm > 0.0 ? limit / norm : 0.0;
  trial[0] *= s, trial[1] *= s, trial[2] *= s;
  return true;
}

// Friction laws (eq. C-9a..C-9c): the coefficient for the contact pressure p [P] and the sliding speed v [L/T].
struct FrictionLaw {
  int kind = 0;             // Ifric: 0 Coulomb, 1 generalized viscous, 2 Darmstad, 3 Renard
  double fric = 0.0;        // Fric: Coulomb coefficient, the constant term of Ifric 1
  double c[6] = {0, 0, 0, 0, 0, 0};  // C1..C6 (dimensions in model/interfaces.hpp)
};
inline double friction_coefficient(const FrictionLaw& law, double p, double v) {
  const double* c = law.c;
  double mu = law.fric;
  switch (law.kind) {
    case 1:  // C-9a
      mu = law.fric + c[0] * p + c[1] * v + c[2] * p * v + c[3] * p * p + c[4] * v * v;
      break;
    case 2:  // C-9b
      mu = c[0] * std::exp(c[1] * v) * p * p + c[2] * std::exp(c[3] * v) * p + c[4] * std::exp(c[5] * v);
      break;
    case 3: {  // C-9c: static C1, dynamic C2, maximum C3, minimum C4 at the critical speeds C5 < C6
      const double v1 = c[4], v2 = c[5];
      if (v <= v1) {
        const double r = v / v1;
        mu = c[0] + (c[2] - c[0]) * r * (2.0 - r);
      } else if (v <= v2) {
        const double r = (v - v1) / (v2 - v1);
        mu = c[2] - (c[2] - c[3]) * r * r * (3.0 - 2.0 * r);
      } else {
        const double w = v - v2;
        mu = c[1] == c[3] ? c[1] : c[1] - 1.0 / (1.0 / (c[1] - c[3]) + w * w);
      }
      break;
    }
    default:
      break;
  }
  return std::max(0.0, mu);  // a negative coefficient has no meaning: no friction
}

// Weight alpha of the new value in the friction filter mu_f = alpha mu + (1 - alpha) mu_f_old (eq. C-9d):
// Ifiltr 1 alpha = Xfreq; 2 alpha = 2 pi dt / Xfreq (Xfreq a period); 3 alpha = 2 pi Xfreq dt (a frequency);
// at most 1 (no filter).
inline double friction_filter_weight(int ifiltr, double xfreq, double dt) {
  constexpr double two_pi = 6.283185307179586;
  double alpha = 1.0;
  if (ifiltr == 1) alpha = xfreq;
  else if (ifiltr == 2) alpha = two_pi * dt / xfreq;
  else if (ifiltr == 3) alpha = two_pi * xfreq * dt;
  return std::clamp(alpha, 0.0, 1.0);
}

// Closest point of a main segment to a node (eq. C-1): the face, an edge or a corner. A quadrilateral is split
// into four triangles around its centroid (robust for warped segments); `weight` are the shape-function weights
// of the closest point on the four nodes (sum 1), used to move the contact force to the segment.
struct SegmentPoint {
  double point[3];
  double weight[4];
  double distance;
};
SegmentPoint closest_point_on_segment(const double node[3], const double x[4][3], bool triangle);

}  // namespace crumple::contact
