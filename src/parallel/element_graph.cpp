// The element graph of the decomposition (element_graph.hpp, docs/parallel.md "Decomposition").
#include "element_graph.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace crumple::parallel {
namespace {

constexpr std::int64_t kLargestIndex = std::numeric_limits<std::int32_t>::max();

// METIS is built with 32-bit indices (Debian's libmetis: IDXTYPEWIDTH 32): every count must fit.
void check_fits(std::int64_t count, const char* what) {
  if (count > kLargestIndex)
    throw std::runtime_error(fmt::format("the decomposition cannot index {} {}: METIS counts with 32-bit integers, "
                                         "at most {}", count, what, kLargestIndex));
}

// The node -> elements lists by a counting sort of the element -> nodes lists: ascending element numbers.
void invert_incidence(Mesh& mesh, std::size_t nodes) {
  mesh.node_start.assign(nodes + 1, 0);
  for (const std::int32_t node : mesh.element_nodes) ++mesh.node_start[static_cast<std::size_t>(node) + 1];
  for (std::size_t k = 0; k < nodes; ++k) mesh.node_start[k + 1] += mesh.node_start[k];
  std::vector<std::int32_t> next(mesh.node_start.begin(), mesh.node_start.end() - 1);
  mesh.node_elements.assign(mesh.element_nodes.size(), 0);
  for (std::int32_t g = 0; g < mesh.elements(); ++g)
    for (std::int32_t i = mesh.element_start[g]; i < mesh.element_start[g + 1]; ++i)
      mesh.node_elements[static_cast<std::size_t>(next[mesh.element_nodes[i]]++)] = g;
}

}  // namespace

Mesh build_mesh(const Model& model) {
  Mesh mesh;
  std::int64_t elements = 0, links = 0;
  for (int k = 0; k < kElementKinds; ++k) {
    const ElementTable& table = model.elements[static_cast<std::size_t>(k)];
    mesh.first_of_kind[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(elements);
    elements += static_cast<std::int64_t>(table.size());
    links += static_cast<std::int64_t>(table.connectivity.size());
    check_fits(elements, "elements");
    check_fits(2 * links, "element-node links");
  }
  mesh.first_of_kind[kElementKinds] = static_cast<std::int32_t>(elements);
  mesh.element_start.reserve(static_cast<std::size_t>(elements) + 1);
  mesh.element_nodes.reserve(static_cast<std::size_t>(links));
  mesh.element_start.push_back(0);
  for (const ElementTable& table : model.elements) {
    const auto n = static_cast<std::size_t>(nodes_per_element(table.kind));
    for (std::size_t e = 0; e < table.size(); ++e) {
      mesh.element_nodes.insert(mesh.element_nodes.end(), table.nodes_of(e), table.nodes_of(e) + n);
      mesh.element_start.push_back(static_cast<std::int32_t>(mesh.element_nodes.size()));
    }
  }
  invert_incidence(mesh, model.nodes.size());
  return mesh;
}

std::vector<std::int32_t> rigid_owner_of_nodes(const Model& model) {
  std::vector<std::int32_t> owner(model.nodes.size(), -1);
  const auto take = [&](std::int32_t body, std::int32_t value) {
    const RigidBody& rb = model.rigid_bodies[static_cast<std::size_t>(body)];
    if (rb.node_group >= 0)
      for (const std::int32_t node : model.node_groups[static_cast<std::size_t>(rb.node_group)].nodes)
        owner[static_cast<std::size_t>(node)] = value;
    if (rb.main_node >= 0) owner[static_cast<std::size_t>(rb.main_node)] = value;
  };
  for (std::size_t b = 0; b < model.rigid_bodies.size(); ++b) take(static_cast<std::int32_t>(b), static_cast<std::int32_t>(b));
  for (const std::int32_t b : model.run.bodies_off) take(b, -1);
  for (const std::int32_t b : model.run.bodies_on) take(b, b);
  return owner;
}

std::vector<std::int32_t> rigid_body_of_elements(const Mesh& mesh, const std::vector<std::int32_t>& owner) {
  std::vector<std::int32_t> body(static_cast<std::size_t>(mesh.elements()), -1);
  for (std::int32_t g = 0; g < mesh.elements(); ++g) {
    const std::int32_t first = owner[static_cast<std::size_t>(mesh.element_nodes[mesh.element_start[g]])];
    bool inside = first >= 0;
    for (std::int32_t i = mesh.element_start[g] + 1; i < mesh.element_start[g + 1] && inside; ++i)
      inside = owner[static_cast<std::size_t>(mesh.element_nodes[i])] == first;
    if (inside) body[static_cast<std::size_t>(g)] = first;
  }
  return body;
}

namespace {

// Vertex numbers in element order: a free element takes the next one, a rigid body the next one at its first
// element. Returns the vertex count.
std::int32_t number_vertices(const std::vector<std::int32_t>& body_of_element, std::vector<std::int32_t>& vertex_of_element) {
  std::vector<std::int32_t> vertex_of_body;
  std::int32_t vertices = 0;
  vertex_of_element.assign(body_of_element.size(), -1);
  for (std::size_t g = 0; g < body_of_element.size(); ++g) {
    const std::int32_t b = body_of_element[g];
    if (b < 0) {
      vertex_of_element[g] = vertices++;
      continue;
    }
    if (static_cast<std::size_t>(b) >= vertex_of_body.size()) vertex_of_body.resize(static_cast<std::size_t>(b) + 1, -1);
    if (vertex_of_body[static_cast<std::size_t>(b)] < 0) vertex_of_body[static_cast<std::size_t>(b)] = vertices++;
    vertex_of_element[g] = vertex_of_body[static_cast<std::size_t>(b)];
  }
  return vertices;
}

// The elements of each vertex, ascending, as compressed lists (a counting sort of vertex_of_element).
void list_members(const std::vector<std::int32_t>& vertex_of_element, std::int32_t vertices,
                  std::vector<std::int32_t>& start, std::vector<std::int32_t>& members) {
  start.assign(static_cast<std::size_t>(vertices) + 1, 0);
  for (const std::int32_t v : vertex_of_element) ++start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertices); ++v) start[v + 1] += start[v];
  std::vector<std::int32_t> next(start.begin(), start.end() - 1);
  members.assign(vertex_of_element.size(), 0);
  for (std::size_t g = 0; g < vertex_of_element.size(); ++g)
    members[static_cast<std::size_t>(next[static_cast<std::size_t>(vertex_of_element[g])]++)] = static_cast<std::int32_t>(g);
}

}  // namespace

ElementGraph build_element_graph(const Mesh& mesh, const std::vector<std::int32_t>& body_of_element,
                                 const std::vector<std::int32_t>& element_weights,
                                 const std::vector<std::int32_t>* contact_weights) {
  ElementGraph graph;
  const std::int32_t vertices = number_vertices(body_of_element, graph.vertex_of_element);
  std::vector<std::int32_t> member_start, members;
  list_members(graph.vertex_of_element, vertices, member_start, members);
  graph.constraints = contact_weights != nullptr ? 2 : 1;
  const auto ncon = static_cast<std::size_t>(graph.constraints);
  std::vector<std::int64_t> weight(static_cast<std::size_t>(vertices) * ncon, 0);
  for (std::size_t g = 0; g < element_weights.size(); ++g) {
    const auto v = static_cast<std::size_t>(graph.vertex_of_element[g]);
    weight[v * ncon] += element_weights[g];
    if (contact_weights != nullptr) weight[v * ncon + 1] += (*contact_weights)[g];
  }
  for (std::size_t c = 0; c < ncon; ++c) {
    std::int64_t total = 0;
    for (std::size_t v = c; v < weight.size(); v += ncon) total += weight[v];
    check_fits(total, "units of element weight");
  }
  graph.vertex_weight.assign(weight.begin(), weight.end());
  // Neighbour u of v: last_of[u] == v once seen for v, its edge at slot_of[u]; the edge counts element pairs.
  std::vector<std::int32_t> seen(static_cast<std::size_t>(mesh.elements()), -1);
  std::vector<std::int32_t> last_of(static_cast<std::size_t>(vertices), -1), slot_of(static_cast<std::size_t>(vertices), 0);
  graph.offsets.reserve(static_cast<std::size_t>(vertices) + 1);
  graph.offsets.push_back(0);
  for (std::int32_t v = 0; v < vertices; ++v) {
    for (std::int32_t m = member_start[v]; m < member_start[v + 1]; ++m)
      for_each_neighbour(mesh, members[m], seen, [&](std::int32_t h) {
        const std::int32_t u = graph.vertex_of_element[static_cast<std::size_t>(h)];
        if (u == v) return;
        if (last_of[u] == v) {
          ++graph.edge_weight[static_cast<std::size_t>(slot_of[u])];
          return;
        }
        last_of[u] = v, slot_of[u] = static_cast<std::int32_t>(graph.adjacency.size());
        graph.adjacency.push_back(u);
        graph.edge_weight.push_back(1);
      });
    check_fits(static_cast<std::int64_t>(graph.adjacency.size()), "graph edge ends");
    graph.offsets.push_back(static_cast<std::int32_t>(graph.adjacency.size()));
  }
  return graph;
}

bool connected(const ElementGraph& graph) {
  if (graph.vertices() == 0) return true;
  std::vector<std::uint8_t> reached(static_cast<std::size_t>(graph.vertices()), 0);
  std::vector<std::int32_t> queue{0};
  reached[0] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::int32_t i = graph.offsets[queue[head]]; i < graph.offsets[queue[head] + 1]; ++i)
      if (!reached[graph.adjacency[i]]) reached[graph.adjacency[i]] = 1, queue.push_back(graph.adjacency[i]);
  return queue.size() == reached.size();
}

}  // namespace crumple::parallel
