// Trusses (docs/theory/truss.md, eq. TR-1 to TR-7).
#include "crumple/elements/truss.hpp"

#include "crumple/elements/two_node_load.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {

TrussGroupParameters truss_parameters(const Material& material, const TrussSection& section,
                                      const std::vector<Function>& functions) {
  TrussGroupParameters p;
  p.young = material.young, p.poisson = material.poisson, p.density = material.density;
  p.gap = std::max(section.gap, 0.0);
  p.hardening = materials::Hardening::of(material, functions);
  return p;
}

// eq. TR-2b: the hardening slope the truss's return divides by, at the plastic strain before the cycle; at 0 the
// slope of b eps^n is b for n = 1 and 0 below (measured, docs/theory/truss.md).
double truss_hardening_slope(const TrussGroupParameters& p, double eps_p) {
  if (p.hardening.law != MaterialLaw::JohnsonCook || eps_p > 0.0) return p.hardening.slope(eps_p, 0.0);
  return p.hardening.johnson_cook->n == 1.0 ? p.hardening.slope(0.0, 0.0) : 0.0;
}

double truss_stress_update(const TrussGroupParameters& p, double stress, double d_eps, double& eps_p) {
  const double trial = stress + p.young * d_eps;
  if (!p.hardening.plastic()) return trial;
  const double yield = p.hardening.yield(eps_p, 0.0);  // no strain rate (TR-2c)
  if (std::abs(trial) <= yield) return trial;
  // eq. TR-2b: one step of the return, the stress set to the yield stress before the step (measured)
  eps_p += (std::abs(trial) - yield) / (p.young + truss_hardening_slope(p, eps_p));
  return std::copysign(yield, trial);
}

GroupStepResult truss_forces(const ElementTable& table, const ElementGroup& group, const TrussGroupParameters& p,
                             NodalState& nodes, TrussState& state, double) {
  GroupStepResult result;
  const bool recording = state.records.on(group.begin);
  const double failure_strain = p.hardening.failure_strain();  // 0: none
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const Vec3 axis = node_position(nodes, n[1]) - node_position(nodes, n[0]);
    const double length = norm(axis), before = state.length[ue];
    if (!(length > 0.0)) {  // the nodes met: no direction left to act along
      result.inverted = e;
      continue;
    }
    state.length[ue] = length;
    const double d_eps = (length - before) / length;  // eq. TR-1, over the new length
    const double force_before = state.force[ue];
    double eps_p = state.eps_p[ue];
    if (truss_acts(p, state.length0[ue], length)) {
      const double area = state.area[ue] * (1.0 - 2.0 * p.poisson * d_eps);  // eq. TR-3
      // eq. TR-2: the stress carried to the new area, so that an elastic force grows by E A1 d_eps
      state.stress[ue] = truss_stress_update(p, state.stress[ue] * state.area[ue] / area, d_eps, eps_p);
      state.area[ue] = area;
    } else {  // eq. TR-5: open, no stress; the law still runs from zero stress (measured: eps_p grows)
      truss_stress_update(p, 0.0, d_eps, eps_p);
      state.stress[ue] = 0.0;
    }
    state.eps_p[ue] = static_cast<point_real>(eps_p);
    // eq. TR-7: a failed truss lets go over a few cycles, its force times 0.8 each, deleted after the cycle its factor
    // falls below 0.1 (measured)
    if (state.off[ue] < 1.0 || (failure_strain > 0.0 && eps_p >= failure_strain)) state.off[ue] *= kLettingGoDecay;
    const bool gone = state.off[ue] < kLettingGoDeleted;
    const double force = state.force[ue] = state.off[ue] * state.area[ue] * state.stress[ue];  // eq. TR-4
    const double work = 0.5 * (force_before + force) * (length - before);
    state.internal_energy[ue] += work;
    result.internal_energy += work;

    hand_two_node_force(nodes, state.records, recording, ue, n, scaled(axis, force / length));
    if (!std::isfinite(force)) result.non_finite = e;
    close_element(state, result, e, truss_critical_step(p, length), gone);
  }
  return result;
}

}  // namespace crumple
