#pragma once
// TYPE7 contact kernels (docs/theory/contact.md): penalty, damping, energy, time step, friction cone and the
// closest point of a segment. Plain functions of scalars and small arrays, inlined into the contact pass.
#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/core/vec3.hpp"
#include "crumple/state/contact_state.hpp"

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

// Normal damping (eq. C-8): C = VisS sqrt(2 Kt M) times the penetration rate, on the way in and on the way out,
// but never more pull than the elastic push `elastic` (>= 0): the normal force elastic + damping stays >= 0, so
// the surfaces are never pulled together.
inline double damping_force(double viss, double kt, double mass, double penetration_rate, double elastic) {
  return std::max(-elastic, viss * std::sqrt(2.0 * kt * mass) * penetration_rate);
}
// Viscous friction (eq. C-9, Iform 1): the dashpot C_t = VisF sqrt(2 Kt M) on the sliding velocity [F T/L].
inline double friction_viscosity(double visf, double kt, double mass) { return visf * std::sqrt(2.0 * kt * mass); }

// The penetration a node can reach within the step dt: at most half its remaining distance, the kinematic bound
// (eq. C-11c); the stiffness there is what an added mass must hold.
inline double reach_penetration(double g, double p, double penetration_rate, double dt) {
  return std::min(p + std::max(penetration_rate, 0.0) * dt, p + 0.5 * (g - p));
}

// What a pair with viscous friction gives its nodes' mass-scaled nodal step (time-step.md, eq. T-4b): its tangent
// stiffness Kt, or the friction's dashpot over the step dt, VisF sqrt((K0 + Ks) M) / dt, where that is larger
// (Ks the secant stiffness K0 g / (g - p), M the secondary node's mass), as the reference solver counts it; dt = 0:
// Kt.
inline double nodal_friction_stiffness(double kt, double k0, double ks, double visf, double mass, double dt) {
  return dt > 0.0 ? std::max(kt, visf * std::sqrt((k0 + ks) * mass) / dt) : kt;
}

// What a pair gives its nodes' interface nodal step (time-step.md, eq. T-4c): its tangent stiffness plus its normal
// dashpot over the last step, Kt + VisS sqrt(2 Kt M) / dt, or with viscous friction the friction's dashpot over it
// (eq. T-4b) where that is larger, as the reference solver counts them; dt = 0 (the first cycle): Kt.
inline double nodal_pair_stiffness(double kt, double k0, double ks, double viss, double visf, double mass, double dt) {
  if (!(dt > 0.0)) return kt;
  return std::max(kt + viss * std::sqrt(2.0 * kt * mass) / dt, nodal_friction_stiffness(kt, k0, ks, visf, mass, dt));
}

// Steps ahead of its entry into the gap that a node closing in counts K0 in its step when the entry is anticipated
// (eq. C-11): with `--accuracy fine`, and for a node that /DT/INTER/CST mass scales at its entry (C-11c).
inline constexpr int kAnticipatedEntrySteps = 3;

// Interface steps (eq. C-11): kinematic 0.5 (g - p) / (dp/dt) while closing; stiffness sqrt(2 M / Kt) reduced by
// the damping fraction xi as for a damped oscillator, (sqrt(1 + xi^2) - xi).
inline double kinematic_step(double g, double p, double penetration_rate) {
  return penetration_rate > 0.0 ? 0.5 * (g - p) / penetration_rate : std::numeric_limits<double>::infinity();
}
inline double stiffness_step(double mass, double kt, double xi) {
  return std::sqrt(2.0 * mass / kt) * (std::sqrt(1.0 + xi * xi) - xi);
}
// Stiffness step with the friction dashpot C (eq. C-11b), already scaled: over a step dt the dashpot's force C v
// acts on the displacement v dt, a spring C / dt for that step, so the node's stiffness is K + C / dt with dt the
// step itself: dt = a sqrt(2 M / (K + C / dt)), a = scale (sqrt(1 + xi^2) - xi), whose root is
// dt = 2 b / (C + sqrt(C^2 + 4 K b)), b = 2 M a^2. C = 0 gives a sqrt(2 M / K) (stiffness_step); K = 0 gives
// 2 M a^2 / C, the explicit dashpot's bound 2 M / C times a^2.
inline double scaled_stiffness_step(double mass, double k, double c, double xi, double scale) {
  if (c == 0.0) return scale * stiffness_step(mass, k, xi);
  const double a = scale * (std::sqrt(1.0 + xi * xi) - xi), b = 2.0 * mass * a * a;
  const double denominator = c + std::sqrt(c * c + 4.0 * k * b);
  return denominator > 0.0 ? 2.0 * b / denominator : std::numeric_limits<double>::infinity();
}
// The mass that gives the node the scaled step dt (eq. C-11b solved for M; /DT/INTER/CST): the dashpot grows
// with sqrt(M), C = c_unit sqrt(M), so 2 a^2 M - c_unit dt sqrt(M) - K dt^2 = 0 with a as above.
inline double mass_for_step(double k, double c_unit, double xi, double scale, double dt) {
  const double a = scale * (std::sqrt(1.0 + xi * xi) - xi);
  if (c_unit == 0.0) return 0.5 * k * (dt / a) * (dt / a);
  const double root = (c_unit * dt + std::sqrt(c_unit * c_unit * dt * dt + 8.0 * a * a * k * dt * dt)) / (4.0 * a * a);
  return root * root;
}

// Coulomb cone (eq. C-9): scales the trial tangential force to at most `limit` = mu Fn. Returns true if it slid.
inline bool friction_cone(double trial[3], double limit) {
  const double norm = std::sqrt(trial[0] * trial[0] + trial[1] * trial[1] + trial[2] * trial[2]);
  if (norm <= limit) return false;
  const double s = norm > 0.0 ? limit / norm : 0.0;
  trial[0] *= s, trial[1] *= s, trial[2] *= s;
  return true;
}

// The coefficient of a friction law (eq. C-9a..C-9c) for the contact pressure p [P] and the sliding speed v [L/T].
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

// Closest point of a main segment to a node (eq. C-1). A quadrilateral is split into four triangles around its
// centroid (robust for warped segments; a triangle segment, its third node repeated, gives the triangle itself);
// `weight` are the shape-function weights of the closest point on the four nodes (sum 1), used to move the
// contact force to the segment.
struct SegmentPoint {
  double point[3];
  double weight[4];
  double distance;
};

// Closest point of the segment with corners x0..x3 to the node p, over the four-triangle fan (corners k, k+1 and
// the centroid c, which carries a quarter to each node). Without branches, so that a loop over pairs vectorises:
// every candidate is computed and the nearest kept by selects. The candidates are the four faces (their
// orthogonal projection when it falls inside), the four outer edges and the four spokes c-x_k, each clamped to
// its ends; everything follows from the corner vectors e_k = x_k - c through the scalars
//   r_k = (p - c).e_k,  q_k = e_k.e_k,  m_k = e_k.e_(k+1),  |p - c|^2.
// Values only (small structs by value, selects on comparisons of doubles instead of std::max / std::clamp, which
// return references), so that the compiler keeps everything in registers and if-converts the selects.
struct FanPoint {
  double w0, w1, w2, w3;  // weights of the closest point on the corners (sum 1)
  double distance2;       // squared distance [L^2]
};
[[gnu::always_inline]] inline FanPoint closest_on_fan(Vec3 p, Vec3 x0, Vec3 x1, Vec3 x2, Vec3 x3) {
  const Vec3 c{0.25 * (x0.x + x1.x + x2.x + x3.x), 0.25 * (x0.y + x1.y + x2.y + x3.y),
               0.25 * (x0.z + x1.z + x2.z + x3.z)};
  const Vec3 cp = p - c;
  const Vec3 e[4] = {x0 - c, x1 - c, x2 - c, x3 - c};
  const double pp = dot(cp, cp);
  double r[4], q[4], m[4];
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k) r[k] = dot(cp, e[k]), q[k] = dot(e[k], e[k]), m[k] = dot(e[k], e[(k + 1) & 3]);
  auto unit = [](double t) { return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t); };
  // Squared distance from p to c + a e_k + b e_k+1, from the vectors (not from |cp|^2 - ..., which cancels for a
  // node close to the segment, exactly where the penetration is measured).
  auto gap2 = [&](double a, double b, int k) {
    const Vec3& u = e[k];
    const Vec3& v = e[(k + 1) & 3];
    const Vec3 d{cp.x - a * u.x - b * v.x, cp.y - a * u.y - b * v.y, cp.z - a * u.z - b * v.z};
    return dot(d, d);
  };
  FanPoint best{0.25, 0.25, 0.25, 0.25, pp};  // the centroid itself (the spokes' common end)
  auto keep = [&best](double d2, double w0, double w1, double w2, double w3) {
    const double b = best.distance2;
    best.w0 = d2 < b ? w0 : best.w0, best.w1 = d2 < b ? w1 : best.w1, best.w2 = d2 < b ? w2 : best.w2;
    best.w3 = d2 < b ? w3 : best.w3, best.distance2 = d2 < b ? d2 : b;
  };
  // The weight vector with `a` on corner k, `b` on corner k+1 and `rest` on all four added.
  auto weights = [](int k, double a, double b, double rest, double w[4]) {
#pragma GCC unroll 4
    for (int n = 0; n < 4; ++n) w[n] = rest + (n == k ? a : 0.0) + (n == ((k + 1) & 3) ? b : 0.0);
  };
#pragma GCC unroll 4  // every index a constant: the loop over pairs around this vectorises
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) & 3;
    double w[4];
    // Spoke c -> x_k: c + t e_k.
    const double ts = unit(q[k] > 0.0 ? r[k] / q[k] : 0.0);
    weights(k, ts, 0.0, 0.25 * (1.0 - ts), w);
    keep(gap2(ts, 0.0, k), w[0], w[1], w[2], w[3]);
    // Outer edge x_k -> x_k+1: x_k + t f, f = e_k+1 - e_k, relative to x_k: (cp - e_k).
    const double ff = q[k] + q[k1] - 2.0 * m[k], along = (r[k1] - r[k]) - (m[k] - q[k]);
    const double te = unit(ff > 0.0 ? along / ff : 0.0);
    weights(k, 1.0 - te, te, 0.0, w);
    keep(gap2(1.0 - te, te, k), w[0], w[1], w[2], w[3]);
    // Face (x_k, x_k+1, c): c + s e_k + t e_k+1 from the normal equations, when inside.
    const double det = q[k] * q[k1] - m[k] * m[k];
    const double inv = det > 0.0 ? 1.0 / det : 0.0;
    const double sf = (q[k1] * r[k] - m[k] * r[k1]) * inv, tf = (q[k] * r[k1] - m[k] * r[k]) * inv;
    const double rest = 1.0 - sf - tf;
    double lowest = sf < tf ? sf : tf;
    lowest = lowest < rest ? lowest : rest;
    lowest = det > 0.0 ? lowest : -1.0;
    weights(k, sf, tf, 0.25 * rest, w);
    keep(lowest >= 0.0 ? gap2(sf, tf, k) : std::numeric_limits<double>::infinity(), w[0], w[1], w[2], w[3]);
  }
  return best;
}

// The same for callers with arrays (setup, tests).
inline SegmentPoint closest_point_on_segment(const double node[3], const double x[4][3]) {
  auto v = [](const double* a) { return Vec3{a[0], a[1], a[2]}; };
  const FanPoint f = closest_on_fan(v(node), v(x[0]), v(x[1]), v(x[2]), v(x[3]));
  SegmentPoint s{{0, 0, 0}, {f.w0, f.w1, f.w2, f.w3}, std::sqrt(f.distance2)};
  for (int k = 0; k < 3; ++k) s.point[k] = f.w0 * x[0][k] + f.w1 * x[1][k] + f.w2 * x[2][k] + f.w3 * x[3][k];
  return s;
}

// The closest points of a batch of gathered pairs (state/contact_state.hpp, PairBatch), in one vectorised loop.
void closest_points(PairBatch& batch, int count);

}  // namespace crumple::contact
