// Springs of one translational degree of freedom, /PROP/TYPE4 (docs/theory/spring.md, eq. SP-1 to SP-4).
#include "crumple/elements/spring.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {
namespace {

Vec3 position(const NodalState& n, std::int32_t k) {
  const auto u = static_cast<std::size_t>(k);
  return {n.x[u], n.y[u], n.z[u]};
}

// The steepest segment of a function, |dy / dx|.
double steepest_slope(const Function& f) {
  double slope = 0.0;
  for (std::size_t k = 1; k < f.x.size(); ++k) slope = std::max(slope, std::abs(f.y[k] - f.y[k - 1]) / (f.x[k] - f.x[k - 1]));
  return slope;
}

}  // namespace

SpringGroupParameters spring_parameters(const SpringSection& s, const std::vector<Function>& functions) {
  SpringGroupParameters p{s.mass, s.stiffness, s.damping, s.delta_min, s.delta_max};
  p.step_stiffness = s.stiffness;
  if (s.function < 0) return p;
  p.function = &functions[static_cast<std::size_t>(s.function)];
  p.function_scale = s.function_scale, p.abscissa_scale = s.abscissa_scale;
  p.hardening = s.hardening;
  if (s.lower_function >= 0) p.lower_function = &functions[static_cast<std::size_t>(s.lower_function)];
  // eq. SP-4b: the steepest segment of A f(delta / Ascale), if steeper than K (measured on the reference: a function
  // of slopes 4000, 2000 and 4020 steps as 4020; K 5000 beside a slope of 2000 as 5000; A 2 doubles it, Ascale 2
  // halves it).
  double slope = steepest_slope(*p.function);
  if (p.lower_function != nullptr) slope = std::max(slope, steepest_slope(*p.lower_function));
  p.step_stiffness = std::max(p.step_stiffness, slope * p.function_scale / p.abscissa_scale);
  return p;
}

double spring_elastic_force(const SpringGroupParameters& p, double delta, double before, double force_before,
                            double& a, double& b) {
  if (p.function == nullptr) return p.stiffness * delta;  // SP-2
  if (p.hardening == 0) return spring_curve(p, delta);    // SP-2b
  if (p.hardening == 1) {
    // SP-6: elastic at K inside |F| <= g(x); beyond it the force is on the curve, g(x), and x grows by the
    // elongation the spring makes past the yield force (x = delta on a first loading: the curve itself).
    const double trial = force_before + p.stiffness * (delta - before);
    const double yield = spring_curve(p, a);
    if (std::abs(trial) <= yield) return trial;
    const double side = trial > 0.0 ? 1.0 : -1.0;
    const double elastic_part = (side * yield - force_before) / p.stiffness;  // the step's elongation to the yield
    a += std::max(0.0, std::abs(delta - before) - std::abs(elastic_part));
    return side * spring_curve(p, a);
  }
  if (p.hardening == 4) {  // SP-8: elastic at K between the lower and the upper curve, on them beyond
    const double trial = force_before + p.stiffness * (delta - before);
    return std::min(std::max(trial, spring_lower_curve(p, delta)), spring_curve(p, delta));  // upper wins if crossed
  }
  // SP-7, H 2: tension and compression each elastic-plastic on their own side of the curve, from their own plastic
  // elongation (a >= 0 in tension, b <= 0 in compression); no force between the two.
  if (delta > a) {
    const double curve = spring_curve(p, delta), elastic = p.stiffness * (delta - a);
    if (elastic <= curve) return elastic;
    a = delta - curve / p.stiffness;
    return curve;
  }
  if (delta < b) {
    const double curve = spring_curve(p, delta), elastic = p.stiffness * (delta - b);
    if (elastic >= curve) return elastic;
    b = delta - curve / p.stiffness;
    return curve;
  }
  return 0.0;
}

GroupStepResult spring_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                              NodalState& nodes, SpringState& state, double dt) {
  GroupStepResult result;
  const bool recording = state.records.on(group.begin);
  const double step = spring_critical_step(p);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue] & kElementElsewhere) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const Vec3 axis = position(nodes, n[1]) - position(nodes, n[0]);
    const double length = norm(axis);
    if (state.deleted[ue]) {  // broken last cycle: the work of its last force over the step it acted (eq. SP-5a)
      if (state.force[ue] != 0.0) {
        const double work = 0.5 * state.force[ue] * (length - state.length0[ue] - state.elongation[ue]);
        state.internal_energy[ue] += work, result.internal_energy += work;
        state.force[ue] = 0.0, state.elongation[ue] = length - state.length0[ue];
      }
      continue;
    }
    if (!(length > 0.0)) {  // the nodes met: no direction left to act along
      result.inverted = e;
      continue;
    }
    const Vec3 along = scaled(axis, 1.0 / length);
    const double elongation = length - state.length0[ue];  // eq. SP-1
    // The elongation rate over the last step (none before the first: the reference's dashpot starts at rest).
    const double rate = dt > 0.0 ? (elongation - state.elongation[ue]) / dt : 0.0;
    const double elastic = spring_elastic_force(p, elongation, state.elongation[ue], state.elastic_force[ue],
                                                state.plastic_a[ue], state.plastic_b[ue]);
    state.elastic_force[ue] = elastic;
    const double force = elastic + p.damping * rate;
    // The work of the force over the step, trapezoidal in the elongation (eq. SP-3).
    const double work = 0.5 * (state.force[ue] + force) * (elongation - state.elongation[ue]);
    state.force[ue] = force, state.elongation[ue] = elongation;
    state.internal_energy[ue] += work;
    result.internal_energy += work;

    const Vec3 pull = scaled(along, force);  // internal force: -pull at node 1, +pull at node 2
    subtract_internal(nodes, static_cast<std::size_t>(n[0]), scaled(pull, -1.0));
    subtract_internal(nodes, static_cast<std::size_t>(n[1]), pull);
    if (recording) {
      record_load(state.records.load_at(ue, 0), scaled(pull, -1.0));
      record_load(state.records.load_at(ue, 1), pull);
    }
    if (!std::isfinite(force)) result.non_finite = e;
    const bool broken = elongation < p.delta_min || elongation > p.delta_max;  // eq. SP-5
    close_element(state, result, e, step, broken);
  }
  return result;
}

}  // namespace crumple
