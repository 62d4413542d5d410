#pragma once
// Springs (docs/theory/spring.md): /PROP/TYPE4, one translational degree of freedom along their two nodes;
// /PROP/TYPE8, six in the global axes; /PROP/TYPE13, six in a frame that turns with the spring.
#include <algorithm>
#include <array>
#include <cmath>

#include "crumple/elements/group_result.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/model/functions.hpp"
#include "crumple/model/skews.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/spring_state.hpp"

namespace crumple {

// One degree of freedom's law of a spring group (docs/theory/spring.md).
struct SpringDofParameters {
  double stiffness = 0.0;  // K [F/L] or [F L/rad]
  double damping = 0.0;    // C [F T/L] or [F L T/rad]
  double delta_min = -1e30, delta_max = 1e30;  // the elongations that break it [L] or [rad]
  const Function* function = nullptr;  // fct_ID1: the force A f(delta / Ascale) (eq. SP-2b); none: K delta
  double function_scale = 1.0, abscissa_scale = 1.0;  // A [F], Ascale [L]
  double step_stiffness = 0.0;  // the stiffness of the step: K, or the function's steepest slope if larger (SP-4b)
  int hardening = 0;  // H: 0 elastic, 1 isotropic (SP-6), 2 uncoupled (SP-7), 4 kinematic (SP-8), 5 residual
                      // (SP-11), 6 unloading curve (SP-12), 7 hysteresis (SP-13), 8 total length (SP-14)
  const Function* lower_function = nullptr;  // fct_ID3: H 4's lower yield curve, H 5's residual elongation,
                                             // H 6 and 7's unloading curve
  double rate_c = 0.0, rate_n = 1.0, alpha = 1.0, beta = 2.0;  // SP-5b
  // SP-23, the rate effects of the elongation rate r: the curve's force times 1 + B' ln(max(1, |r| / D)) + E' g(r / F)
  // (B' = B / A, E' = E / A), and Hscale h(r / F) added.
  double log_rate = 0.0, log_rate_reference = 1.0;  // B / A; D [L/T] or [1/T]
  const Function* rate_factor = nullptr;            // fct_ID2: g
  double rate_factor_scale = 0.0;                   // E / A
  double rate_scale = 1.0;                          // F [L/T] or [1/T]
  const Function* rate_force = nullptr;             // fct_ID4: h
  double rate_force_scale = 0.0;                    // Hscale [F]
  double rate_force_damping = 0.0;  // Hscale max|h'| / F, the dashpot h is to the step (SP-23b) [F T/L]
  double step_damping = 0.0;        // the damping of the step: C + the above (SP-4, SP-23b)
};

// Everything a spring kernel needs about a group that is the same for all its springs.
struct SpringGroupParameters {
  double mass = 0.0;     // M, the spring's mass [M]
  double inertia = 0.0;  // I, a general or beam-type spring's rotational inertia [M L^2]
  SpringFrame frame = SpringFrame::Axial;  // TYPE4 along the nodes; TYPE8 the global axes (SP-9); TYPE13 (SP-15)
  std::array<SpringDofParameters, kSpringDofs> dof{};  // /PROP/TYPE4: dof[0]
  bool radial = false;  // TYPE25: shear and bending on the radial magnitude (SP-20)
  bool per_unit_length = false;  // Ileng 1: each spring's values follow from its rest length (SP-21)
  SpringPretension pretension;   // TYPE32 (SP-22)
  const Function* pretension_stroke = nullptr;  // TYPE32's f1 and f2 (SP-22b); none: 1
  const Function* pretension_time = nullptr;
  SpringFailure failure;  // SP-5b
  std::int32_t skew = -1;  // TYPE8: the skew whose axes its laws act in (SP-9b); -1 the global axes
  SpringSwitch sensor;     // sens_ID, Isflag (SP-24)
  SpringJoint joint;       // TYPE45: its blocking stiffness and damping are each joint's own (SP-25)
};

// Ileng 1 (eq. SP-21): the parameters of one spring of rest length `length0` [L] > 0 whose property gives them per
// unit length: M L0, I L0, K / L0, C / L0, its curves of the strain (Ascale L0), its rate term's reference velocities
// L0 Vo, L0 Wo, and a beam-type spring's elongation limits L0 delta (a 1-D spring's, and force and energy limits,
// stay as given). Without Ileng, the group's own.
SpringGroupParameters spring_of_length(const SpringGroupParameters& p, double length0);

// The curve of the spring, g(delta) = A f(delta / Ascale) [F] (eq. SP-2b).
inline double spring_curve(const SpringDofParameters& p, double delta) {
  return p.function_scale * (*p.function)(delta / p.abscissa_scale);
}
inline double spring_lower_curve(const SpringDofParameters& p, double delta) {
  return p.function_scale * (*p.lower_function)(delta / p.abscissa_scale);
}

// SP-23: the factor R / A of the curve's force at the elongation rate r, 1 + B' ln(max(1, |r| / D)) + E' g(r / F);
// 1 for a linear spring.
inline double spring_rate_factor(const SpringDofParameters& p, double rate) {
  double factor = 1.0;
  if (p.log_rate != 0.0) factor += p.log_rate * std::log(std::max(1.0, std::abs(rate) / p.log_rate_reference));
  if (p.rate_factor != nullptr) factor += p.rate_factor_scale * (*p.rate_factor)(rate / p.rate_scale);
  return factor;
}
// SP-23: the force of the rate, Hscale h(r / F) [F]; 0 without h.
inline double spring_rate_force(const SpringDofParameters& p, double rate) {
  return p.rate_force == nullptr ? 0.0 : p.rate_force_scale * (*p.rate_force)(rate / p.rate_scale);
}

// The spring's force without its dashpot at elongation `delta` from the last cycle's (`before`, `force_before`),
// updating the hardening state `a`, `b` (eq. SP-2, SP-2b, SP-6 to SP-8, SP-11 to SP-14; `length0`: the spring's
// length at rest, for H 8).
double spring_elastic_force(const SpringDofParameters& p, double delta, double before, double force_before,
                            double& a, double& b, double length0 = 0.0);

// SP-22, SP-22c: the energy a pretensioner stores from t = 0 (its internal energy at the start) [E].
double pretension_stored_energy(const SpringGroupParameters& p);

// The group parameters of a spring section (`functions`: the model's).
SpringGroupParameters spring_parameters(const SpringSection& s, const std::vector<Function>& functions);

// The stable step of a mass (or inertia) m held by a stiffness k and a damping c, 2 m / (sqrt(2 m k + c^2) + c)
// (eq. SP-4, SP-19); none without either.
inline double held_mass_step(double mass, double stiffness, double damping) {
  if (!(stiffness > 0.0) && !(damping > 0.0)) return 1e30;
  return 2.0 * mass / (std::sqrt(2.0 * mass * stiffness + damping * damping) + damping);
}

// What a spring hands each of its nodes for the step: the stiffness and damping of its translations and of its
// rotations (eq. SP-4b, SP-10, SP-18; `length`: the current length, which couples a beam-type spring's shear to
// its rotations).
struct SpringStepStiffness {
  double translation = 0.0, translation_damping = 0.0, rotation = 0.0, rotation_damping = 0.0;
};
SpringStepStiffness spring_step_stiffness(const SpringGroupParameters& p, double length);

// SP-19: spring `e`'s step, the smaller of its nodes' (each node's whole mass and inertia held by the sums
// SpringState::node_held of every spring on it); `now`, when given, replaces the spring's own share at rest.
double spring_nodal_step(const SpringState& st, const std::int32_t* n, std::size_t e,
                         const SpringStepStiffness* now = nullptr);

// A spring's own critical step, its two half masses and inertias held by it (eq. SP-4, SP-10, SP-18): the starter's
// element step, which `crumple check` prints.
double spring_critical_step(const SpringGroupParameters& p, double length = 0.0);

// Computes the force of the group's springs at the current positions (velocities at mid-step) at time `time`,
// subtracts it from the nodal force accumulators and adds its work to the springs' internal energy (eq. SP-1 to SP-3).
// `skew_axes`: the model's skews' axes at the current positions (a general spring's in a skew, SP-9b).
GroupStepResult spring_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                              NodalState& nodes, SpringState& state, double dt, double time,
                              const std::vector<SkewAxes>& skew_axes);

}  // namespace crumple
