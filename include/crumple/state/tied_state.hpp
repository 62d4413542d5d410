#pragma once
// What the tied interfaces (/INTER/TYPE2) hold: each tie's node, its segment and its weights, and the forces the
// ties passed in the last cycle (docs/theory/tied-interfaces.md).
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"
#include "crumple/model/elements.hpp"

namespace crumple {

struct TiedInterfaceState {
  int spotflag = 5;  // resolved formulation: 1 (rigid segment, TI-7 to TI-9), 2, 4 or 5 (TI-3 to TI-5)
  // Per tie, in the order of the interface's node group:
  std::vector<std::int32_t> secondary;               // the tied node (dense index)
  std::vector<std::array<std::int32_t, 4>> main;     // its segment's nodes (a triangle repeats its third node)
  std::vector<std::array<double, 4>> weight;         // shape functions at the node's projection, summing to 1 (TI-1)
  std::vector<double> secondary_mass;                // the node's own mass, lumped on the segment at the start [M]
  std::vector<double> secondary_inertia;             // and its own rotational inertia [M L^2]
  // Idel2 (TI-15): 1 releases a tie once every element on its segment's nodes is deleted, 2 once one is; 0 never.
  int idel2 = 0;
  std::vector<std::uint8_t> released;                // per tie: 1 once released (the node moves on its own)
  std::vector<std::uint32_t> segment_elements_first; // per tie (+1): its range in segment_elements (Idel2 only)
  std::vector<ElementRef> segment_elements;          // the shells and bricks that use every node of its segment
  // Slots of the tie's nodes in TiedState::nodes: the tied node, then the segment's four.
  std::vector<std::array<std::int32_t, 5>> slot;
  // /TH/INTER: the sum of the forces the ties passed from their nodes to the segments in the last cycle, normal
  // to the segments and in their plane [F] (TI-6).
  Vec3 normal_force{}, tangential_force{};
  // Spotflag 2 and 4 count the kinetic energy of the nodes' own masses at their velocities, not the segments' share
  // (TI-10): the difference, from the last velocity update [E].
  double kinetic_correction = 0.0;
};

struct TiedState {
  std::vector<TiedInterfaceState> interfaces;  // in the model's order
  // Every node of a tie, once, ascending, with its owner; per cycle their values, shared between the domains so that
  // every domain computes every tie alike (TI-11).
  std::vector<std::int32_t> nodes, owner;
  std::vector<double> values;
  std::vector<double> positions;  // 3 per node: its place at the start of the cycle [L]
};

}  // namespace crumple
