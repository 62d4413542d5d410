// One domain of a run of several (parallel/domain.hpp, docs/parallel.md "Assembly").
#include "crumple/parallel/domain.hpp"

namespace crumple {

Domain single_domain(const Model& m) {
  Domain d;
  for (int k = 0; k < kElementKinds; ++k) d.owner[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  return d;
}

Domain make_domain(const Model& m, const Partition& partition, int index) {
  Domain d;
  d.index = index, d.count = partition.domains;
  d.owner = partition.domain_of_element;
  // Counting sort of (node, load) pairs: kind by kind and element by element, so that each node's list is in the
  // order the kernels visit the elements (element groups are kind by kind, in element order).
  d.first.assign(m.nodes.size() + 1, 0);
  for (const ElementTable& table : m.elements)
    for (std::int32_t node : table.connectivity) ++d.first[static_cast<std::size_t>(node) + 1];
  for (std::size_t k = 0; k < m.nodes.size(); ++k) d.first[k + 1] += d.first[k];
  d.loads.resize(d.first.back());
  std::vector<std::uint32_t> fill(d.first.begin(), d.first.end() - 1);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < count; ++a) {
        const auto node = static_cast<std::size_t>(table.nodes_of(e)[a]);
        d.loads[fill[node]++] = {static_cast<std::uint8_t>(kind), static_cast<std::uint8_t>(a), static_cast<std::int32_t>(e)};
      }
  }
  return d;
}

void assemble_element_loads(const Domain& d, const ShellState& shell4, const ShellState& shell3,
                            const BrickState& brick8, NodalState& n) {
  const ElementRecords* records[kElementKinds] = {&shell4.records, &shell3.records, &brick8.records};
  for (std::size_t k = 0; k < n.size(); ++k) {
    double f[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (std::uint32_t i = d.first[k]; i < d.first[k + 1]; ++i) {
      const NodeLoadRef& ref = d.loads[i];
      const ElementRecords& r = *records[ref.kind];
      const double* v = r.load.data() + (static_cast<std::size_t>(ref.element) * static_cast<std::size_t>(r.nodes_per_element) + ref.node) *
                                            static_cast<std::size_t>(r.values_per_node);
      for (int c = 0; c < r.values_per_node; ++c) f[c] -= v[c];
    }
    n.fx[k] = f[0], n.fy[k] = f[1], n.fz[k] = f[2], n.mx[k] = f[3], n.my[k] = f[4], n.mz[k] = f[5];
  }
}

}  // namespace crumple
