#pragma once
// The geometry of a tie (/INTER/TYPE2): the main segment nearest to a node and the node's place on it
// (docs/theory/tied-interfaces.md, TI-1 and TI-2).
#include <array>
#include <cstdint>
#include <vector>

namespace crumple {

struct Model;
struct Type2Interface;

struct Tie {
  std::int32_t node = -1;                 // the tied (secondary) node, dense index
  std::int32_t segment = -1;              // its segment in the main surface
  std::array<std::int32_t, 4> main{};     // the segment's nodes (a triangle repeats its third)
  std::array<double, 4> weight{};         // shape functions at the projection, summing to 1 (eq. TI-1)
  double s = 0.0, t = 0.0;                // the projection's coordinates in the segment, each in [-1, 1]
  double distance = 0.0;                  // from the node to its projection [L]
};

struct TieSearch {
  std::vector<Tie> ties;                  // in the order of the node group
  std::vector<std::int32_t> unmatched;    // nodes with no segment within the search distance
  double search_distance = 0.0;           // the one used [L] (eq. TI-2)
};

// Ties the interface's nodes to the nearest segments of its surface, at the model's current positions.
TieSearch find_ties(const Model& model, const Type2Interface& interface);

// Per node of the model: the tie of every /INTER/TYPE2 that holds it, or null (the resolved model ties a node once).
std::vector<const Tie*> ties_by_node(const Model& model);

}  // namespace crumple
