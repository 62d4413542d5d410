// References held by loads, imposed motion, added masses, rigid walls and rigid bodies; duplicate ids; the
// geometry of moving walls and the secondary node sets of the walls (docs/cards/loads-output-engine.md).
#include <fmt/format.h>

#include <algorithm>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

std::string_view imposed_keyword(ImposedKind kind) {
  return kind == ImposedKind::Velocity ? "/IMPVEL" : kind == ImposedKind::Displacement ? "/IMPDISP" : "/CLOAD";
}

const std::vector<std::int32_t>& nodes_of(const Model& m, std::int32_t group) {
  return m.node_groups[static_cast<std::size_t>(group)].nodes;
}

bool contains(const std::vector<std::int32_t>& sorted, std::int32_t value) {
  return std::binary_search(sorted.begin(), sorted.end(), value);
}

Vec3 position(const Nodes& nodes, std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  return {nodes.x[k], nodes.y[k], nodes.z[k]};
}

// Cards whose ids are not referenced elsewhere still must not repeat within one keyword.
template <class Record>
void check_unique(Resolver& r, const std::vector<Record>& records, std::string_view keyword) {
  IdMap ids;
  r.index(records, ids, keyword);
}

void check_unique_imposed(Resolver& r, const std::vector<ImposedMotion>& imposed) {
  for (ImposedKind kind : {ImposedKind::Velocity, ImposedKind::Displacement, ImposedKind::Force}) {
    std::vector<ImposedMotion> same;
    std::copy_if(imposed.begin(), imposed.end(), std::back_inserter(same),
                 [kind](const ImposedMotion& im) { return im.kind == kind; });
    check_unique(r, same, imposed_keyword(kind));
  }
}

// Skews: ids, the nodes of the moving ones, and axes that exist at the start (SK-1, SK-2). A moving skew whose
// nodes later line up has no axes; that is the deck's to avoid, as in the reference.
void resolve_skews(Resolver& r) {
  Model& m = r.model;
  r.index(m.skews, m.index.skews, "/SKEW");
  for (Skew& s : m.skews) {
    const std::string kw = fmt::format("/SKEW/{}/{}", s.kind == SkewKind::Fixed ? "FIX" : "MOV", s.user_id);
    if (s.kind == SkewKind::Moving) {
      constexpr const char* kNames[3] = {"node_ID1", "node_ID2", "node_ID3"};
      bool found = true;
      for (int k = 0; k < 3; ++k) {
        s.nodes[k] = r.find(m.index.nodes, s.node_ids[k], s.where, kw, kNames[k], "node");
        found = found && s.nodes[k] >= 0;
      }
      if (!found) continue;
    }
    if (!skew_is_defined(s, m.nodes.x, m.nodes.y, m.nodes.z))
      r.error(s.where, kw, s.kind == SkewKind::Fixed ? "X2, Y2, Z2" : "node_ID3",
              "two non-zero directions that are not parallel (they span the skew's first two axes)",
              s.kind == SkewKind::Fixed ? "a zero or parallel direction" : "nodes on one line, or two at one place");
  }
}

void resolve_boundary_conditions(Resolver& r) {
  const auto& ix = r.model.index;
  for (BoundaryCondition& bc : r.model.boundary_conditions) {
    const std::string kw = fmt::format("/BCS/{}", bc.user_id);
    bc.skew = r.find_optional(ix.skews, bc.skew_id, bc.where, kw, "skew_ID", "skew");
    bc.node_group = r.find(ix.node_groups, bc.node_group_id, bc.where, kw, "grnod_ID", "node group");
  }
}

void resolve_imposed(Resolver& r) {
  const auto& ix = r.model.index;
  for (ImposedMotion& im : r.model.imposed) {
    const std::string kw = fmt::format("{}/{}", imposed_keyword(im.kind), im.user_id);
    im.skew = r.find_optional(ix.skews, im.skew_id, im.where, kw, "skew_ID", "skew");
    im.sensor = sensor_window(r, im.sensor_id, im.where, kw);
    r.require_zero(im.frame_id, im.where, kw, "frame_ID", "frames are");
    r.require_zero(im.icoor, im.where, kw, "Icoor", "cylindrical coordinates are");
    im.function = r.find(ix.functions, im.function_id, im.where, kw, "funct_IDT", "function");
    im.node_group = r.find(ix.node_groups, im.node_group_id, im.where, kw, "grnod_ID", "node group");
  }
}

// An imposed velocity or displacement on a dof that a /BCS in the same axes fixes: the imposed motion wins (the order
// of the kinematic conditions, loads.md L-3). The reference moves such nodes the same way, but its listing then
// counts a quarter of their kinetic energy and its energy error runs away (measured: a plate whose every node is
// fixed by /BCS 111 and driven by /IMPVEL along Z lists 1/4 of 0.5 m v^2, an external work of 0.24 J and an error of
// -99.8 %; its internal and rotational energies, with one edge so held, are Crumple's). Said once per card.
void warn_imposed_on_fixed_dofs(Resolver& r) {
  const Model& m = r.model;
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind == ImposedKind::Force || im.skew >= 0 || im.node_group < 0) continue;
    const auto axis = static_cast<std::size_t>(dof_axis(im.dof));
    for (const BoundaryCondition& bc : m.boundary_conditions) {
      if (bc.skew >= 0 || bc.node_group < 0) continue;
      if (!(is_rotation(im.dof) ? bc.fixed_rotation[axis] : bc.fixed_translation[axis])) continue;
      const auto& fixed = m.node_groups[static_cast<std::size_t>(bc.node_group)].nodes;
      const auto& driven = m.node_groups[static_cast<std::size_t>(im.node_group)].nodes;
      std::size_t both = 0;
      for (std::int32_t n : driven) both += std::binary_search(fixed.begin(), fixed.end(), n) ? 1 : 0;
      if (both == 0) continue;
      r.context.warn(im.where, fmt::format("{}/{}", imposed_keyword(im.kind), im.user_id),
                     fmt::format("{} of its nodes have this dof fixed by /BCS/{} too: the imposed motion wins (the "
                                 "reference moves them alike, but lists a quarter of their kinetic energy)",
                                 both, bc.user_id));
      break;
    }
  }
}

// /IMPDISP/FGEO: the function, sensor and nodes, each node's displacement to its final position, and the nodes another
// kinematic condition drives (a rigid body's, a moving wall's), which one card cannot share.
void resolve_final_geometries(Resolver& r) {
  Model& m = r.model;
  std::vector<char> driven(m.nodes.size(), 0);
  for (const RigidBody& b : m.rigid_bodies) {
    if (b.main_node >= 0) driven[static_cast<std::size_t>(b.main_node)] = 1;
    if (b.node_group >= 0)
      for (std::int32_t n : m.node_groups[static_cast<std::size_t>(b.node_group)].nodes)
        driven[static_cast<std::size_t>(n)] = 1;
  }
  for (const RigidWall& w : m.rigid_walls)
    if (w.node >= 0) driven[static_cast<std::size_t>(w.node)] = 1;
  for (FinalGeometry& g : m.final_geometries) {
    const std::string kw = fmt::format("/IMPDISP/FGEO/{}", g.user_id);
    g.function = r.find(m.index.functions, g.function_id, g.where, kw, "fct_ID", "function");
    g.sensor = sensor_window(r, g.sensor_id, g.where, kw, "sens_ID");
    for (std::size_t i = 0; i < g.node_ids.size(); ++i) {
      const auto n = r.find(m.index.nodes, g.node_ids[i], g.node_where[i], kw, "node_ID", "node");
      if (n < 0) continue;
      if (driven[static_cast<std::size_t>(n)] != 0)
        r.error(g.node_where[i], kw, "node_ID",
                "a node that no rigid body or moving rigid wall carries (Crumple drives a node by one condition)",
                fmt::format("node {}", g.node_ids[i]));
      g.nodes.push_back(n);
      g.displacements.push_back(g.final_positions[i] - m.nodes.position(n));
    }
  }
}

void resolve_initial_conditions(Resolver& r) {
  Model& m = r.model;
  const auto& ix = m.index;
  for (InitialVelocity& iv : m.initial_velocities) {
    const std::string kw = fmt::format("/INIVEL/{}/{}", iv.rotation ? "ROT" : "TRA", iv.user_id);
    iv.skew = r.find_optional(ix.skews, iv.skew_id, iv.where, kw, "Skew_ID", "skew");
    iv.node_group = r.find(ix.node_groups, iv.node_group_id, iv.where, kw, "grnod_ID", "node group");
  }
  for (Gravity& g : m.gravity) {
    const std::string kw = fmt::format("/GRAV/{}", g.user_id);
    g.skew = r.find_optional(ix.skews, g.skew_id, g.where, kw, "skew_ID", "skew");
    g.sensor = sensor_window(r, g.sensor_id, g.where, kw);
    // Both are optional: no function is a constant acceleration, no group is every node.
    g.function = r.find_optional(ix.functions, g.function_id, g.where, kw, "funct_IDT", "function");
    g.node_group = r.find_optional(ix.node_groups, g.node_group_id, g.where, kw, "grnod_ID", "node group");
  }
  for (AddedMass& a : m.added_masses) {
    const std::string kw = fmt::format("/ADMAS/{}/{}", a.type, a.user_id);
    a.node_group = r.find(ix.node_groups, a.node_group_id, a.where, kw, "grnod_ID", "node group");
    // A type-1 mass is shared by the nodes: an empty group would lose it (or divide by zero).
    if (a.node_group >= 0 && nodes_of(m, a.node_group).empty())
      r.error(a.where, kw, "grnod_ID", "a node group with at least one node",
              fmt::format("node group {} is empty", a.node_group_id));
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Rigid bodies

// A body of its main node alone (its group empty or only that node) with no card inertia has none: the reference
// stops (its error 274, "null or negative inertia", measured), where a body with secondary nodes is floored. The
// first torque would otherwise spin it without bound.
void refuse_body_without_inertia(Resolver& r, const RigidBody& b, const std::string& kw) {
  if (b.node_group < 0 || b.main_node < 0) return;
  const auto& nodes = nodes_of(r.model, b.node_group);
  const bool only_main = std::all_of(nodes.begin(), nodes.end(), [&](std::int32_t n) { return n == b.main_node; });
  const bool no_inertia = std::all_of(b.inertia.begin(), b.inertia.begin() + 3, [](double j) { return j == 0.0; });
  if (only_main && no_inertia)
    r.error(b.where, kw, "Jxx, Jyy, Jzz",
            "an inertia for a body of one node (the card's Jxx, Jyy, Jzz, or secondary nodes to give it one)",
            "no secondary node and no inertia");
}

// A body switched by a sensor: the manual says its added mass and inertia, its skew and ICoG are then not used and
// Ikrem is 1. Crumple forms it from its nodes alone (RB-6): a value there would be dropped, so it is refused.
void refuse_what_a_sensor_body_ignores(Resolver& r, RigidBody& b, const std::string& kw) {
  const std::string expected = "0 or blank with a sensor_ID (a body switched by a sensor has no added mass, inertia "
                               "or skew, and ICoG 1, as the manual says)";
  if (b.mass != 0.0) r.error(b.where, kw, "Mass", expected, fmt::format("{}", b.mass));
  if (std::any_of(b.inertia.begin(), b.inertia.end(), [](double j) { return j != 0.0; }))
    r.error(b.where, kw, "Jxx..Jzx", expected, "a non-zero inertia");
  if (b.skew_id != 0) r.error(b.where, kw, "skew_ID", expected, std::to_string(b.skew_id));
  if (b.icog != 1) r.error(b.where, kw, "ICoG", expected, std::to_string(b.icog));
  b.ikrem = 1;  // the manual: Ikrem forced to 1
}

void resolve_rigid_bodies(Resolver& r) {
  Model& m = r.model;
  const auto& ix = m.index;
  IdMap body_of_main_node;  // main node -> body
  for (std::size_t i = 0; i < m.rigid_bodies.size(); ++i) {
    RigidBody& b = m.rigid_bodies[i];
    const std::string kw = fmt::format("/RBODY/{}", b.user_id);
    b.sensor = sensor_window(r, b.sensor_id, b.where, kw, "sensor_ID");
    if (b.sensor_id != 0) refuse_what_a_sensor_body_ignores(r, b, kw);
    b.skew = r.find_optional(ix.skews, b.skew_id, b.where, kw, "skew_ID", "skew");
    r.require_zero(b.surface_id, b.where, kw, "surf_ID", "rigid body surfaces are");
    b.main_node = r.find(ix.nodes, b.main_node_id, b.where, kw, "RBID", "node");
    b.node_group = r.find(ix.node_groups, b.node_group_id, b.where, kw, "grnod_ID", "node group");
    if (b.main_node >= 0) {
      const auto [it, inserted] = body_of_main_node.emplace(b.main_node, static_cast<std::int32_t>(i));
      if (!inserted)
        r.error(b.where, kw, "RBID", "a main node that no other rigid body uses",
                fmt::format("node {} is the main node of /RBODY/{}", b.main_node_id,
                            m.rigid_bodies[static_cast<std::size_t>(it->second)].user_id));
    }
    if (b.node_group >= 0 && nodes_of(m, b.node_group).empty())
      r.context.warn(b.where, kw, fmt::format("node group {} is empty: the body has no secondary nodes",
                                              b.node_group_id));
    refuse_body_without_inertia(r, b, kw);
  }
}

// A main node that is also an element node takes the element's mass and forces into the body.
void warn_main_nodes_in_elements(Resolver& r) {
  const Model& m = r.model;
  if (m.rigid_bodies.empty()) return;
  std::vector<bool> in_element(m.nodes.size(), false);
  for (const ElementTable& table : m.elements)
    for (std::int32_t node : table.connectivity) in_element[static_cast<std::size_t>(node)] = true;
  for (const RigidBody& b : m.rigid_bodies)
    if (b.main_node >= 0 && in_element[static_cast<std::size_t>(b.main_node)])
      r.context.warn(b.where, fmt::format("/RBODY/{}", b.user_id),
                     fmt::format("main node {} belongs to an element", b.main_node_id));
}

// ---------------------------------------------------------------------------------------------------------------
// Rigid walls

// Distance of `x` from the wall on its outer side, as D_search measures it; negative when behind or inside the
// wall. A parallelogram selects by its plane, whatever the point's place beside its edges, as the reference does
// (measured: its starter listing's secondary nodes, docs/theory/rigid-walls.md RW-0).
double wall_distance(const RigidWall& w, const Vec3& x) {
  const Vec3 d = x - w.point;
  switch (w.shape) {
    case RigidWallShape::Plane:
    case RigidWallShape::Parallelogram: return dot(d, w.direction);
    case RigidWallShape::Sphere: return norm(d) - 0.5 * w.diameter;
    case RigidWallShape::Cylinder: {
      const double along = dot(d, w.direction);
      const Vec3 radial{d[0] - along * w.direction[0], d[1] - along * w.direction[1], d[2] - along * w.direction[2]};
      return norm(radial) - 0.5 * w.diameter;
    }
  }
  return -1.0;
}

// Moving walls sit on their node: M is the node's initial position, M1 and M2 stay as given (points).
void place_wall(Resolver& r, RigidWall& w, const std::string& kw) {
  const Model& m = r.model;
  if (w.node >= 0) w.point = position(m.nodes, w.node);
  if (const auto direction = wall_direction(w.shape, w.point, w.point1, w.point2)) {
    w.direction = *direction;
    return;
  }
  const bool paral = w.shape == RigidWallShape::Parallelogram;
  r.error(w.where, kw, paral ? "X_M1 .. Z_M2" : "X_M1, Y_M1, Z_M1",
          paral ? "points M1, M2 that span a parallelogram with M, the position of node_ID"
                : "a point M1 distinct from M, the position of node_ID",
          fmt::format("M = ({:g}, {:g}, {:g}) from node {}", w.point[0], w.point[1], w.point[2], w.node_id));
}

// (nodes within D_search on the outer side) + group 1 - group 2 - the wall node - secondary nodes of rigid
// bodies with Ikrem = 0.
void build_secondary_nodes(const Model& m, RigidWall& w) {
  std::vector<std::int32_t> nodes;
  if (w.search_distance > 0.0)
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      const double d = wall_distance(w, position(m.nodes, static_cast<std::int32_t>(i)));
      if (d >= 0.0 && d <= w.search_distance) nodes.push_back(static_cast<std::int32_t>(i));
    }
  if (w.node_group1 >= 0) {
    const auto& added = nodes_of(m, w.node_group1);
    nodes.insert(nodes.end(), added.begin(), added.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto removed = [&](std::int32_t n) {
    if (n == w.node) return true;
    if (w.node_group2 >= 0 && contains(nodes_of(m, w.node_group2), n)) return true;
    for (const RigidBody& b : m.rigid_bodies)
      if (b.ikrem == 0 && b.node_group >= 0 && contains(nodes_of(m, b.node_group), n)) return true;
    return false;
  };
  nodes.erase(std::remove_if(nodes.begin(), nodes.end(), removed), nodes.end());
  w.secondary_nodes = std::move(nodes);
}

// A wall holds a rigid body through its main node, the body's centre of mass (eq. RW-3). A secondary node that a
// wall keeps (Ikrem = 1) would have to turn the body about its centre, which Crumple does not do: refused rather
// than passed through.
void check_rigid_body_nodes_on_wall(Resolver& r, const RigidWall& w) {
  const Model& m = r.model;
  for (const RigidBody& b : m.rigid_bodies) {
    if (b.ikrem == 0 || b.node_group < 0) continue;
    for (std::int32_t n : nodes_of(m, b.node_group))
      if (n != b.main_node && std::binary_search(w.secondary_nodes.begin(), w.secondary_nodes.end(), n)) {
        r.context.unsupported(DeckError(b.where, fmt::format("/RBODY/{}", b.user_id), "Ikrem",
                                        fmt::format("0 (its secondary nodes off the rigid walls; {} holds node {}): "
                                                    "a wall holds a rigid body through its main node only in Crumple",
                                                    rigid_wall_keyword(w), m.nodes.user_id[static_cast<std::size_t>(n)]),
                                        "1"));
        break;
      }
  }
}

void resolve_rigid_walls(Resolver& r) {
  Model& m = r.model;
  const auto& ix = m.index;
  for (RigidWall& w : m.rigid_walls) {
    const std::string kw = rigid_wall_keyword(w);
    w.node = r.find_optional(ix.nodes, w.node_id, w.where, kw, "node_ID", "node");
    w.node_group1 = r.find_optional(ix.node_groups, w.node_group1_id, w.where, kw, "grnod_ID1", "node group");
    w.node_group2 = r.find_optional(ix.node_groups, w.node_group2_id, w.where, kw, "grnod_ID2", "node group");
    if (w.node_id != 0 && w.node < 0) continue;  // no position for M
    if (w.node >= 0 && w.node_group1 >= 0 && contains(nodes_of(m, w.node_group1), w.node))
      r.error(w.where, kw, "grnod_ID1", "secondary nodes other than the wall node",
              fmt::format("wall node {} is in node group {}", w.node_id, w.node_group1_id));
    // A wall node that belongs to a rigid body would have to pass the wall's reaction through the body's
    // motion, which the rigid-body update (before the walls) does not do.
    for (const RigidBody& b : m.rigid_bodies)
      if (w.node >= 0 && (b.main_node == w.node || (b.node_group >= 0 && contains(nodes_of(m, b.node_group), w.node))))
        r.error(w.where, kw, "node_ID", "a wall node outside rigid bodies (a moving wall carried by a rigid-body node is "
                "not supported by Crumple)", fmt::format("node {} is in /RBODY/{}", w.node_id, b.user_id));
    place_wall(r, w, kw);
    if (w.search_distance == 0.0 && w.node_group1 < 0)
      r.context.warn(w.where, kw, "no secondary nodes: D_search is 0 and grnod_ID1 is blank");
  }
}

}  // namespace

SensorWindow sensor_window(Resolver& r, std::int64_t sensor_id, const SourceLocation& where, const std::string& kw,
                           std::string_view field) {
  const auto k = r.find_optional(r.model.index.sensors, sensor_id, where, kw, field, "sensor");
  if (k < 0) return {};
  const Sensor& s = r.model.sensors[static_cast<std::size_t>(k)];
  return {s.on, s.off};
}

std::string rigid_wall_keyword(const RigidWall& w) {
  return fmt::format("/RWALL/{}/{}", rigid_wall_shape_name(w.shape), w.user_id);
}

// A joint's Skew_ID1 (docs/theory/spring.md, SP-25f): a fixed skew, whose axes at rest set the joint's frame; a moving
// one is refused (what the reference's frame does after it was not measured).
void resolve_joint_skew(Resolver& r, Property& p) {
  SpringJoint& joint = p.spring.joint;
  const std::string kw = fmt::format("/PROP/TYPE45/{}", p.user_id);
  joint.skew = r.find(r.model.index.skews, joint.skew_id, p.where, kw, "Skew_ID1", "skew");
  if (joint.skew >= 0 && r.model.skews[static_cast<std::size_t>(joint.skew)].kind != SkewKind::Fixed)
    r.context.unsupported(DeckError(p.where, kw, "Skew_ID1", default_only("a joint's moving skew is"),
                                    std::to_string(joint.skew_id)));
}

// A spring switched by a sensor (docs/theory/spring.md, SP-24): the sensor's window, and what is measured only.
void resolve_spring_switch(Resolver& r, Property& p) {
  SpringSwitch& sw = p.spring.sensor;
  const std::string kw = fmt::format("/PROP/{}/{}", p.spring.card(), p.user_id);
  const SensorWindow window = sensor_window(r, sw.sensor_id, p.where, kw, "sens_ID");
  sw.on = window.on, sw.off = std::isfinite(window.off) ? window.off : 1e300;
  const auto refuse = [&](std::string_view field, std::string_view what) {
    r.context.unsupported(DeckError(p.where, kw, std::string(field), default_only(what), "given"));
  };
  if (p.spring.radial)  // measured: the reference's inactive TYPE25 pushes with -10 times its force
    return refuse("sens_ID", "a sensor on /PROP/TYPE25 is");
  if (sw.flag == 2 && p.spring.per_unit_length) return refuse("Isflag", "Isflag 2 with Ileng 1 is");
  for (int d = 0; d < p.spring.dofs(); ++d)
    if (p.spring.dof[static_cast<std::size_t>(d)].hardening != 0)
      return refuse("sens_ID", "a sensor on a hardening spring (H 1 to 8) is");
}

void resolve_load_references(Resolver& r) {
  Model& m = r.model;
  resolve_skews(r);
  for (Property& p : r.model.properties)  // a beam-type spring's frame at rest (docs/theory/spring.md, SP-15)
    if (p.kind == PropertyKind::Spring && p.spring.skew_id != 0)
      p.spring.skew = r.find(r.model.index.skews, p.spring.skew_id, p.where,
                             fmt::format("/PROP/{}/{}", p.spring.card(), p.user_id), "skew_ID", "skew");
  for (Property& p : r.model.properties)  // a joint's frame (docs/theory/spring.md, SP-25f)
    if (p.kind == PropertyKind::Spring && p.spring.joint.skew_id != 0) resolve_joint_skew(r, p);
  r.index(m.sensors, m.index.sensors, "/SENSOR");
  for (Property& p : r.model.properties)
    if (p.kind == PropertyKind::Spring && p.spring.sensor.sensor_id != 0) resolve_spring_switch(r, p);
  for (Property& p : r.model.properties) {  // a pretensioner's activation (docs/theory/spring.md, SP-22)
    SpringPretension& pre = p.spring.pretension;
    if (p.kind != PropertyKind::Spring || !pre.on || pre.sensor_id == 0) continue;
    const std::string kw = fmt::format("/PROP/SPR_PRE/{}", p.user_id);
    const SensorWindow window = sensor_window(r, pre.sensor_id, p.where, kw, "sens_ID");
    pre.activation_time = window.on;
    if (std::isfinite(window.off))
      r.error(p.where, kw, "sens_ID", "a sensor that stays on (a pretensioner's sensor turning off is not measured)",
              fmt::format("/SENSOR {} turns off at {:g}", pre.sensor_id, window.off));
  }
  r.index(m.rigid_walls, m.index.rigid_walls, "/RWALL");
  r.index(m.rigid_bodies, m.index.rigid_bodies, "/RBODY");
  r.index(m.dampings, m.index.dampings, "/DAMP");
  for (RayleighDamping& d : m.dampings)
    d.node_group = r.find(m.index.node_groups, d.node_group_id, d.where, fmt::format("/DAMP/{}", d.user_id), "grnod_ID",
                          "node group");
  check_unique(r, m.boundary_conditions, "/BCS");
  check_unique_imposed(r, m.imposed);
  check_unique(r, m.initial_velocities, "/INIVEL/TRA");
  check_unique(r, m.gravity, "/GRAV");
  check_unique(r, m.added_masses, "/ADMAS");

  resolve_boundary_conditions(r);
  resolve_imposed(r);
  resolve_initial_conditions(r);
  resolve_rigid_bodies(r);
  warn_main_nodes_in_elements(r);
  resolve_rigid_walls(r);
  resolve_final_geometries(r);
  if (r.errors.empty()) warn_imposed_on_fixed_dofs(r);
  // Secondary sets need every group and body resolved; skip them when a reference is missing.
  if (!r.errors.empty()) return;
  for (RigidWall& w : m.rigid_walls) {
    build_secondary_nodes(m, w);
    check_rigid_body_nodes_on_wall(r, w);
  }
}

}  // namespace crumple::deck
