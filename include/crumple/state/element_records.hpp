#pragma once
// What each element handed its nodes in the last cycle, kept when a run has several
// domains: every node's sum is then assembled from these records in one fixed order, the same for any partition
// (docs/parallel.md, "Assembly"). In a run of one domain the kernels add their forces to the nodes directly, in the
// same order, and the records are empty, or kept for the element groups of the cut sections that /TH/SECTIO
// writes only (docs/output-format.md, "SECTIO"). Recording changes nothing of a kernel's arithmetic.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"

namespace crumple {

struct ElementRecords {
  int nodes_per_element = 4;
  int values_per_node = 6;  // shells: force x y z, moment x y z; bricks: force x y z
  // Per element, node and value: what the kernel subtracted from the node's sums [F], [F L].
  std::vector<double> load;

  // Run of one domain with cut sections: per element, 1 at the first element of a group that records (the
  // records then cover the elements up to the last such group only); empty: every group records.
  std::vector<std::uint8_t> only;

  bool on() const { return !load.empty(); }
  // Whether the kernel of the group whose first element is `first` records its elements.
  bool on(std::int32_t first) const {
    return !load.empty() && (only.empty() || only[static_cast<std::size_t>(first)] != 0);
  }
  void start(std::size_t elements, int nodes, int values) {
    nodes_per_element = nodes, values_per_node = values;
    load.assign(elements * static_cast<std::size_t>(nodes * values), 0.0);
  }
  double* load_at(std::size_t element, int node) {
    return load.data() + (element * static_cast<std::size_t>(nodes_per_element) + static_cast<std::size_t>(node)) *
                             static_cast<std::size_t>(values_per_node);
  }
  const double* load_at(std::size_t element, int node) const {
    return load.data() + (element * static_cast<std::size_t>(nodes_per_element) + static_cast<std::size_t>(node)) *
                             static_cast<std::size_t>(values_per_node);
  }
  // Whether element `element` has a record (the records of a run of one domain may end before the last element).
  bool covers(std::size_t element) const {
    return (element + 1) * static_cast<std::size_t>(nodes_per_element * values_per_node) <= load.size();
  }
  // An element that computed nothing this cycle (deleted, carried by a rigid body) hands the nodes nothing.
  void clear(std::size_t element) {
    double* v = load_at(element, 0);
    for (int i = 0; i < nodes_per_element * values_per_node; ++i) v[i] = 0.0;
  }
};

// Keeps a node's load in its record (`at`: ElementRecords::load_at).
inline void record_load(double* at, const Vec3& force) { at[0] = force.x, at[1] = force.y, at[2] = force.z; }
inline void record_load(double* at, const Vec3& force, const Vec3& moment) {
  record_load(at, force);
  at[3] = moment.x, at[4] = moment.y, at[5] = moment.z;
}

}  // namespace crumple
