#pragma once
// One domain of a run of several (docs/parallel.md): which elements it computes, and how every node's sum of
// element loads is assembled in one fixed order, the model's, whatever the partition.
//
// Crumple's domains share the nodes: every domain keeps every node and advances it the same way, and computes only
// its own elements. After the element kernels, the domains share each element's loads (state/element_records.hpp)
// and every domain assembles every node's sum from them, element by element in model order, exactly as one domain
// adds them directly. The rest of the cycle (contact, loads, rigid bodies and walls, the step, the update) then
// runs on identical data in every domain and gives identical results.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/parallel/partition.hpp"
#include "crumple/state/brick_state.hpp"
#include "crumple/state/nodal_state.hpp"
#include "crumple/state/shell_state.hpp"

namespace crumple {

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
  // Per node: the domain whose elements alone use it (its direct sum there is complete and final), or -1 when
  // elements of several domains use it (a shared node, assembled from the records) or none does.
  std::vector<std::int32_t> node_owner;
  std::vector<std::int32_t> shared_nodes;  // ascending
  // Per shared node (parallel to shared_nodes): its element loads in the order one domain adds them (kind by
  // kind, element by element): loads[first[i] .. first[i + 1]).
  std::vector<std::uint32_t> first;
  std::vector<NodeLoadRef> loads;
  // Per element kind, per element: its domain when it uses a shared node (its loads must travel), else -1.
  std::array<std::vector<std::int32_t>, kElementKinds> boundary_owner;
  // Per element group: the domain that computes all of it, or -1 when the group is split among domains; per kind,
  // per element: its domain when its group is split (its energy increments must travel), else -1.
  std::vector<std::int32_t> group_owner;
  std::array<std::vector<std::int32_t>, kElementKinds> split_owner;

  bool several() const { return count > 1; }
  bool mine(ElementKind kind, std::size_t element) const {
    return owner[static_cast<std::size_t>(kind)][element] == index;
  }
};

// The whole model as one domain: nothing to share, no assembly list.
Domain single_domain(const Model& model);
// Domain `index` of `partition`, with the assembly lists of every node.
Domain make_domain(const Model& model, const Partition& partition, int index);

// Every shared node's sum of element loads from the records of the three element kinds (Shell4, Shell3, Brick8),
// each node's loads in its list's order: forces into n.fx, n.fy, n.fz and the shells' moments into n.mx, n.my,
// n.mz, from zero. The result is what the kernels give adding directly, bit for bit.
void assemble_element_loads(const Domain& domain, const ShellState& shell4, const ShellState& shell3,
                            const BrickState& brick8, NodalState& n);

}  // namespace crumple
