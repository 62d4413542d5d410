#pragma once
// Physical hourglass stabilisation of the one-point 4-node shell, Ishell 24 (docs/theory/shell4.md, "Physical
// stabilisation", eqs. S-10 to S-14), the damped rotation modes of Ishell 1 and 2 (eqs. S-19, S-20), and the
// warping-free rates and viscous rotation modes of Ishell 3 (eqs. S-18a, S-18b). Plain functions over one
// element's local data, used by the shell kernel.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace crumple::shell_hourglass {

// The reference solver's quadratic hourglass viscosity of the rotation modes of Ishell 1, 2 (eq. S-19):
// 100 rho / 4 times its viscous share 1/2 times 1 / (8 sqrt 3) for the rotation modes = 25 / (16 sqrt 3).
inline constexpr double kRotationHourglassViscosity = 25.0 / (16.0 * 1.7320508075688772);

// Moment of a rotation hourglass mode of Ishell 1, 2 for its rate q = sum_a g_a theta_a [T^-1], g = 4 gamma the
// hourglass vector of S-5 (h = (1, -1, 1, -1) when not orthogonalised) (eq. S-19): C hr rho t^2 A |q| q, given to
// node a as g_a times it, in the deck's working units as the reference does.
inline double rotation_damping_moment(double hr, double density, double thickness, double area, double q) {
  return kRotationHourglassViscosity * hr * density * thickness * thickness * area * std::abs(q) * q;
}

// Moment of a rotation hourglass mode of Ishell 3 for its rate q = sum_a g_a theta_a [T^-1], g = 4 gamma as in S-19
// (eq. S-18b): purely viscous, nothing stored, q (c_l + c_q |q|) with c_l = sqrt(hr) rho t^2 A c / (32 sqrt 3),
// c = sqrt(E / rho) the bar speed, and c_q = 100 hr rho t^2 A / (32 sqrt 3) in the deck's working units, as the
// reference solver takes them. Node a gets g_a times it.
inline double viscous_rotation_moment(double hr, double density, double young, double thickness, double area,
                                      double q) {
  const double scale = density * thickness * thickness * area / (32.0 * std::numbers::sqrt3);  // rho t^2 A / (32 sqrt 3)
  const double linear = std::sqrt(hr) * scale * std::sqrt(young / density), quadratic = 100.0 * hr * scale;
  return q * (linear + quadratic * std::abs(q));
}

// Viscous force of the Ishell 1, 2 transverse hourglass mode for its rate q = gamma . vz [L/T] (eq. S-5b): c |q| q,
// c = (800 / sqrt 3) hf rho t^2 sqrt(kappa / (1 + nu)) [M/L], as measured on the reference solver (in any units).
inline double transverse_hourglass_damping(double hf, double density, double thickness, double shear_factor,
                                           double poisson, double q) {
  const double c = 800.0 / std::numbers::sqrt3 * hf * density * thickness * thickness *
                   std::sqrt(shear_factor / (1.0 + poisson));
  return c * std::abs(q) * q;
}

// Viscous force of an Ishell 1, 2 membrane hourglass mode for its rate q = gamma . vx (or vy) [L/T] (eq. S-5b):
// c |q| q, c = 800 hm rho t sqrt(A) [M/L], as measured on the reference solver (in any units).
inline double membrane_hourglass_damping(double hm, double density, double thickness, double area, double q) {
  return 800.0 * hm * density * thickness * std::sqrt(area) * std::abs(q) * q;
}

// A damper never reverses the motion it resists (eq. S-20): the viscous load of a mode of rate q (the moment of a
// rotation mode, the force of a translational one) is at most the one that stops the mode within the step dt on the
// element's share `inertia` of each node's inertia (rotational, or its mass), I |q| / (|g|^2 dt), g_norm = |g|^2.
inline double within_stopping_load(double load, double q, double inertia, double g_norm, double dt) {
  if (!(dt > 0.0)) return load;
  const double limit = inertia * std::abs(q) / (g_norm * dt);
  return std::clamp(load, -limit, limit);
}

// Warping height W = sum_a gamma_a z_a of a quadrilateral whose nodes stand z_a off its frame plane (eq. S-18a):
// a rigid rotation of the element about its in-plane axes moves its nodes in the plane by the rotation times z_a,
// which gamma reads as a membrane hourglass rate W dvz/dx (W dvz/dy) unless it is taken off.
inline double warping_height(const double gamma[4], const double z[4]) {
  return gamma[0] * z[0] + gamma[1] * z[1] + gamma[2] * z[2] + gamma[3] * z[3];
}

// The hourglass vector gamma of a quadrilateral (eq. S-5), from its local node coordinates and gradient operator
// (eq. S-2): h = (1, -1, 1, -1) orthogonalised against the linear fields, or h / 4 itself (Ishell 2, eq. S-17).
inline void hourglass_vector(const double lx[4], const double ly[4], const double b1[4], const double b2[4],
                             bool orthogonal, double gamma[4]) {
  constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};
  double hx = 0, hy = 0;
  for (int a = 0; a < 4; ++a) hx += h[a] * lx[a], hy += h[a] * ly[a];
  for (int a = 0; a < 4; ++a) gamma[a] = orthogonal ? 0.25 * (h[a] - hx * b1[a] - hy * b2[a]) : 0.25 * h[a];
}

// H_ij = integral over the element of h_,i h_,j with h = xi eta the bilinear mode (eq. S-10), from the Jacobian at
// the centre: H = (A / 3) (grad xi grad xi^T + grad eta grad eta^T), exact for parallelograms.
// lx, ly: local node coordinates (counter-clockwise, nodes at xi, eta = (-1,-1), (1,-1), (1,1), (-1,1)).
// Returns H_xx, H_yy, H_xy [-].
struct ShapeTensor {
  double xx, yy, xy;
};
inline ShapeTensor shape_tensor(const double lx[4], const double ly[4], double area) {
  // Jacobian d(x, y)/d(xi, eta) at the centre.
  const double x_xi = 0.25 * (-lx[0] + lx[1] + lx[2] - lx[3]), x_eta = 0.25 * (-lx[0] - lx[1] + lx[2] + lx[3]);
  const double y_xi = 0.25 * (-ly[0] + ly[1] + ly[2] - ly[3]), y_eta = 0.25 * (-ly[0] - ly[1] + ly[2] + ly[3]);
  const double det = x_xi * y_eta - x_eta * y_xi;
  // Rows of the inverse Jacobian: grad xi = (y_eta, -x_eta) / det, grad eta = (-y_xi, x_xi) / det.
  const double xi_x = y_eta / det, xi_y = -x_eta / det, eta_x = -y_xi / det, eta_y = x_xi / det;
  const double c = area / 3.0;
  return {c * (xi_x * xi_x + eta_x * eta_x), c * (xi_y * xi_y + eta_y * eta_y), c * (xi_x * xi_y + eta_x * eta_y)};
}

// Moments of the hourglass vector against the quadratic fields x^2, y^2, x y at the nodes (eq. S-13).
struct QuadraticMoments {
  double xx, yy, xy;
};
inline QuadraticMoments quadratic_moments(const double gamma[4], const double lx[4], const double ly[4]) {
  QuadraticMoments g{0.0, 0.0, 0.0};
  for (int a = 0; a < 4; ++a) {
    g.xx += gamma[a] * lx[a] * lx[a];
    g.yy += gamma[a] * ly[a] * ly[a];
    g.xy += gamma[a] * lx[a] * ly[a];
  }
  return g;
}

// Coefficients of the nodal rotations in the transverse-shear hourglass rate (eq. S-13):
// q_s = sum_a gamma_a vz_a + sum_a (cx_a tx_a + cy_a ty_a), removing the bilinear part of w that the rotations'
// linear (Kirchhoff) field explains, so that twisting and bending a thin plate leave the shear mode at rest.
inline void shear_rotation_coefficients(const QuadraticMoments& g, const double b1[4], const double b2[4], double cx[4],
                                        double cy[4]) {
  for (int a = 0; a < 4; ++a) {
    cx[a] = -0.5 * (g.yy * b2[a] + g.xy * b1[a]);
    cy[a] = 0.5 * (g.xx * b1[a] + g.xy * b2[a]);
  }
}

// The transverse-shear hourglass split in its two assumed-strain modes (eq. S-13a): the shear gamma_xz varying
// along y and gamma_yz varying along x have the rates q_s + D and q_s - D, with D = (theta_x,x + theta_y,y) g_xy / 2,
// the part of the rotations' gradient no Kirchhoff field has. The coefficients of the nodal rotations in D.
inline void shear_split_coefficients(const QuadraticMoments& g, const double b1[4], const double b2[4], double dx[4],
                                     double dy[4]) {
  for (int a = 0; a < 4; ++a) dx[a] = 0.5 * g.xy * b1[a], dy[a] = 0.5 * g.xy * b2[a];
}

// The QEPH shell's elastic-plastic hourglass (docs/theory/shell4.md, eq. S-12): the fractions of the elastic
// increment of the membrane and of the rotation (bending) hourglass stresses an element keeps in the cycle. The
// transverse-shear mode always keeps all of it.
struct HourglassKept {
  double membrane = 1.0, bending = 1.0;
};
// What the reduction reads of an element of a plastic law in the cycle.
struct HourglassYieldCheck {
  double yield = 0.0;                  // mean yield stress of the points at the start of the step [F/L^2], read
                                       // when every point stayed elastic
  double mean_ratio = 1.0;             // plain mean over the points of their tangent over E (1 for an elastic point)
  double min_ratio = 1.0;              // the smallest of them
  double mean_stress[3] = {0, 0, 0};   // N / t [F/L^2] (xx, yy, xy)
  double mean_moment[3] = {0, 0, 0};   // M / t^2 [F/L^2]
  double membrane_peak[2] = {0, 0};    // peak stress of the trial membrane modes, x and y [F/L^2]
  double bending_peak[2] = {0, 0};     // peak curvature stress of the trial rotation modes, x and y [F/L^3]
  double thickness = 0.0, poisson = 0.0;
  double moment_weight = 25.0;         // 25 with points through the thickness, 16 on the resultants (N = 0)
  double membrane_power = 0.0;         // old hourglass stresses times this cycle's rates: < 0 while unloading
  double bending_power = 0.0;
};
// Von Mises square a^2 + b^2 - a b + 3 c^2 of a plane stress.
inline double von_mises_squared(double a, double b, double c) { return a * a + b * b - a * b + 3.0 * c * c; }
// The hourglass modes' share of a section's von Mises square: the x mode's peak stress s_x comes with -nu s_x
// across, the y mode's likewise, and the two couple; each taken at 0.85 of its peak, as the reference does.
inline double hourglass_von_mises_squared(const double (&peak)[2], double nu) {
  const double own = (1.0 + nu + nu * nu) * (peak[0] * peak[0] + peak[1] * peak[1]);
  const double coupled = (1.0 + 4.0 * nu + nu * nu) * std::abs(peak[0] * peak[1]);
  return 0.85 * 0.85 * (own + coupled);
}
inline HourglassKept qeph_hourglass_kept(const HourglassYieldCheck& c) {
  HourglassKept kept;
  const double y2 = c.yield * c.yield;
  double membrane_cut = 0.0, bending_cut = 0.0;
  bool plastic = 1.0 - c.min_ratio >= 1e-18;  // a point yielded in the cycle
  if (!plastic && y2 > 0.0) {
    // Every point elastic: the section's mean membrane and bending stresses with the hourglass stresses added
    // must stay inside the yield surface, N^2 + K M^2 <= sigma_y^2.
    const double bending_scale[2] = {c.bending_peak[0] * c.thickness / 16.0, c.bending_peak[1] * c.thickness / 16.0};
    const double sn = von_mises_squared(c.mean_stress[0], c.mean_stress[1], c.mean_stress[2]) +
                      hourglass_von_mises_squared(c.membrane_peak, c.poisson);
    const double sm = von_mises_squared(c.mean_moment[0], c.mean_moment[1], c.mean_moment[2]) +
                      hourglass_von_mises_squared(bending_scale, c.poisson);
    if (sn + c.moment_weight * sm > y2) plastic = true, membrane_cut = 0.999 * std::min(sn / y2, 1.0);
  }
  if (plastic) {
    membrane_cut = std::max(membrane_cut, 1.0 - c.mean_ratio);
    bending_cut = std::max(0.999, 1.0 - c.min_ratio);
  }
  if (c.membrane_power < 0.0) membrane_cut = 0.0;  // unloading is elastic
  if (c.bending_power < 0.0) bending_cut = 0.0;
  kept.membrane = 1.0 - membrane_cut, kept.bending = 1.0 - bending_cut;
  return kept;
}

}  // namespace crumple::shell_hourglass
