// Belytschko-Tsay 4-node shell (docs/theory/shell4.md): co-rotational element frame, one quadrature point in
// the plane, `points` through the thickness, plane-stress material, elastic transverse shear, hourglass
// stiffness on the five one-point hourglass modes.
#include <algorithm>
#include <cmath>

#include "crumple/elements/shell4.hpp"
#include "shell4_hourglass.hpp"
#include "shell4_section.hpp"

namespace crumple {
namespace {


}  // namespace

void through_thickness_rule(int n, double* zeta, double* membrane_weight, double* bending_weight) {
  if (n <= 1) {
    zeta[0] = 0.0, membrane_weight[0] = 1.0, bending_weight[0] = 0.0;
    return;
  }
  const double h = 1.0 / (n - 1);
  for (int i = 0; i < n; ++i) {
    const double z = -0.5 + i * h;
    zeta[i] = z;
    // Hat function of point i: 1 at z, 0 at the neighbours. Integrals over the half-hat on each side:
    // int phi dz = h/2, int z phi dz = h/2 (z -+ h/3).
    double w = 0.0, b = 0.0;
    if (i > 0) w += 0.5 * h, b += 0.5 * h * (z - h / 3.0);
    if (i < n - 1) w += 0.5 * h, b += 0.5 * h * (z + h / 3.0);
    membrane_weight[i] = w;
    bending_weight[i] = b;
  }
}

namespace {

// A membrane: one point through the thickness (N = 1), without bending or transverse shear.
bool is_membrane(const ShellGroupParameters& p) { return p.points == 1 && !p.resultant_plasticity; }

// Stiffness of the Ishell 1 to 3 transverse hourglass mode per hf (eq. S-5a, measured on the reference solver): the
// transverse-shear stiffness times t^2 / 3 over the diagonals, kappa G t^3 / 3 * 16 / (d1^2 + d2^2), that is
// 8 / (A^2 |B|^2); on a membrane 2 E t, as the membrane modes' (eq. S-5). [F/L]
double transverse_hourglass_stiffness(const ShellGroupParameters& p, double E, double G, double t, double area,
                                      double bb) {
  return is_membrane(p) ? 2.0 * E * t : p.shear_factor * G * t * t * t / 3.0 * 8.0 / (area * area * bb);
}

// Yield stress of the section for the elasto-plastic hourglass of Ishell 3 (eq. S-18): the law at the points' mean
// plastic strain and the first point's strain rate; 0 (no limit) for an elastic law.
double hourglass_yield_stress(const ShellGroupParameters& p, const ShellState& state, std::size_t first) {
  if (!p.hardening.plastic()) return 0.0;
  double eps_p = 0.0;
  if (p.resultant_plasticity) eps_p = state.eps_p[first];
  else
    for (int k = 0; k < p.points; ++k) eps_p += p.membrane_weight[k] * state.eps_p[first + static_cast<std::size_t>(k)];
  return p.hardening.yield(eps_p, state.eps_rate[first]);
}

// What the QEPH shell's elastic-plastic hourglass (eq. S-12) reads of an element in the cycle: its section's
// tangents and mean stresses after the update, the trial peak stresses of its hourglass modes (the stored ones plus
// the elastic increment, over t sqrt(H A / 3), a mode's stress at the element's edge), and the power of the stored
// ones. The yield stress is read only when every point stayed elastic (then the points' plastic strains are those of
// the start of the step).
shell_hourglass::HourglassYieldCheck qeph_yield_check(const ShellGroupParameters& p, const ShellState& state,
                                                      std::size_t first, const shell_section::Update& section,
                                                      const shell_hourglass::ShapeTensor& H, double area, double t,
                                                      const double* hq, const double (&increment)[kShellHourglassModes],
                                                      const double (&rates)[kShellHourglassModes]) {
  shell_hourglass::HourglassYieldCheck check;
  if (section.min_tangent_ratio >= 1.0) check.yield = hourglass_yield_stress(p, state, first);
  check.mean_ratio = section.tangent_ratio, check.min_ratio = section.min_tangent_ratio;
  for (int c = 0; c < 3; ++c) check.mean_stress[c] = section.n[c] / t, check.mean_moment[c] = section.m[c] / (t * t);
  const double lever_x = std::sqrt(H.xx * area / 3.0), lever_y = std::sqrt(H.yy * area / 3.0), plate = t * t * t / 12.0;
  check.membrane_peak[0] = (hq[0] + increment[0]) / (t * lever_x);
  check.membrane_peak[1] = (hq[1] + increment[1]) / (t * lever_y);
  check.bending_peak[0] = (hq[4] + increment[4]) / (plate * lever_x);
  check.bending_peak[1] = (hq[3] + increment[3]) / (plate * lever_y);
  check.thickness = t, check.poisson = p.poisson;
  check.moment_weight = p.resultant_plasticity ? 16.0 : 25.0;
  check.membrane_power = hq[0] * rates[0] + hq[1] * rates[1];
  check.bending_power = hq[3] * rates[3] + hq[4] * rates[4];
  return check;
}

// The rotation modes of the one-point quadrilateral (Ishell 1 to 3) have no stiffness, only moments recomputed each
// cycle from the nodes' rotation rates tx, ty about the element axes, on g = 4 gamma (h for a parallelogram) so
// that a linear rotation field (constant curvature) is not resisted: Ishell 1, 2 quadratic (eqs. S-19, S-20),
// Ishell 3 linear and quadratic (eq. S-18b). Sets each node's moments, returns their work over dt.
double rotation_mode_moments(const ShellGroupParameters& p, const double (&gamma)[4], const double (&tx)[4],
                             const double (&ty)[4], double t, double area, double dt, double (&moment_x)[4],
                             double (&moment_y)[4]) {
  const double inertia = shell_node_rotational_inertia(p.density * t * area, t, area, 4);
  double g_norm = 0.0, q[2] = {0.0, 0.0};
  for (int a = 0; a < 4; ++a) {
    const double g = 4.0 * gamma[a];
    g_norm += g * g;
    q[0] += g * tx[a], q[1] += g * ty[a];
  }
  double moment[2];
  for (int r = 0; r < 2; ++r) {
    using namespace shell_hourglass;
    const double viscous = p.elastoplastic_hourglass ? viscous_rotation_moment(p.hr, p.density, p.young, t, area, q[r])
                                                     : rotation_damping_moment(p.hr, p.density, t, area, q[r]);
    moment[r] = within_stopping_load(viscous, q[r], inertia, g_norm, dt);
  }
  for (int a = 0; a < 4; ++a) moment_x[a] = 4.0 * gamma[a] * moment[0], moment_y[a] = 4.0 * gamma[a] * moment[1];
  return (moment[0] * q[0] + moment[1] * q[1]) * dt;
}

// One kernel for the 4-node Belytschko-Tsay shell and the 3-node C0 triangle (docs/theory/shell4.md,
// shell3 section): they differ in the element frame, the gradient operator and the hourglass modes only.
template <int NN>
GroupStepResult shell_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                             NodalState& nodes, ShellState& state, double dt) {
  GroupStepResult result;
  const double E = p.young, nu = p.poisson, G = E / (2.0 * (1.0 + nu));
  // The bar speed sqrt(E / rho), as the reference takes for these elements (eq. T-1a: its printed element steps are
  // L / sqrt(E / rho) to all their digits), the plate speed with /MAT/PLAS_TAB [L/T].
  const double wave_speed =
      shell_step_wave_speed(E, nu, p.density, shell_step_at_plate_speed(p.hardening.law, p.fully_integrated));
  const double step_factor = shell_section::damped_step_factor(shell_section::step_damping(p));  // eq. T-1c
  const materials::PlaneStressElastic elastic{E, nu};
  const int np = p.points;
  constexpr double mean = 1.0 / NN;  // shape function value at the element centre

  const bool recording = state.records.on(group.begin);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    // What one of this domain's elements hands the nodes if it computes nothing this cycle.
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const std::int32_t* n = table.nodes_of(ue);
    Vec3 x[NN], v[NN], w[NN];
    for (int a = 0; a < NN; ++a) {
      const auto k = static_cast<std::size_t>(n[a]);
      x[a] = {nodes.x[k], nodes.y[k], nodes.z[k]};
      v[a] = {nodes.vx[k], nodes.vy[k], nodes.vz[k]};
      w[a] = {nodes.wx[k], nodes.wy[k], nodes.wz[k]};
    }
    // Co-rotational frame (eq. S-1).
    shell_section::Frame frame;
    if (!shell_section::corotational_frame<NN>(x, frame)) {
      delete_inverted_shell(state, result, e);
      continue;
    }
    const Vec3 e1 = frame.e1, e2 = frame.e2, e3 = frame.e3, centre = frame.centre;
    // Ishell 24: each node turns the element about the axes of its own corner's plane; its rotation about the
    // corner's normal is a drilling one the element does not see (eq. S-1a). The rotation of the step is taken in
    // the corners' planes at its middle, the mean of their projections at its start and end, and the moments act in
    // those at its end (eq. S-1b). The other kinds take the frame's.
    const bool corner_planes = NN == 4 && p.physical_hourglass;
    shell_section::CornerPlane planes[NN];  // the corners' planes at the step's end
    if (corner_planes) {
      Vec3 start[NN];  // the positions at the step's start [L]
      for (int a = 0; a < NN; ++a) start[a] = x[a] - scaled(v[a], dt);
      for (int a = 0; a < NN; ++a) {
        planes[a] = shell_section::corner_plane(x, a, e3);
        const shell_section::CornerPlane at_start = shell_section::corner_plane(start, a, e3);
        const Vec3 at_end = shell_section::in_corner_plane(w[a], planes[a]);
        w[a] = scaled(at_end + shell_section::in_corner_plane(w[a], at_start), 0.5);
      }
    }
    double lx[NN], ly[NN], vx[NN], vy[NN], vz[NN], tx[NN], ty[NN];
    for (int a = 0; a < NN; ++a) {
      const Vec3 r = x[a] - centre;
      lx[a] = dot(r, e1);
      ly[a] = dot(r, e2);
      vx[a] = dot(v[a], e1);
      vy[a] = dot(v[a], e2);
      vz[a] = dot(v[a], e3);
      tx[a] = dot(w[a], e1);
      ty[a] = dot(w[a], e2);
    }
    // Gradient operator at the centre (eq. S-2; triangle: eq. S-9).
    const bool small_strain = p.small_strain || state.small_strain[ue] != 0;
    if (small_strain) {
      // Ismstr 1, 3 (eq. S-15): strains and forces on the initial shape, carried by the current frame; the
      // element keeps its first step and cannot invert in this formulation. Ismstr 2 after the switch
      // (shell_switch_to_small_strain, eq. S-16): the same on the shape frozen at the switch.
      double* shape = &state.initial_shape[2 * NN * ue];
      if (state.initial_length[ue] == 0.0)
        for (int a = 0; a < NN; ++a) shape[a] = lx[a], shape[NN + a] = ly[a];
      for (int a = 0; a < NN; ++a) lx[a] = shape[a], ly[a] = shape[NN + a];
    }
    const double area = shell_section::local_area<NN>(lx, ly);
    double b1[NN], b2[NN];
    if (!(area > 0.0)) {
      delete_inverted_shell(state, result, e);
      continue;
    }
    if constexpr (NN == 4) {
      // The frame follows the element, so a quadrilateral turned inside out (a bow-tie) still has a positive
      // area in it; what shows it is two corners whose Jacobian (the cross product of the two sides) is not
      // positive. One such corner is a badly distorted but valid dart shape, common in folds.
      int negative_corners = 0;
      for (int a = 0; a < 4; ++a) {
        const int next = (a + 1) % 4, previous = (a + 3) % 4;
        const double corner = (lx[next] - lx[a]) * (ly[previous] - ly[a]) - (ly[next] - ly[a]) * (lx[previous] - lx[a]);
        if (!(corner > 0.0)) ++negative_corners;
      }
      if (negative_corners >= 2) {
        delete_inverted_shell(state, result, e);
        continue;
      }
    }
    const double inv2a = 0.5 / area;
    for (int a = 0; a < NN; ++a) {
      // Quadrilateral: the opposite-diagonal differences; triangle: the opposite side.
      const int next = (a + 1) % NN, previous = (a + NN - 1) % NN;
      b1[a] = (ly[next] - ly[previous]) * inv2a;
      b2[a] = (lx[previous] - lx[next]) * inv2a;
    }
    // Membrane strain rates, curvature rates, transverse shear strain rates (eq. S-3).
    double dxx = 0, dyy = 0, gxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0;
    for (int a = 0; a < NN; ++a) {
      dxx += b1[a] * vx[a];
      dyy += b2[a] * vy[a];
      gxy += b2[a] * vx[a] + b1[a] * vy[a];
      kxx += b1[a] * ty[a];
      kyy -= b2[a] * tx[a];
      kxy += b2[a] * ty[a] - b1[a] * tx[a];
      gxz += b1[a] * vz[a] + mean * ty[a];
      gyz += b2[a] * vz[a] - mean * tx[a];
    }
    // Triangle: the mean shear of the linked deflection field (eq. S-9a), so that a constant curvature carries no
    // transverse shear and a thin triangle does not lock in bending.
    double link[NN] = {};
    if constexpr (NN == 3) {
      shell_section::linked_shear_terms(lx, ly, tx, ty, link);
      for (int k = 0; k < 3; ++k) gxz -= b1[k] * link[k] / 6.0, gyz -= b2[k] * link[k] / 6.0;
    }
    const double t = state.thickness[ue];

    // Stress update at the through-thickness points, resultants per unit length (eq. S-4), and the internal energy:
    // mid-step resultants times the generalized strain increments (eq. S-6).
    const std::size_t first = p.first_point + static_cast<std::size_t>(e - group.begin) * static_cast<std::size_t>(np);
    const shell_section::StrainRates section_rates{dxx, dyy, gxy, kxx, kyy, kxy};
    double* bending_stress = p.resultant_plasticity ? &state.bending_stress[3 * ue] : nullptr;
    const shell_section::Update section = shell_section::update(p, elastic, state, first, bending_stress, t, section_rates, dt);
    double nxx = section.n[0], nyy = section.n[1], nxy = section.n[2];
    const double mxx = section.m[0], myy = section.m[1], mxy = section.m[2];
    const double thickness_strain = section.thickness_strain;
    const bool failed = section.failed;
    double work = 0.0;
    work += shell_section::work(section, section_rates, dt);
    // Transverse shear: elastic, constant through the thickness with the shear correction factor.
    const double shear_stiffness = p.shear_factor * G * t;
    const double old_qx = state.qx[ue], old_qy = state.qy[ue];
    state.qx[ue] += shear_stiffness * gxz * dt;
    state.qy[ue] += shear_stiffness * gyz * dt;
    const double qx = state.qx[ue], qy = state.qy[ue];
    work += 0.5 * (old_qx + qx) * gxz * dt + 0.5 * (old_qy + qy) * gyz * dt;
    if (p.thickness_update && dt > 0.0) state.thickness[ue] = t * std::exp(thickness_strain);
    // Critical step: eq. T-1b for Ishell 1 to 4, T-1d for Ishell 24, T-1 for the triangle.
    double length = shell_section::one_point_length<NN>(p, lx, ly, area);
    if (small_strain) {  // eq. S-15: the step of the initial geometry
      if (state.initial_length[ue] == 0.0) state.initial_length[ue] = length;
      length = state.initial_length[ue];
    }
    const double step = length * step_factor / wave_speed;

    float* last_viscous = &state.viscous[kShellViscousForces * ue];
    if (p.membrane_damping > 0.0) {
      // Membrane damping dm (eqs. S-9d, S-9f): a viscous mean stress, not stored; its work is internal energy,
      // counted on the trapezoid with the last cycle's (eq. S-9e).
      const shell_section::MembraneForces d = shell_section::membrane_damping(
          p.membrane_damping, p.density, wave_speed, shell_section::membrane_damping_length(area, length), t, dxx, dyy, gxy);
      nxx += d.xx, nyy += d.yy, nxy += d.xy;
      const double now[3] = {d.xx, d.yy, d.xy}, rate[3] = {dxx, dyy, gxy};
      for (int c = 0; c < 3; ++c) work += shell_section::viscous_work(last_viscous[c], now[c], rate[c], dt);
    }

    // Hourglass stiffness on the five one-point hourglass modes of the quadrilateral (eq. S-5); the linear
    // triangle has none.
    double gamma[NN] = {};
    double* hq = nullptr;
    double damping[kShellHourglassModes] = {};            // viscous hourglass forces of the cycle (Ishell 24)
    double shear_moment_x[NN] = {}, shear_moment_y[NN] = {};  // rotation coefficients of the shear modes' sum (S-13)
    double split_moment_x[NN] = {}, split_moment_y[NN] = {};  // and of their difference (eq. S-13a)
    double rotation_damping_x[NN] = {}, rotation_damping_y[NN] = {};  // Ishell 1 to 3 rotation modes (S-18b, S-19)
    double warping = 0.0;  // Ishell 3 and 24: warping height W of eq. S-18a [L]
    double hourglass_work = 0.0;  // dissipated in the hourglass modes
    double hourglass_stored = 0.0;  // Ishell 24: the work of its hourglass stresses, internal energy (eq. S-12a)
    if constexpr (NN == 4) {
      shell_hourglass::hourglass_vector(lx, ly, b1, b2, p.orthogonal_hourglass, gamma);
      double bb = 0.0;
      for (int a = 0; a < 4; ++a) bb += b1[a] * b1[a] + b2[a] * b2[a];
      double rates[kShellHourglassModes] = {};
      for (int a = 0; a < 4; ++a) {
        rates[0] += gamma[a] * vx[a];
        rates[1] += gamma[a] * vy[a];
        rates[2] += gamma[a] * vz[a];
        rates[3] += gamma[a] * tx[a];
        rates[4] += gamma[a] * ty[a];
      }
      if (p.elastoplastic_hourglass || p.physical_hourglass) {
        // Ishell 3 and 24 (eq. S-18a): the in-plane motion a rigid rotation gives the nodes of a warped element is
        // no membrane hourglass rate; the forces take the matching transverse part (below).
        double z[4], slope_x = 0.0, slope_y = 0.0;  // nodes' heights off the frame plane [L]; dvz/dx, dvz/dy [T^-1]
        for (int a = 0; a < 4; ++a) z[a] = dot(x[a] - centre, e3), slope_x += b1[a] * vz[a], slope_y += b2[a] * vz[a];
        warping = shell_hourglass::warping_height(gamma, z);
        rates[0] += warping * slope_x, rates[1] += warping * slope_y;
      }
      hq = &state.hourglass[ue * kShellHourglassModes];
      if (p.physical_hourglass) {
        // Ishell 24: stiffness of the assumed-strain field of each mode (eqs. S-10 to S-14). Membrane modes as
        // in-plane bending A11 t H q, rotation modes as plate bending (A11 t^3 / 12) H on (q_ry, -q_rx), the
        // transverse modes as the shears gamma_xz varying along y and gamma_yz varying along x (S-13, S-13a).
        const shell_hourglass::ShapeTensor H = shell_hourglass::shape_tensor(lx, ly, area);
        const shell_hourglass::QuadraticMoments g = shell_hourglass::quadratic_moments(gamma, lx, ly);
        double cx[4], cy[4], dx[4], dy[4];
        shell_hourglass::shear_rotation_coefficients(g, b1, b2, cx, cy);
        shell_hourglass::shear_split_coefficients(g, b1, b2, dx, dy);
        double split = 0.0;
        for (int a = 0; a < 4; ++a) rates[2] += cx[a] * tx[a] + cy[a] * ty[a], split += dx[a] * tx[a] + dy[a] * ty[a];
        rates[5] = rates[2] - split, rates[2] += split;
        // The plane-stress modulus E / (1 - nu^2) of the section (eq. S-11).
        const double a11 = E / (1.0 - nu * nu);
        const double membrane = a11 * t, plate = a11 * t * t * t / 12.0;
        const double shear = p.shear_factor * G * t;
        const double increment[kShellHourglassModes] = {
            membrane * (H.xx * rates[0] + H.xy * rates[1]) * dt, membrane * (H.xy * rates[0] + H.yy * rates[1]) * dt,
            shear * H.xx * rates[2] * dt, -plate * (H.xy * rates[4] - H.yy * rates[3]) * dt,
            plate * (H.xx * rates[4] - H.xy * rates[3]) * dt, shear * H.yy * rates[5] * dt};
        // The elastic-plastic hourglass (eq. S-12): a yielding section keeps part of the elastic increment.
        const shell_hourglass::HourglassKept kept =
            p.hardening.plastic()
                ? shell_hourglass::qeph_hourglass_kept(qeph_yield_check(p, state, first, section, H, area, t, hq, increment, rates))
                : shell_hourglass::HourglassKept{};
        const double keep[kShellHourglassModes] = {kept.membrane, kept.membrane, 1.0, kept.bending, kept.bending, 1.0};
        // Numerical damping dn: the elastic increment over the element's own transit time, not stored (eq. S-14).
        const double viscous = dt > 0.0 ? p.numerical_damping * step / dt : 0.0;
        for (std::size_t m = 0; m < kShellHourglassModes; ++m) {
          const double old = hq[m];
          hq[m] += keep[m] * increment[m];
          hourglass_stored += 0.5 * (old + hq[m]) * rates[m] * dt;
          damping[m] = viscous * increment[m];
          hourglass_work += shell_section::viscous_work(last_viscous[3 + m], damping[m], rates[m], dt);  // eq. S-9e
        }
        for (int a = 0; a < 4; ++a)
          shear_moment_x[a] = cx[a], shear_moment_y[a] = cy[a], split_moment_x[a] = dx[a], split_moment_y[a] = dy[a];
      } else {
        // Each coefficient is a fraction of a stiffness of the section (eqs. S-5, S-5a): the membrane modes' 2 E t
        // whatever the element's shape, the transverse mode's kappa G t^3 / 3 over the diagonals (2 E t on a
        // membrane); the rotation modes have none (below).
        const double membrane = p.hm * 2.0 * E * t;
        const double bending = p.hf * transverse_hourglass_stiffness(p, E, G, t, area, bb);
        const double stiffness[3] = {membrane, membrane, bending};
        // Ishell 3 (eq. S-18): the membrane and transverse modes carry at most what the section's yield stress
        // allows.
        const double limit = p.elastoplastic_hourglass ? hourglass_yield_stress(p, state, first) : 0.0;
        const double cap[3] = {2.0 * p.hm * limit * t * std::sqrt(area), 2.0 * p.hm * limit * t * std::sqrt(area),
                               p.hf * limit * t * t};
        for (int m = 0; m < 3; ++m) {
          const double old = hq[m];
          hq[m] += stiffness[m] * rates[m] * dt;
          if (cap[m] > 0.0) hq[m] = std::clamp(hq[m], -cap[m], cap[m]);
          hourglass_work += 0.5 * (old + hq[m]) * rates[m] * dt;
        }
        // Ishell 1 and 2 with bending points also damp the membrane and transverse modes (eq. S-5b), each at most
        // what stops it within the step on the element's quarter of each node's mass (eq. S-20).
        if (!p.elastoplastic_hourglass && !is_membrane(p)) {
          using namespace shell_hourglass;
          double g_norm = 0.0;
          for (int a = 0; a < 4; ++a) g_norm += gamma[a] * gamma[a];
          const double viscous[3] = {membrane_hourglass_damping(p.hm, p.density, t, area, rates[0]),
                                     membrane_hourglass_damping(p.hm, p.density, t, area, rates[1]),
                                     transverse_hourglass_damping(p.hf, p.density, t, p.shear_factor, nu, rates[2])};
          for (std::size_t m = 0; m < 3; ++m) {
            damping[m] = within_stopping_load(viscous[m], rates[m], 0.25 * p.density * t * area, g_norm, dt);
            hourglass_work += damping[m] * rates[m] * dt;
          }
        }
        hourglass_work += rotation_mode_moments(p, gamma, tx, ty, t, area, dt, rotation_damping_x, rotation_damping_y);
      }
    }

    // The hourglass forces of the cycle, stored plus viscous, and the two shear modes' sum and difference (S-13a).
    double q[kShellHourglassModes] = {};
    if constexpr (NN == 4)
      for (std::size_t m = 0; m < kShellHourglassModes; ++m) q[m] = hq[m] + damping[m];
    const double shear_sum = q[2] + q[5], shear_difference = q[2] - q[5];

    // Nodal forces and moments in the element frame (eq. S-7), back to global, subtracted.
    for (int a = 0; a < NN; ++a) {
      double fx = area * (b1[a] * nxx + b2[a] * nxy);
      double fy = area * (b2[a] * nyy + b1[a] * nxy);
      double fz = area * (b1[a] * qx + b2[a] * qy);
      double mx = area * (-b2[a] * myy - b1[a] * mxy - mean * qy);
      double my = area * (b1[a] * mxx + b2[a] * mxy + mean * qx);
      if constexpr (NN == 4) {
        fx += gamma[a] * q[0], fy += gamma[a] * q[1];
        fz += gamma[a] * shear_sum + warping * (b1[a] * q[0] + b2[a] * q[1]);  // eq. S-18a's transverse part
        mx += gamma[a] * q[3] + shear_moment_x[a] * shear_sum + split_moment_x[a] * shear_difference + rotation_damping_x[a];
        my += gamma[a] * q[4] + shear_moment_y[a] * shear_sum + split_moment_y[a] * shear_difference + rotation_damping_y[a];
      }
      if constexpr (NN == 3) shell_section::add_linked_shear_moments(lx, ly, b1, b2, qx, qy, area, a, mx, my);
      const Vec3 force{fx * e1.x + fy * e2.x + fz * e3.x, fx * e1.y + fy * e2.y + fz * e3.y,
                       fx * e1.z + fy * e2.z + fz * e3.z};
      Vec3 moment{mx * e1.x + my * e2.x, mx * e1.y + my * e2.y, mx * e1.z + my * e2.z};
      if (corner_planes) moment = shell_section::in_corner_plane(moment, planes[a]);  // eq. S-1a
      subtract_internal(nodes, static_cast<std::size_t>(n[a]), force, moment);
      if (recording) record_load(state.records.load_at(ue, a), force, moment);
    }
    // A NaN or an infinity anywhere in the element shows in the sum of its resultants: the run stops at once.
    if (!std::isfinite(nxx + nyy + nxy + mxx + myy + mxy + qx + qy + work)) result.non_finite = e;
    const double internal = work * area + hourglass_stored;
    state.internal_energy[ue] += internal;
    state.hourglass_energy[ue] += hourglass_work;
    result.internal_energy += internal;
    result.hourglass_energy += hourglass_work;

    close_element(state, result, e, step, failed);
  }
  return result;
}

}  // namespace

GroupStepResult shell4_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                              NodalState& nodes, ShellState& state, double dt) {
  if (p.fully_integrated) return shell4_qbat_forces(table, group, p, nodes, state, dt);
  return shell_forces<4>(table, group, p, nodes, state, dt);
}

GroupStepResult shell3_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                              NodalState& nodes, ShellState& state, double dt) {
  return shell_forces<3>(table, group, p, nodes, state, dt);
}


namespace {

// The margin the shear mode keeps over the step it must hold (eq. S-8a): stable at 1.05 times the scaled step.
constexpr double kShearModeMargin = 1.05;

// The Ishell 24 transverse-shear hourglass modes (eqs. S-13, S-13a) move the deflections with gamma and the rotations
// with c + d and c - d, which grow with the element's long side: on a sliver (aspect ratio 1000) their frequency on
// the reference inertia is twice what the element step holds. Their stiffness k (H_xx r1 r1^T + H_yy r2 r2^T),
// k = kappa G t, over the lumped masses m / 4 and inertias (m / 4) X gives, summing the two rank-one bounds,
// omega^2 <= k (4 / m) sum_modes H_m (sum gamma^2 + sum c_m^2 / X) <= (2 / step)^2 for X at least the returned share
// (eq. S-8b); 0 when it holds for any X.
double hourglass_shear_share(const ShellGroupParameters& p, const double (&lx)[4], const double (&ly)[4], double area,
                             double step, double shear_speed2) {
  double b1[4], b2[4], gamma[4];
  for (int a = 0; a < 4; ++a)
    b1[a] = (ly[(a + 1) % 4] - ly[(a + 3) % 4]) / (2.0 * area), b2[a] = (lx[(a + 3) % 4] - lx[(a + 1) % 4]) / (2.0 * area);
  shell_hourglass::hourglass_vector(lx, ly, b1, b2, p.orthogonal_hourglass, gamma);
  const shell_hourglass::QuadraticMoments g = shell_hourglass::quadratic_moments(gamma, lx, ly);
  double cx[4], cy[4], dx[4], dy[4];
  shell_hourglass::shear_rotation_coefficients(g, b1, b2, cx, cy);
  shell_hourglass::shear_split_coefficients(g, b1, b2, dx, dy);
  double deflection = 0.0, rotation_1 = 0.0, rotation_2 = 0.0;
  for (int a = 0; a < 4; ++a) {
    deflection += gamma[a] * gamma[a];
    rotation_1 += (cx[a] + dx[a]) * (cx[a] + dx[a]) + (cy[a] + dy[a]) * (cy[a] + dy[a]);
    rotation_2 += (cx[a] - dx[a]) * (cx[a] - dx[a]) + (cy[a] - dy[a]) * (cy[a] - dy[a]);
  }
  const shell_hourglass::ShapeTensor H = shell_hourglass::shape_tensor(lx, ly, area);
  // (4 / step^2) (m / 4) / k with m / k = rho A / (kappa G) per unit thickness.
  const double room = 4.0 / (step * step) * area / (4.0 * shear_speed2) - (H.xx + H.yy) * deflection;
  return room > 0.0 ? (H.xx * rotation_1 + H.yy * rotation_2) / room : 0.0;  // room <= 0: X cannot mend it
}

template <int NN>
double inertia_share(const ShellGroupParameters& p, const Vec3* x, double thickness, double scale) {
  // The element's plane at the start: its normal from the diagonals (the sides for a triangle), e1 along the
  // first side, the nodes about the centre.
  const Vec3 n3 = NN == 4 ? cross(x[2] - x[0], x[3] - x[1]) : cross(x[1] - x[0], x[2] - x[0]);
  const Vec3 e3 = unit(n3);
  const Vec3 side = x[1] - x[0];
  const Vec3 e1 = unit(side - scaled(e3, dot(side, e3))), e2 = cross(e3, e1);
  Vec3 centre{0.0, 0.0, 0.0};
  for (int a = 0; a < NN; ++a) centre = centre + scaled(x[a], 1.0 / NN);
  double lx[NN], ly[NN];
  for (int a = 0; a < NN; ++a) lx[a] = dot(x[a] - centre, e1), ly[a] = dot(x[a] - centre, e2);
  const double area = shell_section::local_area<NN>(lx, ly);
  // eq. S-8; the triangle's m (t^2 / 12 + 2 A / 9), the reference's, shared by its corner angles (eq. S-9c)
  // (QEPH, Ishell 24: m (t^2 + A) / 48 per node, the reference's, eq. S-8c)
  const double reference = NN == 4 && p.physical_hourglass ? (thickness * thickness + area) / 12.0
                                                           : thickness * thickness / 12.0 + (NN == 3 ? 2.0 : 1.0) * area / 9.0;
  if (!(area > 0.0) || !(p.shear_factor > 0.0)) return reference;
  // The gradient operator (eq. S-2, S-9) and the Gram matrix of the two shear modes' deflection patterns.
  double b11 = 0.0, b22 = 0.0, b12 = 0.0;
  for (int a = 0; a < NN; ++a) {
    const int next = (a + 1) % NN, previous = (a + NN - 1) % NN;
    const double b1 = (ly[next] - ly[previous]) / (2.0 * area), b2 = (lx[previous] - lx[next]) / (2.0 * area);
    b11 += b1 * b1, b22 += b2 * b2, b12 += b1 * b2;
  }
  const double lambda = 0.5 * (b11 + b22) + std::sqrt(0.25 * (b11 - b22) * (b11 - b22) + b12 * b12);
  // The element's critical step, as its kernel takes it (eq. T-1a, T-1b; the plate speed for Ishell 12 and LAW36).
  const double E = p.young, nu = p.poisson;
  const bool plate = p.fully_integrated;
  const double speed = shell_step_wave_speed(E, nu, p.density, shell_step_at_plate_speed(p.hardening.law, plate));
  const double length = (plate ? shell_section::characteristic_length<NN>(lx, ly, area)
                               : shell_section::one_point_length<NN>(p, lx, ly, area)) *
                         shell_section::damped_step_factor(shell_section::step_damping(p));
  const double step = kShearModeMargin * scale * length / speed;
  // eq. S-8a: omega^2 = (kappa G / rho) (n lambda + 1 / X) <= (2 / step)^2.
  const double shear = p.shear_factor * E / (2.0 * (1.0 + nu)) / p.density;
  const double room = 4.0 / (step * step * shear) - NN * lambda;
  if (!(room > 0.0)) return reference;  // not reachable with kappa G < E: the membrane bound is the lower
  double share = std::max(reference, 1.0 / room);
  if constexpr (NN == 4)
    if (p.physical_hourglass) share = std::max(share, hourglass_shear_share(p, lx, ly, area, step, shear));
  return share;
}

}  // namespace

double shell_rotational_inertia_share(const ShellGroupParameters& p, int nodes, const Vec3* x, double thickness,
                                      double scale) {
  return nodes == 4 ? inertia_share<4>(p, x, thickness, scale) : inertia_share<3>(p, x, thickness, scale);
}

}  // namespace crumple
