// References held by loads, imposed motion, added masses, rigid walls and rigid bodies.
#include <fmt/format.h>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

std::string_view imposed_keyword(ImposedKind kind) {
  return kind == ImposedKind::Velocity ? "/IMPVEL" : kind == ImposedKind::Displacement ? "/IMPDISP" : "/CLOAD";
}

}  // namespace

void resolve_load_references(Resolver& r) {
  Model& m = r.model;
  const auto& ix = m.index;
  r.index(m.rigid_walls, m.index.rigid_walls, "/RWALL");
  r.index(m.rigid_bodies, m.index.rigid_bodies, "/RBODY");

  for (BoundaryCondition& bc : m.boundary_conditions) {
    const std::string kw = fmt::format("/BCS/{}", bc.user_id);
    r.require_zero(bc.skew_id, bc.where, kw, "skew_ID", "skew frames are");
    bc.node_group = r.find(ix.node_groups, bc.node_group_id, bc.where, kw, "grnod_ID", "node group");
  }
  for (ImposedMotion& im : m.imposed) {
    const std::string kw = fmt::format("{}/{}", imposed_keyword(im.kind), im.user_id);
    r.require_zero(im.skew_id, im.where, kw, "skew_ID", "skew frames are");
    r.require_zero(im.sensor_id, im.where, kw, "sensor_ID", "sensors are");
    r.require_zero(im.frame_id, im.where, kw, "frame_ID", "frames are");
    im.function = r.find(ix.functions, im.function_id, im.where, kw, "funct_IDT", "function");
    im.node_group = r.find(ix.node_groups, im.node_group_id, im.where, kw, "grnod_ID", "node group");
  }
  for (InitialVelocity& iv : m.initial_velocities) {
    const std::string kw = fmt::format("/INIVEL/TRA/{}", iv.user_id);
    r.require_zero(iv.skew_id, iv.where, kw, "Skew_ID", "skew frames are");
    iv.node_group = r.find(ix.node_groups, iv.node_group_id, iv.where, kw, "grnod_ID", "node group");
  }
  for (Gravity& g : m.gravity) {
    const std::string kw = fmt::format("/GRAV/{}", g.user_id);
    r.require_zero(g.skew_id, g.where, kw, "skew_ID", "skew frames are");
    r.require_zero(g.sensor_id, g.where, kw, "sensor_ID", "sensors are");
    g.function = r.find(ix.functions, g.function_id, g.where, kw, "funct_IDT", "function");
    g.node_group = r.find(ix.node_groups, g.node_group_id, g.where, kw, "grnod_ID", "node group");
  }
  for (AddedMass& a : m.added_masses) {
    const std::string kw = fmt::format("/ADMAS/{}/{}", a.type, a.user_id);
    a.node_group = r.find(ix.node_groups, a.node_group_id, a.where, kw, "grnod_ID", "node group");
  }
  for (RigidWall& w : m.rigid_walls) {
    const std::string kw = fmt::format("/RWALL/{}", w.user_id);
    w.node = r.find_optional(ix.nodes, w.node_id, w.where, kw, "node_ID", "node");
    w.node_group1 = r.find_optional(ix.node_groups, w.node_group1_id, w.where, kw, "grnod_ID1", "node group");
    w.node_group2 = r.find_optional(ix.node_groups, w.node_group2_id, w.where, kw, "grnod_ID2", "node group");
  }
  for (RigidBody& b : m.rigid_bodies) {
    const std::string kw = fmt::format("/RBODY/{}", b.user_id);
    r.require_zero(b.sensor_id, b.where, kw, "sensor_ID", "sensors are");
    r.require_zero(b.skew_id, b.where, kw, "skew_ID", "skew frames are");
    r.require_zero(b.surface_id, b.where, kw, "surf_ID", "rigid body surfaces are");
    b.main_node = r.find(ix.nodes, b.main_node_id, b.where, kw, "RBID", "node");
    b.node_group = r.find(ix.node_groups, b.node_group_id, b.where, kw, "grnod_ID", "node group");
  }
}

}  // namespace crumple::deck
