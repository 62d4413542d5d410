#pragma once
// What a cut section (/SECT) sums (docs/output-format.md, "SECTIO"): the loads its elements hand the nodes of its
// cut. A term is one element's node on the cut; the section's values are sums over its terms in model order.
#include <cstdint>
#include <vector>

#include "crumple/model/model.hpp"

namespace crumple {

struct SectionTerm {
  ElementKind kind;
  std::int32_t element;  // dense index in the kind's table
  std::int32_t slot;     // the node's place in the element's connectivity, 0 .. nodes_per_element - 1
  std::int32_t node;     // dense node index
};

// The section's elements of every kind (its /GRSHEL, /GRSH3N and /GRBRIC groups), each kind sorted, each element
// once.
std::array<std::vector<std::int32_t>, kElementKinds> section_elements(const Model& model, const Section& section);

// Every node slot of the section's elements whose node is one of the section's nodes (grnod_ID), in model order:
// kind by kind (Shell4, Shell3, Brick8), element by element, slot by slot. A degenerate element that repeats a
// node has a term per slot (each slot's load reaches the node).
std::vector<SectionTerm> section_terms(const Model& model, const Section& section);

}  // namespace crumple
