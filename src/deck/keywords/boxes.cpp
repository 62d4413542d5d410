// /BOX/RECTA, /BOX/CYLIN, /BOX/SPHER, /BOX/BOX: the boxes of the box groups (layouts and the reference's rules in
// docs/deck-format.md, "Boxes"). Node ids, skews and listed boxes are resolved in resolve_sets.cpp.
#include <fmt/format.h>

#include <algorithm>

#include "../context.hpp"

namespace crumple::deck {
namespace {

Box begin_box(CardReader& reader, BoxShape shape) {
  Box b;
  b.where = reader.card().where;
  b.user_id = card_id(reader, 2);
  b.shape = shape;
  b.title = read_title(reader);
  return b;
}

std::int64_t node_id(const Line& line, int column, std::string_view name) {
  const std::int64_t id = line.id(column, 10, name, IdKind::Node);
  if (id < 0) line.fail(column, 10, name, "a node id, or blank for the point by coordinates");
  return id;
}

// A point line Xp Yp Zp [L]. With the point at a node the manual does not use the line (nor does the reference): it
// may then be missing, and values in it are said to have no effect.
Vec3 read_point(CardReader& reader, DeckContext& context, char which, bool at_node) {
  const std::string x = fmt::format("Xp{}", which), y = fmt::format("Yp{}", which), z = fmt::format("Zp{}", which);
  if (at_node && reader.at_end()) return {};
  const Line line = reader.next(fmt::format("{}, {}, {}", x, y, z));
  const Vec3 p{line.real(1, 20, x, dim::length), line.real(21, 20, y, dim::length), line.real(41, 20, z, dim::length)};
  if (at_node && !(p == Vec3{}))
    context.warn(line.where(), reader.card().keyword,
                 fmt::format("{}, {}, {} have no effect: the point is at node N{}", x, y, z, which));
  return p;
}

// N1 and N2 of /BOX/RECTA and /BOX/CYLIN: both nodes, or both blank (points by coordinates). The manual takes each
// point from its own node; the reference reads both points' coordinates when one node is missing (measured), so one
// node alone is refused rather than read one way or the other.
void read_two_nodes(const Line& line, Box& b) {
  b.node_ids = {node_id(line, 1, "N1"), node_id(line, 11, "N2")};
  if ((b.node_ids[0] == 0) != (b.node_ids[1] == 0)) {
    const bool n1_missing = b.node_ids[0] == 0;
    line.fail(n1_missing ? 1 : 11, 10, n1_missing ? "N1" : "N2",
              "both N1 and N2, or neither (the reference then ignores the one given and reads both points' "
              "coordinates; the manual would take the node: the card is ambiguous)");
  }
}

void read_points(CardReader& reader, DeckContext& context, Box& b) {
  const bool at_nodes = b.node_ids[0] != 0;
  b.points = {read_point(reader, context, '1', at_nodes), read_point(reader, context, '2', at_nodes)};
  if (!at_nodes && b.points[0] == Vec3{} && b.points[1] == Vec3{})
    reader.fail("Xp1, Yp1, Zp1, Xp2, Yp2, Zp2",
                "two points, by nodes N1 N2 or by coordinates (the reference: undefined box limits)",
                "no node and every coordinate 0");
}

double read_diameter(const Line& line) {
  const double d = line.real(31, 20, "Diameter", dim::length);
  if (!(d > 0.0)) line.fail(31, 20, "Diameter", "a positive diameter");
  return d;
}

// /BOX/RECTA/box_ID: title; N1 N2 skew_ID; Xp1 Yp1 Zp1; Xp2 Yp2 Zp2.
void read_rectangle(CardReader& reader, DeckContext& context) {
  Box b = begin_box(reader, BoxShape::Rectangle);
  const Line line = reader.next("N1, N2, skew_ID");
  read_two_nodes(line, b);
  b.skew_id = line.id(21, 10, "skew_ID", IdKind::Other);
  if (b.skew_id < 0) line.fail(21, 10, "skew_ID", "a skew id, or blank for the global axes");
  read_points(reader, context, b);
  reader.finish();
  context.model.boxes.push_back(std::move(b));
}

// /BOX/CYLIN/box_ID: title; N1 N2 (columns 21-30 blank) Diameter; Xp1 Yp1 Zp1; Xp2 Yp2 Zp2 (the axis' ends).
void read_cylinder(CardReader& reader, DeckContext& context) {
  Box b = begin_box(reader, BoxShape::Cylinder);
  const Line line = reader.next("N1, N2, Diameter");
  read_two_nodes(line, b);
  b.diameter = read_diameter(line);
  read_points(reader, context, b);
  reader.finish();
  context.model.boxes.push_back(std::move(b));
}

// /BOX/SPHER/box_ID: title; N1 (columns 11-30 blank) Diameter; Xp1 Yp1 Zp1 (the centre, when N1 is blank).
void read_sphere(CardReader& reader, DeckContext& context) {
  Box b = begin_box(reader, BoxShape::Sphere);
  const Line line = reader.next("N1, Diameter");
  b.node_ids[0] = node_id(line, 1, "N1");
  b.diameter = read_diameter(line);
  b.points[0] = read_point(reader, context, '1', b.node_ids[0] != 0);
  reader.finish();
  context.model.boxes.push_back(std::move(b));
}

// /BOX/BOX/box_ID: title; box ids, 10 per line: a point is in it when it is in one of the positive boxes and in
// none of the negative ones (measured: the order does not matter).
void read_combination(CardReader& reader, DeckContext& context) {
  Box b = begin_box(reader, BoxShape::Combination);
  b.box_ids = read_id_list(reader, "box_ID", IdKind::Other);
  if (std::none_of(b.box_ids.begin(), b.box_ids.end(), [](std::int64_t id) { return id > 0; }))
    reader.fail("box_ID", "at least one positive box id (with none, the box holds nothing)",
                b.box_ids.empty() ? "no box id" : "only negative box ids");
  context.model.boxes.push_back(std::move(b));
}

void read_box(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  const auto& path = reader.card().path;
  const std::string type = path.size() > 1 ? path[1] : "";
  if (type == "RECTA") return read_rectangle(reader, context);
  if (type == "CYLIN") return read_cylinder(reader, context);
  if (type == "SPHER") return read_sphere(reader, context);
  if (type == "BOX") return read_combination(reader, context);
  reader.fail("type", "RECTA, CYLIN, SPHER or BOX in /BOX/type/box_ID", in_quotes(type));
}

}  // namespace

void register_box_keywords(KeywordTable& table) { table.push_back({"/BOX", DeckPart::Starter, read_box}); }

}  // namespace crumple::deck
