// Beams (docs/theory/beam.md, eq. BM-0 to BM-8).
#include "crumple/elements/beam.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "crumple/elements/two_node_load.hpp"

namespace crumple {
namespace {

constexpr double kShearFactor = 5.0 / 6.0;  // k of Timoshenko's shear, measured (BM-3)

// The shear stiffness of one bending plane, (k G A)_eff = 12 E I / (L^2 (1 + phi)), phi = 12 E I / (k G A L^2): a
// one-point beam with it is Timoshenko's exact cantilever (BM-3); without shear (Ishear 1) phi = 0.
double shear_stiffness(const BeamGroupParameters& p, double inertia, double length) {
  const double bending = 12.0 * p.young * inertia / (length * length);
  if (!p.shear) return bending;
  return bending / (1.0 + bending / (kShearFactor * p.shear_modulus * p.area));
}

// The frame of a beam at the current positions: the chord `ex`, and `y` from the last cycle's made normal to it and
// turned about it by the mean twist of the two nodes over the step (BM-0).
struct BeamFrame {
  Vec3 ex, ey, ez;
};
BeamFrame turned_frame(const Vec3& ex, const Vec3& y_before, double twist) {
  Vec3 y = y_before - scaled(ex, dot(ex, y_before));
  y = scaled(y, 1.0 / norm(y));
  const Vec3 across = cross(ex, y);
  const Vec3 ey = scaled(y, std::cos(twist)) + scaled(across, std::sin(twist));
  return {ex, ey, cross(ex, ey)};
}

// The section's yield in its resultants (eq. BM-5): sqrt((N/A)^2 + 3 T^2/(A Ixx) + 3 My^2/(A Iyy) + 3 Mz^2/(A Izz)),
// an equivalent stress [F/L^2].
double equivalent_stress(const BeamGroupParameters& p, const std::array<double, kBeamResultants>& r) {
  const double n = r[0] / p.area;
  return std::sqrt(n * n + 3.0 * (r[3] * r[3] / (p.area * p.ixx) + r[4] * r[4] / (p.area * p.iyy) +
                                  r[5] * r[5] / (p.area * p.izz)));
}

// eq. BM-5c: the strain rate Johnson-Cook's yield sees, the rate conjugate to the section's work: the resultants
// before the cycle times their generalised strain rates, over the area and the trial's equivalent stress (measured
// to 1.6e-6 on pulls, bendings, torsions and their mixes; 0 in the first cycle).
double work_conjugate_rate(const BeamGroupParameters& p, const double* before, const double* q, double dt,
                           double trial_equivalent) {
  if (!(dt > 0.0) || !(trial_equivalent > 0.0)) return 0.0;
  const double power = before[0] * q[0] + before[3] * q[3] + before[4] * q[4] + before[5] * q[5];  // per length, x dt
  return power / dt / (p.area * trial_equivalent);
}

// eq. BM-5b: a trial outside the yield surface is brought back onto the yield stress before the cycle (with the
// strain rate of BM-5c), the axial force, the torsion and the moments scaled alike (the shear forces are not in
// the surface). The plastic strain grows by the cycle's plastic work at the mean of the resultants before and
// after, over the yield stress before it without the rate's factor (measured to 5e-8 on an axial pull, 6e-7 with
// the rate): dW_p = sum (R0 + R) / 2 (q - (R - R0) / K) per unit length.
void return_to_yield(const BeamGroupParameters& p, const double* before, const double* q, const double* stiffness,
                     double dt, std::array<double, kBeamResultants>& r, double& eps_p) {
  if (!p.hardening.plastic()) return;
  const double equivalent = equivalent_stress(p, r);
  const double yield = p.hardening.yield(eps_p, work_conjugate_rate(p, before, q, dt, equivalent));
  if (equivalent <= yield) return;
  const double scale = yield / equivalent;
  double plastic_work = 0.0;  // per unit length
  for (const std::size_t i : {0u, 3u, 4u, 5u}) {
    r[i] *= scale;
    plastic_work += 0.5 * (before[i] + r[i]) * (q[i] - (r[i] - before[i]) / stiffness[i]);
  }
  eps_p += std::abs(plastic_work) / (p.hardening.yield(eps_p, 0.0) * p.area);
}

// eq. BM-7: the numerical damping's resultants from the rates of the generalised strains (times L where they are
// strains, so that none depends on L): dm damps the axial force, df the shears, the torsion and the bendings. They
// act on the nodes, not in the section's state or its energy (measured: the reference's /TH/BEAM and IE leave them
// out; their work shows in its energy error only).
std::array<double, kBeamResultants> damping_resultants(const BeamGroupParameters& p, const double* rate) {
  const double impedance = std::sqrt(p.young * p.density), torsion = std::sqrt(p.shear_modulus * p.density);
  const double cm = std::sqrt(2.0) * p.dm, cf = std::sqrt(2.0) * p.df;
  return {cm * impedance * p.area * rate[0], cf * impedance * p.area * rate[1], cf * impedance * p.area * rate[2],
          cf * torsion * p.ixx * rate[3],   cf * impedance * p.iyy * rate[4],  cf * impedance * p.izz * rate[5]};
}

}  // namespace

BeamGroupParameters beam_parameters(const Material& material, const BeamSection& section,
                                    const std::vector<Function>& functions) {
  BeamGroupParameters p;
  p.young = material.young, p.shear_modulus = material.shear_modulus(), p.density = material.density;
  p.area = section.area, p.iyy = section.iyy, p.izz = section.izz, p.ixx = section.ixx;
  p.shear = section.ishear == 0;
  p.engineering = section.ismstr == 1;
  p.dm = section.dm, p.df = section.df_or_default();  // as given: a negative one feeds energy in (measured)
  p.damping = std::max({p.dm, p.df, 0.0});           // the step takes none of a negative damping (BM-8)
  p.hardening = materials::Hardening::of(material, functions);
  return p;
}

GroupStepResult beam_forces(const ElementTable& table, const ElementGroup& group, const BeamGroupParameters& p,
                            NodalState& nodes, BeamState& state, double dt) {
  GroupStepResult result;
  const bool recording = state.records.on(group.begin);
  const double failure_strain = p.hardening.failure_strain();  // 0: none
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const auto a = static_cast<std::size_t>(n[0]), b = static_cast<std::size_t>(n[1]);
    const Vec3 axis = node_position(nodes, n[1]) - node_position(nodes, n[0]);
    const double length = norm(axis), before = state.length[ue];
    if (!(length > 0.0)) {  // the nodes met: no chord left to turn with
      result.inverted = e;
      continue;
    }
    const Vec3 wa{nodes.wx[a], nodes.wy[a], nodes.wz[a]}, wb{nodes.wx[b], nodes.wy[b], nodes.wz[b]};
    const Vec3 relative_velocity{nodes.vx[b] - nodes.vx[a], nodes.vy[b] - nodes.vy[a], nodes.vz[b] - nodes.vz[a]};
    double* y_stored = &state.frame_y[3 * ue];
    const BeamFrame f = turned_frame(scaled(axis, 1.0 / length), {y_stored[0], y_stored[1], y_stored[2]},
                                     0.5 * dot(wa + wb, scaled(axis, 1.0 / length)) * dt);
    y_stored[0] = f.ey.x, y_stored[1] = f.ey.y, y_stored[2] = f.ey.z;
    state.length[ue] = length;

    // eq. BM-1 to BM-3: the generalised strains' increments over the step, in the frame
    const Vec3 chord_spin = scaled(cross(f.ex, relative_velocity), 1.0 / length);
    const Vec3 spin_sum = wa + wb - scaled(chord_spin, 2.0);  // the nodes' rotation rates off the chord's, summed
    const Vec3 spin_difference = wb - wa;
    const double q[kBeamResultants] = {
        (length - before) / (p.engineering ? state.length0[ue] : length),  // axial strain
        -0.5 * dot(spin_sum, f.ez) * dt,                                      // shear in the xy plane
        0.5 * dot(spin_sum, f.ey) * dt,                                       // shear in the xz plane
        dot(spin_difference, f.ex) * dt / length,                            // twist
        dot(spin_difference, f.ey) * dt / length,                            // curvature about y
        dot(spin_difference, f.ez) * dt / length};                           // curvature about z
    const double stiffness[kBeamResultants] = {p.young * p.area,           shear_stiffness(p, p.izz, length),
                                               shear_stiffness(p, p.iyy, length), p.shear_modulus * p.ixx,
                                               p.young * p.iyy,            p.young * p.izz};
    double* stored = &state.resultant[kBeamResultants * ue];
    std::array<double, kBeamResultants> r{};
    for (std::size_t i = 0; i < kBeamResultants; ++i) r[i] = stored[i] + stiffness[i] * q[i];
    double eps_p = state.eps_p[ue];
    return_to_yield(p, stored, q, stiffness, dt, r, eps_p);
    state.eps_p[ue] = static_cast<point_real>(eps_p);
    // eq. BM-4: the resultants' work at mid-step, the axial force's over the change of length
    double work = 0.5 * (stored[0] + r[0]) * (length - before);
    for (std::size_t i = 1; i < kBeamResultants; ++i) work += 0.5 * (stored[i] + r[i]) * q[i] * length;
    // eq. BM-9: a failed beam lets go, its resultants and its work times its factor (measured)
    if (state.off[ue] < 1.0 || (failure_strain > 0.0 && eps_p >= failure_strain)) state.off[ue] *= kLettingGoDecay;
    const double off = state.off[ue];
    work *= off;
    for (std::size_t i = 0; i < kBeamResultants; ++i) stored[i] = r[i] *= off;
    state.internal_energy[ue] += work;
    result.internal_energy += work;

    // eq. BM-4: what the section and its damping (BM-7) hand the nodes (internal loads: node 2 the face's, node 1
    // the opposite)
    const double rate[kBeamResultants] = {dot(relative_velocity, f.ex),
                                          dot(relative_velocity, f.ey) - 0.5 * length * dot(wa + wb, f.ez),
                                          dot(relative_velocity, f.ez) + 0.5 * length * dot(wa + wb, f.ey),
                                          dot(spin_difference, f.ex), dot(spin_difference, f.ey),
                                          dot(spin_difference, f.ez)};
    std::array<double, kBeamResultants> load = damping_resultants(p, rate);
    for (std::size_t i = 0; i < kBeamResultants; ++i) load[i] += r[i];
    const Vec3 force = scaled(f.ex, load[0]) + scaled(f.ey, load[1]) + scaled(f.ez, load[2]);
    const Vec3 couple = scaled(f.ex, load[3]) + scaled(f.ey, load[4]) + scaled(f.ez, load[5]);
    const Vec3 shear_moment = scaled(f.ey, 0.5 * length * load[2]) - scaled(f.ez, 0.5 * length * load[1]);
    const Vec3 moment_b = couple + shear_moment, moment_a = shear_moment - couple;
    hand_two_node_load(nodes, state.records, recording, ue, n, force, moment_a, moment_b);
    if (!std::isfinite(load[0] + load[1] + load[2] + load[3] + load[4] + load[5])) result.non_finite = e;
    close_element(state, result, e, beam_critical_step(p, p.engineering ? state.length0[ue] : length),
                  off < kLettingGoDeleted);
  }
  return result;
}

}  // namespace crumple
