#pragma once
// Everything the time loop advances: nodal state, element state, rigid bodies, walls and the energy balance, each
// of a type of include/crumple/state/; with the domains' scratch and the outputs' integrals beside them.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"
#include "crumple/state/contact_state.hpp"
#include "crumple/state/tied_state.hpp"
#include "crumple/state/damping_state.hpp"
#include "crumple/elements/beam.hpp"
#include "crumple/elements/brick8.hpp"
#include "crumple/elements/shell4.hpp"
#include "crumple/elements/spring.hpp"
#include "crumple/elements/truss.hpp"
#include "crumple/model/model.hpp"
#include "crumple/parallel/domain.hpp"
#include "crumple/parallel/reducer.hpp"
#include "crumple/parallel/domain_scratch.hpp"
#include "crumple/solver/output_integrals.hpp"
#include "crumple/state/energy_balance.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/rigid_state.hpp"
#include "crumple/state/selective_mass_state.hpp"
#include "crumple/state/shell_state.hpp"

namespace crumple {

struct SolverState {
  NodalState nodes;
  std::vector<double> x0, y0, z0;                  // initial coordinates
  std::vector<std::uint8_t> fixed;                  // per node: bit k set when dof k (x y z rx ry rz) is fixed
  ShellState shells;   // 4-node shells
  ShellState shells3;  // 3-node shells
  std::vector<ShellGroupParameters> shell_groups;  // per element group (meaningful for shell groups only)
  std::vector<double> shell_zeta, shell_membrane_weight, shell_bending_weight;  // through-thickness rules, 11 per n
  BrickState bricks;                                // 8-node bricks
  std::vector<BrickGroupParameters> brick_groups;  // per element group (meaningful for brick groups only)
  SpringState springs;                              // 2-node springs
  std::vector<SpringGroupParameters> spring_groups;  // per element group (meaningful for spring groups only)
  TrussState trusses;                               // 2-node trusses
  std::vector<TrussGroupParameters> truss_groups;  // per element group (meaningful for truss groups only)
  BeamState beams;                                  // 2-node beams
  std::vector<BeamGroupParameters> beam_groups;    // per element group (meaningful for beam groups only)
  std::vector<RigidBodyState> bodies;
  std::vector<RigidElementState> rigid_elements;   // /RBE2
  std::vector<InterpolationState> interpolations;  // /RBE3
  TiedState ties;                                   // /INTER/TYPE2 (empty without it)
  std::vector<RigidWallState> walls;
  ContactState contact;                             // TYPE7 interfaces (empty without /INTER/TYPE7)
  SelectiveMassState selective_mass;                // /DT/AMS (empty without it)
  std::vector<std::int32_t> rigid_owner;           // per node: rigid body index, -1 when none
  DampingState damping;  // /DAMP (empty without it)
  std::vector<SkewAxes> skew_axes;                  // per skew of the model: its axes at the current positions (SK-3)
  double time = 0.0;
  double dt = 0.0;        // step of the last position update dt^(n-1/2) [T]
  long long cycle = 0;         // cycles of the engine deck being run (the listing's CYCLE)
  long long cycles_done = 0;   // cycles of the earlier engine decks of a continued run
  EnergyBalanceState energy;
  double mass_initial = 0.0;
  double mass_added = 0.0;         // mass added by /DT/NODA/CST [M]
  std::vector<double> nodal_stiffness;  // scratch of the nodal time steps: sum of element stiffness estimates (T-2, T-4)
  // The interface nodal step (TYPE7 decks, docs/theory/time-step.md, T-4): per element kind, per element, the
  // stiffness it gives each of its nodes this cycle, from its owner [F/L].
  std::array<std::vector<double>, kElementKinds> interface_stiffness;
  std::vector<GroupStepResult> group_results;  // scratch of the element phase: per element group of the model
  Domain domain;  // the elements this state computes: all of them, or one domain's of a run of several
  Reducer reducer;  // sums over the domains of a run of several (none for one domain)
  DomainScratch domain_scratch;  // several domains: what the exchanges keep from one cycle to the next
  RecordedNodalResults recorded;
  HistoryIntegrals histories;
};

// The state every element kind has (state/element_kind_state.hpp), for code that treats the kinds alike: the one
// place that maps a kind to its state.
inline ElementKindState& element_state(SolverState& s, ElementKind kind) {
  switch (kind) {
    case ElementKind::Shell4: return s.shells;
    case ElementKind::Shell3: return s.shells3;
    case ElementKind::Brick8: return s.bricks;
    case ElementKind::Spring: return s.springs;
    case ElementKind::Truss: return s.trusses;
    case ElementKind::Beam: return s.beams;
  }
  return s.shells;
}
inline const ElementKindState& element_state(const SolverState& s, ElementKind kind) {
  return element_state(const_cast<SolverState&>(s), kind);
}
// The state of a shell kind (Shell4 or Shell3).
inline ShellState& shell_state(SolverState& s, ElementKind kind) {
  return kind == ElementKind::Shell4 ? s.shells : s.shells3;
}
inline const ShellState& shell_state(const SolverState& s, ElementKind kind) {
  return kind == ElementKind::Shell4 ? s.shells : s.shells3;
}

}  // namespace crumple
