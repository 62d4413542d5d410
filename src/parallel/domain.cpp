// One domain of a run of several (parallel/domain.hpp, docs/parallel.md "Assembly").
#include "crumple/parallel/domain.hpp"

namespace crumple {

Domain single_domain(const Model& m) {
  Domain d;
  for (int k = 0; k < kElementKinds; ++k) d.owner[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  return d;
}

namespace {

// Each node's domain: the one whose elements alone use it, -1 if several or none (Domain::node_owner).
std::vector<std::int32_t> node_owners(const Model& m, const Domain& d) {
  constexpr std::int32_t kNone = -2;
  std::vector<std::int32_t> owner(m.nodes.size(), kNone);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      const std::int32_t domain = d.owner[static_cast<std::size_t>(kind)][e];
      for (int a = 0; a < count; ++a) {
        std::int32_t& o = owner[static_cast<std::size_t>(table.nodes_of(e)[a])];
        o = o == kNone || o == domain ? domain : -1;
      }
    }
  }
  for (std::int32_t& o : owner) o = o == kNone ? -1 : o;
  return owner;
}

// The shared nodes' load lists, in the kernels' order (element groups are kind by kind, in element order).
void load_lists(const Model& m, Domain& d, const std::vector<std::int32_t>& touched_by_several) {
  std::vector<std::int32_t> slot(m.nodes.size(), -1);
  for (std::size_t i = 0; i < d.shared_nodes.size(); ++i) slot[static_cast<std::size_t>(d.shared_nodes[i])] = static_cast<std::int32_t>(i);
  d.first.assign(d.shared_nodes.size() + 1, 0);
  for (const ElementTable& table : m.elements)
    for (std::int32_t node : table.connectivity)
      if (touched_by_several[static_cast<std::size_t>(node)]) ++d.first[static_cast<std::size_t>(slot[static_cast<std::size_t>(node)]) + 1];
  for (std::size_t i = 0; i < d.shared_nodes.size(); ++i) d.first[i + 1] += d.first[i];
  d.loads.resize(d.first.back());
  std::vector<std::uint32_t> fill(d.first.begin(), d.first.end() - 1);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < count; ++a) {
        const std::int32_t i = slot[static_cast<std::size_t>(table.nodes_of(e)[a])];
        if (i < 0) continue;
        d.loads[fill[static_cast<std::size_t>(i)]++] = {static_cast<std::uint8_t>(kind), static_cast<std::uint8_t>(a),
                                                        static_cast<std::int32_t>(e)};
      }
  }
}

}  // namespace

Domain make_domain(const Model& m, const Partition& partition, int index) {
  Domain d;
  d.index = index, d.count = partition.domains;
  d.owner = partition.domain_of_element;
  d.node_owner = node_owners(m, d);
  std::vector<std::int32_t> several(m.nodes.size(), 0);  // used by elements of several domains
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    for (std::int32_t node : table.connectivity)
      several[static_cast<std::size_t>(node)] = d.node_owner[static_cast<std::size_t>(node)] < 0;
  }
  for (std::size_t k = 0; k < m.nodes.size(); ++k)
    if (several[k]) d.shared_nodes.push_back(static_cast<std::int32_t>(k));
  load_lists(m, d, several);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    auto& boundary = d.boundary_owner[static_cast<std::size_t>(kind)];
    boundary.assign(table.size(), -1);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < nodes_per_element(table.kind); ++a)
        if (several[static_cast<std::size_t>(table.nodes_of(e)[a])]) boundary[e] = d.owner[static_cast<std::size_t>(kind)][e];
    d.split_owner[static_cast<std::size_t>(kind)].assign(table.size(), -1);
  }
  for (const ElementGroup& group : m.element_groups) {
    const auto& owner = d.owner[static_cast<std::size_t>(group.kind)];
    std::int32_t whole = owner[static_cast<std::size_t>(group.begin)];
    for (std::int32_t e = group.begin; e < group.end; ++e) whole = owner[static_cast<std::size_t>(e)] == whole ? whole : -1;
    d.group_owner.push_back(whole);
    if (whole < 0)
      for (std::int32_t e = group.begin; e < group.end; ++e)
        d.split_owner[static_cast<std::size_t>(group.kind)][static_cast<std::size_t>(e)] = owner[static_cast<std::size_t>(e)];
  }
  return d;
}

void assemble_element_loads(const Domain& d, const ShellState& shell4, const ShellState& shell3,
                            const BrickState& brick8, NodalState& n) {
  const ElementRecords* records[kElementKinds] = {&shell4.records, &shell3.records, &brick8.records};
  for (std::size_t i = 0; i < d.shared_nodes.size(); ++i) {
    double f[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (std::uint32_t j = d.first[i]; j < d.first[i + 1]; ++j) {
      const NodeLoadRef& ref = d.loads[j];
      const ElementRecords& r = *records[ref.kind];
      const double* v = r.load.data() + (static_cast<std::size_t>(ref.element) * static_cast<std::size_t>(r.nodes_per_element) + ref.node) *
                                            static_cast<std::size_t>(r.values_per_node);
      for (int c = 0; c < r.values_per_node; ++c) f[c] -= v[c];
    }
    const auto k = static_cast<std::size_t>(d.shared_nodes[i]);
    n.fx[k] = f[0], n.fy[k] = f[1], n.fz[k] = f[2], n.mx[k] = f[3], n.my[k] = f[4], n.mz[k] = f[5];
  }
}

}  // namespace crumple
