#pragma once
// One domain of a run of several (docs/parallel.md): which elements it computes, which nodes it advances, and how
// every node's sum of element loads is assembled in one fixed order, the model's, whatever the partition.
//
// A domain computes its own elements and advances its *local* nodes: the nodes of its elements, and the nodes no
// element uses (rigid-body main nodes, wall nodes, point masses), which every domain advances alike. Node arrays
// keep the whole model's size; a node that is not local to a domain holds stale values there, and no phase of the
// cycle reads it (tests: the domains give the one domain's results bit for bit). After the element kernels the
// domains share the loads of the elements at shared nodes (state/element_records.hpp) and every domain assembles
// its shared nodes' sums from them, element by element in model order, exactly as one domain adds them directly.
// Each node also has one *owner*, the lowest domain it is local to: sums over nodes (energies, a rigid body's
// resultant) take each node once, from its owner, as exact sums (core/exact_sum.hpp).
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/parallel/partition.hpp"
#include "crumple/state/element_records.hpp"
#include "crumple/state/nodal_state.hpp"

namespace crumple {

// What one domain sends to and receives from each of its neighbours (the domains it shares nodes with), for values
// held per slot (an element, a node) in arrays of the whole model's size: per neighbour, the slots it sends and the
// slots it receives, ascending. Exchange::halo moves them point to point.
struct HaloPlan {
  std::vector<std::int32_t> neighbours;                // ascending
  std::vector<std::vector<std::uint32_t>> send, receive;  // per neighbour
};

// An element's load at one of its nodes, in the assembly list of the node.
struct NodeLoadRef {
  std::uint8_t kind;      // ElementKind
  std::uint8_t node;      // the node's place in the element (0 .. nodes_per_element - 1)
  std::int32_t element;   // index in the kind's ElementTable
};

struct Domain {
  int index = 0;  // this domain, 0 .. count - 1
  int count = 1;
  // Per element kind, per element: the domain that computes it.
  std::array<std::vector<std::int32_t>, kElementKinds> owner;
  // Per node: its owner, the lowest domain it is local to (0 for a node no element uses).
  std::vector<std::int32_t> node_owner;
  // The nodes this domain advances and the nodes it owns, as ascending runs of consecutive nodes [first, last)
  // (empty in a run of one domain: every node), so that the loops over them stay contiguous and vectorise.
  struct NodeRange {
    std::int32_t first, last;
  };
  std::vector<NodeRange> local_nodes, owned_nodes;
  std::vector<std::uint8_t> local;        // per node: 1 when local (several domains only)
  std::vector<std::uint8_t> multi_local;  // per node: 1 when local to several domains (several domains only)
  std::vector<std::int32_t> shared_nodes;  // local nodes that elements of several domains use, ascending
  // Per shared node (parallel to shared_nodes): its element loads in the order one domain adds them (kind by
  // kind, element by element): loads[first[i] .. first[i + 1]).
  std::vector<std::uint32_t> first;
  std::vector<NodeLoadRef> loads;
  // Per element kind: the loads of the elements at shared nodes, sent to the neighbours that assemble those nodes.
  std::array<HaloPlan, kElementKinds> record_halo;
  // The last element group, in model order, with an element whose loads are sent (-1: none): the element phase
  // starts the records' halo once it has computed that group, and computes the groups after it meanwhile.
  std::int32_t last_sending_group = -1;

  bool several() const { return count > 1; }
  bool mine(ElementKind kind, std::size_t element) const {
    return owner[static_cast<std::size_t>(kind)][element] == index;
  }
  bool owns(std::size_t node) const { return node_owner[node] == index; }
  bool is_local(std::size_t node) const { return count == 1 || local[node] != 0; }
};

// The whole model as one domain: nothing to share, no assembly list.
Domain single_domain(const Model& model);
// Domain `index` of `partition`, with the assembly lists of every node.
Domain make_domain(const Model& model, const Partition& partition, int index);

// Calls f(k) for every local node k, ascending; for every owned node. One domain: every node, as one loop.
template <class F>
void for_each_node_in(const std::vector<Domain::NodeRange>& ranges, F f) {
  for (const Domain::NodeRange& r : ranges)
    for (auto k = static_cast<std::size_t>(r.first); k < static_cast<std::size_t>(r.last); ++k) f(k);
}
template <class F>
void for_each_local_node(const Domain& d, std::size_t nodes, F f) {
  if (!d.several()) {
    for (std::size_t k = 0; k < nodes; ++k) f(k);
    return;
  }
  for_each_node_in(d.local_nodes, f);
}
template <class F>
void for_each_owned_node(const Domain& d, std::size_t nodes, F f) {
  if (!d.several()) {
    for (std::size_t k = 0; k < nodes; ++k) f(k);
    return;
  }
  for_each_node_in(d.owned_nodes, f);
}

// Every local shared node's sum of element loads from the records of every element kind (kAllElementKinds order),
// each node's loads in its list's order: forces into n.fx, n.fy, n.fz and the shells' moments into n.mx, n.my,
// n.mz, from zero. The result is what the kernels give adding directly, bit for bit.
void assemble_element_loads(const Domain& domain, const std::array<const ElementRecords*, kElementKinds>& records,
                            NodalState& n);

}  // namespace crumple
