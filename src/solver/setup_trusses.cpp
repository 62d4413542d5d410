// Solver state of the trusses (docs/theory/truss.md): per-group parameters from the part's material and property
// (/PROP/TYPE2), each truss's length at rest, cross-section and mass.
#include "crumple/elements/truss.hpp"
#include "crumple/model/mass.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {

void setup_trusses(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Truss)];
  TrussState& st = s.trusses;
  st.resize_elements(table.size());
  s.truss_groups.assign(m.element_groups.size(), TrussGroupParameters{});
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Truss) continue;
    const TrussSection& section = m.properties[static_cast<std::size_t>(group.property)].truss;
    const TrussGroupParameters& p = s.truss_groups[g] =
        truss_parameters(m.materials[static_cast<std::size_t>(group.material)], section, m.functions);
    st.point_offset[g] = static_cast<std::size_t>(group.begin), st.points[g] = 1;
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      st.length0[ue] = st.length[ue] = element_measure(m.nodes, ElementKind::Truss, table.nodes_of(ue));
      st.area[ue] = section.area;
      st.mass[ue] = element_mass(m, ElementKind::Truss, ue);
      st.critical_dt[ue] = truss_critical_step(p, st.length0[ue]);
    }
  }
}

}  // namespace crumple::solver
