#pragma once
// Trusses (docs/theory/truss.md): /TRUSS with /PROP/TYPE2, two nodes, one axial stress, the material's law in one
// dimension (LAW1 elastic, LAW2 Johnson-Cook, LAW36 tabulated).
#include <cmath>

#include "crumple/elements/group_result.hpp"
#include "crumple/materials/hardening.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/truss_state.hpp"

namespace crumple {

// Everything the truss kernel needs about a group that is the same for all its trusses.
struct TrussGroupParameters {
  double young = 0.0;    // E [F/L^2]
  double poisson = 0.0;  // nu: the cross-section's change with the axial strain (TR-3)
  double density = 0.0;  // rho [M/L^3]
  double gap = 0.0;      // Gap_ini [L] (TR-5)
  materials::Hardening hardening;  // the law's yield stress (LAW1: never yields)
};

TrussGroupParameters truss_parameters(const Material& material, const TrussSection& section,
                                      const std::vector<Function>& functions);

// Whether a truss of this rest length acts at `length`: always without a gap, else once shortened by more than
// the gap (eq. TR-5).
inline bool truss_acts(const TrussGroupParameters& p, double length0, double length) {
  return p.gap <= 0.0 || length < length0 - p.gap;
}

// A truss's critical step, its current length over the bar wave speed sqrt(E / rho0) (eq. TR-6); a truss with a
// gap bounds no step (measured: the reference leaves it out, open or closed) [T].
inline double truss_critical_step(const TrussGroupParameters& p, double length) {
  return p.gap > 0.0 ? 1e30 : length / std::sqrt(p.young / p.density);
}

// The one-dimensional law (eq. TR-2, TR-2b): the stress after a strain increment `d_eps` from `stress`, and the
// plastic strain `eps_p` it leaves. No strain rate enters (TR-2c: the reference's trusses take none, measured).
double truss_stress_update(const TrussGroupParameters& p, double stress, double d_eps, double& eps_p);

// Computes the axial force of the group's trusses at the current positions, subtracts it from the nodal force
// accumulators and adds its work to the trusses' internal energy (eq. TR-1 to TR-6).
GroupStepResult truss_forces(const ElementTable& table, const ElementGroup& group, const TrussGroupParameters& p,
                             NodalState& nodes, TrussState& state, double dt);

}  // namespace crumple
