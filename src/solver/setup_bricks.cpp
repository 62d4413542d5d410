// Solver state of the 8-node bricks (docs/theory/brick8.md): per-group parameters from the part's property
// (/PROP/SOLID) and material, zero initial stresses, initial volumes for the current density.
#include "crumple/elements/brick8.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/model/mass.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// Radioss defaults of /PROP/SOLID (docs/cards/starter-model.md, section 8).
constexpr double kDefaultBrickHourglass = 0.1;  // viscous hourglass coefficient, Isolid 1 and 2
constexpr double kDefaultDamping = 0.1;    // numerical damping dn of Isolid 24 (the reference listing prints it)

}  // namespace

void setup_bricks(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Brick8)];
  const std::size_t n = table.size();
  BrickState& st = s.bricks;
  st.resize_elements(n);
  s.brick_groups.assign(m.element_groups.size(), BrickGroupParameters{});
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);

  std::size_t total_points = 0;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Brick8) continue;
    const Property& prop = m.properties[static_cast<std::size_t>(group.property)];
    const ResolvedFormulation& f = m.formulations[static_cast<std::size_t>(group.property)];
    const Material& mat = m.materials[static_cast<std::size_t>(group.material)];
    BrickGroupParameters& p = s.brick_groups[g];
    p.hardening = materials::Hardening::of(mat, m.functions);
    p.young = mat.young, p.poisson = mat.poisson, p.density = mat.density;
    brick8_configure(f.isolid, f.icpre, p);
    p.ismstr = f.ismstr;
    p.corotational = f.iframe == 2;
    p.qa = prop.solid.qa_or_default(), p.qb = prop.solid.qb_or_default();
    p.hourglass = prop.solid.h > 0.0 ? prop.solid.h : kDefaultBrickHourglass;
    p.numerical_damping = prop.solid.dn > 0.0 ? prop.solid.dn : kDefaultDamping;
    p.failure_strain = p.hardening.failure_strain() >= 1e20 ? 0.0 : p.hardening.failure_strain();
    p.first_point = total_points;
    st.point_offset[g] = total_points;
    st.points[g] = p.points;
    total_points += static_cast<std::size_t>(group.end - group.begin) * static_cast<std::size_t>(p.points);
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(e));
      st.volume0[static_cast<std::size_t>(e)] = geometry::brick_volume(m.nodes.x, m.nodes.y, m.nodes.z, nodes);
      st.mass[static_cast<std::size_t>(e)] = element_mass(m, ElementKind::Brick8, static_cast<std::size_t>(e));
      st.volume_scale[static_cast<std::size_t>(e)] = one_point_volume_scale(m, static_cast<std::size_t>(e));
      st.degenerate[static_cast<std::size_t>(e)] = geometry::repeats_a_node(nodes) ? 1 : 0;
      if (p.ismstr == 1 || p.ismstr == 3) brick8_switch_to_small_strain(table, e, s.nodes, st);  // from t = 0
    }
  }
  st.resize_points(total_points);
}

}  // namespace crumple::solver
