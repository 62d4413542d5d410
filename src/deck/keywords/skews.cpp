// /SKEW/FIX, /SKEW/MOV, /SKEW/MOV2: the skew systems (docs/theory/skews.md; layouts in docs/deck-format.md,
// "Skews"). References to them are resolved in resolve_loads.cpp and resolve_output.cpp; their geometry is checked
// there too (a moving skew's nodes are known only once every /NODE is read).
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

Skew begin_skew(CardReader& reader, SkewKind kind) {
  Skew s;
  s.where = reader.card().where;
  s.user_id = card_id(reader, 2);
  s.kind = kind;
  s.title = read_title(reader);
  return s;
}

Vec3 read_direction(CardReader& reader, std::string_view what, const char* const (&names)[3], Dimension d) {
  const Line line = reader.next(what);
  Vec3 v{};
  for (std::size_t k = 0; k < 3; ++k) v[k] = line.real(1 + 20 * static_cast<int>(k), 20, names[k], d);
  return v;
}

// /SKEW/FIX/id: title; the origin Ox Oy Oz (from input version 120 on); X1 Y1 Z1, the direction of Y'; X2 Y2 Z2, a
// direction in the Y'Z' plane (eq. SK-1). Their lengths do not matter, and the origin does not move the axes.
void read_fixed_skew(CardReader& reader, DeckContext& context) {
  Skew s = begin_skew(reader, SkewKind::Fixed);
  if (context.model.input_version >= 120)
    s.origin = read_direction(reader, "Ox, Oy, Oz", {"Ox", "Oy", "Oz"}, dim::length);
  s.y_direction = read_direction(reader, "X1, Y1, Z1", {"X1", "Y1", "Z1"}, dim::none);
  s.z_direction = read_direction(reader, "X2, Y2, Z2", {"X2", "Y2", "Z2"}, dim::none);
  reader.finish();
  context.model.skews.push_back(std::move(s));
}

// /SKEW/MOV/id and /SKEW/MOV2/id: title; node_ID1 node_ID2 node_ID3 and, for /SKEW/MOV, Dir (X, Y or Z: the axis
// N1 N2 gives; blank: X) (eq. SK-2). /SKEW/MOV2 is Dir = Z.
void read_moving_skew(CardReader& reader, DeckContext& context, bool mov2) {
  Skew s = begin_skew(reader, SkewKind::Moving);
  const Line line = reader.next(mov2 ? "node_ID1, node_ID2, node_ID3" : "node_ID1, node_ID2, node_ID3, Dir");
  constexpr const char* kNames[3] = {"node_ID1", "node_ID2", "node_ID3"};
  for (int k = 0; k < 3; ++k) {
    s.node_ids[k] = line.id(1 + 10 * k, 10, kNames[k], IdKind::Node);
    if (s.node_ids[k] <= 0) line.fail(1 + 10 * k, 10, kNames[k], "a positive node id");
  }
  s.first_axis = 2;
  if (!mov2) {
    const std::string dir = line.text(31, 10);
    if (dir.empty() || dir == "X") s.first_axis = 0;
    else if (dir == "Y") s.first_axis = 1;
    else if (dir == "Z") s.first_axis = 2;
    else line.fail(31, 10, "Dir", "X, Y or Z (the axis that node_ID1 to node_ID2 gives; blank: X)");
  }
  reader.finish();
  context.model.skews.push_back(std::move(s));
}

void read_skew(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const std::string type = path.size() > 1 ? path[1] : "";
  if (type == "FIX") return read_fixed_skew(reader, context);
  if (type == "MOV") return read_moving_skew(reader, context, false);
  if (type == "MOV2") return read_moving_skew(reader, context, true);
  reader.fail("type", "FIX, MOV or MOV2 in /SKEW/type/id (other skews are not supported by Crumple)",
              in_quotes(type));
}

}  // namespace

void register_skew_keywords(KeywordTable& table) { table.push_back({"/SKEW", DeckPart::Starter, read_skew}); }

}  // namespace crumple::deck
