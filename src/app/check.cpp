#include "app/check.hpp"
#include "app/console.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <ostream>

#include "crumple/elements/critical_step.hpp"
#include "crumple/model/summary.hpp"

namespace crumple::app {
namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : " ") + item;
  return out.empty() ? "(none)" : out;
}

// Up to 16 values one by one, more as their range and mean.
template <class T>
std::string per_domain(const std::vector<T>& values) {
  if (values.size() <= 16) {
    std::vector<std::string> items;
    for (const T v : values) items.push_back(fmt::format("{}", v));
    return join(items);
  }
  double sum = 0.0;
  for (const T v : values) sum += static_cast<double>(v);
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return fmt::format("min {} mean {:.1f} max {}", *low, sum / static_cast<double>(values.size()), *high);
}

// A box group's members by user id, as the reference's starter listing prints them (Ipri 5): the first 40.
template <class Members>
void print_box_group(std::ostream& out, std::string_view what, std::int64_t id, std::int64_t box, std::string_view rule,
                     const Members& members, const std::vector<std::int64_t>& user_ids) {
  std::vector<std::string> items;
  for (std::size_t k = 0; k < members.size() && k < 40; ++k)
    items.push_back(fmt::format("{}", user_ids[static_cast<std::size_t>(members[k])]));
  if (members.size() > 40) items.push_back("...");
  fmt::print(out, "  {:<11} {:<8} box {}{}: {}: {}\n", what, id, box, rule, members.size(), join(items));
}

void print_box_groups(const Model& m, std::ostream& out) {
  for (const NodeGroup& g : m.node_groups)
    if (g.source == SetSource::Boxes)
      print_box_group(out, "node group", g.user_id, g.items.front(), "", g.nodes, m.nodes.user_id);
  for (const auto* groups : {&m.shell_groups, &m.sh3n_groups, &m.brick_groups})
    for (const ElementSet& g : *groups)
      if (g.source == SetSource::Boxes)
        print_box_group(out, fmt::format("{} group", element_kind_name(g.kind)), g.user_id, g.items.front(),
                        g.any_node_in_box ? " (BOX2)" : " (BOX)", g.elements,
                        m.elements[static_cast<int>(g.kind)].user_id);
}

// What the reading resolved, as the reference's starter listing prints it: each property's formulation after
// /DEF_SHELL, /DEF_SOLID and the defaults (docs/deck-format.md, "Defaults that matter"), each wall's secondary
// nodes, each body's centre choice, each skew and the members of each box group.
void print_resolved(const Model& m, std::ostream& out) {
  fmt::print(out, "Resolved\n");
  for (std::size_t i = 0; i < m.properties.size() && i < m.formulations.size(); ++i) {
    const Property& p = m.properties[i];
    const ResolvedFormulation& f = m.formulations[i];
    if (p.kind == PropertyKind::Shell)
      fmt::print(out, "  property {:<10} shell: Ishell {} Ish3n {} Ismstr {} N {} Iplas {}\n", p.user_id, f.ishell,
                 f.ish3n, f.ismstr, f.n_points, f.iplas);
    else
      fmt::print(out, "  property {:<10} solid: Isolid {} Ismstr {} Icpre {} Iframe {}\n", p.user_id, f.isolid,
                 f.ismstr, f.icpre, f.iframe);
  }
  for (const RigidWall& w : m.rigid_walls)
    fmt::print(out, "  rigid wall {:<8} {}: {} secondary nodes{}\n", w.user_id, rigid_wall_shape_name(w.shape),
               w.secondary_nodes.size(), w.node >= 0 ? " (moving)" : "");
  for (const RigidBody& b : m.rigid_bodies)
    fmt::print(out, "  rigid body {:<8} main node {} ICoG {} Ispher {}\n", b.user_id, b.main_node_id, b.icog,
               b.ispher);
  for (const Skew& k : m.skews)
    fmt::print(out, "  skew {:<14} {}\n", k.user_id, k.kind == SkewKind::Fixed ? "fixed" : "moving");
  print_box_groups(m, out);
}

}  // namespace

void print_check_report(const Deck& deck, std::ostream& out) {
  const Model& m = deck.model;
  const auto count = [&](ElementKind k) { return m.elements[static_cast<int>(k)].size(); };
  fmt::print(out, "Model {}{}\n", m.run_name, m.title.empty() ? "" : " - " + m.title);
  fmt::print(out, "  files read            {}\n", join(deck.report.files));
  fmt::print(out, "  units                 input (kg, m, s) x [{:g}, {:g}, {:g}], working x [{:g}, {:g}, {:g}]\n",
             m.units.input[0], m.units.input[1], m.units.input[2], m.units.work[0], m.units.work[1], m.units.work[2]);
  const UnitNames units = unit_names(m.units.work);
  fmt::print(out, "  working units         {}\n", describe(units));
  fmt::print(out, "Counts\n");
  fmt::print(out, "  nodes                 {}\n", m.nodes.size());
  for (const ElementKindDescription& kind : kElementKindTable)
    fmt::print(out, "  {:<22}{}\n", kind.counted, count(kind.kind));
  fmt::print(out, "  element groups        {}\n", m.element_groups.size());
  fmt::print(out, "  parts                 {}\n", m.parts.size());
  fmt::print(out, "  materials             {}\n", m.materials.size());
  fmt::print(out, "  properties            {}\n", m.properties.size());
  fmt::print(out, "  functions             {}\n", m.functions.size());
  fmt::print(out, "  node groups           {}\n", m.node_groups.size());
  fmt::print(out, "  shell groups          {}\n", m.shell_groups.size());
  fmt::print(out, "  surfaces              {}\n", m.surfaces.size());
  if (!m.lines.empty()) {
    std::size_t segments = 0;
    for (const LineSet& l : m.lines) segments += l.segments.size();
    fmt::print(out, "  lines                 {} ({} segments)\n", m.lines.size(), segments);
  }
  fmt::print(out, "  subsets               {}\n", m.subsets.size());
  fmt::print(out, "  interfaces            {}\n", m.type7_interfaces.size());
  if (!m.type2_interfaces.empty()) {
    std::size_t ties = 0;
    for (const Type2Interface& i : m.type2_interfaces) ties += i.ties.size();
    fmt::print(out, "  tied interfaces       {} ({} tied nodes)\n", m.type2_interfaces.size(), ties);
  }
  fmt::print(out, "  rigid walls           {}\n", m.rigid_walls.size());
  fmt::print(out, "  rigid bodies          {}\n", m.rigid_bodies.size());
  if (!m.rigid_elements.empty()) {
    std::size_t carried = 0;
    for (const RigidElement& e : m.rigid_elements) carried += e.secondary_nodes.size();
    fmt::print(out, "  rigid elements /RBE2  {} ({} secondary nodes)\n", m.rigid_elements.size(), carried);
  }
  fmt::print(out, "  boundary conditions   {}\n", m.boundary_conditions.size());
  fmt::print(out, "  imposed motions/loads {}\n", m.imposed.size());
  fmt::print(out, "  initial velocities    {}\n", m.initial_velocities.size());
  fmt::print(out, "  time histories        {}\n", m.histories.size());
  fmt::print(out, "  sections              {}\n", m.sections.size());
  fmt::print(out, "Mass\n");
  fmt::print(out, "  total mass            {:.6g} {}\n", m.total_mass(), units.mass);
  fmt::print(out, "  element mass          {:.6g} {}\n", m.element_mass, units.mass);
  // The deck's own point masses, not the mass scaling adds during a run (the listing's MASS ADDED).
  fmt::print(out, "  point masses          {:.6g} {} (/ADMAS, /RBODY MASS)\n", m.added_mass, units.mass);
  const BoundingBox box = bounding_box(m.nodes);
  fmt::print(out, "Bounding box\n");
  fmt::print(out, "  min                   {:.6g} {:.6g} {:.6g} {}\n", box.min[0], box.min[1], box.min[2], units.length);
  fmt::print(out, "  max                   {:.6g} {:.6g} {:.6g} {}\n", box.max[0], box.max[1], box.max[2], units.length);
  fmt::print(out, "Time step\n");
  const ControllingElement dt = smallest_element_time_step(m);
  if (dt.time_step > 0.0) {
    const double scale = m.run.dt.scale > 0.0 ? m.run.dt.scale : 0.9;
    fmt::print(out, "  smallest element step {:.6g} {} ({} {} in part {})\n", dt.time_step, units.time,
               element_kind_name(dt.kind), dt.element_user_id, dt.part_user_id);
    fmt::print(out, "  scaled step           {:.6g} {} (scale {:g})\n", dt.time_step * scale, units.time, scale);
  } else {
    fmt::print(out, "  smallest element step none (no elements)\n");
  }
  print_resolved(m, out);
  if (m.run.present)
    fmt::print(out, "Run\n  end time              {:g} {}\n", m.run.end_time, units.time);
  fmt::print(out, "Keywords\n");
  fmt::print(out, "  read                  {}\n", join(deck.report.keywords_read));
  fmt::print(out, "  accepted, no effect   {}\n", join(deck.report.accepted_without_effect));
  print_warnings(deck.report.warnings, deck.report.files.empty() ? "" : deck.report.files.front(), out);
}

void print_partition_report(const Partition& p, std::ostream& out) {
  std::vector<long long> elements(static_cast<std::size_t>(p.domains), 0);
  for (const auto& kind : p.domain_of_element)
    for (const std::int32_t d : kind) ++elements[static_cast<std::size_t>(d)];
  fmt::print(out, "Partition (METIS k-way on the element graph)\n");
  fmt::print(out, "  ranks                 {}\n", p.domains);
  fmt::print(out, "  edge cut              {}\n", p.edge_cut);
  fmt::print(out, "  shared nodes          {}\n", p.shared_nodes);
  fmt::print(out, "  imbalance             {:.3f}\n", p.imbalance);
  fmt::print(out, "  elements per rank     {}\n", per_domain(elements));
  fmt::print(out, "  weight per rank       {}\n", per_domain(p.weight));
  fmt::print(out, "  neighbours per rank   {}\n", per_domain(p.neighbours));
}

}  // namespace crumple::app
