// Node groups, element groups, surfaces and subsets: members resolved to dense indices.
#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Dense indices of the parts listed by a set card.
std::vector<std::int32_t> parts_of(Resolver& r, const std::vector<std::int64_t>& ids, const SourceLocation& where,
                                   const std::string& keyword) {
  std::vector<std::int32_t> parts;
  for (std::int64_t id : ids)
    if (const auto p = r.find(r.model.index.parts, id, where, keyword, "part_ID", "part"); p >= 0) parts.push_back(p);
  return parts;
}

template <class Visit>
void for_each_element_of_parts(const Model& m, const std::vector<std::int32_t>& parts, Visit visit) {
  for (const ElementGroup& g : m.element_groups)
    if (std::find(parts.begin(), parts.end(), g.part) != parts.end())
      for (std::int32_t e = g.begin; e < g.end; ++e) visit(g.kind, e);
}

// Boxes (docs/deck-format.md, "Boxes"): their points at nodes, their skew's axes, the boxes a /BOX/BOX lists.
// Deepest /BOX/BOX nesting: as for groups, the membership test recurses.
constexpr int kMaxBoxNesting = 100;

std::string box_keyword(const Box& b) {
  constexpr const char* kTypes[] = {"RECTA", "CYLIN", "SPHER", "BOX"};
  return fmt::format("/BOX/{}/{}", kTypes[static_cast<int>(b.shape)], b.user_id);
}

void place_box_points(Resolver& r, Box& b) {
  const Model& m = r.model;
  const std::size_t points = b.shape == BoxShape::Sphere ? 1 : 2;
  for (std::size_t k = 0; k < points; ++k)
    if (b.node_ids[k] != 0)
      if (const auto n = r.find(m.index.nodes, b.node_ids[k], b.where, box_keyword(b), k == 0 ? "N1" : "N2", "node");
          n >= 0)
        b.points[k] = m.nodes.position(n);
  if (b.shape == BoxShape::Cylinder && b.points[0] == b.points[1])
    r.error(b.where, box_keyword(b), b.node_ids[0] != 0 ? "N2" : "Xp2, Yp2, Zp2",
            "an axis: two different end points", "both ends at one point");
  if (b.shape == BoxShape::Sphere && b.points[0] == Vec3{})
    r.context.warn(b.where, box_keyword(b),
                   "centre at the origin: the reference refuses such a sphere (undefined box limits), Crumple "
                   "reads it as the manual does");
}

// A fixed skew's axes, or a moving one's at its nodes' initial positions (the reference, measured: the box follows
// a /SKEW/MOV at 45 degrees). An undefined skew is reported with the skew (resolve_loads.cpp).
void set_box_axes(Resolver& r, Box& b) {
  if (b.skew_id == 0) return;
  const Model& m = r.model;
  const auto found = std::find_if(m.skews.begin(), m.skews.end(), [&](const Skew& k) { return k.user_id == b.skew_id; });
  if (found == m.skews.end())
    return r.error(b.where, box_keyword(b), "skew_ID", "an existing skew", fmt::format("skew {} not defined", b.skew_id));
  Skew skew = *found;
  if (skew.kind == SkewKind::Moving)
    for (int k = 0; k < 3; ++k) {
      const auto node = m.index.nodes.find(skew.node_ids[k]);
      if (node == m.index.nodes.end()) return;
      skew.nodes[k] = node->second;
    }
  if (skew_is_defined(skew, m.nodes.x, m.nodes.y, m.nodes.z)) b.axes = skew_axes(skew, m.nodes.x, m.nodes.y, m.nodes.z);
}

void list_combined_boxes(Resolver& r, Box& b) {
  for (std::int64_t id : b.box_ids)
    if (const auto k = r.find(r.model.index.boxes, id < 0 ? -id : id, b.where, box_keyword(b), "box_ID", "box"); k >= 0)
      (id < 0 ? b.removed : b.added).push_back(k);
}

// 0 unvisited, 1 on the path, 2 done: a /BOX/BOX that lists itself, directly or not, is an error.
bool boxes_acyclic(Resolver& r, std::size_t b, std::vector<int>& state, int depth = 0) {
  Box& box = r.model.boxes[b];
  if (state[b] == 2) return true;
  if (state[b] == 1 || depth > kMaxBoxNesting) {
    r.error(box.where, box_keyword(box), "box_ID",
            fmt::format("boxes that do not contain themselves, nested at most {} deep", kMaxBoxNesting),
            state[b] == 1 ? "a cycle of /BOX/BOX" : "a deeper nesting");
    return false;
  }
  state[b] = 1;
  bool ok = true;
  for (const auto* list : {&box.added, &box.removed})
    for (std::int32_t k : *list) ok = ok && boxes_acyclic(r, static_cast<std::size_t>(k), state, depth + 1);
  state[b] = 2;
  return ok;
}

void resolve_boxes(Resolver& r) {
  Model& m = r.model;
  r.index(m.boxes, m.index.boxes, "/BOX");
  for (Box& b : m.boxes) {
    place_box_points(r, b);
    set_box_axes(r, b);
    list_combined_boxes(r, b);
  }
  std::vector<int> state(m.boxes.size(), 0);
  for (std::size_t b = 0; b < m.boxes.size(); ++b)
    if (!boxes_acyclic(r, b, state)) {
      for (Box& box : m.boxes) {  // reported; the box groups must not recurse
        box.added.clear();
        box.removed.clear();
      }
      return;
    }
}

// The dense index of a box group's one box; -1 when missing (reported).
std::int32_t group_box(Resolver& r, std::int64_t id, const SourceLocation& where, const std::string& keyword) {
  return r.find(r.model.index.boxes, id, where, keyword, "box_ID", "box");
}

// Every node of the model in the box, at its initial position.
void nodes_in_box(Resolver& r, NodeGroup& group, const std::string& keyword) {
  const Model& m = r.model;
  const auto box = group_box(r, group.items.front(), group.where, keyword);
  if (box < 0) return;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (box_contains(m.boxes, static_cast<std::size_t>(box), m.nodes.position(static_cast<std::int32_t>(n))))
      group.nodes.push_back(static_cast<std::int32_t>(n));
}

// The elements of the group's kind with every node (/BOX) or at least one node (/BOX2) in the box.
void elements_in_box(Resolver& r, ElementSet& group, const std::string& keyword) {
  const Model& m = r.model;
  const auto box = group_box(r, group.items.front(), group.where, keyword);
  if (box < 0) return;
  std::vector<char> inside(m.nodes.size(), 0);
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    inside[n] = box_contains(m.boxes, static_cast<std::size_t>(box), m.nodes.position(static_cast<std::int32_t>(n)));
  const ElementTable& t = m.elements[static_cast<int>(group.kind)];
  const int count = nodes_per_element(group.kind);
  for (std::size_t e = 0; e < t.size(); ++e) {
    const std::int32_t* nodes = t.nodes_of(e);
    const auto in = [&](std::int32_t n) { return inside[static_cast<std::size_t>(n)] != 0; };
    if (group.any_node_in_box ? std::any_of(nodes, nodes + count, in) : std::all_of(nodes, nodes + count, in))
      group.elements.push_back(static_cast<std::int32_t>(e));
  }
}

// Deepest /GRNOD/GRNOD nesting resolved (the resolution recurses; a deeper chain would overflow the stack).
constexpr int kMaxGroupNesting = 1000;

void resolve_node_group(Resolver& r, std::size_t g, std::vector<int>& state, int depth = 0) {
  Model& m = r.model;
  NodeGroup& group = m.node_groups[g];
  if (state[g] == 2) return;
  const std::string keyword = fmt::format("/GRNOD/{}/{}", group.source == SetSource::Ids     ? "NODE"
                                                          : group.source == SetSource::Parts ? "PART"
                                                          : group.source == SetSource::Surfaces ? "SURF"
                                                          : group.source == SetSource::Boxes    ? "BOX"
                                                                                             : "GRNOD",
                                          group.user_id);
  if (state[g] == 1) {
    r.error(group.where, keyword, "grnod_ID", "groups that do not contain themselves", "a cycle of /GRNOD/GRNOD");
    return;
  }
  state[g] = 1;
  switch (group.source) {
    case SetSource::Ids:
      for (std::int64_t id : group.items)
        if (const auto n = r.find(m.index.nodes, id, group.where, keyword, "node_ID", "node"); n >= 0)
          group.nodes.push_back(n);
      break;
    case SetSource::Parts:
      for_each_element_of_parts(m, parts_of(r, group.items, group.where, keyword), [&](ElementKind kind, std::int32_t e) {
        const ElementTable& t = m.elements[static_cast<int>(kind)];
        const std::int32_t* nodes = t.nodes_of(static_cast<std::size_t>(e));
        group.nodes.insert(group.nodes.end(), nodes, nodes + nodes_per_element(kind));
      });
      break;
    case SetSource::Surfaces:  // every node of the surfaces' segments
      for (std::int64_t id : group.items)
        if (const auto k = r.find(m.index.surfaces, id, group.where, keyword, "surf_ID", "surface"); k >= 0)
          for (const Segment& seg : m.surfaces[static_cast<std::size_t>(k)].segments)
            group.nodes.insert(group.nodes.end(), seg.nodes.begin(), seg.nodes.end());
      break;
    case SetSource::Boxes:
      nodes_in_box(r, group, keyword);
      break;
    case SetSource::Groups:
      for (std::int64_t id : group.items) {
        const auto child = r.find(m.index.node_groups, id, group.where, keyword, "grnod_ID", "node group");
        if (child < 0) continue;
        if (depth >= kMaxGroupNesting && state[static_cast<std::size_t>(child)] != 2) {
          r.error(group.where, keyword, "grnod_ID",
                  fmt::format("at most {} levels of nested /GRNOD/GRNOD", kMaxGroupNesting),
                  fmt::format("node group {} nested deeper", id));
          continue;
        }
        resolve_node_group(r, static_cast<std::size_t>(child), state, depth + 1);
        const auto& nodes = m.node_groups[static_cast<std::size_t>(child)].nodes;
        group.nodes.insert(group.nodes.end(), nodes.begin(), nodes.end());
      }
      break;
  }
  sort_unique(group.nodes);
  state[g] = 2;
}

void resolve_element_set(Resolver& r, ElementSet& group) {
  Model& m = r.model;
  const ElementKindDescription& words = describe(group.kind);
  const std::string_view how = group.source == SetSource::Ids     ? words.group_item
                              : group.source == SetSource::Parts ? "PART"
                              : group.any_node_in_box            ? "BOX2"
                                                                 : "BOX";
  const std::string keyword = fmt::format("{}/{}/{}", words.group_card, how, group.user_id);
  if (group.source == SetSource::Boxes) {
    elements_in_box(r, group, keyword);
  } else if (group.source == SetSource::Ids) {
    for (std::int64_t id : group.items)
      if (const auto e = r.find(m.index.elements[static_cast<int>(group.kind)], id, group.where, keyword,
                                words.group_field, words.what);
          e >= 0)
        group.elements.push_back(e);
  } else {
    for_each_element_of_parts(m, parts_of(r, group.items, group.where, keyword), [&](ElementKind kind, std::int32_t e) {
      if (kind == group.kind) group.elements.push_back(e);
    });
  }
  sort_unique(group.elements);
}

using FaceKey = std::array<std::int32_t, 4>;
FaceKey face_key(std::array<std::int32_t, 4> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

// Outer faces of bricks (faces used once within the set) and both-sided shell segments of the listed parts.
void surface_from_parts(Resolver& r, Surface& s) {
  Model& m = r.model;
  const std::string keyword = fmt::format("/SURF/PART/{}{}", s.all_parts ? "ALL/" : "", s.user_id);
  if (s.all_parts)
    for (const Part& part : m.parts) s.parts.push_back(part.user_id);
  const auto parts = parts_of(r, s.parts, s.where, keyword);
  constexpr int brick_faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<FaceKey, std::pair<int, Segment>> brick_face_use;
  for_each_element_of_parts(m, parts, [&](ElementKind kind, std::int32_t e) {
    const std::int32_t* n = m.elements[static_cast<int>(kind)].nodes_of(static_cast<std::size_t>(e));
    if (kind == ElementKind::Shell4) s.segments.push_back({{n[0], n[1], n[2], n[3]}, {kind, e}});
    else if (kind == ElementKind::Shell3) s.segments.push_back({{n[0], n[1], n[2], n[2]}, {kind, e}});
    else
      for (const auto& f : brick_faces) {
        const Segment seg{{n[f[0]], n[f[1]], n[f[2]], n[f[3]]}, {kind, e}};
        auto& use = brick_face_use[face_key(seg.nodes)];
        if (use.first++ == 0) use.second = seg;
      }
  });
  for (const auto& [key, use] : brick_face_use)
    if (use.first == 1) s.segments.push_back(use.second);
  if (s.segments.empty())
    r.error(s.where, keyword, "part_ID", "parts with elements", "a surface without segments");
}

void surface_from_segments(Resolver& r, Surface& s) {
  Model& m = r.model;
  const std::string keyword = fmt::format("/SURF/SEG/{}", s.user_id);
  // Owner lookup: a segment belongs to the shell with the same nodes or to the brick with that face.
  std::map<FaceKey, ElementRef> owners;
  constexpr int brick_faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const ElementGroup& g : m.element_groups)
    for (std::int32_t e = g.begin; e < g.end; ++e) {
      const std::int32_t* n = m.elements[static_cast<int>(g.kind)].nodes_of(static_cast<std::size_t>(e));
      if (g.kind == ElementKind::Shell4) owners.emplace(face_key({n[0], n[1], n[2], n[3]}), ElementRef{g.kind, e});
      else if (g.kind == ElementKind::Shell3) owners.emplace(face_key({n[0], n[1], n[2], n[2]}), ElementRef{g.kind, e});
      else
        for (const auto& f : brick_faces)
          owners.emplace(face_key({n[f[0]], n[f[1]], n[f[2]], n[f[3]]}), ElementRef{g.kind, e});
    }
  for (std::size_t k = 0; k < s.raw_segments.size(); ++k) {
    Segment seg{{-1, -1, -1, -1}, {ElementKind::Shell4, -1}};
    bool ok = true;
    for (std::size_t j = 0; j < 4; ++j) {
      const std::int64_t id = s.raw_segments[k][j];
      if (id == 0) {
        seg.nodes[j] = seg.nodes[2];  // triangle
        continue;
      }
      seg.nodes[j] = r.find(m.index.nodes, id, s.raw_segment_where[k], keyword, fmt::format("node_ID{}", j + 1), "node");
      ok = ok && seg.nodes[j] >= 0;
    }
    if (!ok) continue;
    if (const auto it = owners.find(face_key(seg.nodes)); it != owners.end()) seg.owner = it->second;
    s.segments.push_back(seg);
  }
}

// The segments of the elements of shell (or 3-node shell) groups, oriented by each element, each element once.
void surface_from_element_groups(Resolver& r, Surface& s) {
  Model& m = r.model;
  const bool quads = s.group_kind == ElementKind::Shell4;
  const std::string keyword = fmt::format("/SURF/{}/{}", quads ? "GRSHEL" : "GRSH3N", s.user_id);
  const auto& groups = quads ? m.shell_groups : m.sh3n_groups;
  std::vector<std::int32_t> elements;
  for (std::int64_t id : s.element_groups)
    if (const auto g = r.find(quads ? m.index.shell_groups : m.index.sh3n_groups, id, s.where, keyword,
                              quads ? "grshel_ID" : "grsh3n_ID", quads ? "shell group" : "3-node shell group");
        g >= 0)
      for (std::int32_t e : groups[static_cast<std::size_t>(g)].elements) elements.push_back(e);
  sort_unique(elements);
  for (std::int32_t e : elements) {
    const std::int32_t* n = m.elements[static_cast<int>(s.group_kind)].nodes_of(static_cast<std::size_t>(e));
    s.segments.push_back({{n[0], n[1], n[2], quads ? n[3] : n[2]}, {s.group_kind, e}});
  }
}

// A line's segments from its surfaces' edges (docs/deck-format.md, "Lines"): each edge once, in the order first met;
// for /LINE/EDGE only the edges one segment alone has.
void resolve_line(Resolver& r, LineSet& l) {
  Model& m = r.model;
  const std::string keyword =
      fmt::format("/LINE/{}/{}", l.source == LineSource::SurfaceEdges ? "SURF" : "EDGE", l.user_id);
  std::map<std::pair<std::int32_t, std::int32_t>, int> uses;
  std::vector<std::pair<std::int32_t, std::int32_t>> order;
  for (std::int64_t id : l.surfaces) {
    const auto k = r.find(m.index.surfaces, id, l.where, keyword, "surf_ID", "surface");
    if (k < 0) continue;
    for (const Segment& seg : m.surfaces[static_cast<std::size_t>(k)].segments) {
      const int corners = seg.nodes[3] == seg.nodes[2] || seg.nodes[3] < 0 ? 3 : 4;
      for (int c = 0; c < corners; ++c) {
        const std::int32_t a = seg.nodes[static_cast<std::size_t>(c)];
        const std::int32_t b = seg.nodes[static_cast<std::size_t>((c + 1) % corners)];
        const auto key = std::minmax(a, b);
        if (uses[key]++ == 0) order.push_back(key);
      }
    }
  }
  for (const auto& edge : order)
    if (l.source == LineSource::SurfaceEdges || uses[edge] == 1) l.segments.push_back({edge.first, edge.second});
}

}  // namespace

void resolve_sets(Resolver& r) {
  Model& m = r.model;
  r.index(m.node_groups, m.index.node_groups, "/GRNOD");
  r.index(m.shell_groups, m.index.shell_groups, "/GRSHEL");
  r.index(m.sh3n_groups, m.index.sh3n_groups, "/GRSH3N");
  r.index(m.brick_groups, m.index.brick_groups, "/GRBRIC");
  r.index(m.surfaces, m.index.surfaces, "/SURF");
  r.index(m.subsets, m.index.subsets, "/SUBSET");
  resolve_boxes(r);
  // Element groups, then surfaces (of parts, segments or element groups), then node groups (of surfaces too).
  for (auto* groups : {&m.shell_groups, &m.sh3n_groups, &m.brick_groups})
    for (ElementSet& g : *groups) resolve_element_set(r, g);
  for (Surface& s : m.surfaces) {
    if (s.source == SetSource::Parts) surface_from_parts(r, s);
    else if (s.source == SetSource::Groups) surface_from_element_groups(r, s);
    else surface_from_segments(r, s);
  }
  r.index(m.lines, m.index.lines, "/LINE");
  for (LineSet& l : m.lines) resolve_line(r, l);
  std::vector<int> state(m.node_groups.size(), 0);
  for (std::size_t g = 0; g < m.node_groups.size(); ++g) resolve_node_group(r, g, state);
  for (const Subset& s : m.subsets)
    for (std::int64_t child : s.children)
      r.find(m.index.subsets, child, s.where, fmt::format("/SUBSET/{}", s.user_id), "subset_ID", "subset");
  for (const Part& p : m.parts)
    r.find_optional(m.index.subsets, p.subset_id, p.where, fmt::format("/PART/{}", p.user_id), "subset_ID", "subset");
}

}  // namespace crumple::deck
