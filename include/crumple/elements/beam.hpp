#pragma once
// Beams (docs/theory/beam.md): /BEAM with /PROP/TYPE3, two nodes of six degrees of freedom, a co-rotational frame
// along the chord, the section's six resultants (Timoshenko's shear with k = 5/6), LAW1 elastic or LAW2 with a
// yield surface of the resultants.
#include <cmath>

#include "crumple/core/vec3.hpp"
#include "crumple/elements/group_result.hpp"
#include "crumple/materials/hardening.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/state/beam_state.hpp"
#include "crumple/state/nodal_state.hpp"

namespace crumple {

// Everything the beam kernel needs about a group that is the same for all its beams.
struct BeamGroupParameters {
  double young = 0.0, shear_modulus = 0.0, density = 0.0;  // E, G [F/L^2], rho [M/L^3]
  double area = 0.0, iyy = 0.0, izz = 0.0, ixx = 0.0;     // the section [L^2], [L^4]
  bool shear = true;          // Timoshenko's shear flexibility (Ishear 0)
  bool engineering = false;   // Ismstr 1: the axial strain and the step on L0 (BM-1, BM-8)
  double damping = 0.0;       // d = max(dm, df), the step's damping (BM-8)
  double dm = 0.0, df = 0.0;  // the axial and the flexural numerical damping (BM-7)
  materials::Hardening hardening;  // the law's yield stress (LAW1: never yields)
};

BeamGroupParameters beam_parameters(const Material& material, const BeamSection& section,
                                    const std::vector<Function>& functions);

// A beam's critical step, (L / c) (sqrt(1 + 2 d^2) - sqrt(2) d), c = sqrt(E / rho) (eq. BM-8) [T].
inline double beam_critical_step(const BeamGroupParameters& p, double length) {
  const double d = p.damping;
  return length / std::sqrt(p.young / p.density) * (std::sqrt(1.0 + 2.0 * d * d) - std::sqrt(2.0) * d);
}

// The rotational inertia each node of a beam of length L takes (eq. BM-6, measured) [M L^2].
inline double beam_node_inertia(const BeamGroupParameters& p, double length) {
  const double polar = 0.5 * p.density * length * p.ixx;
  const double bending = 0.072 * p.density * p.area * length * length * length +
                         0.5 * p.density * length * std::max(p.iyy, p.izz);
  return std::max(polar, bending);
}

// Computes the resultants of the group's beams from their rates over the last step dt, subtracts the forces and
// moments they hand their nodes from the nodal accumulators and adds their work to the beams' internal energy
// (eq. BM-0 to BM-7).
GroupStepResult beam_forces(const ElementTable& table, const ElementGroup& group, const BeamGroupParameters& p,
                            NodalState& nodes, BeamState& state, double dt);

}  // namespace crumple
