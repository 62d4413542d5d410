#pragma once
// Pieces shared by the shell kernels (docs/theory/shell4.md): the element frames and the stress update of one
// section (the through-thickness points of one in-plane integration point, eq. S-4, or the stress resultants of
// N = 0, eqs. RP-1 to RP-3). Plain inline functions, used inside the element loops.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstddef>

#include "crumple/elements/shell4.hpp"
#include "crumple/materials/plane_stress.hpp"
#include "crumple/materials/resultant_plasticity.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/core/vec3.hpp"
#include "crumple/model/properties.hpp"

namespace crumple::shell_section {

// Co-rotational frame of an element (eq. S-1) from its current node positions. Quadrilateral: normal from the
// diagonals, e1 along the mean of the sides 1-2 and 4-3. Triangle: normal from two sides, e1 along the side 1-2.
// Returns false (frame unset) when the normal vanishes.
struct Frame {
  Vec3 e1, e2, e3, centre;
};
template <int NN>
inline bool corotational_frame(const Vec3 (&x)[NN], Frame& f) {
  Vec3 normal, side;
  if constexpr (NN == 4) {
    normal = cross(x[2] - x[0], x[3] - x[1]);
    side = (x[1] - x[0]) + (x[2] - x[3]);
  } else {
    normal = cross(x[1] - x[0], x[2] - x[0]);
    side = x[1] - x[0];
  }
  const double normal_length = std::sqrt(dot(normal, normal));
  if (!(normal_length > 0.0)) return false;
  f.e3 = scaled(normal, 1.0 / normal_length);
  f.e1 = unit(side - scaled(f.e3, dot(side, f.e3)));
  f.e2 = cross(f.e3, f.e1);
  constexpr double mean = 1.0 / NN;
  f.centre = Vec3{0.0, 0.0, 0.0};
  for (int a = 0; a < NN; ++a) f.centre = f.centre + scaled(x[a], mean);
  return true;
}

// Corner a's plane, spanned by its two sides (eq. S-1a): its normal of any length and `dual` = normal / |normal|^2,
// so that v - dual (v . normal) is v in the plane without a square root. Parallel sides take the unit `fallback`.
struct CornerPlane {
  Vec3 normal, dual;
};
template <int NN>
inline CornerPlane corner_plane(const Vec3 (&x)[NN], int a, const Vec3& fallback) {
  const Vec3 n = cross(x[(a + 1) % NN] - x[a], x[(a + NN - 1) % NN] - x[a]);
  const double length2 = dot(n, n);
  if (!(length2 > 0.0)) return {fallback, fallback};
  return {n, scaled(n, 1.0 / length2)};
}
// v without its component along the corner's normal.
inline Vec3 in_corner_plane(const Vec3& v, const CornerPlane& plane) {
  return v - scaled(plane.dual, dot(v, plane.normal));
}

// Area of the element's projection on its frame plane from the local coordinates (eqs. S-2, S-9).
template <int NN>
inline double local_area(const double (&lx)[NN], const double (&ly)[NN]) {
  if constexpr (NN == 4) return 0.5 * ((lx[2] - lx[0]) * (ly[3] - ly[1]) - (lx[3] - lx[1]) * (ly[2] - ly[0]));
  return 0.5 * ((lx[1] - lx[0]) * (ly[2] - ly[0]) - (lx[2] - lx[0]) * (ly[1] - ly[0]));
}

// Characteristic length of the critical step [L]: triangle twice the area over its longest side, quadrilateral
// the area over its longest side (eq. T-1), or with `belytschko_tsay` (Ishell 1 to 4) the length of eq. T-1b.
template <int NN>
inline double characteristic_length(const double (&lx)[NN], const double (&ly)[NN], double area,
                                    bool belytschko_tsay = false) {
  double longest = 0.0, shortest = 1e300;
  for (int a = 0; a < NN; ++a) {
    const double sx = lx[(a + 1) % NN] - lx[a], sy = ly[(a + 1) % NN] - ly[a];
    longest = std::max(longest, sx * sx + sy * sy);
    shortest = std::min(shortest, sx * sx + sy * sy);
  }
  if constexpr (NN == 4) {
    if (belytschko_tsay) {
      const double d13 = (lx[2] - lx[0]) * (lx[2] - lx[0]) + (ly[2] - ly[0]) * (ly[2] - ly[0]);
      const double d24 = (lx[3] - lx[1]) * (lx[3] - lx[1]) + (ly[3] - ly[1]) * (ly[3] - ly[1]);
      return geometry::belytschko_tsay_length(area, std::sqrt(shortest), std::sqrt(std::max(d13, d24)));
    }
  }
  return (NN == 4 ? area : 2.0 * area) / std::sqrt(longest);
}

// The one-point shells' characteristic length (docs/theory/time-step.md): eq. T-1b for Ishell 1 to 4, T-1d for the
// QEPH shell (Ishell 24), T-1 for the triangle; the kernel's and the small-strain switch's [L].
template <int NN>
inline double one_point_length(const ShellGroupParameters& p, const double (&lx)[NN], const double (&ly)[NN],
                               double area) {
  if constexpr (NN == 4)
    if (p.physical_hourglass) return geometry::qeph_length(lx, ly, area);
  return characteristic_length<NN>(lx, ly, area, true);
}

// Generalised strain rates of a section in its frame: membrane (dxx, dyy, gxy = 2 dxy) [1/T] and curvature
// (kxx, kyy, kxy = 2 kxy) [1/(L T)] (eq. S-3).
struct StrainRates {
  double dxx, dyy, gxy, kxx, kyy, kxy;
};

// Resultants per unit length of a section: N [M T^-2], M [M L T^-2] (xx, yy, xy).
struct Resultants {
  double n[3] = {0.0, 0.0, 0.0}, m[3] = {0.0, 0.0, 0.0};
};

// The resultants of the section's stored stresses (eq. S-4): N = t sum w_k sigma_k, M = t^2 sum b_k sigma_k over the
// through-thickness points; N = 0 (RP-1): N = t sigma_m from the membrane stress at the point and M = t^2 / 6 sigma_b
// from the outer-fibre bending stress. `first` is the ShellState index of the section's first point, `bending` its
// three bending stresses when N = 0 (else unused).
inline Resultants resultants(const ShellGroupParameters& p, const ShellState& state, std::size_t first,
                             const double* bending, double t) {
  Resultants r;
  if (p.resultant_plasticity) {
    const double bending_lever = t * t / 6.0;
    const double membrane[3] = {state.sxx[first], state.syy[first], state.sxy[first]};
    for (int c = 0; c < 3; ++c) r.n[c] = t * membrane[c], r.m[c] = bending_lever * bending[c];
    return r;
  }
  for (int k = 0; k < p.points; ++k) {
    const std::size_t ip = first + static_cast<std::size_t>(k);
    const double wn = p.membrane_weight[k] * t, wm = p.bending_weight[k] * t * t;
    const double sxx = state.sxx[ip], syy = state.syy[ip], sxy = state.sxy[ip];
    r.n[0] += wn * sxx, r.n[1] += wn * syy, r.n[2] += wn * sxy;
    r.m[0] += wm * sxx, r.m[1] += wm * syy, r.m[2] += wm * sxy;
  }
  return r;
}

// Resultants per unit length before and after the update: N [M T^-2], M [M L T^-2] (xx, yy, xy).
struct Update {
  double n[3] = {0.0, 0.0, 0.0}, m[3] = {0.0, 0.0, 0.0};
  double old_n[3] = {0.0, 0.0, 0.0}, old_m[3] = {0.0, 0.0, 0.0};
  double thickness_strain = 0.0;  // membrane-weighted through-thickness strain increment
  double tangent_ratio = 1.0;     // plain mean over the points of their tangent over E (eq. S-12)
  double min_tangent_ratio = 1.0; // the smallest of them
  bool failed = false;            // a point reached the failure strain
};

// N = 0: one set of resultants, carried as the membrane stress N / t at the point and the outer-fibre bending
// stress 6 M / t^2 (docs/theory/materials.md, RP-1 to RP-3), updated over dt > 0.
inline void update_resultants(const ShellGroupParameters& p, const materials::PlaneStressElastic& elastic,
                              ShellState& state, std::size_t first, double* bending, double t, const StrainRates& s,
                              double dt, Update& u) {
  double membrane[3] = {state.sxx[first], state.syy[first], state.sxy[first]};
  const double h = 0.5 * t;
  const materials::ResultantIncrement d{{s.dxx * dt, s.dyy * dt, s.gxy * dt},
                                        {h * s.kxx * dt, h * s.kyy * dt, h * s.kxy * dt}};
  // Strain rate of the more strained surface fibre.
  auto fibre_rate = [&](double sign) {
    const double ex = d.membrane[0] + sign * d.bending[0], ey = d.membrane[1] + sign * d.bending[1];
    const double g = d.membrane[2] + sign * d.bending[2];
    return std::sqrt(2.0 / 3.0 * (ex * ex + ey * ey + (ex + ey) * (ex + ey) + 0.5 * g * g)) / dt;
  };
  const double rate = p.hardening.filtered_rate(std::max(fibre_rate(1.0), fibre_rate(-1.0)), state.eps_rate[first], dt);
  state.eps_rate[first] = stored(rate);
  const auto r = materials::resultant_update(elastic, p.hardening, d, rate, state.eps_p[first], membrane, bending);
  state.eps_p[first] = stored(state.eps_p[first] + r.plastic_strain_increment);
  if (r.plastic_strain_increment > 0.0 && p.physical_hourglass) {
    const double slope = std::max(p.hardening.slope(state.eps_p[first], rate), 0.0);
    u.tangent_ratio = u.min_tangent_ratio = slope / (p.young + slope);  // eq. S-12
  }
  u.thickness_strain = r.thickness_strain;
  if (p.failure_strain > 0.0 && state.eps_p[first] >= p.failure_strain) u.failed = true;
  state.sxx[first] = stored(membrane[0]), state.syy[first] = stored(membrane[1]), state.sxy[first] = stored(membrane[2]);
}

// The stresses at the through-thickness points, updated over dt > 0 by the plane-stress return (eq. S-4).
inline void update_points(const ShellGroupParameters& p, const materials::PlaneStressElastic& elastic,
                          ShellState& state, std::size_t first, double t, const StrainRates& s, double dt, Update& u) {
  const double E = p.young;
  for (int k = 0; k < p.points; ++k) {
    const std::size_t ip = first + static_cast<std::size_t>(k);
    const double z = p.zeta[k] * t;
    double sxx = state.sxx[ip], syy = state.syy[ip], sxy = state.sxy[ip];
    const double ex = (s.dxx + z * s.kxx) * dt, ey = (s.dyy + z * s.kyy) * dt, g = (s.gxy + z * s.kxy) * dt;
    const double increment_rate = std::sqrt(2.0 / 3.0 * (ex * ex + ey * ey + (ex + ey) * (ex + ey) + 0.5 * g * g)) / dt;
    const double rate = p.hardening.filtered_rate(increment_rate, state.eps_rate[ip], dt);  // eq. RF
    state.eps_rate[ip] = stored(rate);
    const auto return_to_yield = p.radial_return ? materials::plane_stress_radial_return : materials::plane_stress_update;
    const auto r = return_to_yield(elastic, p.hardening, ex, ey, g, rate, state.eps_p[ip], sxx, syy, sxy,
                                   &state.hardening_term[ip]);
    state.eps_p[ip] = stored(state.eps_p[ip] + r.plastic_strain_increment);
    if (r.plastic_strain_increment > 0.0 && p.physical_hourglass) {
      // Elastic-plastic tangent of the point, E H' / (E + H'), for the hourglass modes (eq. S-12).
      const double slope = std::max(p.hardening.has_kept_term()
                                        ? p.hardening.slope_from_term(state.eps_p[ip], state.hardening_term[ip], rate)
                                        : p.hardening.slope(state.eps_p[ip], rate),
                                    0.0);
      u.tangent_ratio -= (E / (E + slope)) / p.points;
      u.min_tangent_ratio = std::min(u.min_tangent_ratio, slope / (E + slope));
    }
    u.thickness_strain += p.membrane_weight[k] * r.thickness_strain;
    if (p.failure_strain > 0.0 && state.eps_p[ip] >= p.failure_strain) u.failed = true;
    state.sxx[ip] = stored(sxx), state.syy[ip] = stored(syy), state.sxy[ip] = stored(sxy);
  }
}

// Updates the section's stresses over dt (dt = 0: no update) and returns its resultants before and after. `first`
// is the ShellState index of its first point; `bending` its three outer-fibre bending stresses 6 M / t^2 when N = 0
// (else unused).
inline Update update(const ShellGroupParameters& p, const materials::PlaneStressElastic& elastic, ShellState& state,
                     std::size_t first, double* bending, double t, const StrainRates& s, double dt) {
  Update u;
  const Resultants before = resultants(p, state, first, bending, t);
  for (int c = 0; c < 3; ++c) u.old_n[c] = before.n[c], u.old_m[c] = before.m[c];
  if (dt > 0.0 && p.resultant_plasticity) update_resultants(p, elastic, state, first, bending, t, s, dt, u);
  else if (dt > 0.0) update_points(p, elastic, state, first, t, s, dt, u);
  const Resultants after = resultants(p, state, first, bending, t);
  for (int c = 0; c < 3; ++c) u.n[c] = after.n[c], u.m[c] = after.m[c];
  return u;
}

// Work of the section over the step, trapezoidal in the resultants (eq. S-6), per unit area [M T^-2].
inline double work(const Update& u, const StrainRates& s, double dt) {
  return 0.5 * dt * ((u.old_n[0] + u.n[0]) * s.dxx + (u.old_n[1] + u.n[1]) * s.dyy + (u.old_n[2] + u.n[2]) * s.gxy +
                     (u.old_m[0] + u.m[0]) * s.kxx + (u.old_m[1] + u.m[1]) * s.kyy + (u.old_m[2] + u.m[2]) * s.kxy);
}

// Membrane forces per unit length [F/L] (xx, yy, xy).
struct MembraneForces {
  double xx, yy, xy;
};
// The length of the membrane damping (eq. S-9d, S-9f): the square root of the area [L^2], as the reference takes
// it, but at most twice the element's step length [L], so that a sliver's damping stays within what its step holds.
inline double membrane_damping_length(double area, double step_length) {
  return std::min(std::sqrt(area), 2.0 * step_length);
}
// Membrane damping dm of a section of thickness t [L] (docs/theory/shell4.md, eq. S-9d): the viscous mean stress
// eta (d_xx + d_yy / 2, d_yy + d_xx / 2, g_xy / 3), eta = sqrt(2) dm rho c l, c the element's wave speed [L/T] and
// l membrane_damping_length, times t; d the membrane strain rates [1/T].
inline MembraneForces membrane_damping(double dm, double density, double wave_speed, double length, double t, double dxx,
                                       double dyy, double gxy) {
  const double eta = std::numbers::sqrt2 * dm * density * wave_speed * length * t;
  return {eta * (dxx + 0.5 * dyy), eta * (dyy + 0.5 * dxx), eta * gxy / 3.0};
}
// The work over dt of a viscous force `now` [F] that replaces `last`, the previous cycle's, on a rate [1/T] (eq.
// S-9e): the trapezoid, as the stresses' (S-6), so that the force of a cycle is paired with the mean of the rates
// before and after it; `last` becomes `now`. A force times the rate it was computed from counts, in a mode near
// the step's limit whose rate changes sign each cycle, work that the mode does not lose.
inline double viscous_work(float& last, double now, double rate, double dt) {
  const double work = 0.5 * (static_cast<double>(last) + now) * rate * dt;
  last = static_cast<float>(now);
  return work;
}
using crumple::damped_step_factor;  // eq. T-1c (model/properties.hpp)
// The viscous fraction that shortens a one-point shell's step (eq. T-1c, model/properties.hpp).
inline double step_damping(const ShellGroupParameters& p) {
  return shell_step_damping(p.physical_hourglass, p.membrane_damping, p.numerical_damping);
}

// The linked deflection of the 3-node shell (docs/theory/shell4.md, eq. S-9a): along each side i-j the deflection
// takes the quadratic term (1/2) N_i N_j (x_j - x_i) . (beta_j - beta_i), beta = (theta_y, -theta_x) the fibre's
// tilt, so that the mean transverse shear over the element is grad w + mean beta - (1/6) sum_k grad N_k s_k with
// s_k that term's amplitude on the side opposite node k. Fills s_k [L/T] from the local coordinates lx, ly [L]
// and the rotation rates tx, ty [1/T].
inline void linked_shear_terms(const double (&lx)[3], const double (&ly)[3], const double (&tx)[3],
                               const double (&ty)[3], double (&s)[3]) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    s[k] = (lx[j] - lx[i]) * (ty[j] - ty[i]) - (ly[j] - ly[i]) * (tx[j] - tx[i]);
  }
}
// The moments at node `a` that the linked terms of eq. S-9a give the shear resultants (qx, qy) [F/L]: the transpose
// of linked_shear_terms, so that their power is A (qx, qy) . (the shear they take off). Adds to mx, my [F L].
inline void add_linked_shear_moments(const double (&lx)[3], const double (&ly)[3], const double (&b1)[3],
                                     const double (&b2)[3], double qx, double qy, double area, int a, double& mx,
                                     double& my) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (a != i && a != j) continue;
    const double c = -area * (b1[k] * qx + b2[k] * qy) / 6.0, sign = a == j ? 1.0 : -1.0;
    my += sign * c * (lx[j] - lx[i]);
    mx -= sign * c * (ly[j] - ly[i]);
  }
}

}  // namespace crumple::shell_section
