// Solver state of the springs (docs/theory/spring.md): per-group parameters from the part's property (/PROP/TYPE4),
// each spring's length at rest and mass.
#include "crumple/core/vec3.hpp"
#include "crumple/elements/spring.hpp"
#include "crumple/model/mass.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {

void setup_springs(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  SpringState& st = s.springs;
  st.resize_elements(table.size());
  s.spring_groups.assign(m.element_groups.size(), SpringGroupParameters{});
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Spring) continue;
    s.spring_groups[g] = spring_parameters(m.properties[static_cast<std::size_t>(group.property)].spring, m.functions);
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      st.length0[ue] = element_measure(m.nodes, ElementKind::Spring, table.nodes_of(ue));
      st.mass[ue] = element_mass(m, ElementKind::Spring, ue);
      st.step_stiffness[ue] = s.spring_groups[g].step_stiffness;
    }
  }
}

}  // namespace crumple::solver
