#pragma once
// The elements' step estimates on the initial geometry, beside the kernels that compute the same steps every cycle
// from the same lengths, wave speeds and damping factors (docs/theory/time-step.md, T-1 to T-4): what `crumple
// check` and the listing report, the nodal steps of the solver and the accuracy presets.
#include <cstdint>

#include "crumple/core/vec3.hpp"
#include "crumple/model/model.hpp"

namespace crumple {

// Critical (unscaled) time step of one element on the initial geometry (docs/theory/time-step.md):
// dt = L / c with L the characteristic length and c the plate (shells) or dilatational (bricks) wave speed.
double initial_element_time_step(const Model& model, ElementKind kind, std::size_t element);

// The factor beta of an element in the nodal step: it gives each of its nodes the stiffness
// k = beta rho V / dt_e^2, V its current volume and dt_e its unscaled critical step. Measured on the reference solver
// one kind and one shape at a time (docs/theory/time-step.md, T-4, T-2, T-2a, T-2b): the interface nodal step (T-4)
// and the step of /DT/NODA/CST (T-2) take the same for QEPH and bricks; under /DT/NODA/CST the triangles take their
// plate stiffness, and the Belytschko-Tsay (T-2a) and QBAT (T-2b) shells (1/2) V A11 / L^2 with a length of their
// own, not their critical step's.
enum class NodalLength : std::uint8_t {
  CriticalStep,    // beta rho V / dt_e^2
  BelytschkoTsay,  // T-2a: L = sqrt(2) A / D_max
  QbatAsQeph,      // T-2b: L = sqrt(15/16) f(dn) times the QEPH's length
};
struct NodalStiffnessFactor {
  double interface = 0.0;     // T-4, with a TYPE7 and without mass scaling
  double mass_scaling = 0.0;  // T-2, /DT/NODA/CST
  NodalLength mass_scaling_length = NodalLength::CriticalStep;  // T-2a, T-2b: under /DT/NODA/CST
};
NodalStiffnessFactor nodal_stiffness_factor(ElementKind kind, int ishell, double poisson);
// The length L of k = (1/2) V A11 / L^2 (eqs. T-2a, T-2b) of a 4-node shell of this section with these corners.
double mass_scaling_nodal_length(NodalLength length, const ShellSection& section, const Vec3& p1, const Vec3& p2,
                                 const Vec3& p3, const Vec3& p4);

// The nodal step of /DT/NODA/CST (eqs. T-2, T-2a) that an element alone gives its nodes, unscaled, on the initial
// geometry: sqrt(2 (m_e / n) / k_e), m_e its mass and n its nodes.
double initial_element_nodal_step(const Model& model, ElementKind kind, std::size_t element);

struct ControllingElement {
  double time_step = 0.0;  // unscaled critical step [T]; 0 when the model has no element
  ElementKind kind = ElementKind::Shell4;
  std::int64_t element_user_id = 0;
  std::int64_t part_user_id = 0;
};

ControllingElement smallest_element_time_step(const Model& model);

}  // namespace crumple
