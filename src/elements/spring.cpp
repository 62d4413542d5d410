// Springs (docs/theory/spring.md): /PROP/TYPE4, one translational degree of freedom along the nodes (eq. SP-1 to
// SP-8, SP-11), and /PROP/TYPE8, six in the global axes (SP-9, SP-10).
#include "crumple/elements/spring.hpp"

#include "crumple/core/geometry.hpp"
#include "crumple/elements/two_node_load.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {
namespace {


SpringDofParameters dof_parameters(const SpringLaw& s, const std::vector<Function>& functions) {
  SpringDofParameters p{s.stiffness, s.damping, s.delta_min, s.delta_max};
  p.rate_c = s.rate_c, p.rate_n = s.rate_n, p.alpha = s.alpha, p.beta = s.beta;
  p.step_stiffness = s.stiffness;
  p.rate_scale = s.rate_scale;
  if (s.rate_force_function >= 0) {  // SP-23b: h's steepest slope is a dashpot of the step
    p.rate_force = &functions[static_cast<std::size_t>(s.rate_force_function)];
    p.rate_force_scale = s.rate_force_scale;
    p.rate_force_damping = std::abs(p.rate_force_scale) * p.rate_force->steepest_slope() / p.rate_scale;
  }
  p.step_damping = p.damping + p.rate_force_damping;
  if (s.function < 0) return p;
  p.function = &functions[static_cast<std::size_t>(s.function)];
  p.log_rate = s.log_rate, p.log_rate_reference = s.log_rate_reference;
  if (s.rate_factor_function >= 0)
    p.rate_factor = &functions[static_cast<std::size_t>(s.rate_factor_function)], p.rate_factor_scale = s.rate_factor_scale;
  p.function_scale = s.function_scale, p.abscissa_scale = s.abscissa_scale;
  p.hardening = s.hardening;
  if (s.lower_function >= 0) p.lower_function = &functions[static_cast<std::size_t>(s.lower_function)];
  // eq. SP-4b: the steepest segment of A f(delta / Ascale), if steeper than K, sets the step (measured on the
  // reference: a function of slopes 4000, 2000 and 4020 steps as 4020; K 5000 beside a slope of 2000 as 5000; A 2
  // doubles it, Ascale 2 halves it; H 4's lower curve does not enter).
  const double slope = p.function->steepest_slope() * p.function_scale / p.abscissa_scale;
  p.step_stiffness = std::max(p.step_stiffness, slope);
  // SP-4c: a hardening spring unloads at no less than that slope (the reference raises K to it, with a warning;
  // measured with K 500 beside a slope of 2000: the runs of K 500 and K 2000 are the same to every digit).
  if (p.hardening != 0) p.stiffness = std::max(p.stiffness, slope);
  return p;
}

}  // namespace

SpringGroupParameters spring_parameters(const SpringSection& s, const std::vector<Function>& functions) {
  SpringGroupParameters p;
  p.mass = s.mass, p.inertia = s.inertia, p.frame = s.frame, p.radial = s.radial;
  p.per_unit_length = s.per_unit_length, p.pretension = s.pretension, p.failure = s.failure, p.sensor = s.sensor;
  p.joint = s.joint;
  const auto function = [&functions](std::int32_t k) {
    return k >= 0 ? &functions[static_cast<std::size_t>(k)] : nullptr;
  };
  p.pretension_stroke = function(s.pretension.stroke_function);
  p.pretension_time = function(s.pretension.time_function);
  for (int d = 0; d < s.dofs(); ++d)
    p.dof[static_cast<std::size_t>(d)] = dof_parameters(s.dof[static_cast<std::size_t>(d)], functions);
  if (p.joint.on)  // SP-25: a joint's step is its bodies' (SpringState::joint), not its laws' on its massless nodes
    for (SpringDofParameters& d : p.dof) d.step_stiffness = 0.0, d.step_damping = 0.0;
  return p;
}

SpringGroupParameters spring_of_length(const SpringGroupParameters& p, double length0) {
  SpringGroupParameters q = p;
  if (!p.per_unit_length) return q;
  q.per_unit_length = false, q.mass *= length0, q.inertia *= length0;
  q.failure.translation_rate *= length0, q.failure.rotation_rate *= length0;
  // A beam-type spring's elongation limits are strains; a 1-D or TYPE25 spring's stay lengths (measured).
  const bool limits =
      p.frame == SpringFrame::Beam && !p.radial && p.failure.measure == SpringFailureMeasure::Elongation;
  for (SpringDofParameters& d : q.dof) {
    d.stiffness /= length0, d.damping /= length0, d.step_stiffness /= length0, d.abscissa_scale *= length0;
    d.log_rate_reference *= length0, d.rate_scale *= length0;  // SP-23 on the strain rate
    d.rate_force_damping /= length0, d.step_damping /= length0;
    if (limits && d.delta_min > -1e29) d.delta_min *= length0;  // none stays none
    if (limits && d.delta_max < 1e29) d.delta_max *= length0;
  }
  return q;
}

// SP-22c (measured on the reference's internal energy at t = 0, 48 probes): with f1, the area under S f1 over
// [max(u_lo, x_first), 0] in f1's own abscissa, its segments (split at f1's points) counted where f1 >= 0 at both
// ends, over Sd, plus (S f1(u_lo))^2 / (2 K0) when u_lo is within f1 and its lowest segment counted; u_lo = -D1 Sd,
// or without D1 f1's first point where f1 <= 0 there (else nothing); S = Sf g0, g0 f2 at its first point (1 without
// f2). With f2 alone, (Sf g0)^2 / (2 K0). Linear mode: |E1|.
double pretension_stored_energy(const SpringGroupParameters& p) {
  const SpringPretension& pre = p.pretension;
  if (!pre.by_functions()) return std::abs(pre.energy);
  const double k0 = p.dof[0].stiffness;
  const double g0 = p.pretension_time != nullptr ? p.pretension_time->y.front() : 1.0;
  const double scale = pre.force_scale * g0;
  if (p.pretension_stroke == nullptr) return scale * scale / (2.0 * k0);
  const Function& f = *p.pretension_stroke;
  const double first = f.x.front();
  double lower = 0.0;
  if (pre.stroke != 0.0) lower = -pre.stroke * pre.stroke_scale;
  else if (f(first) <= 0.0) lower = first;
  else return 0.0;
  std::vector<double> at{std::max(lower, first)};
  for (double x : f.x)
    if (x > at.front() && x < 0.0) at.push_back(x);
  at.push_back(0.0);
  double area = 0.0;
  bool lowest_counted = false;
  for (std::size_t i = 0; i + 1 < at.size(); ++i) {
    const double a = f(at[i]), b = f(at[i + 1]);
    if (!(a >= 0.0 && b >= 0.0) || !(at[i + 1] > at[i])) continue;
    area += 0.5 * (a + b) * (at[i + 1] - at[i]);
    if (i == 0) lowest_counted = true;
  }
  double energy = scale * area / pre.stroke_scale;
  if (lower >= first && lowest_counted) energy += (scale * f(lower)) * (scale * f(lower)) / (2.0 * k0);
  return energy;
}

SpringStepStiffness spring_step_stiffness(const SpringGroupParameters& p, double length) {
  if (p.frame == SpringFrame::Axial) return {p.dof[0].step_stiffness, p.dof[0].step_damping};
  // SP-10: the translations as one degree of freedom with their largest stiffness and largest damping, the rotations
  // likewise (measured: K 1000 on X beside C 3 on Y steps as K 1000 with C 3).
  SpringStepStiffness k;
  for (std::size_t d = 0; d < 3; ++d) {
    k.translation = std::max(k.translation, p.dof[d].step_stiffness);
    k.translation_damping = std::max(k.translation_damping, p.dof[d].step_damping);
    k.rotation = std::max(k.rotation, p.dof[d + 3].step_stiffness);
    k.rotation_damping = std::max(k.rotation_damping, p.dof[d + 3].step_damping);
  }
  if (p.frame == SpringFrame::Beam) {  // SP-18: the shear turns the ends as well, its stiffness times l^2
    const double arm = length * length;
    k.rotation += std::max(p.dof[1].step_stiffness, p.dof[2].step_stiffness) * arm;
    k.rotation_damping += std::max(p.dof[1].step_damping, p.dof[2].step_damping) * arm;
    // SP-23b: a shear's rate force h damps the ends' rotations once more, without the arm (measured).
    k.rotation_damping += std::max(p.dof[1].rate_force_damping, p.dof[2].rate_force_damping);
  }
  return k;
}

double spring_nodal_step(const SpringState& st, const std::int32_t* n, std::size_t e, const SpringStepStiffness* now) {
  const double change[4] = {now ? now->translation - st.own_held[4 * e] : 0.0,
                            now ? now->translation_damping - st.own_held[4 * e + 1] : 0.0,
                            now ? now->rotation - st.own_held[4 * e + 2] : 0.0,
                            now ? now->rotation_damping - st.own_held[4 * e + 3] : 0.0};
  double step = 1e30;
  for (int a = 0; a < 2; ++a) {
    const auto k = static_cast<std::size_t>(n[a]);
    const double* h = &st.node_held[SpringState::kNodeHeldValues * k];
    step = std::min({step, held_mass_step(h[4], h[0] + change[0], h[1] + change[1]),
                     held_mass_step(h[5], h[2] + change[2], h[3] + change[3])});
  }
  return step;
}

double spring_critical_step(const SpringGroupParameters& p, double length) {
  if (p.per_unit_length) return spring_critical_step(spring_of_length(p, length), length);  // SP-21, at rest
  const SpringStepStiffness k = spring_step_stiffness(p, length);
  return std::min(held_mass_step(0.5 * p.mass, k.translation, k.translation_damping),
                  held_mass_step(0.5 * p.inertia, k.rotation, k.rotation_damping));
}

namespace {

// H 5 on one side of the spring (eq. SP-11), written for tension (sign +1) and mirrored for compression (sign -1):
// the curve f up to the side's largest elongation `peak`; below it, back to 0 at the residual elongation r = g(peak
// / Ascale), along the unloading curve P, the reloading line S and the line T of slope K through the peak.
double residual_side(const SpringDofParameters& p, double sign, double delta, double trial, double& peak) {
  if (sign * delta > sign * peak) {  // loading past the side's largest elongation: on the curve
    peak = delta;
    return spring_curve(p, delta);
  }
  const double residual = (*p.lower_function)(peak / p.abscissa_scale);  // g, not scaled by A
  if (peak == 0.0 || sign * delta <= sign * residual) return 0.0;
  const double peak_force = spring_curve(p, peak);
  const double x = (delta - residual) / (peak - residual);
  const double elastic_peak = p.abscissa_scale * peak_force;  // the reference's Fe = Ascale Fmax (measured)
  const double exponent = p.stiffness * (peak - residual) / elastic_peak;  // P leaves the peak at slope K
  const double unloading = elastic_peak * std::pow(x, exponent);           // P
  const double reloading = elastic_peak * x;                               // S
  const double line = peak_force - p.stiffness * (peak - delta);           // T
  const double curve = spring_curve(p, delta);
  // Tension: min(max(trial, max(P, T)), min(max(S, T), f)); compression the mirror (multiply through by -1).
  const double low = sign * std::max(sign * unloading, sign * line);
  const double high = sign * std::min(std::max(sign * reloading, sign * line), sign * curve);
  return sign * std::min(std::max(sign * trial, sign * low), sign * high);
}

// SP-11, H 5: tension and compression each on their own side, from their own largest elongation (a >= 0, b <= 0);
// no force between the two residual elongations.
double residual_force(const SpringDofParameters& p, double delta, double before, double force_before, double& a,
                      double& b) {
  const double trial = force_before + p.stiffness * (delta - before);
  return delta >= 0.0 ? residual_side(p, 1.0, delta, trial, a) : residual_side(p, -1.0, delta, trial, b);
}

// SP-6, H 1: elastic at K inside |F| <= g(x); beyond it the force is on the curve, g(x), and x grows by the
// elongation the spring makes past the yield force (x = delta on a first loading: the curve itself).
double isotropic_force(const SpringDofParameters& p, double delta, double before, double force_before, double& x) {
  const double trial = force_before + p.stiffness * (delta - before);
  const double yield = spring_curve(p, x);
  if (std::abs(trial) <= yield) return trial;
  const double side = trial > 0.0 ? 1.0 : -1.0;
  const double elastic_part = (side * yield - force_before) / p.stiffness;  // the step's elongation to the yield
  x += std::max(0.0, std::abs(delta - before) - std::abs(elastic_part));
  return side * spring_curve(p, x);
}

// SP-7, H 2: tension and compression each elastic-plastic on their own side of the curve, from their own plastic
// elongation (a >= 0 in tension, b <= 0 in compression); no force between the two.
double uncoupled_force(const SpringDofParameters& p, double delta, double& a, double& b) {
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

// The slope of the segment of an increasing function that holds the ordinate y (the end segments beyond).
double slope_at_ordinate(const Function& g, double y) {
  std::size_t k = 1;
  while (k + 1 < g.x.size() && y > g.y[k]) ++k;
  return (g.y[k] - g.y[k - 1]) / (g.x[k] - g.x[k - 1]);
}

// SP-12, H 6: isotropic hardening on the curve f (x, one for both sides), elastic along the unloading curve u
// (fct_ID31) inside the yield band, at u's slope where the last force sits on it.
double unloading_curve_force(const SpringDofParameters& p, double delta, double before, double force_before,
                             double& x) {
  const double slope = p.function_scale * slope_at_ordinate(*p.lower_function, force_before / p.function_scale);
  const double trial = force_before + slope * (delta - before);
  const double upper = spring_curve(p, x), lower = spring_curve(p, -x);
  if (trial >= lower && trial <= upper) return trial;
  x += std::abs(delta - before);
  return trial > 0.0 ? spring_curve(p, x) : spring_curve(p, -x);
}

// SP-13, H 7: elastic hysteresis, loading at K capped by the loading curve f, unloading at K held above the
// unloading curve u (fct_ID31), in tension; compression the mirror. No permanent elongation.
double hysteresis_force(const SpringDofParameters& p, double delta, double before, double force_before) {
  const double trial = force_before + p.stiffness * (delta - before);
  const double loading = spring_curve(p, delta), unloading = spring_lower_curve(p, delta);
  const bool away = delta >= 0.0 ? delta >= before : delta <= before;  // moving away from 0: loading
  if (delta >= 0.0) return away ? std::min(trial, loading) : std::max(trial, unloading);
  return away ? std::max(trial, loading) : std::min(trial, unloading);
}

}  // namespace

double spring_elastic_force(const SpringDofParameters& p, double delta, double before, double force_before,
                            double& a, double& b, double length0) {
  if (p.function == nullptr) return p.stiffness * delta;  // SP-2
  switch (p.hardening) {
    case 0: return spring_curve(p, delta);  // SP-2b
    case 1: return isotropic_force(p, delta, before, force_before, a);
    case 2: return uncoupled_force(p, delta, a, b);
    case 4: {  // SP-8: elastic at K between the lower and the upper curve, on them beyond (the upper wins if crossed)
      const double trial = force_before + p.stiffness * (delta - before);
      return std::min(std::max(trial, spring_lower_curve(p, delta)), spring_curve(p, delta));
    }
    case 5: return residual_force(p, delta, before, force_before, a, b);
    case 6: return unloading_curve_force(p, delta, before, force_before, a);
    case 7: return hysteresis_force(p, delta, before, force_before);
    case 8: return spring_curve(p, length0 + delta);  // SP-14: the curve of the total length
    default: return 0.0;  // refused by the reader
  }
}

namespace {

// A broken spring's last force still acts over the step after it breaks: its work there, once (eq. SP-5a, SP-9).
double last_work(SpringState& state, std::size_t slot, double elongation) {
  const double work = 0.5 * state.force[slot] * (elongation - state.elongation[slot]);
  state.force[slot] = 0.0, state.elongation[slot] = elongation;
  return work;
}

// What one law keeps from cycle to cycle: its elongation, force, elastic force and hardening variables.
struct LawHistory {
  double& elongation;
  double& force;
  double& elastic;
  double& plastic_a;
  double& plastic_b;
};
LawHistory slot_history(SpringState& state, std::size_t slot) {
  return {state.elongation[slot], state.force[slot], state.elastic_force[slot], state.plastic_a[slot],
          state.plastic_b[slot]};
}
// A TYPE25 spring's radial law (SP-20): `which` 0 the shear's, 1 the bending's.
LawHistory radial_history(SpringState& state, std::size_t ue, std::size_t which) {
  double* h = &state.radial_law[SpringState::kRadialValues * ue + 5 * which];
  return {h[0], h[1], h[2], h[3], h[4]};
}

// One law's force at elongation `delta` (its elastic part and dashpot, eq. SP-2) and its work over the step,
// trapezoidal (eq. SP-3); the history keeps the elongation, the force and the hardening.
double law_force(const SpringDofParameters& p, LawHistory h, double delta, double dt, double& work,
                 double length0 = 0.0) {
  // The elongation rate over the last step (none before the first: the reference's dashpot starts at rest).
  const double rate = dt > 0.0 ? (delta - h.elongation) / dt : 0.0;
  const double elastic = spring_elastic_force(p, delta, h.elongation, h.elastic, h.plastic_a, h.plastic_b, length0);
  h.elastic = elastic;  // the static history: the rate effects do not enter it (SP-23)
  const double force = elastic * spring_rate_factor(p, rate) + p.damping * rate + spring_rate_force(p, rate);
  work += 0.5 * (h.force + force) * (delta - h.elongation);
  h.force = force, h.elongation = delta;
  return force;
}

bool outside(const SpringDofParameters& p, double delta) { return delta < p.delta_min || delta > p.delta_max; }  // SP-5

// The pretensioner's phases (SP-22), kept in its law's second hardening variable; the first holds its shortening
// since the sensor came on.
constexpr double kBeforeSensor = 0.0, kPretensioning = 1.0, kLocked = 2.0;

// SP-22, SP-22b: the pretension at shortening `shortening` and time `time`, and whether it holds the spring (positive,
// and in function mode within the stroke D1, when one is given).
struct Pretension {
  double force = 0.0;
  bool live = false;
};
Pretension pretension_at(const SpringGroupParameters& p, double shortening, double time) {
  const SpringPretension& pre = p.pretension;
  if (!pre.by_functions()) {
    const double force = pre.force - pre.stiffness * shortening;
    return {force, force > 0.0};
  }
  double force = pre.force_scale;
  if (p.pretension_stroke != nullptr) force *= (*p.pretension_stroke)(-shortening / pre.stroke_scale);
  if (p.pretension_time != nullptr) force *= (*p.pretension_time)((time - pre.activation_time) / pre.time_scale);
  return {force, force > 0.0 && (pre.stroke == 0.0 || shortening <= pre.stroke)};
}

// SP-22: an elastic K0 spring whose force, while the sensor is on and the pretension is live, is at least that
// pretension; with Ilock 2 it stays elastic once it has held more. Its work as SP-3.
double pretension_force(const SpringGroupParameters& p, LawHistory h, double delta, double time, double& work) {
  const SpringPretension& pre = p.pretension;
  const SpringDofParameters& law = p.dof[0];
  const double increment = delta - h.elongation;
  const double elastic = h.force + law.stiffness * increment;
  double& shortening = h.plastic_a;
  double& phase = h.plastic_b;
  // A sensor is looked at after a cycle, for the next: one on at t = 0 acts from the second cycle (measured).
  const bool sensor_on = pre.sensor_id == 0 || (time >= pre.activation_time && time > 0.0);
  if (phase == kBeforeSensor && sensor_on) phase = kPretensioning;
  double force = elastic;
  if (phase == kPretensioning) {
    shortening -= increment;
    const Pretension pretension = pretension_at(p, shortening, time);
    if (pretension.live && elastic > pretension.force && pre.lock) phase = kLocked;
    if (pretension.live && elastic <= pretension.force) force = pretension.force;
  }
  work += 0.5 * (h.force + force) * increment;
  h.force = force, h.elastic = force, h.elongation = delta;
  return force;
}

// SP-24: a sensor-switched spring's phase, kept in its first law's second hardening variable (a switched spring has
// no hardening): before the sensor, on, and off for good.
constexpr double kSwitchBefore = 0.0, kSwitchOn = 1.0, kSwitchOff = 2.0;
enum class SwitchStep : std::uint8_t { Acting, Idle, ComesOn, GoesOff };

// SP-24: what a switched spring does this cycle, at the time of the positions `time` (a sensor is seen from the first
// cycle at or past its Tdelay, never in the cycle at t = 0, measured), its phase advanced.
SwitchStep switch_step(const SpringSwitch& sw, double& phase, double time) {
  if (sw.sensor_id == 0) return SwitchStep::Acting;
  const bool sensor_on = time >= sw.on && time > 0.0 && time < sw.off;
  if (phase == kSwitchBefore && sensor_on) {
    phase = sw.flag == 1 ? kSwitchOff : kSwitchOn;
    return sw.flag == 1 ? SwitchStep::GoesOff : SwitchStep::ComesOn;
  }
  if (phase == kSwitchOn && sw.flag == 2 && !sensor_on) {
    phase = kSwitchOff;
    return SwitchStep::GoesOff;
  }
  const bool acting = sw.flag == 1 ? phase == kSwitchBefore : phase == kSwitchOn;
  return acting ? SwitchStep::Acting : SwitchStep::Idle;
}

// SP-24: a spring that leaves the run when its sensor switches it off: deleted, its last force's work over the step
// done as a break's (SP-5a).
void switch_off(SpringState& state, GroupStepResult& result, std::size_t ue) {
  state.deleted[ue] = kElementDeleted;
  ++result.failed;
}

// SP-24b: Isflag 2, the six laws' rest taken anew as the spring comes on: each deformation counts from the last idle
// cycle's, so that its first is the cycle's increment; the measures kept whole move their rest by as much (a general
// spring's offsets, a beam-type spring's length; one whose nodes meet at rest keeps its distance as its measure).
void take_rest_anew(SpringState& state, std::size_t ue, SpringFrame frame, std::array<double, kSpringDofs>& delta) {
  const std::size_t slot = kSpringDofs * ue;
  for (std::size_t d = 0; d < kSpringDofs; ++d) {
    const double before = state.elongation[slot + d];
    if (frame == SpringFrame::Global && d < 3) state.rest_offset[3 * ue + d] += before;
    if (frame == SpringFrame::Beam && d == 0) {
      if (!(state.length0[ue] > 0.0)) continue;
      state.length0[ue] += before;
    }
    delta[d] -= before;
    state.elongation[slot + d] = 0.0;
  }
}

// SP-24: a general or beam-type spring's switch this cycle; true while it is idle (no force, its elongations
// followed, its step not the run's), false when its laws act (or, switched off, do their last work).
bool six_law_spring_idles(const SpringSwitch& sw, SpringFrame frame, SpringState& state, GroupStepResult& result,
                          std::int32_t e, std::array<double, kSpringDofs>& delta, double time) {
  const auto ue = static_cast<std::size_t>(e), slot = kSpringDofs * ue;
  const SwitchStep step = state.deleted[ue] ? SwitchStep::Acting : switch_step(sw, state.plastic_b[slot], time);
  if (step == SwitchStep::GoesOff) switch_off(state, result, ue);
  if (step == SwitchStep::ComesOn && sw.flag == 2) take_rest_anew(state, ue, frame, delta);
  if (step != SwitchStep::Idle) return false;
  for (std::size_t d = 0; d < kSpringDofs; ++d)
    state.elongation[slot + d] = delta[d], state.force[slot + d] = state.elastic_force[slot + d] = 0.0;
  close_element(state, result, e, 1e30, false);
  return true;
}

// /PROP/TYPE4: one degree of freedom along the nodes (eq. SP-1 to SP-5).
GroupStepResult axial_spring_forces(const ElementTable& table, const ElementGroup& group,
                                    const SpringGroupParameters& group_p, NodalState& nodes, SpringState& state,
                                    double dt, double time) {
  GroupStepResult result;
  SpringGroupParameters own;  // Ileng 1: each spring's own (SP-21)
  const bool recording = state.records.on(group.begin);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e), slot = kSpringDofs * ue;
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue] & kElementElsewhere) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const Vec3 axis = node_position(nodes, n[1]) - node_position(nodes, n[0]);
    const double length = norm(axis);
    double elongation = length - state.length0[ue];  // eq. SP-1
    const SpringGroupParameters& p =
        group_p.per_unit_length ? (own = spring_of_length(group_p, state.length0[ue])) : group_p;
    const SwitchStep sw = state.deleted[ue] ? SwitchStep::Acting : switch_step(p.sensor, state.plastic_b[slot], time);
    if (sw == SwitchStep::GoesOff) switch_off(state, result, ue);
    if (sw == SwitchStep::Idle) {  // no force, its elongation followed, its step not the run's (SP-24)
      state.elongation[slot] = elongation, state.force[slot] = state.elastic_force[slot] = 0.0;
      close_element(state, result, e, 1e30, false);
      continue;
    }
    if (sw == SwitchStep::ComesOn && p.sensor.flag == 2) {  // at rest at the last cycle's length (SP-24)
      state.length0[ue] += state.elongation[slot];
      state.elongation[slot] = 0.0, elongation = length - state.length0[ue];
    }
    if (state.deleted[ue]) {  // broken last cycle: the work of its last force over the step it acted (eq. SP-5a)
      if (state.force[slot] != 0.0) {
        const double work = last_work(state, slot, elongation);
        state.internal_energy[ue] += work, result.internal_energy += work;
      }
      continue;
    }
    if (!(length > 0.0)) {  // the nodes met: no direction left to act along
      result.inverted = e;
      continue;
    }
    double work = 0.0;
    const double force = p.pretension.on
                             ? pretension_force(p, slot_history(state, slot), elongation, time, work)
                             : law_force(p.dof[0], slot_history(state, slot), elongation, dt, work, state.length0[ue]);
    state.internal_energy[ue] += work;
    result.internal_energy += work;

    hand_two_node_force(nodes, state.records, recording, ue, n, scaled(scaled(axis, 1.0 / length), force));
    if (!std::isfinite(force)) result.non_finite = e;
    close_element(state, result, e, state.nodal_step[ue], outside(p.dof[0], elongation));
  }
  return result;
}

// What a law's failure criterion reads from its cycle (SP-5b): its elongation, force and rate, and the work done on
// it so far.
struct LawFailureValues {
  double elongation = 0.0, force = 0.0, rate = 0.0, energy = 0.0;
  bool present = false;
};

// One law's force at elongation `delta` and its failure values; the work over the step into `work` and the law's own.
double law_step(const SpringDofParameters& law, LawHistory h, double& energy, double delta, double dt, double& work,
                LawFailureValues& values) {
  const double rate = dt > 0.0 ? (delta - h.elongation) / dt : 0.0;
  double own = 0.0;
  const double force = law_force(law, h, delta, dt, own);
  work += own, energy += own;
  values = {delta, force, rate, energy, true};
  return force;
}

// A TYPE25 spring's radial pair of degrees of freedom `d`, `d + 1` (shear Y and Z, or bending Y and Z): one law of
// the magnitude r of (delta_d, delta_d+1), its force along them (SP-20); the slots keep the components.
void radial_pair_step(const SpringDofParameters& law, SpringState& state, std::size_t ue, std::size_t d,
                      const std::array<double, kSpringDofs>& delta, double dt, std::array<double, kSpringDofs>& f,
                      double& work, LawFailureValues& values) {
  const std::size_t slot = kSpringDofs * ue + d;
  const double r = std::hypot(delta[d], delta[d + 1]);
  const double magnitude =
      law_step(law, radial_history(state, ue, d == 1 ? 0 : 1), state.law_energy[slot], r, dt, work, values);
  for (std::size_t c = 0; c < 2; ++c) {
    f[d + c] = r > 0.0 ? magnitude * delta[d + c] / r : 0.0;
    state.force[slot + c] = f[d + c], state.elongation[slot + c] = delta[d + c];
  }
}

// A law's share of the failure criterion (SP-5b): its value over its limit, the limit raised by c (|rate| / V)^n
// where the rate acts; 0 where it has no limit on that side.
double failure_ratio(const SpringFailure& failure, const SpringDofParameters& law, const LawFailureValues& v,
                     bool rotation) {
  const double x = failure.measure == SpringFailureMeasure::Force    ? v.force
                 : failure.measure == SpringFailureMeasure::Energy ? v.energy : v.elongation;
  // The energy against delta_max always; the others against delta_max or |delta_min| by their sign.
  const double limit = failure.measure == SpringFailureMeasure::Energy || x >= 0.0 ? law.delta_max : -law.delta_min;
  if (!(limit < 1e29)) return 0.0;  // none on that side
  double raised = limit;
  if (failure.rate_effect && law.rate_c != 0.0)
    raised += law.rate_c * std::pow(std::abs(v.rate) / (rotation ? failure.rotation_rate : failure.translation_rate),
                                    law.rate_n);
  return std::abs(x) / raised;
}

// Ifail 0: one law with alpha x / lim >= 1; Ifail 1: the sum of alpha (x / lim)^beta >= 1 (SP-5b).
bool spring_breaks(const SpringGroupParameters& p, const std::array<LawFailureValues, kSpringDofs>& values) {
  double sum = 0.0;
  for (std::size_t d = 0; d < kSpringDofs; ++d) {
    if (!values[d].present) continue;
    const SpringDofParameters& law = p.dof[d];
    const double ratio = failure_ratio(p.failure, law, values[d], d >= 3);
    if (!p.failure.combined && law.alpha * ratio >= 1.0) return true;
    if (p.failure.combined && ratio > 0.0) sum += law.alpha * std::pow(ratio, law.beta);
  }
  return p.failure.combined && sum >= 1.0;
}

// The six laws of a general or beam-type spring at their elongations: their forces `f` and work, and whether they
// break it (SP-5b). False for a spring broken last cycle: its last forces do their work over the step they acted
// (SP-5a), and nothing more.
bool six_law_step(const SpringGroupParameters& p, SpringState& state, std::int32_t e,
                  const std::array<double, kSpringDofs>& delta, double dt, GroupStepResult& result,
                  std::array<double, kSpringDofs>& f, bool& broken) {
  const auto ue = static_cast<std::size_t>(e), slot = kSpringDofs * ue;
  double work = 0.0;
  const bool active = !state.deleted[ue];
  std::array<LawFailureValues, kSpringDofs> values{};
  for (std::size_t d = 0; d < kSpringDofs; ++d) {
    if (!active) {
      if (state.force[slot + d] != 0.0) work += last_work(state, slot + d, delta[d]);
      continue;
    }
    if (p.radial && (d == 1 || d == 4)) {  // the pair d, d + 1 as one law (SP-20)
      radial_pair_step(p.dof[d], state, ue, d, delta, dt, f, work, values[d]);
      ++d;
      continue;
    }
    // A law without K, C or function: 0.
    f[d] = law_step(p.dof[d], slot_history(state, slot + d), state.law_energy[slot + d], delta[d], dt, work, values[d]);
  }
  if (active) broken = broken || spring_breaks(p, values);
  for (std::size_t d = 0; d < kSpringDofs && active; ++d)
    if (!std::isfinite(f[d])) result.non_finite = e;
  state.internal_energy[ue] += work;
  result.internal_energy += work;
  return active;
}

// The general spring's six elongations in its axes `axes` (the global ones, or a skew's at the current positions):
// node 2's offset from node 1 in them less the rest offset in the axes at rest, and the relative rotation, its
// steps' increments in the axes of each step (eq. SP-9, SP-9b).
std::array<double, kSpringDofs> general_elongations(const NodalState& nodes, const SpringState& state, std::size_t ue,
                                                    const std::int32_t* n, double dt, const SkewAxes& axes) {
  const auto a = static_cast<std::size_t>(n[0]), b = static_cast<std::size_t>(n[1]), slot = kSpringDofs * ue;
  const Vec3 offset = to_skew(axes, node_position(nodes, n[1]) - node_position(nodes, n[0]));
  const Vec3 turn = to_skew(axes, Vec3{nodes.wx[b] - nodes.wx[a], nodes.wy[b] - nodes.wy[a], nodes.wz[b] - nodes.wz[a]});
  return {offset.x - state.rest_offset[3 * ue], offset.y - state.rest_offset[3 * ue + 1],
          offset.z - state.rest_offset[3 * ue + 2], state.elongation[slot + 3] + turn.x * dt,
          state.elongation[slot + 4] + turn.y * dt, state.elongation[slot + 5] + turn.z * dt};
}

// /PROP/TYPE8: six degrees of freedom in the global axes, each its own law (eq. SP-9, SP-10).
GroupStepResult general_spring_forces(const ElementTable& table, const ElementGroup& group,
                                      const SpringGroupParameters& p, NodalState& nodes, SpringState& state, double dt,
                                      double time, const std::vector<SkewAxes>& skew_axes) {
  GroupStepResult result;
  const SkewAxes axes = p.skew >= 0 ? skew_axes[static_cast<std::size_t>(p.skew)] : SkewAxes{};
  const bool recording = state.records.on(group.begin);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue] & kElementElsewhere) continue;
    const std::int32_t* n = table.nodes_of(ue);
    std::array<double, kSpringDofs> delta = general_elongations(nodes, state, ue, n, dt, axes);
    if (six_law_spring_idles(p.sensor, SpringFrame::Global, state, result, e, delta, time)) continue;
    std::array<double, kSpringDofs> f{};
    bool broken = false;
    if (!six_law_step(p, state, e, delta, dt, result, f, broken)) continue;
    // On node 2, internal; node 1 the opposite.
    const Vec3 force = to_global(axes, {f[0], f[1], f[2]}), moment = to_global(axes, {f[3], f[4], f[5]});
    hand_two_node_load(nodes, state.records, recording, ue, n, force, scaled(moment, -1.0), moment);
    close_element(state, result, e, state.nodal_step[ue], broken);
  }
  return result;
}

Vec3 velocity(const NodalState& n, std::size_t k) { return {n.vx[k], n.vy[k], n.vz[k]}; }
Vec3 spin(const NodalState& n, std::size_t k) { return {n.wx[k], n.wy[k], n.wz[k]}; }

// v turned by the rotation vector phi (Rodrigues).
Vec3 turned(const Vec3& v, const Vec3& phi) {
  const double angle = norm(phi);
  if (!(angle > 0.0)) return v;
  const Vec3 k = scaled(phi, 1.0 / angle);
  return scaled(v, std::cos(angle)) + scaled(cross(k, v), std::sin(angle)) + scaled(k, dot(k, v) * (1.0 - std::cos(angle)));
}

// SP-25: the joint's frame turned by the mean of its nodes' rotation increments over the step, made orthonormal again.
std::array<Vec3, 3> turn_joint_frame(double* frame, const Vec3& mean_turn) {
  Vec3 x = turned({frame[0], frame[1], frame[2]}, mean_turn), y = turned({frame[3], frame[4], frame[5]}, mean_turn);
  x = scaled(x, 1.0 / norm(x));
  y = y - scaled(x, dot(x, y));
  y = scaled(y, 1.0 / norm(y));
  const Vec3 z = cross(x, y);
  const Vec3 axes[3] = {x, y, z};
  for (std::size_t a = 0; a < 3; ++a) frame[3 * a] = axes[a].x, frame[3 * a + 1] = axes[a].y, frame[3 * a + 2] = axes[a].z;
  return {x, y, z};
}

// SP-25f: the universal joint's frame, its Y turned with body 1 (node 1) and its Z with body 2, X = Y x Z, each kept
// normal to X; the frame the joint acts in is (X, Y, X x Y). The storage keeps Z as body 2 turned it.
std::array<Vec3, 3> turn_universal_frame(double* frame, const Vec3& turn1, const Vec3& turn2) {
  const auto unit = [](const Vec3& v) { return scaled(v, 1.0 / norm(v)); };
  Vec3 y = turned({frame[3], frame[4], frame[5]}, turn1), z = turned({frame[6], frame[7], frame[8]}, turn2);
  const Vec3 x = unit(cross(y, z));
  y = unit(y - scaled(x, dot(x, y)));
  z = unit(z - scaled(x, dot(x, z)));
  const Vec3 kept[3] = {x, y, z};
  for (std::size_t a = 0; a < 3; ++a)
    frame[3 * a] = kept[a].x, frame[3 * a + 1] = kept[a].y, frame[3 * a + 2] = kept[a].z;
  return {x, y, cross(x, y)};
}

Vec3 in_frame(const std::array<Vec3, 3>& f, const Vec3& v) { return {dot(f[0], v), dot(f[1], v), dot(f[2], v)}; }
Vec3 from_frame(const std::array<Vec3, 3>& f, double a, double b, double c) {
  return scaled(f[0], a) + scaled(f[1], b) + scaled(f[2], c);
}

// /PROP/TYPE45: the joint's six degrees of freedom in its own frame (eq. SP-25): the offset of node 2 from node 1
// less the rest offset and the relative rotation, the sum of each step's increment in the frame; the blocked ones
// held by the stiffness and damping the engine took at its first step, the free ones by their own laws.
GroupStepResult joint_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                             NodalState& nodes, SpringState& state, double dt) {
  GroupStepResult result;
  const bool recording = state.records.on(group.begin);
  SpringGroupParameters own = p;
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue] & kElementElsewhere) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const Vec3 w1 = spin(nodes, static_cast<std::size_t>(n[0])), w2 = spin(nodes, static_cast<std::size_t>(n[1]));
    double* frame = &state.joint_frame[9 * ue];
    const std::array<Vec3, 3> f = p.joint.universal() ? turn_universal_frame(frame, scaled(w1, dt), scaled(w2, dt))
                                                    : turn_joint_frame(frame, scaled(w1 + w2, 0.5 * dt));
    const Vec3 offset = in_frame(f, node_position(nodes, n[1]) - node_position(nodes, n[0]));
    const Vec3 turn = in_frame(f, scaled(w2 - w1, dt));
    const double* rest = &state.rest_offset[3 * ue];
    const double* last = &state.elongation[kSpringDofs * ue];
    const std::array<double, kSpringDofs> delta{offset.x - rest[0], offset.y - rest[1], offset.z - rest[2],
                                                last[3] + turn.x,   last[4] + turn.y,   last[5] + turn.z};
    const double* blocking = &state.joint[SpringState::kJointValues * ue];
    for (std::size_t d = 0; d < kSpringDofs; ++d)
      if (!p.joint.free(d))  // the translations' stiffness and damping, or the rotations'
        own.dof[d].stiffness = blocking[d < 3 ? 0 : 1], own.dof[d].damping = blocking[d < 3 ? 2 : 3];
    std::array<double, kSpringDofs> force{};
    bool broken = false;
    if (!six_law_step(own, state, e, delta, dt, result, force, broken)) continue;
    const Vec3 on2 = from_frame(f, force[0], force[1], force[2]), moment = from_frame(f, force[3], force[4], force[5]);
    // SP-25h: the pair's couple (x1 - x2) x F, half on each node, as the work of the turning frame asks.
    const Vec3 half_couple = scaled(cross(node_position(nodes, n[0]) - node_position(nodes, n[1]), on2), 0.5);
    hand_two_node_load(nodes, state.records, recording, ue, n, on2, half_couple - moment, half_couple + moment);
    close_element(state, result, e, blocking[4], broken);  // its bodies' step on it (SP-25)
  }
  return result;
}

// The beam-type spring's frame at the current positions: X along the nodes; Y the last one turned by the nodes'
// mean rotation over the step and made normal to X; Z = X x Y (eq. SP-15).
std::array<Vec3, 3> beam_frame(const Vec3& x_axis, Vec3 y, const Vec3& mean_spin, double dt) {
  y = y + scaled(cross(mean_spin, y), dt);
  y = y - scaled(x_axis, dot(y, x_axis));
  y = scaled(y, 1.0 / norm(y));
  return {x_axis, y, cross(x_axis, y)};
}

// A beam-type spring's elongations this cycle and the axes its forces (`axis`) and moments (`turn`) act along;
// `arm`, the length its shear's couple acts over.
struct BeamKinematics {
  std::array<double, kSpringDofs> delta{};
  std::array<Vec3, 3> axis{}, turn{};
  double arm = 0.0;
};

// SP-15, SP-16: the spring's turning frame and the elongations in it.
BeamKinematics beam_kinematics(const NodalState& nodes, SpringState& state, std::size_t ue, const std::int32_t* n,
                               double dt, const Vec3& axis, double length) {
  const auto n1 = static_cast<std::size_t>(n[0]), n2 = static_cast<std::size_t>(n[1]);
  const Vec3 w1 = spin(nodes, n1), w2 = spin(nodes, n2);
  double* y = &state.frame_y[3 * ue];
  const auto [ex, ey, ez] = beam_frame(scaled(axis, 1.0 / length), {y[0], y[1], y[2]}, scaled(w1 + w2, 0.5), dt);
  y[0] = ey.x, y[1] = ey.y, y[2] = ey.z;
  // SP-16: the elongations, the shear's rate less the ends' mean turn times the length.
  const Vec3 dv = velocity(nodes, n2) - velocity(nodes, n1), dw = w2 - w1;
  const double* last = &state.elongation[kSpringDofs * ue];
  BeamKinematics k;
  k.delta = {length - state.length0[ue],
             last[1] + (dot(dv, ey) - 0.5 * length * (dot(w1, ez) + dot(w2, ez))) * dt,
             last[2] + (dot(dv, ez) + 0.5 * length * (dot(w1, ey) + dot(w2, ey))) * dt,
             last[3] + dot(dw, ex) * dt, last[4] + dot(dw, ey) * dt, last[5] + dot(dw, ez) * dt};
  k.axis = k.turn = {ex, ey, ez};
  k.arm = length;
  return k;
}

// SP-15a: nodes that coincide give no frame: the rotations act in the global axes, nothing else (measured on the
// reference, which warns at rest that it cannot define the frame). Once they part, the frame is made along them
// (beam_spring_forces) and the spring is a beam-type spring of length 0 at rest.
BeamKinematics coincident_beam_kinematics(const NodalState& nodes, const SpringState& state, std::size_t ue,
                                          const std::int32_t* n, double dt) {
  const auto n1 = static_cast<std::size_t>(n[0]), n2 = static_cast<std::size_t>(n[1]);
  const Vec3 chord = node_position(nodes, n[1]) - node_position(nodes, n[0]), dw = spin(nodes, n2) - spin(nodes, n1);
  const double distance = norm(chord);
  const double* last = &state.elongation[kSpringDofs * ue];
  BeamKinematics k;
  k.delta = {distance, 0.0, 0.0, last[3] + dw.x * dt, last[4] + dw.y * dt, last[5] + dw.z * dt};
  k.turn = {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}, Vec3{0.0, 0.0, 1.0}};
  k.axis = {distance > 0.0 ? scaled(chord, 1.0 / distance) : Vec3{}, Vec3{}, Vec3{}};
  return k;
}

// /PROP/TYPE13: six laws in the spring's own frame, tension, shear, torsion and bending, the shear coupled to the
// ends' rotations as a beam's (eq. SP-15 to SP-18).
GroupStepResult beam_spring_forces(const ElementTable& table, const ElementGroup& group,
                                   const SpringGroupParameters& group_p, NodalState& nodes, SpringState& state,
                                   double dt, double time) {
  GroupStepResult result;
  SpringGroupParameters own;  // Ileng 1: each spring's own (SP-21)
  const bool recording = state.records.on(group.begin);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue] & kElementElsewhere) continue;
    const std::int32_t* n = table.nodes_of(ue);
    const Vec3 axis = node_position(nodes, n[1]) - node_position(nodes, n[0]);
    const double length = norm(axis);
    const bool at_rest_coincident = state.length0[ue] == 0.0;
    const SpringGroupParameters& p =
        group_p.per_unit_length ? (own = spring_of_length(group_p, state.length0[ue])) : group_p;
    if (!(length > 0.0) && !at_rest_coincident) {  // the nodes met: no frame left
      result.inverted = e;
      continue;
    }
    double* y0 = &state.frame_y[3 * ue];
    if (at_rest_coincident && length > 0.0 && y0[0] == 0.0 && y0[1] == 0.0 && y0[2] == 0.0) {
      const Vec3 y = geometry::rest_frame_y(scaled(axis, 1.0 / length), {0.0, 1.0, 0.0});
      y0[0] = y.x, y0[1] = y.y, y0[2] = y.z;
    }
    BeamKinematics k = !(length > 0.0) ? coincident_beam_kinematics(nodes, state, ue, n, dt)
                                       : beam_kinematics(nodes, state, ue, n, dt, axis, length);
    std::array<double, kSpringDofs>& delta = k.delta;
    if (six_law_spring_idles(p.sensor, SpringFrame::Beam, state, result, e, delta, time)) continue;
    std::array<double, kSpringDofs> f{};
    bool broken = false;
    if (!six_law_step(p, state, e, delta, dt, result, f, broken)) continue;
    // SP-17: what the spring exerts on node 1 (node 2 the opposite force), the shear's couple shared by the ends.
    const Vec3 force = scaled(k.axis[0], f[0]) + scaled(k.axis[1], f[1]) + scaled(k.axis[2], f[2]);
    const Vec3 couple = scaled(k.axis[1], -0.5 * k.arm * f[2]) + scaled(k.axis[2], 0.5 * k.arm * f[1]);
    const Vec3 moment = scaled(k.turn[0], f[3]) + scaled(k.turn[1], f[4]) + scaled(k.turn[2], f[5]);
    const Vec3 on1 = couple + moment, on2 = couple - moment;  // internal: the opposite of what acts on the node
    hand_two_node_load(nodes, state.records, recording, ue, n, force, scaled(on1, -1.0), scaled(on2, -1.0));
    const SpringStepStiffness now = spring_step_stiffness(p, k.arm);  // SP-18 at the current length
    close_element(state, result, e, spring_nodal_step(state, n, ue, &now), broken);
  }
  return result;
}

}  // namespace

GroupStepResult spring_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                              NodalState& nodes, SpringState& state, double dt, double time,
                              const std::vector<SkewAxes>& skew_axes) {
  switch (p.frame) {
    case SpringFrame::Axial: return axial_spring_forces(table, group, p, nodes, state, dt, time);
    case SpringFrame::Global:
      if (p.joint.on) return joint_forces(table, group, p, nodes, state, dt);
      return general_spring_forces(table, group, p, nodes, state, dt, time, skew_axes);
    case SpringFrame::Beam: return beam_spring_forces(table, group, p, nodes, state, dt, time);
  }
  return {};
}

}  // namespace crumple
