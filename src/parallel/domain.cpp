// One domain of a run of several (parallel/domain.hpp, docs/parallel.md "Assembly").
#include "crumple/parallel/domain.hpp"

#include <algorithm>

namespace crumple {

Domain single_domain(const Model& m) {
  Domain d;
  for (int k = 0; k < kElementKinds; ++k) d.owner[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  d.node_owner.assign(m.nodes.size(), 0);
  return d;
}

namespace {

// Per node: the lowest and the highest domain whose elements use it (-1, -1 when none does).
struct NodeUse {
  std::vector<std::int32_t> lowest, highest;
};
NodeUse node_use(const Model& m, const Domain& d) {
  NodeUse use{std::vector<std::int32_t>(m.nodes.size(), -1), std::vector<std::int32_t>(m.nodes.size(), -1)};
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      const std::int32_t domain = d.owner[static_cast<std::size_t>(kind)][e];
      for (int a = 0; a < count; ++a) {
        const auto k = static_cast<std::size_t>(table.nodes_of(e)[a]);
        use.lowest[k] = use.lowest[k] < 0 ? domain : std::min(use.lowest[k], domain);
        use.highest[k] = std::max(use.highest[k], domain);
      }
    }
  }
  return use;
}

// Whether domain `index` uses node k through one of its elements (domain.hpp: local nodes).
std::vector<std::uint8_t> used_by(const Model& m, const Domain& d) {
  std::vector<std::uint8_t> used(m.nodes.size(), 0);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e)
      if (d.owner[static_cast<std::size_t>(kind)][e] == d.index)
        for (int a = 0; a < count; ++a) used[static_cast<std::size_t>(table.nodes_of(e)[a])] = 1;
  }
  return used;
}

// The local shared nodes' load lists, in the kernels' order (element groups are kind by kind, in element order).
void load_lists(const Model& m, Domain& d) {
  std::vector<std::int32_t> slot(m.nodes.size(), -1);
  for (std::size_t i = 0; i < d.shared_nodes.size(); ++i) slot[static_cast<std::size_t>(d.shared_nodes[i])] = static_cast<std::int32_t>(i);
  d.first.assign(d.shared_nodes.size() + 1, 0);
  for (const ElementTable& table : m.elements)
    for (std::int32_t node : table.connectivity)
      if (const std::int32_t i = slot[static_cast<std::size_t>(node)]; i >= 0) ++d.first[static_cast<std::size_t>(i) + 1];
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

// Per node used by elements of several domains: those domains, ascending (CSR: first[k] .. first[k + 1]).
struct NodeDomains {
  std::vector<std::uint32_t> first;
  std::vector<std::int32_t> domains;
};
NodeDomains node_domains(const Model& m, const Domain& d, const std::vector<std::int32_t>& several) {
  std::vector<std::vector<std::int32_t>> lists(m.nodes.size());
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < count; ++a) {
        const auto k = static_cast<std::size_t>(table.nodes_of(e)[a]);
        if (!several[k]) continue;
        std::vector<std::int32_t>& list = lists[k];
        const std::int32_t domain = d.owner[static_cast<std::size_t>(kind)][e];
        if (std::find(list.begin(), list.end(), domain) == list.end()) list.push_back(domain);
      }
  }
  NodeDomains nd;
  nd.first.assign(m.nodes.size() + 1, 0);
  for (std::size_t k = 0; k < lists.size(); ++k) {
    std::sort(lists[k].begin(), lists[k].end());
    nd.first[k + 1] = nd.first[k] + static_cast<std::uint32_t>(lists[k].size());
    nd.domains.insert(nd.domains.end(), lists[k].begin(), lists[k].end());
  }
  return nd;
}

// The record halos (Domain::record_halo): an element at a shared node goes to every other domain that uses the
// node, which assembles it; this domain receives the others' elements at its shared nodes.
void record_halos(const Model& m, Domain& d, const std::vector<std::int32_t>& several) {
  const NodeDomains nd = node_domains(m, d, several);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const int count = nodes_per_element(table.kind);
    std::vector<std::vector<std::uint32_t>> send(static_cast<std::size_t>(d.count)), receive(static_cast<std::size_t>(d.count));
    std::vector<std::uint8_t> to(static_cast<std::size_t>(d.count));
    for (std::size_t e = 0; e < table.size(); ++e) {
      const std::int32_t owner = d.owner[static_cast<std::size_t>(kind)][e];
      std::fill(to.begin(), to.end(), 0);
      for (int a = 0; a < count; ++a) {
        const auto k = static_cast<std::size_t>(table.nodes_of(e)[a]);
        for (std::uint32_t j = nd.first[k]; j < nd.first[k + 1]; ++j) to[static_cast<std::size_t>(nd.domains[j])] = 1;
      }
      for (int s = 0; s < d.count; ++s) {
        if (!to[static_cast<std::size_t>(s)] || s == owner) continue;
        if (owner == d.index) send[static_cast<std::size_t>(s)].push_back(static_cast<std::uint32_t>(e));
        if (s == d.index) receive[static_cast<std::size_t>(owner)].push_back(static_cast<std::uint32_t>(e));
      }
    }
    HaloPlan& plan = d.record_halo[static_cast<std::size_t>(kind)];
    for (int s = 0; s < d.count; ++s)
      if (!send[static_cast<std::size_t>(s)].empty() || !receive[static_cast<std::size_t>(s)].empty()) {
        plan.neighbours.push_back(s);
        plan.send.push_back(std::move(send[static_cast<std::size_t>(s)]));
        plan.receive.push_back(std::move(receive[static_cast<std::size_t>(s)]));
      }
  }
}

// Node k (ascending) joins the runs of consecutive nodes.
void extend(std::vector<Domain::NodeRange>& ranges, std::size_t k) {
  const auto node = static_cast<std::int32_t>(k);
  if (!ranges.empty() && ranges.back().last == node) ++ranges.back().last;
  else ranges.push_back({node, node + 1});
}

// The last group (model order) that holds an element of a send list of the records' halo, or -1.
std::int32_t last_sending_group(const Model& m, const Domain& d) {
  std::array<std::vector<std::uint8_t>, kElementKinds> sent;
  for (int k = 0; k < kElementKinds; ++k) {
    sent[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
    for (const auto& list : d.record_halo[static_cast<std::size_t>(k)].send)
      for (std::uint32_t e : list) sent[static_cast<std::size_t>(k)][e] = 1;
  }
  std::int32_t last = -1;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    const auto& s = sent[static_cast<std::size_t>(group.kind)];
    if (std::any_of(s.begin() + group.begin, s.begin() + group.end, [](std::uint8_t x) { return x != 0; }))
      last = static_cast<std::int32_t>(g);
  }
  return last;
}

}  // namespace

Domain make_domain(const Model& m, const Partition& partition, int index) {
  Domain d;
  d.index = index, d.count = partition.domains;
  d.owner = partition.domain_of_element;
  const NodeUse use = node_use(m, d);
  const std::vector<std::uint8_t> used = used_by(m, d);
  std::vector<std::int32_t> several(m.nodes.size(), 0);  // used by elements of several domains
  d.node_owner.assign(m.nodes.size(), 0);
  d.local.assign(m.nodes.size(), 0), d.multi_local.assign(m.nodes.size(), 0);
  // Nodes every domain advances although elements use them: the main nodes of rigid bodies and the nodes that
  // carry moving walls, whose motion every domain needs (a body's centre, an /RBE2's main node, an /RBE3's dependent node, a wall's plane).
  std::vector<std::uint8_t> everywhere(m.nodes.size(), 0);
  for (const RigidBody& b : m.rigid_bodies) everywhere[static_cast<std::size_t>(b.main_node)] = 1;
  for (const RigidElement& e : m.rigid_elements) everywhere[static_cast<std::size_t>(e.main_node)] = 1;
  for (const InterpolationConstraint& c : m.interpolation_constraints)
    everywhere[static_cast<std::size_t>(c.dependent_node)] = 1;
  for (const RigidWall& w : m.rigid_walls)
    if (w.node >= 0) everywhere[static_cast<std::size_t>(w.node)] = 1;
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    const bool free = use.lowest[k] < 0;  // no element uses it: every domain advances it, domain 0 owns it
    several[k] = !free && use.lowest[k] != use.highest[k];
    d.node_owner[k] = free ? 0 : use.lowest[k];
    if (free || used[k] || everywhere[k]) extend(d.local_nodes, k), d.local[k] = 1;
    d.multi_local[k] = free || everywhere[k] || several[k];
    if (d.node_owner[k] == index) extend(d.owned_nodes, k);
    if (several[k] && used[k]) d.shared_nodes.push_back(static_cast<std::int32_t>(k));
  }
  load_lists(m, d);
  record_halos(m, d, several);
  d.last_sending_group = last_sending_group(m, d);
  return d;
}

void assemble_element_loads(const Domain& d, const std::array<const ElementRecords*, kElementKinds>& records,
                            NodalState& n) {
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
