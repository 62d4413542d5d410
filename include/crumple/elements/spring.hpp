#pragma once
// Springs of one translational degree of freedom along their two nodes, /PROP/TYPE4 (docs/theory/spring.md).
#include <cmath>

#include "crumple/elements/group_result.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/spring_state.hpp"

namespace crumple {

// Everything a spring kernel needs about a group that is the same for all its springs.
struct SpringGroupParameters {
  double mass = 0.0;       // M, the spring's mass [M]
  double stiffness = 0.0;  // K [F/L]
  double damping = 0.0;    // C [F T/L]
  double delta_min = -1e30, delta_max = 1e30;  // the elongations that break it [L]
};

// The group parameters of a /PROP/TYPE4 section.
inline SpringGroupParameters spring_parameters(const SpringSection& s) {
  return {s.mass, s.stiffness, s.damping, s.delta_min, s.delta_max};
}

// The critical step of a spring of mass M, stiffness K and damping C (eq. SP-4): the step of its two half masses
// joined by the spring and the dashpot, M / (sqrt(K M + C^2) + C).
inline double spring_critical_step(const SpringGroupParameters& p) {
  return p.mass / (std::sqrt(p.stiffness * p.mass + p.damping * p.damping) + p.damping);
}

// Computes the force of the group's springs at the current positions (velocities at mid-step), subtracts it from
// the nodal force accumulators and adds its work to the springs' internal energy (eq. SP-1 to SP-3).
GroupStepResult spring_forces(const ElementTable& table, const ElementGroup& group, const SpringGroupParameters& p,
                              NodalState& nodes, SpringState& state, double dt);

}  // namespace crumple
