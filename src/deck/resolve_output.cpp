// References held by contact interfaces, output requests and run control.
#include <fmt/format.h>

#include "resolve.hpp"

namespace crumple::deck {
namespace {


}  // namespace

void resolve_output_references(Resolver& r) {
  Model& m = r.model;
  r.index(m.type7_interfaces, m.index.interfaces, "/INTER");
  r.index(m.sections, m.index.sections, "/SECT");
  const auto& ix = m.index;
  for (Type7Interface& i : m.type7_interfaces) {
    const std::string kw = fmt::format("/INTER/TYPE7/{}", i.user_id);
    i.secondary_group = r.find(ix.node_groups, i.secondary_group_id, i.where, kw, "Slav_id", "node group");
    i.main_surface = r.find(ix.surfaces, i.main_surface_id, i.where, kw, "Mast_id", "surface");
    r.require_zero(i.sensor_id, i.where, kw, "sens_ID", "sensors are");
    r.require_zero(i.friction_function_id, i.where, kw, "fct_IDf", "friction scale functions are");
    r.require_zero(i.friction_id, i.where, kw, "fric_ID", "/FRICTION definitions are");
  }
  for (Section& s : m.sections) {
    const std::string kw = fmt::format("/SECT/{}", s.user_id);
    for (int k = 0; k < 3; ++k)
      r.find_optional(ix.nodes, s.node_ids[k], s.where, kw, fmt::format("node_ID{}", k + 1), "node");
    s.node_group = r.find_optional(ix.node_groups, s.node_group_id, s.where, kw, "grnod_ID", "node group");
    s.shell_group = r.find_optional(ix.shell_groups, s.shell_group_id, s.where, kw, "grshel_ID", "shell group");
  }
  for (TimeHistoryRequest& th : m.histories) {
    const std::string& kw = th.keyword;
    const IdMap* map = nullptr;
    std::string_view what;
    switch (th.object) {
      case HistoryObject::Node: map = &ix.nodes, what = "node"; break;
      case HistoryObject::Part: map = &ix.parts, what = "part"; break;
      case HistoryObject::RigidWall: map = &ix.rigid_walls, what = "rigid wall"; break;
      case HistoryObject::Interface: map = &ix.interfaces, what = "interface"; break;
      case HistoryObject::Shell: map = &ix.elements[static_cast<int>(ElementKind::Shell4)], what = "shell"; break;
      case HistoryObject::Sh3n: map = &ix.elements[static_cast<int>(ElementKind::Shell3)], what = "3-node shell"; break;
      case HistoryObject::Brick: map = &ix.elements[static_cast<int>(ElementKind::Brick8)], what = "brick"; break;
      case HistoryObject::Subset: map = &ix.subsets, what = "subset"; break;
      case HistoryObject::Section: map = &ix.sections, what = "section"; break;
      case HistoryObject::RigidBody: map = &ix.rigid_bodies, what = "rigid body"; break;
    }
    for (std::int64_t id : th.object_ids) th.objects.push_back(r.find(*map, id, th.where, kw, "Obj_ID", what));
  }
  for (std::int64_t id : m.run.rbody_on)
    r.find(ix.rigid_bodies, id, m.run.where, "/RBODY/ON", "RBID", "rigid body");
  for (std::int64_t id : m.run.rbody_off)
    r.find(ix.rigid_bodies, id, m.run.where, "/RBODY/OFF", "RBID", "rigid body");
}

}  // namespace crumple::deck
