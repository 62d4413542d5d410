// The decomposition of a model into domains (parallel/partition.hpp, docs/parallel.md).
#include "crumple/parallel/partition.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace crumple {

int element_weight(const Model&, ElementKind, std::size_t) { return 1; }

Partition partition_model(const Model& model, int domains) {
  if (domains != 1) throw std::runtime_error(fmt::format("a partition into {} domains is not built yet", domains));
  Partition p;
  for (int k = 0; k < kElementKinds; ++k)
    p.domain_of_element[static_cast<std::size_t>(k)].assign(model.elements[static_cast<std::size_t>(k)].size(), 0);
  p.weight.assign(1, 0);
  for (int k = 0; k < kElementKinds; ++k)
    for (std::size_t e = 0; e < model.elements[static_cast<std::size_t>(k)].size(); ++e)
      p.weight[0] += element_weight(model, static_cast<ElementKind>(k), e);
  p.neighbours.assign(1, 0);
  return p;
}

std::vector<std::string> describe(const Partition& p) {
  return {fmt::format("DOMAINS {}  EDGE CUT {}  SHARED NODES {}  IMBALANCE {:.3f}", p.domains, p.edge_cut,
                      p.shared_nodes, p.imbalance)};
}

}  // namespace crumple
