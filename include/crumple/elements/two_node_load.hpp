#pragma once
// How a two-node element (spring, truss, beam) hands its nodes its internal load: the load on node 2's side, its
// opposite on node 1's (a beam's moments each their own), recorded for the domains when the group records.
#include <cstdint>

#include "crumple/core/vec3.hpp"
#include "crumple/state/element_records.hpp"
#include "crumple/state/nodal_state.hpp"

namespace crumple {

// A force along the element: `force` at node 2, `-force` at node 1.
inline void hand_two_node_force(NodalState& nodes, ElementRecords& records, bool recording, std::size_t e,
                                const std::int32_t* n, const Vec3& force) {
  subtract_internal(nodes, static_cast<std::size_t>(n[0]), scaled(force, -1.0));
  subtract_internal(nodes, static_cast<std::size_t>(n[1]), force);
  if (recording) {
    record_load(records.load_at(e, 0), scaled(force, -1.0));
    record_load(records.load_at(e, 1), force);
  }
}

// A force and the two nodes' moments: `force` and `moment_b` at node 2, `-force` and `moment_a` at node 1.
inline void hand_two_node_load(NodalState& nodes, ElementRecords& records, bool recording, std::size_t e,
                               const std::int32_t* n, const Vec3& force, const Vec3& moment_a, const Vec3& moment_b) {
  subtract_internal(nodes, static_cast<std::size_t>(n[0]), scaled(force, -1.0), moment_a);
  subtract_internal(nodes, static_cast<std::size_t>(n[1]), force, moment_b);
  if (recording) {
    record_load(records.load_at(e, 0), scaled(force, -1.0), moment_a);
    record_load(records.load_at(e, 1), force, moment_b);
  }
}

}  // namespace crumple
