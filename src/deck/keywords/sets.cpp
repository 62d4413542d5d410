// Groups, surfaces and lines: /GRNOD, /GRSHEL, /GRSH3N, /GRBRIC, /SURF, /LINE, /SUBSET (docs/deck-format.md).
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

std::vector<std::int64_t> positive_ids(CardReader& reader, std::string_view name, IdKind kind) {
  std::vector<std::int64_t> ids = read_id_list(reader, name, kind);
  for (std::int64_t id : ids)
    if (id < 0) reader.fail(name, "positive ids (removing members with negative ids is not supported by Crumple)",
                            fmt::format("{}", id));
  return ids;
}

template <class Group>
Group begin_group(CardReader& reader, SetSource source) {
  Group g;
  g.where = reader.card().where;
  g.user_id = object_id(reader, 2);
  read_unit_id(reader, 3);
  g.source = source;
  g.title = read_title(reader);
  return g;
}

// The box groups' one box_ID (the manual's layout). The reference reads the first positive id of a longer list and
// skips the rest, negative ids included, without a word (measured): a list is refused rather than cut.
std::vector<std::int64_t> one_box_id(CardReader& reader) {
  const std::vector<std::int64_t> ids = read_id_list(reader, "box_ID", IdKind::Other);
  if (ids.size() != 1)
    reader.fail("box_ID", "one box id (of a list, the reference would read only the first positive one)",
                ids.empty() ? "none" : fmt::format("{} box ids", ids.size()));
  if (ids[0] < 0)
    reader.fail("box_ID", "a positive box id (the reference skips a negative one)", fmt::format("{}", ids[0]));
  return ids;
}

// The kind of the ids a group lists: its members' own (nodes or elements), parts, or other sets.
IdKind member_kind(SetSource source, IdKind own) {
  return source == SetSource::Ids ? own : source == SetSource::Parts ? IdKind::Part : IdKind::Other;
}

void read_node_group(CardReader& reader, DeckContext& context, SetSource source, std::string_view item) {
  auto g = begin_group<NodeGroup>(reader, source);
  g.items = source == SetSource::Boxes ? one_box_id(reader)
                                       : positive_ids(reader, item, member_kind(source, IdKind::Node));
  context.model.node_groups.push_back(std::move(g));
}

// `any_node_in_box`: /BOX2 (source Boxes only).
void read_element_group(CardReader& reader, DeckContext& context, ElementKind kind, SetSource source,
                        std::string_view item, bool any_node_in_box = false) {
  auto g = begin_group<ElementSet>(reader, source);
  g.kind = kind;
  g.items = source == SetSource::Boxes ? one_box_id(reader)
                                       : positive_ids(reader, item, member_kind(source, IdKind::Element));
  g.any_node_in_box = any_node_in_box;
  Model& m = context.model;
  (kind == ElementKind::Shell4 ? m.shell_groups : kind == ElementKind::Shell3 ? m.sh3n_groups : m.brick_groups)
      .push_back(std::move(g));
}

// /SURF/PART/surf_ID with a list of parts, or /SURF/PART/ALL/surf_ID (every part of the model, no list).
// /SURF/PART/EXT (external faces of solids only) is another Radioss keyword, which Crumple does not read.
void read_surface_parts(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const bool all = path.size() > 2 && path[2] == "ALL";
  if (path.size() > 2 && !all && !path[2].empty() && !parse_integer(path[2]))
    return context.unsupported(reader.error("keyword", "/SURF/PART/surf_ID or /SURF/PART/ALL/surf_ID",
                                            fmt::format("/SURF/PART/{}, which is not supported by Crumple", path[2])));
  Surface s;
  s.where = reader.card().where;
  s.user_id = object_id(reader, all ? 3 : 2);
  read_unit_id(reader, all ? 4 : 3);
  s.source = SetSource::Parts;
  s.title = read_title(reader);
  s.all_parts = all;
  if (!all) s.parts = positive_ids(reader, "part_ID", IdKind::Part);
  reader.finish();
  context.model.surfaces.push_back(std::move(s));
}

void read_surface_segments(CardReader& reader, DeckContext& context) {
  auto s = begin_group<Surface>(reader, SetSource::Ids);
  while (auto line = reader.next_nonblank()) {
    line->id(1, 10, "seg_ID", IdKind::Other);  // a label
    std::array<std::int64_t, 4> nodes{};
    for (int k = 0; k < 4; ++k) {
      const std::string name = fmt::format("node_ID{}", k + 1);
      nodes[static_cast<std::size_t>(k)] = line->id(11 + 10 * k, 10, name, IdKind::Node);
      if (nodes[static_cast<std::size_t>(k)] < 0 || (k < 3 && nodes[static_cast<std::size_t>(k)] == 0))
        line->fail(11 + 10 * k, 10, name, k < 3 ? "a positive node id" : "a positive node id or blank (triangle)");
    }
    s.raw_segments.push_back(nodes);
    s.raw_segment_where.push_back(line->where());
  }
  context.model.surfaces.push_back(std::move(s));
}

// /SURF/GRSHEL/surf_ID and /SURF/GRSH3N/surf_ID: a list of shell (3-node shell) groups whose elements are the
// surface's segments, oriented by each element.
void read_surface_element_groups(CardReader& reader, DeckContext& context, ElementKind kind) {
  auto s = begin_group<Surface>(reader, SetSource::Groups);
  s.group_kind = kind;
  s.element_groups = positive_ids(reader, kind == ElementKind::Shell4 ? "grshel_ID" : "grsh3n_ID", IdKind::Other);
  reader.finish();
  context.model.surfaces.push_back(std::move(s));
}

// /LINE/SURF/line_ID and /LINE/EDGE/line_ID: title; surface ids, ten a line.
void read_line_of_surfaces(CardReader& reader, DeckContext& context, LineSource source) {
  LineSet l;
  l.where = reader.card().where;
  l.user_id = object_id(reader, 2);
  read_unit_id(reader, 3);
  l.source = source;
  l.title = read_title(reader);
  l.surfaces = positive_ids(reader, "surf_ID", IdKind::Other);
  if (l.surfaces.empty()) reader.fail("surf_ID", "at least one surface id", "none");
  context.model.lines.push_back(std::move(l));
}

void read_subset(CardReader& reader, DeckContext& context) {
  Subset s;
  s.where = reader.card().where;
  s.user_id = object_id(reader, 1);
  read_unit_id(reader, 2);
  s.title = read_title(reader);
  s.children = positive_ids(reader, "subset_ID", IdKind::Other);
  context.model.subsets.push_back(std::move(s));
}

}  // namespace

void register_set_keywords(KeywordTable& table) {
  auto node_group = [](SetSource source, std::string_view item) {
    return [source, item](CardReader& r, DeckContext& c) { read_node_group(r, c, source, item); };
  };
  auto element_group = [](ElementKind kind, SetSource source, std::string_view item) {
    return [kind, source, item](CardReader& r, DeckContext& c) { read_element_group(r, c, kind, source, item); };
  };
  // /GRSHEL/BOX: the elements whose nodes are all in the box; /GRSHEL/BOX2: those with at least one node in it.
  auto box_group = [](ElementKind kind, bool any_node_in_box) {
    return [kind, any_node_in_box](CardReader& r, DeckContext& c) {
      read_element_group(r, c, kind, SetSource::Boxes, "box_ID", any_node_in_box);
    };
  };
  using K = ElementKind;
  table.push_back({"/GRNOD/NODE", DeckPart::Starter, node_group(SetSource::Ids, "node_ID")});
  table.push_back({"/GRNOD/PART", DeckPart::Starter, node_group(SetSource::Parts, "part_ID")});
  table.push_back({"/GRNOD/GRNOD", DeckPart::Starter, node_group(SetSource::Groups, "grnod_ID")});
  table.push_back({"/GRNOD/SURF", DeckPart::Starter, node_group(SetSource::Surfaces, "surf_ID")});
  table.push_back({"/GRNOD/BOX", DeckPart::Starter, node_group(SetSource::Boxes, "box_ID")});
  table.push_back({"/GRSHEL/BOX", DeckPart::Starter, box_group(K::Shell4, false)});
  table.push_back({"/GRSHEL/BOX2", DeckPart::Starter, box_group(K::Shell4, true)});
  table.push_back({"/GRSH3N/BOX", DeckPart::Starter, box_group(K::Shell3, false)});
  table.push_back({"/GRSH3N/BOX2", DeckPart::Starter, box_group(K::Shell3, true)});
  table.push_back({"/GRBRIC/BOX", DeckPart::Starter, box_group(K::Brick8, false)});
  table.push_back({"/GRBRIC/BOX2", DeckPart::Starter, box_group(K::Brick8, true)});
  table.push_back({"/GRSHEL/SHEL", DeckPart::Starter, element_group(K::Shell4, SetSource::Ids, "shell_ID")});
  table.push_back({"/GRSHEL/PART", DeckPart::Starter, element_group(K::Shell4, SetSource::Parts, "part_ID")});
  table.push_back({"/GRSH3N/SH3N", DeckPart::Starter, element_group(K::Shell3, SetSource::Ids, "sh3n_ID")});
  table.push_back({"/GRSH3N/PART", DeckPart::Starter, element_group(K::Shell3, SetSource::Parts, "part_ID")});
  table.push_back({"/GRBRIC/BRIC", DeckPart::Starter, element_group(K::Brick8, SetSource::Ids, "brick_ID")});
  table.push_back({"/GRBRIC/PART", DeckPart::Starter, element_group(K::Brick8, SetSource::Parts, "part_ID")});
  table.push_back({"/SURF/PART", DeckPart::Starter, read_surface_parts});
  table.push_back({"/SURF/GRSHEL", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_surface_element_groups(r, c, K::Shell4); }});
  table.push_back({"/SURF/GRSH3N", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_surface_element_groups(r, c, K::Shell3); }});
  table.push_back({"/SURF/SEG", DeckPart::Starter, read_surface_segments});
  table.push_back({"/LINE/SURF", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_line_of_surfaces(r, c, LineSource::SurfaceEdges); }});
  table.push_back({"/LINE/EDGE", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_line_of_surfaces(r, c, LineSource::SurfaceFreeEdges); }});
  table.push_back({"/SUBSET", DeckPart::Starter, read_subset});
}

}  // namespace crumple::deck
