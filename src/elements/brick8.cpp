// 8-node bricks (docs/theory/brick8.md). Isolid 1: Flanagan-Belytschko uniform gradient at one point, bulk
// viscosity, viscous hourglass control on the orthogonalised hourglass vectors. Isolid 24: the same one point with
// an elastic, assumed-strain hourglass stiffness in a co-rotational frame. Isolid 14: 2x2x2 Gauss points with the
// mean dilatation (B-bar) for the pressure. All three share the 3-D material update (materials/solid_update).
#include "crumple/elements/brick8.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/materials/solid_update.hpp"
#include "crumple/model/properties.hpp"
#include "crumple/core/geometry.hpp"

namespace crumple {
namespace {

// Natural coordinates of the nodes (eq. B-1): node I sits at (kS1[I], kS2[I], kS3[I]).
constexpr double kS1[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr double kS2[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr double kS3[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
// Hourglass base vectors (eq. B-5): the nodal values of r s... products s t, r t, r s, r s t.
constexpr double kH[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                             {1, -1, -1, 1, -1, 1, 1, -1},
                             {1, -1, 1, -1, 1, -1, 1, -1},
                             {-1, 1, -1, 1, 1, -1, 1, -1}};

// Faces for the characteristic length (eq. B-12).
constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Derivatives of the shape functions with respect to r, s, t at the 2x2x2 Gauss points (eq. B-10); point g sits at
// (kS1[g], kS2[g], kS3[g]) / sqrt(3), next to node g.
struct GaussDerivatives {
  double d[8][3][8];  // [point][natural direction][node]
};
constexpr GaussDerivatives gauss_derivatives() {
  constexpr double a = 0.57735026918962576451;  // 1 / sqrt(3)
  GaussDerivatives t{};
  for (int g = 0; g < 8; ++g) {
    const double r = a * kS1[g], s = a * kS2[g], u = a * kS3[g];
    for (int i = 0; i < 8; ++i) {
      t.d[g][0][i] = 0.125 * kS1[i] * (1.0 + kS2[i] * s) * (1.0 + kS3[i] * u);
      t.d[g][1][i] = 0.125 * kS2[i] * (1.0 + kS1[i] * r) * (1.0 + kS3[i] * u);
      t.d[g][2][i] = 0.125 * kS3[i] * (1.0 + kS1[i] * r) * (1.0 + kS2[i] * s);
    }
  }
  return t;
}
constexpr GaussDerivatives kGauss = gauss_derivatives();

// Cofactor matrix C of a 3x3 matrix (C / det = A^-T) and the determinant.
double cofactor(const double a[3][3], double c[3][3]) {
  c[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  c[0][1] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  c[0][2] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  c[1][0] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
  c[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
  c[1][2] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
  c[2][0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
  c[2][1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
  c[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  return a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
}

// Rotation R of the polar decomposition J = R U (eq. B-8), by the scaled Newton iteration
// X <- (z X + X^-T / z) / 2 with z = |det X|^(-1/3). The scaling only speeds the iteration up: once the first
// step has brought det X near 1, z = 1 converges as fast, and the cube root is a fifth of a brick's cycle.
void polar_rotation(const double j[3][3], double r[3][3]) {
  double x[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) x[i][k] = j[i][k];
  for (int it = 0; it < 50; ++it) {
    double c[3][3];
    const double det = cofactor(x, c);
    const double z = std::abs(std::abs(det) - 1.0) < 0.1 ? 1.0 : 1.0 / std::cbrt(std::abs(det));
    double change = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        const double next = 0.5 * (z * x[i][k] + c[i][k] / (det * z));
        change += (next - x[i][k]) * (next - x[i][k]);
        x[i][k] = next;
      }
    if (change < 1e-28) break;
  }
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) r[i][k] = x[i][k];
}

double largest_face_area(const double* x, const double* y, const double* z) {
  double largest = 0.0;
  for (const auto& f : kFaces) {
    // A = |d13 x d24| / 2
    const double ax = x[f[2]] - x[f[0]], ay = y[f[2]] - y[f[0]], az = z[f[2]] - z[f[0]];
    const double bx = x[f[3]] - x[f[1]], by = y[f[3]] - y[f[1]], bz = z[f[3]] - z[f[1]];
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    largest = std::max(largest, 0.25 * (cx * cx + cy * cy + cz * cz));
  }
  return std::sqrt(largest);
}

// Element data gathered once: coordinates relative to the centroid (round-off) and velocities.
struct Element {
  double x[8], y[8], z[8];     // current, relative to the centroid
  double vx[8], vy[8], vz[8];
  double mx[8], my[8], mz[8];  // mid-step x - dt v / 2
};

void gather(const NodalState& nodes, const std::int32_t* n, double dt, Element& el) {
  double cx = 0.0, cy = 0.0, cz = 0.0;
  for (int a = 0; a < 8; ++a) {
    const auto k = static_cast<std::size_t>(n[a]);
    el.x[a] = nodes.x[k], el.y[a] = nodes.y[k], el.z[a] = nodes.z[k];
    el.vx[a] = nodes.vx[k], el.vy[a] = nodes.vy[k], el.vz[a] = nodes.vz[k];
    cx += el.x[a], cy += el.y[a], cz += el.z[a];
  }
  cx *= 0.125, cy *= 0.125, cz *= 0.125;
  for (int a = 0; a < 8; ++a) {
    el.x[a] -= cx, el.y[a] -= cy, el.z[a] -= cz;
    el.mx[a] = el.x[a] - 0.5 * dt * el.vx[a];
    el.my[a] = el.y[a] - 0.5 * dt * el.vy[a];
    el.mz[a] = el.z[a] - 0.5 * dt * el.vz[a];
  }
}

// Centre Jacobian J0 = [g_r g_s g_t], g_k = sum_I k_I x_I / 8 (eq. B-8).
void centre_jacobian(const double* x, const double* y, const double* z, double j0[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) j0[i][k] = 0.0;
  for (int a = 0; a < 8; ++a) {
    const double xa[3] = {x[a], y[a], z[a]}, sa[3] = {kS1[a], kS2[a], kS3[a]};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) j0[i][k] += 0.125 * sa[k] * xa[i];
  }
}

// Turn of the element frame over the step (Iframe 2, eq. B-3a): the frames R0, R1 of eq. B-8 at x^(n-1) and x^n
// give dR = R1 R0^T.
void frame_turn(const Element& el, double dr[3][3]) {
  double x0[8], y0[8], z0[8];
  for (int a = 0; a < 8; ++a) x0[a] = 2.0 * el.mx[a] - el.x[a], y0[a] = 2.0 * el.my[a] - el.y[a], z0[a] = 2.0 * el.mz[a] - el.z[a];
  double j[3][3], r0[3][3], r1[3][3];
  centre_jacobian(x0, y0, z0, j);
  polar_rotation(j, r0);
  centre_jacobian(el.x, el.y, el.z, j);
  polar_rotation(j, r1);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) dr[i][k] = r1[i][0] * r0[k][0] + r1[i][1] * r0[k][1] + r1[i][2] * r0[k][2];
}

// The spin whose Cayley transform (eq. SU-2) is dR exactly: w dt = 4 axial(dR) / (1 + tr dR). Per unit time.
void spin_of_turn(const double dr[3][3], double dt, double w[3]) {
  w[0] = w[1] = w[2] = 0.0;
  if (!(dt > 0.0)) return;
  const double f = 2.0 / ((1.0 + dr[0][0] + dr[1][1] + dr[2][2]) * dt);  // 4 / (1 + tr) times the half difference
  w[0] = f * (dr[2][1] - dr[1][2]), w[1] = f * (dr[0][2] - dr[2][0]), w[2] = f * (dr[1][0] - dr[0][1]);
}

// Small strain (eq. B-14): the element's current and mid-step geometries become its frozen reference shape, turned
// by the rotation of the element frame since the freeze (Ismstr 1, 2) or kept as frozen (Ismstr 3).
void use_reference_shape(const BrickGroupParameters& p, const BrickState& state, std::size_t e, double dt,
                         const double dr[3][3], Element& el) {
  const double* shape = &state.reference_shape[24 * e];
  if (p.ismstr != 3 && dt > 0.0)  // objective: the velocities lose the frame's rigid turn, (I - dR^T) x / dt
    for (int a = 0; a < 8; ++a) {
      const double x[3] = {el.x[a], el.y[a], el.z[a]};
      double* v[3] = {&el.vx[a], &el.vy[a], &el.vz[a]};
      for (int i = 0; i < 3; ++i) *v[i] -= (x[i] - dr[0][i] * x[0] - dr[1][i] * x[1] - dr[2][i] * x[2]) / dt;
    }
  double turn[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // R_now R_freeze^T
  if (p.ismstr != 3) {
    double j0[3][3], now[3][3];
    centre_jacobian(el.x, el.y, el.z, j0);
    polar_rotation(j0, now);
    const double* frozen = &state.reference_frame[9 * e];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) turn[i][j] = now[i][0] * frozen[3 * j] + now[i][1] * frozen[3 * j + 1] +
                                               now[i][2] * frozen[3 * j + 2];
  }
  for (int a = 0; a < 8; ++a) {
    const double* x = shape + 3 * a;
    el.x[a] = el.mx[a] = turn[0][0] * x[0] + turn[0][1] * x[1] + turn[0][2] * x[2];
    el.y[a] = el.my[a] = turn[1][0] * x[0] + turn[1][1] * x[1] + turn[1][2] * x[2];
    el.z[a] = el.mz[a] = turn[2][0] * x[0] + turn[2][1] * x[1] + turn[2][2] * x[2];
  }
}

// Rate of deformation (engineering shears) and spin axial vector from the velocity gradient L_ij = dv_i/dx_j
// (eq. B-3).
struct Rates {
  double d[6];  // dxx, dyy, dzz, gxy, gyz, gzx
  double w[3];  // axial vector of W = (L - L^T) / 2
};
Rates rates_of(const double l[3][3]) {
  Rates r{};
  r.d[0] = l[0][0], r.d[1] = l[1][1], r.d[2] = l[2][2];
  r.d[3] = l[0][1] + l[1][0], r.d[4] = l[1][2] + l[2][1], r.d[5] = l[2][0] + l[0][2];
  r.w[0] = 0.5 * (l[2][1] - l[1][2]);
  r.w[1] = 0.5 * (l[0][2] - l[2][0]);
  r.w[2] = 0.5 * (l[1][0] - l[0][1]);
  return r;
}

// Stress at point ip: load, rotate by the spin increment, update with the strain increment; returns the
// stress power's mid-step value (s_old + s_new) : d / 2 per unit volume and updates eps_p.
struct PointUpdate {
  double power = 0.0;
  bool failed = false;
};
PointUpdate update_point(const BrickGroupParameters& p, const materials::SolidElastic& elastic, BrickState& st,
                         std::size_t ip, const Rates& r, double dt, double* s) {
  s[0] = st.sxx[ip], s[1] = st.syy[ip], s[2] = st.szz[ip], s[3] = st.sxy[ip], s[4] = st.syz[ip], s[5] = st.szx[ip];
  PointUpdate u;
  if (!(dt > 0.0)) return u;
  materials::rotate_stress(s, r.w[0] * dt, r.w[1] * dt, r.w[2] * dt);  // eq. SU-2
  double old[6], de[6];
  for (int k = 0; k < 6; ++k) old[k] = s[k], de[k] = r.d[k] * dt;
  const double rate = p.hardening.filtered_rate(materials::equivalent_strain(de) / dt, st.eps_rate[ip], dt);  // eq. RF
  st.eps_rate[ip] = stored(rate);
  const auto res = materials::solid_update(elastic, p.hardening, de, rate, st.eps_p[ip], s);  // eq. SU-1, SU-3
  st.eps_p[ip] = stored(st.eps_p[ip] + res.plastic_strain_increment);
  if (p.failure_strain > 0.0 && st.eps_p[ip] >= p.failure_strain) u.failed = true;
  // The stored stress carries on, also into this step's work (eq. PR-2).
  point_real* const stress[6] = {&st.sxx[ip], &st.syy[ip], &st.szz[ip], &st.sxy[ip], &st.syz[ip], &st.szx[ip]};
  for (int k = 0; k < 6; ++k) *stress[k] = stored(s[k]), s[k] = *stress[k];
  for (int k = 0; k < 6; ++k) u.power += 0.5 * (old[k] + s[k]) * r.d[k];  // engineering shears: no factor 2
  return u;
}

// Bulk viscosity pressure q and the speed Q it adds in the time-step estimate (eq. B-7, B-12): the pressure acts
// in compression only, the linear term's speed bounds the step at rest and in tension too, as in the reference.
struct Viscosity {
  double q = 0.0;      // [stress], > 0 in compression
  double speed = 0.0;  // Q = qb c (+ qa^2 L |dv| in compression) [L/T]
};
Viscosity bulk_viscosity(const BrickGroupParameters& p, double rho, double c, double length, double dv) {
  Viscosity v{0.0, p.qb * c};
  if (dv < 0.0) {
    v.speed += p.qa * p.qa * length * (-dv);
    v.q = rho * length * v.speed * (-dv);
  }
  return v;
}

// Assumed-strain stabilisation of Isolid 24 (eq. B-9): increments dQ of the 12 generalized hourglass stresses
// (local frame, [direction][mode]) for the increments dq of the hourglass rates times dt, in a parallelepiped of
// half-widths a[3] and volume V. Modes 0, 1, 2 are the products s t, r t, r s (mode k lacks coordinate k); mode 3
// is r s t. `bulk` is the modulus that the hourglass strains' volume change meets: the material's K, or 0 with a
// constant pressure (Icpre 1, eq. B-9a).
void stabilisation_increment(const double a[3], double volume, double bulk, double shear, const double dq[3][4],
                             double dQ[3][4]) {
  const double normal = bulk + 4.0 / 3.0 * shear;  // d sigma_nn / d e_nn with the other normal strains held
  const double cross = bulk - 2.0 / 3.0 * shear;   // d sigma_nn / d e_pp
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 4; ++k) dQ[i][k] = 0.0;
  for (int m = 0; m < 3; ++m) {
    const int n = (m + 1) % 3, q = (m + 2) % 3;
    // Strain field linear in the natural coordinate of axis m: mode q (= coordinates n, m) along n stretches n,
    // mode n (= coordinates q, m) along q stretches q, and the two cross terms shear the n-q plane. The shears
    // of the m direction (d v_m / d x_n ... linear in that same coordinate) are left out: they are the parasitic
    // shears of bending. The stretch along m is zero: that field has no d/dx_m.
    const double hn = 1.0 / (8.0 * a[n]), hq = 1.0 / (8.0 * a[q]);
    const double enn = dq[n][q] * hn, eqq = dq[q][n] * hq;
    const double gnq = dq[n][n] * hq + dq[q][q] * hn;
    const double w = volume / 3.0;  // integral of the coordinate squared
    const double snn = normal * enn + cross * eqq, sqq = cross * enn + normal * eqq, tnq = shear * gnq;
    dQ[n][q] += w * snn * hn;
    dQ[q][n] += w * sqq * hq;
    dQ[n][n] += w * tnq * hq;
    dQ[q][q] += w * tnq * hn;
    // Mode 3 (r s t): gradient along axis m times the product of the two other coordinates, one stretch and two
    // shears.
    const double hm = 1.0 / (8.0 * a[m]);
    const double w3 = volume / 9.0;
    dQ[m][3] += w3 * normal * dq[m][3] * hm * hm;
    dQ[n][3] += w3 * shear * dq[n][3] * hm * hm;
    dQ[q][3] += w3 * shear * dq[q][3] * hm * hm;
  }
}

// Kinematics of Gauss point g (eq. B-10): the velocity gradient on the mid-step geometry, the cofactor matrix of
// the current Jacobian (det J B_I = C grad_rst N_I) and both determinants. False when a determinant is not
// positive.
struct PointKinematics {
  double l[3][3] = {};  // L = dv/dx at x^(n-1/2)
  double cn[3][3];      // cofactors of J at x^n
  double det_mid = 0.0, det_now = 0.0;
};
bool point_kinematics(const Element& el, int g, PointKinematics& pk) {
  const auto& dn = kGauss.d[g];
  double jm[3][3] = {}, jn[3][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k) {
      jm[0][k] += el.mx[a] * dn[k][a], jm[1][k] += el.my[a] * dn[k][a], jm[2][k] += el.mz[a] * dn[k][a];
      jn[0][k] += el.x[a] * dn[k][a], jn[1][k] += el.y[a] * dn[k][a], jn[2][k] += el.z[a] * dn[k][a];
    }
  double cm[3][3];
  pk.det_mid = cofactor(jm, cm);
  pk.det_now = cofactor(jn, pk.cn);
  if (!(pk.det_mid > 0.0) || !(pk.det_now > 0.0)) return false;
  for (int a = 0; a < 8; ++a) {
    double b[3];  // dN_a/dx = J^-T dN_a/dxi = C dN_a/dxi / det
    for (int i = 0; i < 3; ++i) b[i] = (cm[i][0] * dn[0][a] + cm[i][1] * dn[1][a] + cm[i][2] * dn[2][a]) / pk.det_mid;
    const double v[3] = {el.vx[a], el.vy[a], el.vz[a]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) pk.l[i][j] += v[i] * b[j];
  }
  return true;
}

// The share of the 8-point element's pressure taken constant over it (eq. B-9c): 1 with Icpre 1, 0 with Icpre 3, and
// with Icpre 2 sqrt(eps_p / (sigma_vm / E + eps_p)) of the element's mean plastic strain and mean stress before the
// step: 0 while it is elastic, towards 1 as plastic flow, incompressible, takes over.
double constant_pressure_share(const BrickGroupParameters& p, const BrickState& st, std::size_t first) {
  if (p.constant_pressure) return 1.0;
  if (!p.plastic_pressure) return 0.0;
  double eps_p = 0.0, s[6] = {};
  for (std::size_t g = 0; g < 8; ++g) {
    const std::size_t ip = first + g;
    eps_p += st.eps_p[ip] / 8.0;
    const double point[6] = {st.sxx[ip], st.syy[ip], st.szz[ip], st.sxy[ip], st.syz[ip], st.szx[ip]};
    for (int k = 0; k < 6; ++k) s[k] += point[k] / 8.0;
  }
  if (!(eps_p > 0.0)) return 0.0;
  const double elastic_strain = materials::von_mises(s) / p.young;
  return std::sqrt(eps_p / (elastic_strain + eps_p));
}

// Adds the forces of the 8 point stresses to f and returns sum det J p for the mean-gradient pressure forces
// (eq. B-10): with a constant pressure the points carry their deviatoric stress, otherwise the whole stress.
double point_forces(const PointKinematics* pk, const double (*sigma)[6], double constant_share, double* fx,
                    double* fy, double* fz) {
  double pressure_volume = 0.0;
  for (int g = 0; g < 8; ++g) {
    const auto& dn = kGauss.d[g];
    const double* s = sigma[g];
    const double pressure = constant_share * (s[0] + s[1] + s[2]) / 3.0;
    pressure_volume += pk[g].det_now * pressure;
    const double dxx = s[0] - pressure, dyy = s[1] - pressure, dzz = s[2] - pressure;
    const auto& cn = pk[g].cn;
    for (int a = 0; a < 8; ++a) {
      double b[3];  // det J B = C dN/dxi: the weight det J cancels the division
      for (int i = 0; i < 3; ++i) b[i] = cn[i][0] * dn[0][a] + cn[i][1] * dn[1][a] + cn[i][2] * dn[2][a];
      fx[a] += b[0] * dxx + b[1] * s[3] + b[2] * s[5];
      fy[a] += b[0] * s[3] + b[1] * dyy + b[2] * s[4];
      fz[a] += b[0] * s[5] + b[1] * s[4] + b[2] * dzz;
    }
  }
  return pressure_volume;
}

// Assumed shears of Isolid 14 (eq. B-10a): in the element frame R of eq. B-8 (polar decomposition of the centre
// Jacobian of x, y, z), the shear of the plane of natural axes i, j at each point becomes the w-weighted mean over
// the four points on the same side of the third axis. t holds 8 symmetric tensors (xx yy zz xy yz zx), with
// engineering shears when `engineering`.
void average_local_shears(const double* x, const double* y, const double* z, const double* w, bool engineering,
                          double (*t)[6]) {
  double j0[3][3], rot[3][3];
  centre_jacobian(x, y, z, j0);
  polar_rotation(j0, rot);
  const double f = engineering ? 0.5 : 1.0;  // tensor shear = f * stored shear
  double local[8][3][3];
  for (int g = 0; g < 8; ++g) {
    const double a[3][3] = {{t[g][0], f * t[g][3], f * t[g][5]},
                            {f * t[g][3], t[g][1], f * t[g][4]},
                            {f * t[g][5], f * t[g][4], t[g][2]}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double v = 0.0;  // (R^T a R)_ij
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) v += rot[k][i] * a[k][l] * rot[l][j];
        local[g][i][j] = v;
      }
  }
  const double* side[3] = {kS1, kS2, kS3};
  for (int third = 0; third < 3; ++third) {
    const int i = (third + 1) % 3, j = (third + 2) % 3;
    for (double sign : {-1.0, 1.0}) {
      double sum = 0.0, weight = 0.0;
      for (int g = 0; g < 8; ++g)
        if (side[third][g] == sign) sum += w[g] * local[g][i][j], weight += w[g];
      for (int g = 0; g < 8; ++g)
        if (side[third][g] == sign) local[g][i][j] = local[g][j][i] = sum / weight;
    }
  }
  for (int g = 0; g < 8; ++g) {
    double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double v = 0.0;  // (R local R^T)_ij
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) v += rot[i][k] * local[g][k][l] * rot[j][l];
        a[i][j] = v;
      }
    t[g][0] = a[0][0], t[g][1] = a[1][1], t[g][2] = a[2][2];
    t[g][3] = a[0][1] / f, t[g][4] = a[1][2] / f, t[g][5] = a[2][0] / f;
  }
}

// Orthogonalised hourglass vectors gamma and hourglass rates q_i,alpha = gamma_alpha . v_i (eq. B-5); with
// `plain` (Isolid 2) the base vectors h themselves (eq. B-6a). b = dV/dx of eq. B-2 at x^n.
void hourglass_rates(const Element& el, const double* bx, const double* by, const double* bz, double volume,
                     bool plain, double gamma[4][8], double q[3][4]) {
  for (int m = 0; m < 4; ++m) {
    double hx = 0.0, hy = 0.0, hz = 0.0;
    if (!plain)
      for (int a = 0; a < 8; ++a) hx += kH[m][a] * el.x[a], hy += kH[m][a] * el.y[a], hz += kH[m][a] * el.z[a];
    hx /= volume, hy /= volume, hz /= volume;
    double qx = 0.0, qy = 0.0, qz = 0.0;
    for (int a = 0; a < 8; ++a) {
      const double g = kH[m][a] - (hx * bx[a] + hy * by[a] + hz * bz[a]);
      gamma[m][a] = g;
      qx += g * el.vx[a], qy += g * el.vy[a], qz += g * el.vz[a];
    }
    q[0][m] = qx, q[1][m] = qy, q[2][m] = qz;
  }
}

// Viscous hourglass forces Q = coefficient q (eq. B-6) and their work over dt. Returns the damper's rate bound
// coefficient * max row sum of |gamma gamma^T| (Gershgorin, eq. B-13); on flattened elements gamma grows.
double viscous_hourglass(const double gamma[4][8], const double q[3][4], double coefficient, double dt,
                         double global_q[3][4], double& work) {
  double largest_row = 0.0;
  for (int m = 0; m < 4; ++m) {
    double row = 0.0;
    for (int k = 0; k < 4; ++k) {
      double dot = 0.0;
      for (int a = 0; a < 8; ++a) dot += gamma[m][a] * gamma[k][a];
      row += std::abs(dot);
    }
    largest_row = std::max(largest_row, row);
  }
  for (int i = 0; i < 3; ++i)
    for (int m = 0; m < 4; ++m) {
      global_q[i][m] = coefficient * q[i][m];
      work += global_q[i][m] * q[i][m] * dt;
    }
  return coefficient * largest_row;
}

// Isolid 24: updates the 12 stored generalized hourglass stresses hq (element frame) for the rates q over dt and
// gives their global forces (eq. B-8 to B-9b). `stored` gets the elastic work, `damped` the dn part's. False
// when the centre Jacobian is not positive (no frame).
bool physical_stabilisation(const Element& el, const BrickGroupParameters& p, double bulk, double shear,
                            double volume, double transit, const double q[3][4], double dt, double* hq,
                            double global_q[3][4], double& stored, double& damped) {
  // Co-rotational frame and half-widths (eq. B-8): J0 = R U, a_k = 1 / |row k of J0^-1|.
  double j0[3][3], cof[3][3], rot[3][3];
  centre_jacobian(el.x, el.y, el.z, j0);
  const double det = cofactor(j0, cof);
  if (!(det > 0.0)) return false;
  polar_rotation(j0, rot);
  double half[3];
  for (int k = 0; k < 3; ++k)
    half[k] = std::abs(det) / std::sqrt(cof[0][k] * cof[0][k] + cof[1][k] * cof[1][k] + cof[2][k] * cof[2][k]);
  double dq[3][4], dQ[3][4];
  for (int i = 0; i < 3; ++i)
    for (int m = 0; m < 4; ++m) dq[i][m] = (rot[0][i] * q[0][m] + rot[1][i] * q[1][m] + rot[2][i] * q[2][m]) * dt;
  stabilisation_increment(half, volume, p.constant_pressure ? 0.0 : bulk, shear, dq, dQ);  // eq. B-9, B-9a
  // Numerical damping dn (eq. B-9b): a viscous force dn (dt_e / dt) dQ, the elastic increment over the element's
  // own transit time, not stored; its work is dissipated (hourglass energy).
  const double viscous = dt > 0.0 ? p.numerical_damping * transit / dt : 0.0;
  double local[3][4];
  for (int i = 0; i < 3; ++i)
    for (int m = 0; m < 4; ++m) {
      double& h = hq[m * 3 + i];
      const double old = h;
      h += dQ[i][m];
      stored += 0.5 * (old + h) * dq[i][m];
      damped += viscous * dQ[i][m] * dq[i][m];
      local[i][m] = h + viscous * dQ[i][m];
    }
  for (int j = 0; j < 3; ++j)
    for (int m = 0; m < 4; ++m)
      global_q[j][m] = rot[j][0] * local[0][m] + rot[j][1] * local[1][m] + rot[j][2] * local[2][m];
  return true;
}

}  // namespace

void brick8_switch_to_small_strain(const ElementTable& table, std::int32_t element, const NodalState& nodes,
                                   BrickState& state) {
  const auto e = static_cast<std::size_t>(element);
  Element el;
  gather(nodes, table.nodes_of(e), 0.0, el);
  double j0[3][3], frame[3][3];
  centre_jacobian(el.x, el.y, el.z, j0);
  polar_rotation(j0, frame);
  for (int a = 0; a < 8; ++a) {
    double* x = &state.reference_shape[24 * e + 3 * static_cast<std::size_t>(a)];
    x[0] = el.x[a], x[1] = el.y[a], x[2] = el.z[a];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) state.reference_frame[9 * e + 3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)] = frame[i][j];
  state.small_strain[e] = 1;
}

void brick8_configure(int isolid, int icpre, BrickGroupParameters& p) {
  p.isolid = isolid;
  p.plain_hourglass = isolid == 2;  // Hallquist's viscous form (eq. B-6a)
  p.points = fully_integrated_brick(isolid) ? 8 : 1;
  p.assumed_shear = isolid == 14 || isolid == 18;      // shear-locking free 2x2x2 (eq. B-10a)
  p.constant_pressure = icpre == 1 || isolid == 12;  // Isolid 12: bulk always at one point (eq. B-10)
  p.plastic_pressure = icpre == 2 && p.points == 8;
}

GroupStepResult brick8_forces(const ElementTable& table, const ElementGroup& group, const BrickGroupParameters& p,
                              NodalState& nodes, BrickState& state, double dt) {
  return p.points == 8 ? brick8_full_forces(table, group, p, nodes, state, dt)
                       : brick8_one_point_forces(table, group, p, nodes, state, dt);
}

GroupStepResult brick8_one_point_forces(const ElementTable& table, const ElementGroup& group,
                                        const BrickGroupParameters& p, NodalState& nodes, BrickState& state,
                                        double dt) {
  GroupStepResult result;
  const materials::SolidElastic elastic{p.young, p.poisson};
  const double G = elastic.shear(), K = elastic.bulk();
  const double wave_modulus = K + 4.0 / 3.0 * G;  // rho c^2 of the dilatational wave
  const bool physical = p.isolid == 24;
  const bool recording = state.records.on(group.begin);

  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    // What one of this domain's elements hands the nodes if it computes nothing this cycle.
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const std::int32_t* n = table.nodes_of(ue);
    Element el;
    gather(nodes, n, dt, el);
    // Iframe 2, or an objective small-strain element: the stresses turn with the element frame (eq. B-3a).
    const bool small_strain = state.small_strain[ue] != 0;
    const bool frame_turns = p.corotational || (small_strain && p.ismstr != 3);
    double spin[3], turn[3][3];
    if (frame_turns) frame_turn(el, turn), spin_of_turn(turn, dt, spin);
    if (small_strain) use_reference_shape(p, state, ue, dt, turn, el);

    // Uniform gradients at x^n (forces) and at the mid-step geometry (rates), eq. B-2, B-3.
    double bx[8], by[8], bz[8], mbx[8], mby[8], mbz[8];
    const double volume = geometry::brick_volume_gradient(el.x, el.y, el.z, bx, by, bz);
    const double volume_mid = geometry::brick_volume_gradient(el.mx, el.my, el.mz, mbx, mby, mbz);
    if (!(volume > 0.0) || !(volume_mid > 0.0)) {
      result.inverted = e;
      continue;
    }
    double l[3][3] = {};
    for (int a = 0; a < 8; ++a) {
      const double v[3] = {el.vx[a], el.vy[a], el.vz[a]}, b[3] = {mbx[a], mby[a], mbz[a]};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) l[i][j] += v[i] * b[j];
    }
    for (auto& row : l)
      for (double& v : row) v /= volume_mid;
    Rates r = rates_of(l);
    if (frame_turns) std::copy(spin, spin + 3, r.w);

    // Stress update at the single point (eq. SU-1 to SU-4), stress power (eq. B-11).
    const std::size_t ip = p.first_point + static_cast<std::size_t>(e - group.begin);
    double s[6];
    const PointUpdate u = update_point(p, elastic, state, ip, r, dt, s);

    // Current density, wave speed, characteristic length, bulk viscosity (eq. B-7, B-12).
    const double rho = p.density * state.volume0[ue] / volume;
    const double c = std::sqrt(wave_modulus / rho);
    // A tetrahedron or a pyramid written as a brick integrates 3/4 of its volume, as the reference (eq. B-2b).
    const double scale = state.volume_scale[ue];
    const double length = scale * volume / largest_face_area(el.x, el.y, el.z);
    const double dv = r.d[0] + r.d[1] + r.d[2];
    const Viscosity visc = bulk_viscosity(p, rho, c, length, dv);
    const double internal = scale * volume_mid * (u.power - visc.q * dv) * dt;

    // Internal forces f_I = V (sigma - q I) B_I = (sigma - q I) dV/dx_I (eq. B-4).
    double fx[8], fy[8], fz[8];
    const double sxx = s[0] - visc.q, syy = s[1] - visc.q, szz = s[2] - visc.q;
    for (int a = 0; a < 8; ++a) {
      fx[a] = scale * (bx[a] * sxx + by[a] * s[3] + bz[a] * s[5]);
      fy[a] = scale * (bx[a] * s[3] + by[a] * syy + bz[a] * s[4]);
      fz[a] = scale * (bx[a] * s[5] + by[a] * s[4] + bz[a] * szz);
    }

    double gamma[4][8], q[3][4];
    hourglass_rates(el, bx, by, bz, volume, p.plain_hourglass, gamma, q);  // eq. B-5, B-6a
    double hourglass_work = 0.0, stabilisation_work = 0.0, damping_work = 0.0;  // viscous, elastic, dn
    double global_q[3][4];  // generalized hourglass forces in the global frame
    double damper_rate = 0.0;  // bound of the hourglass damper's largest eigenvalue (C = m lambda) [M/T]
    const double transit = length / (visc.speed + std::sqrt(visc.speed * visc.speed + c * c));  // eq. B-12
    if (!physical) {
      // Viscous hourglass forces (eq. B-6): Q = h rho c V^(2/3) / 4 q.
      const double cbrt_v = std::cbrt(volume);
      damper_rate = viscous_hourglass(gamma, q, 0.25 * p.hourglass * rho * c * cbrt_v * cbrt_v, dt, global_q,
                                      hourglass_work);
    } else if (!physical_stabilisation(el, p, K, G, volume, transit, q, dt, &state.hourglass[ue * 12], global_q,
                                       stabilisation_work, damping_work)) {
      result.inverted = e;  // the one-point Jacobian of a badly distorted element: no frame
      continue;
    }
    for (int a = 0; a < 8; ++a)
      for (int m = 0; m < 4; ++m) {
        fx[a] += gamma[m][a] * global_q[0][m];
        fy[a] += gamma[m][a] * global_q[1][m];
        fz[a] += gamma[m][a] * global_q[2][m];
      }
    double check = internal + hourglass_work + stabilisation_work + damping_work;
    for (int a = 0; a < 8; ++a) {
      const Vec3 force{fx[a], fy[a], fz[a]};
      subtract_internal(nodes, static_cast<std::size_t>(n[a]), force);
      if (recording) record_load(state.records.load_at(ue, a), force);
      check += fx[a] + fy[a] + fz[a];
    }
    if (!std::isfinite(check)) result.non_finite = e;  // a NaN or an infinity stops the run at once
    // Isolid 24's stabilisation stores the strain energy of the assumed-strain field: internal energy (eq. B-11).
    // The viscous forces (Isolid 1, 2; dn of Isolid 24) dissipate: hourglass energy.
    const double strain_work = internal + stabilisation_work;
    const double viscous_work = hourglass_work + damping_work;
    state.internal_energy[ue] += strain_work;
    state.hourglass_energy[ue] += viscous_work;
    result.internal_energy += strain_work;
    result.hourglass_energy += viscous_work;

    // Critical step L / (Q + sqrt(Q^2 + c^2)) (eq. B-12), where Q carries the bulk viscosity, and the hourglass
    // damper's own bound 2 m / lambda_max (eq. B-13): hourglass modes carry no stiffness in Isolid 1.
    const double nodal_mass = 0.125 * p.density * state.volume0[ue] * scale;
    const double step = std::min(transit, damper_rate > 0.0 ? 2.0 * nodal_mass / damper_rate
                                                            : std::numeric_limits<double>::infinity());
    close_element(state, result, e, step, u.failed);
  }
  return result;
}

GroupStepResult brick8_full_forces(const ElementTable& table, const ElementGroup& group,
                                   const BrickGroupParameters& p, NodalState& nodes, BrickState& state, double dt) {
  GroupStepResult result;
  const materials::SolidElastic elastic{p.young, p.poisson};
  const double wave_modulus = elastic.bulk() + 4.0 / 3.0 * elastic.shear();
  const bool recording = state.records.on(group.begin);

  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    // What one of this domain's elements hands the nodes if it computes nothing this cycle.
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const std::int32_t* n = table.nodes_of(ue);
    Element el;
    gather(nodes, n, dt, el);
    // Iframe 2, or an objective small-strain element: the stresses turn with the element frame (eq. B-3a).
    const bool small_strain = state.small_strain[ue] != 0;
    const bool frame_turns = p.corotational || (small_strain && p.ismstr != 3);
    double spin[3], turn[3][3];
    if (frame_turns) frame_turn(el, turn), spin_of_turn(turn, dt, spin);
    if (small_strain) use_reference_shape(p, state, ue, dt, turn, el);
    double bx[8], by[8], bz[8], mbx[8], mby[8], mbz[8];
    const double volume = geometry::brick_volume_gradient(el.x, el.y, el.z, bx, by, bz);
    const double volume_mid = geometry::brick_volume_gradient(el.mx, el.my, el.mz, mbx, mby, mbz);
    PointKinematics pk[8];
    bool inverted = !(volume > 0.0) || !(volume_mid > 0.0);
    for (int g = 0; g < 8 && !inverted; ++g) inverted = !point_kinematics(el, g, pk[g]);
    if (inverted) {  // a point with det J <= 0 counts as an inverted element
      result.inverted = e;
      continue;
    }
    // Mean dilatation rate over the mid-step element (eq. B-10): the trace of the uniform gradient.
    double dv_mean = 0.0;
    for (int a = 0; a < 8; ++a) dv_mean += el.vx[a] * mbx[a] + el.vy[a] * mby[a] + el.vz[a] * mbz[a];
    dv_mean /= volume_mid;

    const double rho = p.density * state.volume0[ue] / volume;
    const double c = std::sqrt(wave_modulus / rho);
    // A degenerate brick's length follows its smallest point (eq. B-12a); a hexahedron's is B-12's.
    double length = volume / largest_face_area(el.x, el.y, el.z);
    if (state.degenerate[ue]) {
      double smallest_det = pk[0].det_now;
      for (int g = 1; g < 8; ++g) smallest_det = std::min(smallest_det, pk[g].det_now);
      length = geometry::full_integration_length(el.x, el.y, el.z, smallest_det);
    }
    const Viscosity visc = bulk_viscosity(p, rho, c, length, dv_mean);

    // Rates of the points (eq. B-10), with the assumed shears of eq. B-10a and the mean dilatation (Icpre 1).
    Rates r[8];
    double weight[8];
    for (int g = 0; g < 8; ++g) {
      r[g] = rates_of(pk[g].l), weight[g] = pk[g].det_mid;
      if (frame_turns) std::copy(spin, spin + 3, r[g].w);
    }
    if (p.assumed_shear) {
      double d[8][6];
      for (int g = 0; g < 8; ++g) std::copy(r[g].d, r[g].d + 6, d[g]);
      average_local_shears(el.mx, el.my, el.mz, weight, true, d);
      for (int g = 0; g < 8; ++g) std::copy(d[g], d[g] + 6, r[g].d);
    }
    const double share = constant_pressure_share(p, state, p.first_point + static_cast<std::size_t>(e - group.begin) * 8);
    if (share > 0.0)
      for (auto& rg : r) {
        const double correction = share * (dv_mean - (rg.d[0] + rg.d[1] + rg.d[2])) / 3.0;
        for (int k = 0; k < 3; ++k) rg.d[k] += correction;
      }

    double sigma[8][6];
    double internal = 0.0;
    bool failed = false;
    const std::size_t first = p.first_point + static_cast<std::size_t>(e - group.begin) * 8;
    for (int g = 0; g < 8; ++g) {
      const PointUpdate u = update_point(p, elastic, state, first + static_cast<std::size_t>(g), r[g], dt, sigma[g]);
      failed = failed || u.failed;
      internal += pk[g].det_mid * u.power * dt;  // Gauss weights are 1
    }
    internal -= visc.q * dv_mean * volume_mid * dt;
    // The forces are the transpose of the rates' operator: with assumed shears each point carries the weighted
    // mean shear stress of its group (eq. B-10a).
    if (p.assumed_shear) {
      for (int g = 0; g < 8; ++g) weight[g] = pk[g].det_now;
      average_local_shears(el.x, el.y, el.z, weight, false, sigma);
    }
    double fx[8] = {}, fy[8] = {}, fz[8] = {};
    const double mean_stress = point_forces(pk, sigma, share, fx, fy, fz) / volume - visc.q;

    // Pressure forces (sum det J p) B_bar - q V B_bar with B_bar = dV/dx / V (eq. B-10).
    double check = internal + mean_stress;
    for (int a = 0; a < 8; ++a) {
      const Vec3 force{fx[a] + mean_stress * bx[a], fy[a] + mean_stress * by[a], fz[a] + mean_stress * bz[a]};
      subtract_internal(nodes, static_cast<std::size_t>(n[a]), force);
      if (recording) record_load(state.records.load_at(ue, a), force);
      check += fx[a] + fy[a] + fz[a];
    }
    if (!std::isfinite(check)) result.non_finite = e;  // a NaN or an infinity stops the run at once
    state.internal_energy[ue] += internal;
    result.internal_energy += internal;

    const double step = length / (visc.speed + std::sqrt(visc.speed * visc.speed + c * c));
    close_element(state, result, e, step, failed);
  }
  return result;
}

}  // namespace crumple
