// Elements: node and part references, repeated nodes, property kind, positive area or volume; then the tables
// ordered by part and cut into ElementGroups of at most kElementGroupSize elements.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "crumple/core/geometry.hpp"
#include "crumple/model/mass.hpp"
#include "resolve.hpp"

namespace crumple::deck {
namespace {

// node_ID3: a beam's orientation node (docs/theory/beam.md, BM-0), a beam-type spring's (docs/theory/spring.md,
// SP-15) or a joint's axis (SP-25f); node_ID4 (`second`): a joint's second frame node. The other spring types take
// neither.
std::int32_t orientation_node(Resolver& r, ElementKind kind, const RawElements& raw, std::size_t e, std::int32_t part,
                              bool second = false) {
  const std::int64_t id = second ? raw.plane_node_id[e] : raw.orientation_node_id[e];
  if (id == 0) return -1;
  const Model& m = r.model;
  const std::string keyword = fmt::format("{}/{}", describe(kind).card, raw.part_id[e]);
  const std::string field = second ? "node_ID4" : "node_ID3";
  const std::int32_t property = m.parts[static_cast<std::size_t>(part)].property;
  const SpringSection& spring = m.properties[static_cast<std::size_t>(property)].spring;
  const bool takes = spring.joint.on || (!second && spring.frame == SpringFrame::Beam);
  if (kind == ElementKind::Spring && !takes) {
    const std::string expected =
        second ? "blank (a fourth node sets the frame of /PROP/TYPE45 joints only; on another type it is not "
                 "supported by Crumple)"
               : "blank (a third node orients /PROP/TYPE13 and TYPE25 springs and /PROP/TYPE45 joints only; on "
                 "another type it is not supported by Crumple)";
    r.context.unsupported(DeckError(raw.orientation_where[e], keyword, field, expected, std::to_string(id)));
    return -1;
  }
  return r.find(m.index.nodes, id, raw.orientation_where[e], keyword, field, "node");
}

// A beam's vector Vx Vy Vz along the beam orients nothing: the reference warns (its warning 3090) and takes its
// rule without one (docs/theory/beam.md, BM-0); Crumple says the same.
void warn_parallel_orientation(Resolver& r, const RawElements& raw, std::size_t e, const std::int32_t* nodes,
                               const std::string& keyword) {
  const Vec3 v{raw.orientation_vector[3 * e], raw.orientation_vector[3 * e + 1], raw.orientation_vector[3 * e + 2]};
  if (norm(v) == 0.0) return;
  const Vec3 along = r.model.nodes.position(nodes[1]) - r.model.nodes.position(nodes[0]);
  if (norm(cross(along, v)) > 1e-6 * norm(along) * norm(v)) return;
  r.context.warn(raw.where[e], keyword,
                 fmt::format("beam {}: its vector Vx, Vy, Vz lies along it and orients nothing; its third node, else "
                             "global Y (global Z for a beam along Y), orients it, as in the reference",
                             raw.user_id[e]));
}

// A brick may repeat nodes to write a prism, pyramid or tetrahedron, as the reference accepts: the equal node ids
// must sit at connectivity positions joined by edges of the hexahedron (nodes merged along edges, e.g. the prism
// 1 2 3 3 5 6 7 7 or the tetrahedron 1 2 3 3 4 4 4 4), and at least 4 nodes must stay distinct
// (docs/theory/brick8.md, "Degenerate bricks"). A repetition across a face or body diagonal is an error.
bool check_degenerate_brick(Resolver& r, const SourceLocation& where, const std::string& keyword, std::int64_t id,
                            const std::int64_t* nodes) {
  constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  int component[8];  // positions joined through edges whose two ends carry the same node
  for (int a = 0; a < 8; ++a) component[a] = a;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& edge : kEdges)
      if (nodes[edge[0]] == nodes[edge[1]] && component[edge[0]] != component[edge[1]]) {
        component[edge[0]] = component[edge[1]] = std::min(component[edge[0]], component[edge[1]]);
        changed = true;
      }
  }
  int distinct = 0;
  for (int a = 0; a < 8; ++a) {
    bool first = true;
    for (int b = 0; b < a; ++b)
      if (nodes[b] == nodes[a]) {
        first = false;
        if (component[b] != component[a]) {
          r.error(where, keyword, fmt::format("node_ID{}", a + 1),
                  fmt::format("repeated nodes only along edges of BRICK {} (a degenerate prism 1 2 3 3 5 6 7 7, "
                              "pyramid or tetrahedron 1 2 3 3 4 4 4 4)",
                              id),
                  fmt::format("node {} as node_ID{} and node_ID{}, not joined by an edge", nodes[a], b + 1, a + 1));
          return false;
        }
      }
    distinct += first ? 1 : 0;
  }
  if (distinct < 4) {
    r.error(where, keyword, "node_ID1..", fmt::format("at least 4 distinct nodes in BRICK {}", id),
            fmt::format("{} distinct nodes", distinct));
    return false;
  }
  return true;
}

void resolve_kind(Resolver& r, ElementKind kind) {
  Model& m = r.model;
  const RawElements& raw = r.context.raw_elements[static_cast<int>(kind)];
  const ElementKindDescription& description = describe(kind);
  const int n = description.nodes;
  const std::string_view name = description.name;
  const std::size_t count = raw.user_id.size();

  std::vector<std::int32_t> part(count, -1);
  std::vector<std::int32_t> connectivity(count * static_cast<std::size_t>(n), -1);
  IdMap seen;
  seen.reserve(count);
  for (std::size_t e = 0; e < count; ++e) {
    const SourceLocation& where = raw.where[e];
    const std::string keyword = fmt::format("{}/{}", description.card, raw.part_id[e]);
    const auto [first, inserted] = seen.emplace(raw.user_id[e], static_cast<std::int32_t>(e));
    if (!inserted) {
      const auto& other = raw.where[static_cast<std::size_t>(first->second)];
      r.error(where, keyword, "elem_ID", fmt::format("an id not used by another {}", name),
              fmt::format("{} {} already defined at {}:{}", name, raw.user_id[e], other.file, other.line));
    }
    part[e] = r.find(m.index.parts, raw.part_id[e], where, keyword, "part_ID (keyword line)", "part");
    bool nodes_ok = true;
    for (int k = 0; k < n; ++k) {
      const std::int64_t id = raw.node_ids[e * static_cast<std::size_t>(n) + static_cast<std::size_t>(k)];
      const std::int32_t node = r.find(m.index.nodes, id, where, keyword, fmt::format("node_ID{}", k + 1), "node");
      connectivity[e * static_cast<std::size_t>(n) + static_cast<std::size_t>(k)] = node;
      nodes_ok = nodes_ok && node >= 0;
      for (int j = 0; j < k && !description.may_degenerate; ++j)
        if (raw.node_ids[e * static_cast<std::size_t>(n) + static_cast<std::size_t>(j)] == id) {
          r.error(where, keyword, fmt::format("node_ID{}", k + 1),
                  fmt::format("{} distinct nodes in {} {}", n, name, raw.user_id[e]),
                  fmt::format("node {} repeated (node_ID{} and node_ID{})", id, j + 1, k + 1));
          nodes_ok = false;
          break;
        }
    }
    if (description.may_degenerate && nodes_ok)
      nodes_ok = check_degenerate_brick(r, where, keyword, raw.user_id[e], &raw.node_ids[e * 8]);
    if (part[e] >= 0) {
      const Part& p = m.parts[static_cast<std::size_t>(part[e])];
      if (p.property >= 0) {
        const PropertyKind want = description.property;
        if (m.properties[static_cast<std::size_t>(p.property)].kind != want)
          r.error(where, keyword, "part_ID (keyword line)",
                  fmt::format("a part with a {} ({}) property for {} {}", describe(want).what,
                              describe(want).card, name, raw.user_id[e]),
                  fmt::format("part {} with property {}", p.user_id, p.property_id));
      }
    }
    // A general spring (/PROP/TYPE8) acts in the global axes and a beam-type one (TYPE13) has a rule for it: their
    // nodes may coincide (SP-9, SP-15a).
    const bool may_coincide = kind == ElementKind::Spring && part[e] >= 0 &&
                              m.parts[static_cast<std::size_t>(part[e])].property >= 0 &&
                              m.properties[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(part[e])].property)]
                                      .spring.frame != SpringFrame::Axial;
    if (nodes_ok) {
      const double size = element_measure(m.nodes, kind, &connectivity[e * static_cast<std::size_t>(n)]);
      const SpringSection* section =
          may_coincide
              ? &m.properties[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(part[e])].property)].spring
              : nullptr;
      const bool skewed_beam = section && section->frame == SpringFrame::Beam && section->skew_id != 0;
      const bool per_unit_length = section && section->per_unit_length;
      if (size == 0.0 && per_unit_length)
        r.error(where, keyword, "node_ID1..", "nodes apart for a spring given per unit length (Ileng 1, SP-21)",
                fmt::format("{} {} with its nodes at one place", name, raw.user_id[e]));
      else if (size == 0.0 && skewed_beam)
        r.error(where, keyword, "node_ID1..",
                "nodes apart for a beam-type spring oriented by a skew (coincident nodes with a skew are not supported "
                "by Crumple)",
                fmt::format("{} {} with its nodes at one place", name, raw.user_id[e]));
      else if (!(size > 0.0) && !(may_coincide && size == 0.0))
        r.error(where, keyword, "node_ID1..",
                std::string(description.valid_shape),
                fmt::format("{} {} with {} {:.6g}", name, raw.user_id[e], description.measure, size));
      else if (!std::isfinite(size))  // huge coordinates overflow: no usable size, mass or time step
        r.error(where, keyword, "node_ID1..", "node coordinates that give a finite size",
                fmt::format("{} {} with an infinite {}", name, raw.user_id[e], description.measure));
      else if (kind == ElementKind::Beam)
        warn_parallel_orientation(r, raw, e, &connectivity[2 * e], keyword);
    }
  }
  if (!r.errors.empty()) return;

  // Order by part (stable: deck order within a part) so that every group is one contiguous range.
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return part[a] < part[b]; });
  ElementTable& table = m.elements[static_cast<int>(kind)];
  table.user_id.resize(count);
  table.part.resize(count);
  table.connectivity.resize(connectivity.size());
  const bool own_thickness = std::any_of(raw.thickness.begin(), raw.thickness.end(), [](double t) { return t > 0.0; });
  table.thickness.assign(own_thickness ? count : 0, 0.0);
  const bool oriented = std::any_of(raw.orientation_node_id.begin(), raw.orientation_node_id.end(),
                                    [](std::int64_t id) { return id != 0; });
  table.orientation_node.assign(oriented ? count : 0, -1);
  const bool planed =
      std::any_of(raw.plane_node_id.begin(), raw.plane_node_id.end(), [](std::int64_t id) { return id != 0; });
  table.plane_node.assign(planed ? count : 0, -1);
  table.orientation_vector.assign(raw.orientation_vector.empty() ? 0 : 3 * count, 0.0);
  IdMap& index = m.index.elements[static_cast<int>(kind)];
  index.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t e = order[i];
    table.user_id[i] = raw.user_id[e];
    table.part[i] = part[e];
    if (own_thickness) table.thickness[i] = raw.thickness[e];
    if (oriented) table.orientation_node[i] = orientation_node(r, kind, raw, e, part[e]);
    if (planed) table.plane_node[i] = orientation_node(r, kind, raw, e, part[e], true);
    if (!raw.orientation_vector.empty()) std::copy_n(&raw.orientation_vector[3 * e], 3, &table.orientation_vector[3 * i]);
    std::copy_n(&connectivity[e * static_cast<std::size_t>(n)], n, &table.connectivity[i * static_cast<std::size_t>(n)]);
    index.emplace(raw.user_id[e], static_cast<std::int32_t>(i));
  }
  for (std::size_t begin = 0; begin < count;) {
    std::size_t end = begin;
    while (end < count && table.part[end] == table.part[begin] && end - begin < kElementGroupSize) ++end;
    const Part& p = m.parts[static_cast<std::size_t>(table.part[begin])];
    m.element_groups.push_back({kind, table.part[begin], p.property, p.material, static_cast<std::int32_t>(begin),
                                static_cast<std::int32_t>(end)});
    begin = end;
  }
}

}  // namespace

void resolve_elements(Resolver& r) {
  for (ElementKind kind : kAllElementKinds) resolve_kind(r, kind);
}

}  // namespace crumple::deck
