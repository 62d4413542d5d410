// /TRANSFORM/TRA, /ROT, /SCA, /SYM, /MATRIX, /POSITION: node transformations (layouts and what the reference measured
// in docs/deck-format.md, "Transformations"). They are applied in resolve_transforms.cpp, once the node groups are
// known.
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

// The first input version whose layout of the card Crumple reads: TRA, ROT, SCA, SYM from 90 on (sub_ID from 100
// on), MATRIX from 100 on. POSITION's one layout is 2021's, which the reference also read in a 2019 deck (measured):
// from 2017 on. Earlier versions have no layout of the card: refused rather than guessed.
void require_version(const CardReader& reader, const DeckContext& context, int first) {
  refuse_narrow_layout(reader);
  if (context.model.input_version < first)
    reader.fail("layout",
                fmt::format("an input version of {} or later in /BEGIN (the card has no layout before)", first),
                fmt::format("input version {}", context.model.input_version));
}

Transform begin_transform(CardReader& reader, TransformKind kind) {
  Transform t;
  t.where = reader.card().where;
  t.user_id = card_id(reader, 2);
  t.kind = kind;
  t.title = read_title(reader);
  return t;
}

// grnd_ID: the node group moved; blank when sub_ID names a submodel instead (checked once both are read, in
// resolve_transforms.cpp).
void read_group(const Line& line, Transform& t) {
  t.group_id = line.id(1, 10, "grnd_ID", IdKind::Other);
  if (t.group_id < 0) line.fail(1, 10, "grnd_ID", "a node group id (the nodes transformed)");
}

std::int64_t read_node(const Line& line, int column, std::string_view name) {
  const std::int64_t id = line.id(column, 10, name, IdKind::Node);
  if (id < 0) line.fail(column, 10, name, "a node id, or blank");
  return id;
}

// sub_ID: a //SUBMODEL block whose nodes are moved, instead of (or beside) a node group.
void read_submodel(const Line& line, int column, Transform& t) {
  t.submodel_id = line.id(column, 10, "sub_ID", IdKind::Submodel);
  if (t.submodel_id < 0) line.fail(column, 10, "sub_ID", "a submodel id, or blank");
}

// node_ID1 and node_ID2 (TRA, ROT, SYM): both, or neither (the points or the vector are then used). The manual
// calls one node alone an error.
void read_two_nodes(const Line& line, Transform& t) {
  t.node_ids[0] = read_node(line, 71, "node_ID1");
  t.node_ids[1] = read_node(line, 81, "node_ID2");
  if ((t.node_ids[0] == 0) != (t.node_ids[1] == 0)) {
    const bool first_missing = t.node_ids[0] == 0;
    line.fail(first_missing ? 71 : 81, 10, first_missing ? "node_ID1" : "node_ID2",
              "both node_ID1 and node_ID2, or neither (the manual: one node alone is an error)");
  }
}

Vec3 read_point(const Line& line, int column, std::string_view x, std::string_view y, std::string_view z, Dimension d) {
  return {line.real(column, 20, x, d), line.real(column + 20, 20, y, d), line.real(column + 40, 20, z, d)};
}

// /TRANSFORM/TRA/id: title; grnd_ID, X_translation Y_translation Z_translation, node_ID1 node_ID2, sub_ID. With the
// nodes, the translation is node_ID1 -> node_ID2; else the vector. Version 2026 adds a line skew_ID.
void read_translation(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 90);
  Transform t = begin_transform(reader, TransformKind::Translation);
  const Line line = reader.next("grnd_ID, X_translation, Y_translation, Z_translation, node_ID1, node_ID2");
  read_group(line, t);
  t.vector = read_point(line, 11, "X_translation", "Y_translation", "Z_translation", dim::length);
  read_two_nodes(line, t);
  if (context.model.input_version >= 100) read_submodel(line, 91, t);
  if (context.model.input_version >= 2026 && !reader.at_end()) {
    const Line skew = reader.next("skew_ID");
    if (skew.integer(1, 10, "skew_ID") != 0)
      skew.fail(1, 10, "skew_ID", "0 or blank (a translation written in a skew is not supported by Crumple)");
  }
  reader.finish();
  context.transforms.push_back(std::move(t));
}

// /TRANSFORM/ROT/id: title; grnd_ID, X_point_1 Y_point_1 Z_point_1, node_ID1 node_ID2, sub_ID; X_point_2 Y_point_2
// Z_point_2, Angle (degrees). The axis runs from node_ID1 to node_ID2 (the points are then not used), else from
// point 1 to point 2, through its first end; the rotation is right-handed about it.
void read_rotation(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 90);
  Transform t = begin_transform(reader, TransformKind::Rotation);
  const Line first = reader.next("grnd_ID, X_point_1, Y_point_1, Z_point_1, node_ID1, node_ID2");
  read_group(first, t);
  t.points[0] = read_point(first, 11, "X_point_1", "Y_point_1", "Z_point_1", dim::length);
  read_two_nodes(first, t);
  if (context.model.input_version >= 100) read_submodel(first, 91, t);
  const Line second = reader.next("X_point_2, Y_point_2, Z_point_2, Angle");
  t.points[1] = read_point(second, 11, "X_point_2", "Y_point_2", "Z_point_2", dim::length);
  t.angle = second.real(71, 20, "Angle", dim::none);
  reader.finish();
  context.transforms.push_back(std::move(t));
}

// /TRANSFORM/SCA/id: title; grnd_ID, Fscale_X Fscale_Y Fscale_Z, node_IDc (sub_ID from version 2026 on). A blank or
// 0 factor is 1 (the reference, measured); the centre is node_IDc, or the origin.
void read_scaling(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 90);
  Transform t = begin_transform(reader, TransformKind::Scaling);
  const Line line = reader.next("grnd_ID, Fscale_X, Fscale_Y, Fscale_Z, node_IDc");
  read_group(line, t);
  constexpr const char* kNames[3] = {"Fscale_X", "Fscale_Y", "Fscale_Z"};
  for (std::size_t k = 0; k < 3; ++k) {
    const int column = 11 + 20 * static_cast<int>(k);
    const double f = line.real(column, 20, kNames[k], dim::none);
    if (f < 0.0) line.fail(column, 20, kNames[k], "a positive scale factor (0 or blank: 1)");
    t.vector[k] = f == 0.0 ? 1.0 : f;
  }
  t.node_ids[0] = read_node(line, 71, "node_IDc");
  if (context.model.input_version >= 2026) read_submodel(line, 91, t);
  reader.finish();
  context.transforms.push_back(std::move(t));
}

// /TRANSFORM/SYM/id: title; grnd_ID, X_point_1 Y_point_1 Z_point_1, node_ID1 node_ID2 (sub_ID from version 2026 on);
// X_point_2 Y_point_2 Z_point_2. The mirror plane goes through node_ID1 normal to node_ID1 -> node_ID2, else through
// point 1 normal to point 1 -> point 2.
void read_symmetry(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 90);
  Transform t = begin_transform(reader, TransformKind::Symmetry);
  const Line first = reader.next("grnd_ID, X_point_1, Y_point_1, Z_point_1, node_ID1, node_ID2");
  read_group(first, t);
  t.points[0] = read_point(first, 11, "X_point_1", "Y_point_1", "Z_point_1", dim::length);
  read_two_nodes(first, t);
  if (context.model.input_version >= 2026) read_submodel(first, 91, t);
  if (!(t.node_ids[0] != 0 && reader.at_end())) {
    const Line second = reader.next("X_point_2, Y_point_2, Z_point_2");
    t.points[1] = read_point(second, 11, "X_point_2", "Y_point_2", "Z_point_2", dim::length);
  }
  reader.finish();
  context.transforms.push_back(std::move(t));
}

// /TRANSFORM/MATRIX/id: title; three lines (grnd_ID or blank), Mi1 Mi2 Mi3, Ti, and sub_ID on the first: x' = M x + T
// (measured). Blank entries are 0; M must be orthonormal (resolve_transforms.cpp), as the reference requires.
void read_matrix(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 100);
  Transform t = begin_transform(reader, TransformKind::Matrix);
  for (int i = 0; i < 3; ++i) {
    const std::string m = fmt::format("M{}", i + 1), shift = std::string(1, static_cast<char>('x' + i));
    const Line line = reader.next(fmt::format("{}1, {}2, {}3, T{}", m, m, m, shift));
    if (i == 0) read_group(line, t);
    t.rows[static_cast<std::size_t>(i)] = read_point(line, 11, m + "1", m + "2", m + "3", dim::none);
    t.shift[static_cast<std::size_t>(i)] = line.real(71, 20, "T" + shift, dim::length);
    if (i == 0) read_submodel(line, 91, t);
  }
  reader.finish();
  context.transforms.push_back(std::move(t));
}

// /TRANSFORM/POSITION/id: title; grnd_ID, node_ID1..node_ID6, sub_ID; six lines of points 1 to 6. The frame of
// points 1, 2, 3 is carried onto that of points 4, 5, 6 (resolve_transforms.cpp). With nodes, all six are needed.
void read_position(CardReader& reader, DeckContext& context) {
  require_version(reader, context, 2017);
  Transform t = begin_transform(reader, TransformKind::Position);
  const Line first = reader.next("grnd_ID, node_ID1, ..., node_ID6");
  read_group(first, t);
  int given = 0;
  for (int k = 0; k < 6; ++k) {
    t.node_ids[static_cast<std::size_t>(k)] = read_node(first, 11 + 10 * k, fmt::format("node_ID{}", k + 1));
    given += t.node_ids[static_cast<std::size_t>(k)] != 0 ? 1 : 0;
  }
  if (given != 0 && given != 6)
    first.fail(11, 60, "node_ID1..node_ID6", "all six nodes, or none (the points are then used)");
  read_submodel(first, 91, t);
  for (std::size_t k = 0; k < 6; ++k) {
    if (given == 6 && reader.at_end()) break;
    const std::string n = std::to_string(k + 1);
    const Line line = reader.next(fmt::format("X_point_{0}, Y_point_{0}, Z_point_{0}", n));
    t.points[k] = read_point(line, 11, "X_point_" + n, "Y_point_" + n, "Z_point_" + n, dim::length);
  }
  reader.finish();
  context.transforms.push_back(std::move(t));
}

void read_transform(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const std::string type = path.size() > 1 ? path[1] : "";
  if (type == "TRA") return read_translation(reader, context);
  if (type == "ROT") return read_rotation(reader, context);
  if (type == "SCA") return read_scaling(reader, context);
  if (type == "SYM") return read_symmetry(reader, context);
  if (type == "MATRIX") return read_matrix(reader, context);
  if (type == "POSITION") return read_position(reader, context);
  reader.fail("type",
              "TRA, ROT, SCA, SYM, MATRIX or POSITION in /TRANSFORM/type/transform_ID (other forms are "
              "not supported by Crumple)",
              in_quotes(type));
}

}  // namespace

void register_transform_keywords(KeywordTable& table) {
  table.push_back({"/TRANSFORM", DeckPart::Starter, read_transform});
}

}  // namespace crumple::deck
