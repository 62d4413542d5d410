// Solver state of the beams (docs/theory/beam.md): per-group parameters from the part's material and property
// (/PROP/TYPE3), each beam's length at rest, frame, mass and its nodes' rotational inertia.
#include "crumple/core/geometry.hpp"
#include "crumple/elements/beam.hpp"
#include "crumple/model/mass.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// Whether `reference` has a part normal to the unit `along` (it can orient a beam).
bool across(const Vec3& along, const Vec3& reference) {
  return norm(reference - scaled(along, dot(along, reference))) > 1e-6 * norm(reference);
}

// Where a beam's local y lies at rest (BM-0, measured): along its card's vector where it has one not parallel to
// the beam (it wins over the node), else towards its orientation node, else global Y (global Z for a beam along Y).
Vec3 orientation(const Model& m, std::size_t e, const Vec3& along) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Beam)];
  const Vec3 vector = table.orientation_vector.empty()
                          ? Vec3{}
                          : Vec3{table.orientation_vector[3 * e], table.orientation_vector[3 * e + 1],
                                 table.orientation_vector[3 * e + 2]};
  if (across(along, vector)) return vector;
  if (!table.orientation_node.empty() && table.orientation_node[e] >= 0) {
    const Vec3 node = m.nodes.position(table.orientation_node[e]) - m.nodes.position(table.nodes_of(e)[0]);
    if (across(along, node)) return node;
  }
  return across(along, {0.0, 1.0, 0.0}) ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0};
}

}  // namespace

void setup_beams(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Beam)];
  BeamState& st = s.beams;
  st.resize_elements(table.size());
  s.beam_groups.assign(m.element_groups.size(), BeamGroupParameters{});
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Beam) continue;
    const BeamGroupParameters& p = s.beam_groups[g] =
        beam_parameters(m.materials[static_cast<std::size_t>(group.material)],
                        m.properties[static_cast<std::size_t>(group.property)].beam, m.functions);
    st.point_offset[g] = static_cast<std::size_t>(group.begin), st.points[g] = 1;
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int32_t* n = table.nodes_of(ue);
      const double length = st.length0[ue] = st.length[ue] = element_measure(m.nodes, ElementKind::Beam, n);
      const Vec3 along = scaled(m.nodes.position(n[1]) - m.nodes.position(n[0]), 1.0 / length);
      const Vec3 y = geometry::rest_frame_y(along, orientation(m, ue, along));
      st.frame_y[3 * ue] = y.x, st.frame_y[3 * ue + 1] = y.y, st.frame_y[3 * ue + 2] = y.z;
      st.mass[ue] = element_mass(m, ElementKind::Beam, ue);
      st.area[ue] = p.area;
      st.critical_dt[ue] = beam_critical_step(p, length);
      for (int k = 0; k < 2; ++k) s.nodes.inertia[static_cast<std::size_t>(n[k])] += beam_node_inertia(p, length);
    }
  }
}

}  // namespace crumple::solver
