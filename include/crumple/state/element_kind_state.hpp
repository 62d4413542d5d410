#pragma once
// What the state of every element kind holds, for the code that treats the kinds alike (the step's minimum, the
// energies, deletion, the domains' records, rebalancing, /TH/SECTIO): each kind's state (ShellState, BrickState)
// derives from it, and solver_state.hpp's element_state(s, kind) gives it for a kind.
#include <cstdint>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/state/element_records.hpp"

namespace crumple {

struct ElementKindState {
  // Per element group (index into Model::element_groups; unused for the groups of other kinds).
  std::vector<std::size_t> point_offset;  // index of the group's first integration point
  std::vector<int> points;                // integration points per element of the group

  // Per integration point: the equivalent plastic strain (rebalancing reads which points flow).
  std::vector<point_real> eps_p;

  // Per element (index in the kind's ElementTable).
  std::vector<double> internal_energy;   // [M L^2 T^-2]
  std::vector<double> hourglass_energy;  // [M L^2 T^-2]
  std::vector<double> critical_dt;       // critical step of the last cycle [T] (nodal time step, mass scaling)
  std::vector<double> mass;              // element mass [M] (nodal stiffness estimate of the nodal time step)
  std::vector<std::uint8_t> deleted;     // status byte (state/element_status.hpp): 1 once the element has failed
  ElementRecords records;                // the last cycle's loads and energies per element (several domains, or
                                         // the groups of the cut sections /TH/SECTIO writes)
  // /TH/SECTIO WORK: per element and node, the work of the element's load at the node since the start, for the
  // elements of the sections a request asks WORK of; empty otherwise [M L^2 T^-2].
  std::vector<double> section_work;

  // Sizes the common per-element arrays for n elements, every value zero.
  void resize_common(std::size_t n) {
    for (auto* v : {&internal_energy, &hourglass_energy, &critical_dt, &mass}) v->assign(n, 0.0);
    deleted.assign(n, 0);
  }
};

}  // namespace crumple
