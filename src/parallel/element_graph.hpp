#pragma once
// The element graph of the decomposition (docs/parallel.md, "Decomposition"): every element of every kind in one
// numbering (kind by kind in the order of Model::elements, element by element), two elements adjacent when they
// share a node. The elements of one rigid body are contracted into one vertex, so that METIS keeps them together.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/model/model.hpp"

namespace crumple::parallel {

// Element <-> node incidence in the one numbering of all elements, both ways, as compressed lists.
struct Mesh {
  std::array<std::int32_t, kElementKinds + 1> first_of_kind{};  // global number of each kind's first element
  std::vector<std::int32_t> element_start, element_nodes;      // element -> its nodes
  std::vector<std::int32_t> node_start, node_elements;         // node -> its elements, ascending

  std::int32_t elements() const { return first_of_kind[kElementKinds]; }
  std::int32_t nodes() const { return static_cast<std::int32_t>(node_start.size()) - 1; }
};

Mesh build_mesh(const Model& model);

// Calls visit(h) once for every element h != g that shares at least one node with g. `seen` holds one stamp per
// element, -1 initially; the calls for different g reuse it (seen[h] == g: already visited for g).
template <class Visit>
void for_each_neighbour(const Mesh& mesh, std::int32_t g, std::vector<std::int32_t>& seen, Visit&& visit) {
  seen[static_cast<std::size_t>(g)] = g;
  for (std::int32_t i = mesh.element_start[g]; i < mesh.element_start[g + 1]; ++i) {
    const std::int32_t node = mesh.element_nodes[static_cast<std::size_t>(i)];
    for (std::int32_t j = mesh.node_start[node]; j < mesh.node_start[node + 1]; ++j) {
      const std::int32_t h = mesh.node_elements[static_cast<std::size_t>(j)];
      if (seen[static_cast<std::size_t>(h)] == g) continue;
      seen[static_cast<std::size_t>(h)] = g;
      visit(h);
    }
  }
}

// Per node, the rigid body that carries it at the start of the run (-1: none), as the solver forms them: every
// body in deck order (a later body takes a node of an earlier one), then the run's /RBODY/OFF, then /RBODY/ON.
std::vector<std::int32_t> rigid_owner_of_nodes(const Model& model);

// Per element, the rigid body all its nodes belong to (-1: none): such an element is carried, not computed.
std::vector<std::int32_t> rigid_body_of_elements(const Mesh& mesh, const std::vector<std::int32_t>& owner);

// The graph METIS partitions, in compressed form: vertex v's neighbours are adjacency[offsets[v] .. offsets[v+1]).
struct ElementGraph {
  std::vector<std::int32_t> offsets, adjacency;
  int constraints = 1;                      // weights per vertex: the element cost, and the contact cost if any
  std::vector<std::int32_t> vertex_weight;  // per vertex, per constraint: the sum of its elements' weights
  std::vector<std::int32_t> edge_weight;    // how many element pairs the edge stands for
  std::vector<std::int32_t> vertex_of_element;

  std::int32_t vertices() const { return static_cast<std::int32_t>(offsets.size()) - 1; }
};

// One vertex per element, except the elements of one rigid body (body_of_element >= 0), which share one vertex.
// With `contact_weights`, a second constraint: METIS balances the element and the contact cost each, since the two
// phases of a cycle wait for each other in turn.
ElementGraph build_element_graph(const Mesh& mesh, const std::vector<std::int32_t>& body_of_element,
                                 const std::vector<std::int32_t>& element_weights,
                                 const std::vector<std::int32_t>* contact_weights = nullptr);

// True when every vertex can be reached from vertex 0 (METIS builds contiguous domains only then).
bool connected(const ElementGraph& graph);

}  // namespace crumple::parallel
