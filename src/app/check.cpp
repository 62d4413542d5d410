#include "app/check.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <ostream>

#include "crumple/model/summary.hpp"

namespace crumple::app {
namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : " ") + item;
  return out.empty() ? "(none)" : out;
}

}  // namespace

void print_check_report(const Deck& deck, std::ostream& out) {
  const Model& m = deck.model;
  const auto count = [&](ElementKind k) { return m.elements[static_cast<int>(k)].size(); };
  fmt::print(out, "Model {}{}\n", m.run_name, m.title.empty() ? "" : " - " + m.title);
  fmt::print(out, "  files read            {}\n", join(deck.report.files));
  fmt::print(out, "  units                 input (kg, m, s) x [{:g}, {:g}, {:g}], working x [{:g}, {:g}, {:g}]\n",
             m.units.input[0], m.units.input[1], m.units.input[2], m.units.work[0], m.units.work[1], m.units.work[2]);
  fmt::print(out, "Counts\n");
  fmt::print(out, "  nodes                 {}\n", m.nodes.size());
  fmt::print(out, "  4-node shells         {}\n", count(ElementKind::Shell4));
  fmt::print(out, "  3-node shells         {}\n", count(ElementKind::Shell3));
  fmt::print(out, "  8-node bricks         {}\n", count(ElementKind::Brick8));
  fmt::print(out, "  element groups        {}\n", m.element_groups.size());
  fmt::print(out, "  parts                 {}\n", m.parts.size());
  fmt::print(out, "  materials             {}\n", m.materials.size());
  fmt::print(out, "  properties            {}\n", m.properties.size());
  fmt::print(out, "  functions             {}\n", m.functions.size());
  fmt::print(out, "  node groups           {}\n", m.node_groups.size());
  fmt::print(out, "  shell groups          {}\n", m.shell_groups.size());
  fmt::print(out, "  surfaces              {}\n", m.surfaces.size());
  fmt::print(out, "  subsets               {}\n", m.subsets.size());
  fmt::print(out, "  interfaces            {}\n", m.type7_interfaces.size());
  fmt::print(out, "  rigid walls           {}\n", m.rigid_walls.size());
  fmt::print(out, "  rigid bodies          {}\n", m.rigid_bodies.size());
  fmt::print(out, "  boundary conditions   {}\n", m.boundary_conditions.size());
  fmt::print(out, "  imposed motions/loads {}\n", m.imposed.size());
  fmt::print(out, "  initial velocities    {}\n", m.initial_velocities.size());
  fmt::print(out, "  time histories        {}\n", m.histories.size());
  fmt::print(out, "  sections              {}\n", m.sections.size());
  fmt::print(out, "Mass\n");
  fmt::print(out, "  total mass            {:.6g}\n", m.total_mass());
  fmt::print(out, "  element mass          {:.6g}\n", m.element_mass);
  fmt::print(out, "  added mass            {:.6g} (/ADMAS, /RBODY)\n", m.added_mass);
  const BoundingBox box = bounding_box(m.nodes);
  fmt::print(out, "Bounding box\n");
  fmt::print(out, "  min                   {:.6g} {:.6g} {:.6g}\n", box.min[0], box.min[1], box.min[2]);
  fmt::print(out, "  max                   {:.6g} {:.6g} {:.6g}\n", box.max[0], box.max[1], box.max[2]);
  fmt::print(out, "Time step\n");
  const ControllingElement dt = smallest_element_time_step(m);
  if (dt.time_step > 0.0) {
    const double scale = m.run.dt.scale > 0.0 ? m.run.dt.scale : 0.9;
    fmt::print(out, "  smallest element step {:.6g} ({} {} in part {})\n", dt.time_step, element_kind_name(dt.kind),
               dt.element_user_id, dt.part_user_id);
    fmt::print(out, "  scaled step           {:.6g} (scale {:g})\n", dt.time_step * scale, scale);
  } else {
    fmt::print(out, "  smallest element step none (no elements)\n");
  }
  if (m.run.present)
    fmt::print(out, "Run\n  end time              {:g}\n", m.run.end_time);
  fmt::print(out, "Keywords\n");
  fmt::print(out, "  read                  {}\n", join(deck.report.keywords_read));
  fmt::print(out, "  accepted, no effect   {}\n", join(deck.report.accepted_without_effect));
  for (const auto& w : deck.report.warnings) fmt::print(out, "warning: {}\n", w.text());
}

}  // namespace crumple::app
