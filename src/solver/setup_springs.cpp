// Solver state of the springs (docs/theory/spring.md): per-group parameters from the part's property (/PROP/TYPE4),
// each spring's length at rest and mass.
#include <algorithm>

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
    const SpringGroupParameters& p = s.spring_groups[g] =
        spring_parameters(m.properties[static_cast<std::size_t>(group.property)].spring, m.functions);
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int32_t* n = table.nodes_of(ue);
      st.length0[ue] = element_measure(m.nodes, ElementKind::Spring, n);
      const Vec3 offset = m.nodes.position(n[1]) - m.nodes.position(n[0]);
      st.rest_offset[3 * ue] = offset.x, st.rest_offset[3 * ue + 1] = offset.y, st.rest_offset[3 * ue + 2] = offset.z;
      if (p.frame == SpringFrame::Beam) {  // SP-15: Y at rest, global Y normal to the spring (global X along it)
        const Vec3 along = scaled(offset, 1.0 / st.length0[ue]);
        Vec3 y = Vec3{0.0, 1.0, 0.0} - scaled(along, along.y);
        if (norm(y) < 1e-6) y = Vec3{1.0, 0.0, 0.0} - scaled(along, along.x);
        y = scaled(y, 1.0 / norm(y));
        st.frame_y[3 * ue] = y.x, st.frame_y[3 * ue + 1] = y.y, st.frame_y[3 * ue + 2] = y.z;
      }
      st.mass[ue] = element_mass(m, ElementKind::Spring, ue);
      // The stiffness it gives each node in the nodal steps (SP-4a): a general spring's stiffest translation.
      st.step_stiffness[ue] = std::max({p.dof[0].step_stiffness, p.dof[1].step_stiffness, p.dof[2].step_stiffness});
      for (int a = 0; a < 2; ++a) s.nodes.inertia[static_cast<std::size_t>(n[a])] += 0.5 * p.inertia;  // half each
    }
  }
}

}  // namespace crumple::solver
