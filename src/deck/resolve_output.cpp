// References held by contact interfaces, output requests and run control; run-control times to working units.
#include <fmt/format.h>

#include <algorithm>

#include "crumple/model/cut_sections.hpp"
#include "resolve.hpp"

namespace crumple::deck {
namespace {

// Engine cards keep their times in input units (keywords/engine.cpp): in the Radioss single-file form they are
// read before /BEGIN sets the units. Every time of the run control is converted here, once.
void convert_run_times(RunControl& run, const UnitSystem& units) {
  const double t = units.factor(dim::time);
  run.end_time *= t;
  run.history_interval *= t;
  run.anim_start *= t;
  run.anim_interval *= t;
  for (TimeStepControl* c : {&run.dt, &run.dt_nodal_cst, &run.dt_inter_del, &run.dt_inter_cst}) c->minimum *= t;
  for (const ElementKindDescription& kind : kElementKindTable) (run.*kind.step_control).minimum *= t;
  run.dt_ams.minimum *= t;
  run.dt_initial *= t;
  for (DampingChange& change : run.damping_changes) change.alpha /= t, change.beta *= t;
  run.dt_max *= t;
}

const IdMap* history_map(const Model::Index& ix, HistoryObject object, std::string_view& what) {
  switch (object) {
    case HistoryObject::Node: what = "node"; return &ix.nodes;
    case HistoryObject::Part: what = "part"; return &ix.parts;
    case HistoryObject::RigidWall: what = "rigid wall"; return &ix.rigid_walls;
    case HistoryObject::Interface: what = "interface"; return &ix.interfaces;
    case HistoryObject::Shell: what = "shell"; return &ix.elements[static_cast<int>(ElementKind::Shell4)];
    case HistoryObject::Sh3n: what = "3-node shell"; return &ix.elements[static_cast<int>(ElementKind::Shell3)];
    case HistoryObject::Brick: what = "brick"; return &ix.elements[static_cast<int>(ElementKind::Brick8)];
    case HistoryObject::Spring: what = "spring"; return &ix.elements[static_cast<int>(ElementKind::Spring)];
    case HistoryObject::Truss: what = "truss"; return &ix.elements[static_cast<int>(ElementKind::Truss)];
    case HistoryObject::Beam: what = "beam"; return &ix.elements[static_cast<int>(ElementKind::Beam)];
    case HistoryObject::Subset: what = "subset"; return &ix.subsets;
    case HistoryObject::Section: what = "section"; return &ix.sections;
    case HistoryObject::RigidBody: what = "rigid body"; return &ix.rigid_bodies;
    case HistoryObject::Accelerometer: what = "accelerometer"; return &ix.accelerometers;
  }
  return nullptr;
}

// /RBODY/ON, /RBODY/OFF name rigid bodies by their main node (the engine manual's node_ID list).
void resolve_rigid_body_switches(Resolver& r, const std::vector<std::int64_t>& ids,
                                 const std::vector<SourceLocation>& where, const char* keyword,
                                 std::vector<std::int32_t>& bodies) {
  const Model& m = r.model;
  bodies.clear();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto body = std::find_if(m.rigid_bodies.begin(), m.rigid_bodies.end(),
                                   [&](const RigidBody& b) { return b.main_node_id == ids[k]; });
    if (body == m.rigid_bodies.end())
      r.error(where[k], keyword, "node_ID", "the main node of a rigid body",
              fmt::format("node {}, which is the main node of no /RBODY", ids[k]));
    else
      bodies.push_back(static_cast<std::int32_t>(body - m.rigid_bodies.begin()));
  }
}

// /DT/AMS needs the starter's /AMS (the reference stops: "WITH /DT/AMS, OPTION /AMS IS COMPULSORY"). Crumple
// scales the whole model: the nodal and interface mass scalings, which the reference combines with it on the parts
// /AMS leaves out, would act on the same nodes.
void check_selective_mass(Resolver& r, const RunControl& run) {
  const SelectiveMassControl& ams = run.dt_ams;
  if (!ams.given) return;
  if (!r.model.ams_selected)
    r.error(ams.where, "/DT/AMS", "", "the starter's /AMS card, which selects the parts to scale",
            "no /AMS in the starter deck");
  for (const auto& [keyword, control] : {std::pair{"/DT/NODA/CST", &run.dt_nodal_cst}, {"/DT/INTER/CST", &run.dt_inter_cst}})
    if (control->given)
      r.context.unsupported(DeckError(control->where, keyword, "",
                                      "no nodal mass scaling together with /DT/AMS on the whole model (Crumple does not "
                                      "combine them)",
                                      keyword));
  // /DAMP's mass damping solves each node's update with its own mass (D-2), which the selective mass's coupled
  // solve replaces.
  for (const RayleighDamping& d : r.model.dampings)
    r.context.unsupported(DeckError(d.where, fmt::format("/DAMP/{}", d.user_id), "",
                                    "no /DAMP together with /DT/AMS (Crumple does not combine them)", "/DT/AMS"));
  // A moving wall takes its nodes' impulse into its own motion (RW-2) before it holds them; the solve holds them
  // at the wall's velocity first (SM-4), so the exchange would lag a cycle: refused, not approximated.
  for (const RigidWall& w : r.model.rigid_walls)
    if (w.node_id != 0)
      r.context.unsupported(DeckError(w.where, rigid_wall_keyword(w), "node_ID",
                                      "a fixed rigid wall (node_ID 0) with /DT/AMS: Crumple does not hold nodes on a "
                                      "moving wall inside the selective mass solve",
                                      std::to_string(w.node_id)));
  // The solve holds the global dofs its conditions fix (SM-4); a condition along a skew's axes couples them.
  const std::string skewed = "0 with /DT/AMS (the selective mass solve holds the global axes' dofs only; a condition "
                             "along a skew is not supported by Crumple there)";
  for (const BoundaryCondition& bc : r.model.boundary_conditions)
    if (bc.skew >= 0)
      r.context.unsupported(DeckError(bc.where, fmt::format("/BCS/{}", bc.user_id), "skew_ID", skewed,
                                      std::to_string(bc.skew_id)));
  for (const ImposedMotion& im : r.model.imposed)
    if (im.skew >= 0 && im.kind != ImposedKind::Force)
      r.context.unsupported(DeckError(im.where, im.kind == ImposedKind::Velocity ? "/IMPVEL" : "/IMPDISP", "skew_ID",
                                      skewed, std::to_string(im.skew_id)));
}

// /VEL/TRA: nodes, skew; a link may not hold a rigid body's secondary node (the body sets its velocity) and does not
// act inside the selective mass solve, which would have to couple the linked dofs.
void resolve_velocity_links(Resolver& r, RunControl& run) {
  const Model& m = r.model;
  for (RunControl::VelocityLink& link : run.velocity_links) {
    const std::string kw = "/VEL/TRA";
    link.skew = r.find_optional(m.index.skews, link.skew_id, link.where, kw, "skew_ID", "skew");
    link.nodes.clear();
    for (std::int64_t id : link.node_ids)
      if (const auto n = r.find(m.index.nodes, id, link.where, kw, "node_ID", "node"); n >= 0) link.nodes.push_back(n);
    std::sort(link.nodes.begin(), link.nodes.end());
    link.nodes.erase(std::unique(link.nodes.begin(), link.nodes.end()), link.nodes.end());
    for (const RigidBody& b : m.rigid_bodies)
      for (std::int32_t n : link.nodes)
        if (n == b.main_node ||
            (b.node_group >= 0 && std::binary_search(m.node_groups[static_cast<std::size_t>(b.node_group)].nodes.begin(),
                                                      m.node_groups[static_cast<std::size_t>(b.node_group)].nodes.end(), n)))
          r.context.unsupported(DeckError(link.where, kw, "node_ID",
                                            "nodes of no rigid body (the body sets their velocity; a link of a "
                                            "body's node is not supported by Crumple)",
                                            fmt::format("node {} of /RBODY/{}", m.nodes.user_id[static_cast<std::size_t>(n)],
                                                        b.user_id)));
    if (run.dt_ams.given)
      r.context.unsupported(DeckError(link.where, kw, "", "no /VEL/TRA with /DT/AMS (the selective mass solve "
                                      "does not couple linked nodes in Crumple)", "/VEL/TRA"));
  }
}

void resolve_run_control(Resolver& r, RunControl& run) {
  Model& m = r.model;
  convert_run_times(run, m.units);
  resolve_rigid_body_switches(r, run.rbody_on, run.rbody_on_where, "/RBODY/ON", run.bodies_on);
  resolve_rigid_body_switches(r, run.rbody_off, run.rbody_off_where, "/RBODY/OFF", run.bodies_off);
  check_selective_mass(r, run);
  resolve_velocity_links(r, run);
  for (DampingChange& change : run.damping_changes)
    change.damping = r.find(m.index.dampings, change.damping_id, change.where, fmt::format("/DAMP/{}", change.damping_id),
                            "damp_ID (keyword line)", "starter /DAMP");
  // Radioss pairs the engine deck with the starter by run name; a different name usually means a stray file.
  if (run.present && !m.run_name.empty() && run.run_name != m.run_name)
    r.context.warn(run.where, "/RUN",
                   fmt::format("run name '{}' differs from the /BEGIN run name '{}'", run.run_name, m.run_name));
}

// A section a /TH/SECTIO request writes (docs/output-format.md, "SECTIO"): its frame needs three distinct nodes
// off one line, and the forces of interfaces across the cut are not computed (a section value without them would
// be silently short).
void check_written_section(Resolver& r, Section& s) {
  const std::string kw = fmt::format("/SECT/{}", s.user_id);
  r.require_zero(s.ninter, s.where, kw, "Ninter", "interface forces across a cut section (Ninter > 0) are");
  if (s.ninter == 0) s.interfaces.clear(), s.interface_ids.clear();
  for (int k = 0; k < 3; ++k)
    if (s.node_ids[k] == 0) {
      r.error(s.where, kw, fmt::format("node_ID{}", k + 1),
              "a node (N1, N2 and N3 define the frame of a section that /TH/SECTIO writes)", "blank");
      return;
    }
  // A cut and elements that do not meet (the card's other warnings cover a missing group): the values would be 0.
  const bool elements = s.shell_group >= 0 || s.sh3n_group >= 0 || s.brick_group >= 0;
  if (s.node_group >= 0 && elements && section_terms(r.model, s).empty())
    r.context.warn(s.where, kw, "no element of the section's groups has a node of its cut (grnod_ID): its force and "
                                "moment are 0");
  if (s.nodes[0] < 0 || s.nodes[1] < 0 || s.nodes[2] < 0) return;  // reported already
  const Nodes& n = r.model.nodes;
  const Vec3 u = n.position(s.nodes[1]) - n.position(s.nodes[0]), w = n.position(s.nodes[2]) - n.position(s.nodes[0]);
  if (!(norm(u) > 0.0))
    r.error(s.where, kw, "node_ID2", "a node at another place than N1 (N1N2 is the frame's first axis)",
            fmt::format("node {} at the place of node {}", s.node_ids[1], s.node_ids[0]));
  else if (!(norm(cross(u, w)) > 1e-9 * norm(u) * norm(w)))
    r.error(s.where, kw, "node_ID3", "a node off the line N1N2 (N1, N2, N3 span the section's plane)",
            fmt::format("node {} on the line of nodes {} and {}", s.node_ids[2], s.node_ids[0], s.node_ids[1]));
}

// /INTER ids are one numbering over both types: a /TH/INTER object is a TYPE7 interface below
// type7_interfaces.size(), a TYPE2 one from there (docs/output-format.md, "INTER").
void index_tied_interfaces(Resolver& r) {
  Model& m = r.model;
  const auto first = static_cast<std::int32_t>(m.type7_interfaces.size());
  for (std::size_t k = 0; k < m.type2_interfaces.size(); ++k) {
    const Type2Interface& i = m.type2_interfaces[k];
    const auto [it, inserted] = m.index.interfaces.emplace(i.user_id, first + static_cast<std::int32_t>(k));
    if (inserted) continue;
    const auto other = static_cast<std::size_t>(it->second);
    const SourceLocation& there = other < m.type7_interfaces.size() ? m.type7_interfaces[other].where
                                                                    : m.type2_interfaces[other - m.type7_interfaces.size()].where;
    r.error(i.where, fmt::format("/INTER/TYPE2/{}", i.user_id), "id", "an id not used by another /INTER",
            fmt::format("duplicate of the one at {}:{}", there.file, there.line));
  }
}

// A tied node moved by another condition too, or a tie whose segment moves with another tie: refused, as the
// reference refuses the second (a main node tied elsewhere); the reference runs the others with a warning and an
// answer Crumple does not reproduce.
void check_tie_conflicts(Resolver& r, const std::vector<std::int64_t>& tied_by) {
  const Model& m = r.model;
  auto user = [&m](std::int32_t node) { return m.nodes.user_id[static_cast<std::size_t>(node)]; };
  auto conflict = [&](std::int32_t node, const SourceLocation& where, const std::string& keyword, std::string_view field,
                      const std::string& why) {
    const std::int64_t by = tied_by[static_cast<std::size_t>(node)];
    if (by != 0)
      r.error(where, keyword, std::string(field), "no node of a /INTER/TYPE2's grnd_IDs (a tied node moves with its segment)",
              fmt::format("node {} is tied by /INTER/TYPE2/{}{}", user(node), by, why));
  };
  for (const Type2Interface& i : m.type2_interfaces)
    for (const Tie& tie : i.ties)
      for (std::int32_t node : tie.main)
        conflict(node, i.where, fmt::format("/INTER/TYPE2/{}", i.user_id), "surf_IDm",
                 ": ties of ties (hierarchy levels) are refused, as the reference refuses them");
  for (const RigidBody& b : m.rigid_bodies) {
    const std::string kw = fmt::format("/RBODY/{}", b.user_id);
    if (b.main_node >= 0) conflict(b.main_node, b.where, kw, "node_ID", "");
    if (b.node_group >= 0)
      for (std::int32_t node : m.node_groups[static_cast<std::size_t>(b.node_group)].nodes) conflict(node, b.where, kw, "grnd_ID", "");
  }
  for (const BoundaryCondition& bc : m.boundary_conditions)
    if (bc.node_group >= 0)
      for (std::int32_t node : m.node_groups[static_cast<std::size_t>(bc.node_group)].nodes)
        conflict(node, bc.where, fmt::format("/BCS/{}", bc.user_id), "grnod_ID", "");
}

// Each tied interface's nodes on their segments (TI-1, TI-2). A node with no segment within the search distance is
// an error unless Ignore lets it out of the tie; a node tied twice would be moved by two conditions.
void tie_nodes(Resolver& r) {
  Model& m = r.model;
  std::vector<std::int64_t> tied_by(m.nodes.size(), 0);
  for (Type2Interface& i : m.type2_interfaces) {
    if (i.secondary_group < 0 || i.main_surface < 0) continue;
    const std::string kw = fmt::format("/INTER/TYPE2/{}", i.user_id);
    const TieSearch search = find_ties(m, i);
    i.ties = search.ties;
    if (!search.unmatched.empty()) {
      std::string nodes;
      for (std::size_t k = 0; k < std::min<std::size_t>(search.unmatched.size(), 5); ++k)
        nodes += fmt::format("{}{}", k ? ", " : "", m.nodes.user_id[static_cast<std::size_t>(search.unmatched[k])]);
      if (search.unmatched.size() > 5) nodes += ", ...";
      const std::string what = fmt::format("{} node(s) with no main segment within {:g} ({})", search.unmatched.size(),
                                           search.search_distance, nodes);
      if (i.ignore == 0)
        r.error(i.where, kw, "Ignore", "every node of grnd_IDs near a segment of surf_IDm (or Ignore 1 to 3, which "
                                       "leaves such nodes out)", what);
      else
        r.context.warn(i.where, kw, what + ": left out of the tie (Ignore " + std::to_string(i.ignore) + ")");
    }
    for (const Tie& tie : i.ties) {
      std::int64_t& by = tied_by[static_cast<std::size_t>(tie.node)];
      if (by != 0)
        r.error(i.where, kw, "grnd_IDs", "nodes tied by one interface only",
                fmt::format("node {} is tied by /INTER/TYPE2/{} too", m.nodes.user_id[static_cast<std::size_t>(tie.node)], by));
      by = i.user_id;
    }
  }
  check_tie_conflicts(r, tied_by);
}

}  // namespace

void resolve_output_references(Resolver& r, std::vector<RunControl>& continued_runs) {
  Model& m = r.model;
  r.index(m.type7_interfaces, m.index.interfaces, "/INTER");
  index_tied_interfaces(r);
  r.index(m.sections, m.index.sections, "/SECT");
  r.index(m.accelerometers, m.index.accelerometers, "/ACCEL");
  const auto& ix = m.index;
  // Unsupported TYPE7 options (friction functions, /FRICTION...) are rejected by the card reader.
  for (Type7Interface& i : m.type7_interfaces) {
    const std::string kw = fmt::format("/INTER/TYPE7/{}", i.user_id);
    i.sensor = sensor_window(r, i.sensor_id, i.where, kw, "sens_ID");
    i.secondary_group = r.find(ix.node_groups, i.secondary_group_id, i.where, kw, "Slav_id", "node group");
    i.main_surface = r.find(ix.surfaces, i.main_surface_id, i.where, kw, "Mast_id", "surface");
    // An interface with no secondary node would contact nothing, without a word.
    if (i.secondary_group >= 0 && m.node_groups[static_cast<std::size_t>(i.secondary_group)].nodes.empty())
      r.error(i.where, kw, "Slav_id", "a node group with nodes (the interface's secondary nodes)",
              fmt::format("node group {} is empty", i.secondary_group_id));
  }
  for (Type2Interface& i : m.type2_interfaces) {
    const std::string kw = fmt::format("/INTER/TYPE2/{}", i.user_id);
    i.secondary_group = r.find(ix.node_groups, i.secondary_group_id, i.where, kw, "grnd_IDs", "node group");
    i.main_surface = r.find(ix.surfaces, i.main_surface_id, i.where, kw, "surf_IDm", "surface");
  }
  tie_nodes(r);
  for (Section& s : m.sections) {
    const std::string kw = fmt::format("/SECT/{}", s.user_id);
    for (int k = 0; k < 3; ++k)
      s.nodes[k] = r.find_optional(ix.nodes, s.node_ids[k], s.where, kw, fmt::format("node_ID{}", k + 1), "node");
    s.node_group = r.find_optional(ix.node_groups, s.node_group_id, s.where, kw, "grnod_ID", "node group");
    s.shell_group = r.find_optional(ix.shell_groups, s.shell_group_id, s.where, kw, "grshel_ID", "shell group");
    s.sh3n_group = r.find_optional(ix.sh3n_groups, s.sh3n_group_id, s.where, kw, "grtria_ID", "3-node shell group");
    s.brick_group = r.find_optional(ix.brick_groups, s.brick_group_id, s.where, kw, "grbric_ID", "brick group");
    s.interfaces.clear();
    for (std::size_t k = 0; k < s.interface_ids.size(); ++k)
      s.interfaces.push_back(
          r.find(ix.interfaces, s.interface_ids[k], s.where, kw, fmt::format("int_ID{}", k + 1), "interface"));
  }
  for (Accelerometer& a : m.accelerometers) {
    a.node = r.find(ix.nodes, a.node_id, a.where, fmt::format("/ACCEL/{}", a.user_id), "node_ID", "node");
    a.skew = r.find_optional(ix.skews, a.skew_id, a.where, fmt::format("/ACCEL/{}", a.user_id), "skew_ID", "skew");
  }
  for (TimeHistoryRequest& th : m.histories) {
    std::string_view what;
    const IdMap* map = history_map(ix, th.object, what);
    th.objects.clear();
    for (std::int64_t id : th.object_ids) th.objects.push_back(r.find(*map, id, th.where, th.keyword, "Obj_ID", what));
    th.object_skews.clear();
    for (std::int64_t id : th.object_skew_ids)
      th.object_skews.push_back(r.find_optional(ix.skews, id, th.where, th.keyword, "skew_ID", "skew"));
  }
  std::vector<bool> written(m.sections.size(), false);
  for (const TimeHistoryRequest& th : m.histories)
    if (th.object == HistoryObject::Section)
      for (std::int32_t k : th.objects)
        if (k >= 0) written[static_cast<std::size_t>(k)] = true;
  for (std::size_t k = 0; k < m.sections.size(); ++k)
    if (written[k]) check_written_section(r, m.sections[k]);
  resolve_run_control(r, m.run);
  for (RunControl& run : continued_runs) resolve_run_control(r, run);
  // /AMS without /DT/AMS does nothing, in the reference too: said, so that a user who meant it knows.
  bool selective = m.run.dt_ams.given;
  for (const RunControl& run : continued_runs) selective = selective || run.dt_ams.given;
  if (m.ams_selected && !selective && m.run.present)
    r.context.warn(m.ams_where, "/AMS", "no effect: no engine deck has /DT/AMS, which turns selective mass scaling on");
}

}  // namespace crumple::deck
