#include "crumple/model/mass.hpp"

#include "crumple/core/geometry.hpp"

namespace crumple {
namespace {

const Part& part_of(const Model& model, ElementKind kind, std::size_t element) {
  return model.parts[static_cast<std::size_t>(model.elements[static_cast<int>(kind)].part[element])];
}

}  // namespace

std::array<double, 8> corner_mass_fractions(const Model& model, ElementKind kind, const std::int32_t* nodes) {
  std::array<double, 8> share{};
  const int n = nodes_per_element(kind);
  if (kind == ElementKind::Shell3) {  // by the corner angles (docs/theory/shell4.md, eq. S-9c)
    const Nodes& x = model.nodes;
    const auto f = geometry::triangle_corner_fractions(x.position(nodes[0]), x.position(nodes[1]), x.position(nodes[2]));
    std::copy(f.begin(), f.end(), share.begin());
  } else {
    std::fill(share.begin(), share.begin() + n, 1.0 / n);
  }
  return share;
}

double one_point_volume_scale(const Model& model, std::size_t brick) {
  const Part& part = part_of(model, ElementKind::Brick8, brick);
  const std::int32_t* n = model.elements[static_cast<int>(ElementKind::Brick8)].nodes_of(brick);
  if (part.property < 0 || fully_integrated_brick(model.formulations[static_cast<std::size_t>(part.property)].isolid) ||
      !geometry::repeats_a_node(n))
    return 1.0;
  double x[8], y[8], z[8];
  for (std::size_t a = 0; a < 8; ++a) {
    const auto k = static_cast<std::size_t>(n[a]);
    x[a] = model.nodes.x[k], y[a] = model.nodes.y[k], z[a] = model.nodes.z[k];
  }
  const double exact = geometry::brick_volume(model.nodes.x, model.nodes.y, model.nodes.z, n);
  return exact > 0.0 ? geometry::one_point_volume(x, y, z) / exact : 1.0;
}

double shell_thickness(const Model& model, ElementKind kind, std::size_t shell) {
  const ElementTable& table = model.elements[static_cast<int>(kind)];
  if (shell < table.thickness.size() && table.thickness[shell] > 0.0) return table.thickness[shell];
  const Part& part = part_of(model, kind, shell);
  return model.properties[static_cast<std::size_t>(part.property)].shell.thickness;
}

double element_measure(const Nodes& x, ElementKind kind, const std::int32_t* n) {
  switch (kind) {
    case ElementKind::Shell4:
      return geometry::quad_area(x.position(n[0]), x.position(n[1]), x.position(n[2]), x.position(n[3]));
    case ElementKind::Shell3: return geometry::triangle_area(x.position(n[0]), x.position(n[1]), x.position(n[2]));
    case ElementKind::Brick8: {
      std::array<Vec3, 8> p;
      for (int a = 0; a < 8; ++a) p[static_cast<std::size_t>(a)] = x.position(n[a]);
      return geometry::brick_volume(p);
    }
    case ElementKind::Spring:
    case ElementKind::Truss:
    case ElementKind::Beam: return norm(x.position(n[1]) - x.position(n[0]));
  }
  return 0.0;
}

double element_mass(const Model& model, ElementKind kind, std::size_t element) {
  const Part& part = part_of(model, kind, element);
  const Property& property = model.properties[static_cast<std::size_t>(part.property)];
  const double measure = element_measure(model.nodes, kind, model.elements[static_cast<int>(kind)].nodes_of(element));
  if (property.kind == PropertyKind::Spring)  // the property's, half at each node; per unit length times L0 (SP-21)
    return property.spring.mass * (property.spring.per_unit_length ? measure : 1.0);
  const double density = model.materials[static_cast<std::size_t>(part.material)].density;
  if (property.kind == PropertyKind::Truss) return density * property.truss.area * measure;  // rho A L0, half a node
  if (property.kind == PropertyKind::Beam) return density * property.beam.area * measure;
  if (describe(kind).property == PropertyKind::Shell) return density * shell_thickness(model, kind, element) * measure;
  return density * measure * one_point_volume_scale(model, element);
}

void compute_mass(Model& model) {
  model.nodal_mass.assign(model.nodes.size(), 0.0);
  model.element_mass = 0.0;
  model.added_mass = 0.0;
  for (const ElementGroup& g : model.element_groups) {
    const int n = nodes_per_element(g.kind);
    const ElementTable& table = model.elements[static_cast<int>(g.kind)];
    for (std::int32_t e = g.begin; e < g.end; ++e) {
      const double mass = element_mass(model, g.kind, static_cast<std::size_t>(e));
      model.element_mass += mass;
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(e));
      const std::array<double, 8> share = corner_mass_fractions(model, g.kind, nodes);
      for (int a = 0; a < n; ++a) model.nodal_mass[static_cast<std::size_t>(nodes[a])] += mass * share[static_cast<std::size_t>(a)];
    }
  }
  for (const AddedMass& a : model.added_masses) {
    const auto& nodes = model.node_groups[static_cast<std::size_t>(a.node_group)].nodes;
    if (nodes.empty()) continue;  // rejected by the reader; kept so that a type-1 mass never divides by zero
    // Type 0: the mass is added to each node; type 1: the mass is shared equally by the nodes of the group.
    const double per_node = a.type == 0 ? a.mass : a.mass / static_cast<double>(nodes.size());
    for (std::int32_t node : nodes) model.nodal_mass[static_cast<std::size_t>(node)] += per_node;
    model.added_mass += per_node * static_cast<double>(nodes.size());
  }
  // /RBODY Mass is added to the body at its main node. The secondary nodes keep their own (element) mass here;
  // gathering it into the body (and moving the main node to the centre of mass, ICoG) is the rigid-body
  // initialisation's job, which leaves the total unchanged.
  for (const RigidBody& b : model.rigid_bodies) {
    model.nodal_mass[static_cast<std::size_t>(b.main_node)] += b.mass;
    model.added_mass += b.mass;
  }
  // An /RBE3's dependent node has no mass of its own: what it was given goes to its independent nodes in the share of
  // their weights as given (docs/theory/rigid-bodies.md, RI-5, measured).
  for (const InterpolationConstraint& c : model.interpolation_constraints) {
    const auto dependent = static_cast<std::size_t>(c.dependent_node);
    const double mass = model.nodal_mass[dependent];
    if (!(mass > 0.0) || !(c.total_weight > 0.0)) continue;
    for (const InterpolationNode& i : c.independent)
      model.nodal_mass[static_cast<std::size_t>(i.node)] += mass * i.given_weight / c.total_weight;
    model.nodal_mass[dependent] = 0.0;
  }
  // A moving rigid wall's Mass is added to the node that carries the wall.
  for (const RigidWall& w : model.rigid_walls) {
    if (w.node < 0) continue;  // fixed wall
    model.nodal_mass[static_cast<std::size_t>(w.node)] += w.mass;
    model.added_mass += w.mass;
  }
}

}  // namespace crumple
