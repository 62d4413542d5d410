// The terms of a cut section (include/crumple/model/cut_sections.hpp).
#include "crumple/model/cut_sections.hpp"

#include <algorithm>

namespace crumple {

std::array<std::vector<std::int32_t>, kElementKinds> section_elements(const Model& m, const Section& s) {
  std::array<std::vector<std::int32_t>, kElementKinds> out;
  const std::pair<std::int32_t, const std::vector<ElementSet>*> groups[] = {
      {s.shell_group, &m.shell_groups}, {s.sh3n_group, &m.sh3n_groups}, {s.brick_group, &m.brick_groups}};
  for (const auto& [group, sets] : groups) {
    if (group < 0) continue;
    const ElementSet& set = (*sets)[static_cast<std::size_t>(group)];
    auto& elements = out[static_cast<std::size_t>(set.kind)];
    elements.insert(elements.end(), set.elements.begin(), set.elements.end());
  }
  for (auto& elements : out) {
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  }
  return out;
}

std::vector<SectionTerm> section_terms(const Model& m, const Section& s) {
  std::vector<SectionTerm> terms;
  if (s.node_group < 0) return terms;
  const std::vector<std::int32_t>& cut = m.node_groups[static_cast<std::size_t>(s.node_group)].nodes;  // sorted
  const auto elements = section_elements(m, s);
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    const ElementTable& table = m.elements[static_cast<std::size_t>(k)];
    for (std::int32_t e : elements[static_cast<std::size_t>(k)]) {
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(e));
      for (int a = 0; a < nodes_per_element(kind); ++a)
        if (std::binary_search(cut.begin(), cut.end(), nodes[a])) terms.push_back({kind, e, a, nodes[a]});
    }
  }
  return terms;
}

}  // namespace crumple
