#pragma once
// Springs: /PROP/TYPE4, one translational degree of freedom along their two nodes, and /PROP/TYPE8, six in the
// global axes (docs/theory/spring.md).
#include <array>
#include <cmath>

#include "crumple/elements/group_result.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/model/functions.hpp"
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
  bool acts() const { return step_stiffness > 0.0 || damping > 0.0; }
};

// Everything a spring kernel needs about a group that is the same for all its springs.
struct SpringGroupParameters {
  double mass = 0.0;     // M, the spring's mass [M]
  double inertia = 0.0;  // I, a general spring's rotational inertia [M L^2]
  SpringFrame frame = SpringFrame::Axial;  // TYPE4 along the nodes; TYPE8 the global axes (SP-9); TYPE13 (SP-15)
  std::array<SpringDofParameters, kSpringDofs> dof{};  // /PROP/TYPE4: dof[0]
};

// The curve of the spring, g(delta) = A f(delta / Ascale) [F] (eq. SP-2b).
inline double spring_curve(const SpringDofParameters& p, double delta) {
  return p.function_scale * (*p.function)(delta / p.abscissa_scale);
}
inline double spring_lower_curve(const SpringDofParameters& p, double delta) {
  return p.function_scale * (*p.lower_function)(delta / p.abscissa_scale);
}

// The spring's force without its dashpot at elongation `delta` from the last cycle's (`before`, `force_before`),
// updating the hardening state `a`, `b` (eq. SP-2, SP-2b, SP-6 to SP-8, SP-11 to SP-14; `length0`: the spring's
// length at rest, for H 8).
double spring_elastic_force(const SpringDofParameters& p, double delta, double before, double force_before,
                            double& a, double& b, double length0 = 0.0);

// H 5, elastic-plastic with nonlinear unloading to a residual elongation, each side on its own (eq. SP-11).
double spring_residual_force(const SpringDofParameters& p, double delta, double before, double force_before,
                             double& a, double& b);

// The group parameters of a /PROP/TYPE4 section (`functions`: the model's).
SpringGroupParameters spring_parameters(const SpringSection& s, const std::vector<Function>& functions);

// The critical step of one degree of freedom of mass (or inertia) M, stiffness k and damping C (eq. SP-4): the step
// of its two half masses joined by the spring and the dashpot, M / (sqrt(k M + C^2) + C); none without either.
inline double spring_dof_critical_step(const SpringDofParameters& d, double mass) {
  if (!d.acts()) return 1e30;
  return mass / (std::sqrt(d.step_stiffness * mass + d.damping * d.damping) + d.damping);
}
// A spring's critical step: its one degree of freedom's, or a general or beam-type spring's smallest (eq. SP-4,
// SP-10, SP-18; `length`: the current length, which couples a beam-type spring's shear to its rotations).
double spring_critical_step(const SpringGroupParameters& p, double length = 0.0);

// Computes the force of the group's springs at the current positions (velocities at mid-step), subtracts it from
// the nodal force accumulators and adds its work to the springs' internal energy (eq. SP-1 to SP-3).
GroupStepResult spring_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                              NodalState& nodes, SpringState& state, double dt);

}  // namespace crumple
