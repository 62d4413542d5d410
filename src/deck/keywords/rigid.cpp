// /RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER, /RWALL/PARAL and /RBODY. Layouts, defaults and checks:
// docs/cards/loads-output-engine.md sections 2 and 3. References are resolved in resolve_loads.cpp, which also
// checks the geometry of moving walls (their point M is the wall node's position) and builds the secondary sets.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>

#include "../context.hpp"

namespace crumple::deck {
namespace {

// Three reals in columns 1-20, 21-40, 41-60 (a point, a velocity...) named `names`.
Vec3 read_vector(const Line& line, const std::array<const char*, 3>& names, Dimension d, int first_column = 1) {
  Vec3 v{};
  for (std::size_t k = 0; k < 3; ++k)
    v[k] = line.real(first_column + 20 * static_cast<int>(k), 20, names[k], d);
  return v;
}

// ---------------------------------------------------------------------------------------------------------------
// /RWALL/type/id

RigidWallShape wall_shape(const CardReader& reader) {
  const auto& path = reader.card().path;
  const std::string type = path.size() > 1 ? path[1] : "";
  if (type == "PLANE") return RigidWallShape::Plane;
  if (type == "CYL") return RigidWallShape::Cylinder;
  if (type == "SPHER") return RigidWallShape::Sphere;
  if (type == "PARAL") return RigidWallShape::Parallelogram;
  reader.fail("type", "PLANE, CYL, SPHER or PARAL in /RWALL/type/id (other rigid walls are not supported)",
              in_quotes(type));
}

// Line 2: node_ID, Slide, grnod_ID1, grnod_ID2.
void read_wall_nodes(const Line& line, RigidWall& w, DeckContext& context) {
  w.node_id = line.optional_id(1, 10, "node_ID", IdKind::Node);
  const std::int64_t slide = line.integer(11, 10, "Slide");
  if (slide < 0 || slide > 2) line.fail(11, 10, "Slide", "0 (sliding), 1 (tied) or 2 (sliding with friction)");
  w.slide = static_cast<WallSliding>(slide);
  w.node_group1_id = line.optional_id(21, 10, "grnod_ID1");
  w.node_group2_id = line.optional_id(31, 10, "grnod_ID2");
  // Blank in the 2019-2021 layouts; later versions read a penalty formulation flag there (Iform), which Crumple
  // does not have: its walls are kinematic.
  const std::string penalty = line.text(41, 10);
  if (!penalty.empty() && parse_integer(penalty) != std::optional<std::int64_t>(0))
    context.unsupported(line.error(41, 10, "Iform",
                                   default_only("the penalty rigid-wall formulation (columns 41-50) is")));
}

// Line 3: D_search, fric, Diameter, ffac, ifq.
void read_wall_contact(const CardReader& reader, const Line& line, RigidWall& w, DeckContext& context) {
  const std::string& keyword = reader.card().keyword;
  w.search_distance = line.real(1, 20, "D_search", dim::length);
  if (w.search_distance < 0.0) line.fail(1, 20, "D_search", "a non-negative search distance (0: none)");
  w.friction = line.real(21, 20, "fric", dim::none);
  if (w.friction < 0.0) line.fail(21, 20, "fric", "a non-negative friction coefficient");
  if (w.friction != 0.0 && w.slide != WallSliding::Friction)
    context.warn(line.where(), keyword, "fric ignored: friction applies only with Slide = 2");

  w.diameter = line.real(41, 20, "Diameter", dim::length);
  const bool round = w.shape == RigidWallShape::Cylinder || w.shape == RigidWallShape::Sphere;
  if (round && w.diameter <= 0.0) line.fail(41, 20, "Diameter", "a positive diameter");
  if (!round && w.diameter != 0.0)
    context.warn(line.where(), keyword, "Diameter ignored: it applies only to /RWALL/CYL and /RWALL/SPHER");

  // The flag decides what the factor is: a coefficient, a period or a frequency.
  const std::int64_t ifq = line.integer(81, 10, "ifq");
  if (ifq < 0 || ifq > 3)
    line.fail(81, 10, "ifq", "0 (no filter), 1 (coefficient), 2 (period) or 3 (frequency)");
  const Dimension d = ifq == 2 ? dim::time : ifq == 3 ? dim::rate : dim::none;
  w.filter_factor = line.real(61, 20, "ffac", d);
  if (w.filter_factor < 0.0) line.fail(61, 20, "ffac", "a non-negative filter factor");
  if (ifq == 1 && w.filter_factor > 1.0) line.fail(61, 20, "ffac", "a filter coefficient in [0, 1] (ifq = 1)");
  if (ifq == 0 && w.filter_factor != 0.0)
    context.warn(line.where(), keyword, "ffac ignored: ifq = 0 (no friction filter)");
  // Radioss turns the filter off when the factor is 0, whatever the flag; without friction nothing is filtered.
  if (ifq != 0 && w.filter_factor == 0.0)
    context.warn(line.where(), keyword, "ifq ignored: ffac = 0 (the friction filter is off)");
  else if (ifq != 0 && w.slide != WallSliding::Friction)
    context.warn(line.where(), keyword, "ifq and ffac ignored: the friction filter acts only with Slide = 2");
  w.filter_flag = w.filter_factor == 0.0 ? 0 : static_cast<int>(ifq);
  if (w.filter_flag == 0) w.filter_factor = 0.0;
}

// Line 4: the point M of a fixed wall, or the added mass and initial velocity of the node of a moving wall.
void read_wall_origin(const Line& line, RigidWall& w) {
  if (w.node_id == 0) {
    w.point = read_vector(line, {"XM", "YM", "ZM"}, dim::length);
    return;
  }
  w.mass = line.real(1, 20, "Mass", dim::mass);
  if (w.mass < 0.0) line.fail(1, 20, "Mass", "a non-negative wall mass");
  w.velocity0 = read_vector(line, {"VX_0", "VY_0", "VZ_0"}, dim::velocity, 21);
}

// A fixed wall's points are all known here: check them on the line that defines them. Moving walls are
// checked once the wall node's position is known (resolve_loads.cpp).
void check_fixed_wall(const Line& line, const RigidWall& w) {
  if (w.node_id != 0 || wall_direction(w.shape, w.point, w.point1, w.point2)) return;
  if (w.shape == RigidWallShape::Parallelogram)
    line.fail(1, 60, "X_M2, Y_M2, Z_M2",
              "a point M2 off the line M M1 (M, M1, M2 must span a parallelogram; M1 distinct from M)");
  line.fail(1, 60, "X_M1, Y_M1, Z_M1",
            w.shape == RigidWallShape::Cylinder ? "a point M1 distinct from M (M -> M1 is the cylinder axis)"
                                                : "a point M1 distinct from M (M -> M1 is the wall normal)");
}

void read_rigid_wall(CardReader& reader, DeckContext& context) {
  RigidWall w;
  w.where = reader.card().where;
  w.shape = wall_shape(reader);
  w.user_id = card_id(reader, 2);
  w.title = read_title(reader);
  read_wall_nodes(reader.next("node_ID, Slide, grnod_ID1, grnod_ID2"), w, context);
  read_wall_contact(reader, reader.next("D_search, fric, Diameter, ffac, ifq"), w, context);
  const Line origin = reader.next(w.node_id == 0 ? "XM, YM, ZM" : "Mass, VX_0, VY_0, VZ_0");
  read_wall_origin(origin, w);
  std::optional<Line> last;
  if (w.shape != RigidWallShape::Sphere) {
    last = reader.next("X_M1, Y_M1, Z_M1");
    w.point1 = read_vector(*last, {"X_M1", "Y_M1", "Z_M1"}, dim::length);
  }
  if (w.shape == RigidWallShape::Parallelogram) {
    last = reader.next("X_M2, Y_M2, Z_M2");
    w.point2 = read_vector(*last, {"X_M2", "Y_M2", "Z_M2"}, dim::length);
  }
  reader.finish();
  check_fixed_wall(last ? *last : origin, w);
  context.model.rigid_walls.push_back(std::move(w));
}

// ---------------------------------------------------------------------------------------------------------------
// /RBODY/id

// An integer flag in `column` whose blank or 0 means `zero_means`, restricted to [low, high].
int read_flag(const Line& line, int column, std::string_view name, int zero_means, int low, int high,
              std::string_view expected) {
  const std::int64_t value = line.integer(column, 10, name);
  if (value == 0) return zero_means;
  if (value < low || value > high) line.fail(column, 10, name, expected);
  return static_cast<int>(value);
}

// Line 2: RBID, sensor_ID, skew_ID, Ispher, Mass, grnod_ID, Ikrem, ICoG, surf_ID.
void read_body_definition(const Line& line, RigidBody& b) {
  b.main_node_id = line.id(1, 10, "RBID", IdKind::Node);
  if (b.main_node_id <= 0) line.fail(1, 10, "RBID", "a positive main node id");
  b.sensor_id = line.optional_id(11, 10, "sensor_ID");
  b.skew_id = line.optional_id(21, 10, "skew_ID");
  b.ispher = read_flag(line, 31, "Ispher", 2, 1, 3,
                       "1 (spherical inertia), 2 (computed, default) or 3 (from data); 0 or blank: 2");
  b.mass = line.real(41, 20, "Mass", dim::mass);
  if (b.mass < 0.0) line.fail(41, 20, "Mass", "a non-negative added mass");
  b.node_group_id = line.id(61, 10, "grnod_ID", IdKind::Other);
  if (b.node_group_id <= 0) line.fail(61, 10, "grnod_ID", "a positive node group id (the secondary nodes)");
  b.ikrem = read_flag(line, 71, "Ikrem", 0, 0, 1, "0 (secondary nodes removed from rigid walls) or 1 (kept)");
  b.icog = read_flag(line, 81, "ICoG", 1, 1, 4, "1, 2, 3 or 4 (0 or blank: 1)");
  b.surface_id = line.optional_id(91, 10, "surf_ID");
}

// The solver (solver/rigid_bodies.cpp) computes the inertia from the nodes plus the added inertia (Ispher 2), made
// spherical for Ispher 1, about the centre ICoG chooses (RB-0e): inertia from the card alone (Ispher 3) is an
// option it lacks.
void reject_body_options(const Line& line, RigidBody& b, DeckContext& context) {
  if (b.ispher == 3) {
    context.unsupported(line.error(31, 10, "Ispher", "0, 1 or 2 (inertia from the card only, Ispher = 3, is not "
                                                     "supported by Crumple)"));
    b.ispher = 2;
  }
}

void read_added_inertia(CardReader& reader, RigidBody& b) {
  const Line diagonal = reader.next("Jxx, Jyy, Jzz");
  constexpr const char* kDiagonal[3] = {"Jxx", "Jyy", "Jzz"};
  for (std::size_t k = 0; k < 3; ++k) {
    const int column = 1 + 20 * static_cast<int>(k);
    b.inertia[k] = diagonal.real(column, 20, kDiagonal[k], dim::inertia);
    if (b.inertia[k] < 0.0) diagonal.fail(column, 20, kDiagonal[k], "a non-negative added moment of inertia");
  }
  const Line products = reader.next("Jxy, Jyz, Jxz");
  constexpr const char* kProducts[3] = {"Jxy", "Jyz", "Jxz"};
  for (std::size_t k = 0; k < 3; ++k)
    b.inertia[3 + k] = products.real(1 + 20 * static_cast<int>(k), 20, kProducts[k], dim::inertia);
}

// Line 5 (Ioptoff, Iexpams, Ifail) came with Radioss 2019; older decks end after the inertia lines.
void read_body_options(CardReader& reader, RigidBody& b, DeckContext& context) {
  if (reader.at_end()) {
    context.warn(reader.card().where, reader.card().keyword,
                 "no Ioptoff/Iexpams line (pre-2019 layout): taken as 0 0");
    return;
  }
  const Line line = reader.next("Ioptoff, Iexpams, Ifail");
  b.ioptoff = static_cast<int>(line.integer(1, 10, "Ioptoff"));
  if (b.ioptoff != 0)
    context.note(line.where(), reader.card().keyword, "Ioptoff (columns 1-10)",
                 "performance hint: domain decomposition of the body, no effect on Crumple's results",
                 SkipKind::PerformanceHint);
  b.iexpams = static_cast<int>(line.integer(11, 10, "Iexpams"));
  // Iexpams extends /AMS to the whole body; Crumple's /AMS scales the whole model, every body included.
  if (b.iexpams != 0 && b.iexpams != 2)
    context.warn(line.where(), reader.card().keyword,
                 "Iexpams: /AMS scales the whole model in Crumple, this body included: no effect");
  if (line.integer(21, 10, "Ifail") != 0)
    line.fail(21, 10, "Ifail", "0 (rigid body failure is not supported by Crumple)");
}

void read_rigid_body(CardReader& reader, DeckContext& context) {
  RigidBody b;
  b.where = reader.card().where;
  b.user_id = card_id(reader, 1);
  b.title = read_title(reader);
  const Line definition = reader.next("RBID, sensor_ID, skew_ID, Ispher, Mass, grnod_ID, Ikrem, ICoG, surf_ID");
  read_body_definition(definition, b);
  reject_body_options(definition, b, context);
  read_added_inertia(reader, b);
  read_body_options(reader, b, context);
  reader.finish();
  context.model.rigid_bodies.push_back(std::move(b));
}


// ---------------------------------------------------------------------------------------------------------------
// /RBE2/id and /RBE3/id: degree-of-freedom codes are single digits, TX TY TZ in columns 14-16 and RX RY RZ in 18-20
// after a 10-column node id (Trarot). A code of six zeros, like a blank one, couples every degree of freedom, as
// the manual says (the reference reads the digits as integers, so the two cannot differ).

struct DofCodes {
  std::array<bool, 3> translation{}, rotation{};
  bool none() const {
    return std::none_of(translation.begin(), translation.end(), [](bool b) { return b; }) &&
           std::none_of(rotation.begin(), rotation.end(), [](bool b) { return b; });
  }
};

bool read_dof_digit(const Line& line, int column, std::string_view name) {
  const char code = line.raw(column, 1)[0];
  if (code == '1') return true;
  if (code != ' ' && code != '0') line.fail(column, 1, name, "0, 1 or blank (1 couples the degree of freedom)");
  return false;
}

constexpr DofCodes kAllSix{{true, true, true}, {true, true, true}};

// Trarot at `first` (TX) .. first + 6 (RZ), with the blank separators around it; blank or six zeros: `when_blank`.
DofCodes read_trarot(const Line& line, int first, std::string_view field, DofCodes when_blank = kAllSix) {
  const int lead = first - 3;  // the three blanks before the codes
  if (!line.text(lead, 3).empty())
    line.fail(lead, 3, "blank", fmt::format("blank (the {} codes are in columns {}-{} and {}-{})", field, first,
                                            first + 2, first + 4, first + 6));
  if (!line.text(first + 3, 1).empty())
    line.fail(first + 3, 1, "separator", fmt::format("blank (between the {} translation and rotation codes)", field));
  DofCodes codes;
  constexpr const char* kNames[2][3] = {{"TX", "TY", "TZ"}, {"RX", "RY", "RZ"}};
  for (int k = 0; k < 3; ++k) {
    codes.translation[static_cast<std::size_t>(k)] = read_dof_digit(line, first + k, kNames[0][k]);
    codes.rotation[static_cast<std::size_t>(k)] = read_dof_digit(line, first + 4 + k, kNames[1][k]);
  }
  return codes.none() ? when_blank : codes;
}

std::string trarot_text(const DofCodes& c) {
  std::string t;
  for (bool b : c.translation) t += b ? '1' : '0';
  t += ' ';
  for (bool b : c.rotation) t += b ? '1' : '0';
  return t;
}

// Line 2: node_ID, Trarot, skew_ID, grnod_ID, Iflag (Iflag came with input version 110; blank before).
void read_rbe2(CardReader& reader, DeckContext& context) {
  RigidElement e;
  e.where = reader.card().where;
  e.user_id = card_id(reader, 1);
  e.title = read_title(reader);
  const Line line = reader.next("node_ID, Trarot, skew_ID, grnod_ID, Iflag").as_written();
  e.main_node_id = line.id(1, 10, "node_ID", IdKind::Node);
  if (e.main_node_id <= 0) line.fail(1, 10, "node_ID", "a positive main node id");
  const DofCodes codes = read_trarot(line, 14, "Trarot");
  // Secondary nodes that follow the main node in some translations only: not in Crumple (RE-1).
  if (codes.translation != std::array<bool, 3>{true, true, true})
    context.unsupported(line.error(14, 3, "Trarot TX TY TZ",
                                   fmt::format("111 (every translation coupled; found {}: partial translation coupling "
                                               "is not supported by Crumple)", trarot_text(codes))));
  e.rotation = codes.rotation;
  e.skew_id = line.optional_id(21, 10, "skew_ID");
  const bool all_six = codes.rotation == std::array<bool, 3>{true, true, true};
  if (e.skew_id != 0 && !all_six)
    context.unsupported(line.error(21, 10, "skew_ID",
                                   "0 (a skew orients partial Trarot codes, which Crumple does not support in a skew; "
                                   "with Trarot 111 111 it changes nothing)"));
  e.node_group_id = line.id(31, 10, "grnod_ID", IdKind::Other);
  if (e.node_group_id <= 0) line.fail(31, 10, "grnod_ID", "a positive node group id (the secondary nodes)");
  e.iflag = read_flag(line, 41, "Iflag", 0, 0, 1, "0 (whole rotation of the main node, default) or 1 (its coupled "
                                                  "rotations only)");
  reader.finish();
  context.model.rigid_elements.push_back(std::move(e));
}

// Line 2: Node_IDr, Trarot_ref, N_set, I_modif, Iform (2026); then N_set lines WT_i, Trarot_Mi, skew_IDi, grnod_IDi.
void read_interpolation_set(const Line& line, InterpolationSet& set, DeckContext& context) {
  set.weight = line.real(1, 20, "WT", dim::none);
  if (set.weight < 0.0) line.fail(1, 20, "WT", "a non-negative weight (0 or blank: 1)");
  if (set.weight == 0.0) set.weight = 1.0;
  // Blank or zero codes: the reference takes 111 000 here (measured), where its manual says all six.
  const DofCodes codes = read_trarot(line, 24, "Trarot_Mi", DofCodes{{true, true, true}, {false, false, false}});
  set.translation = codes.translation, set.rotation = codes.rotation;
  set.skew_id = line.optional_id(31, 10, "skew_IDi");
  const auto uniform = [](const std::array<bool, 3>& a) { return a[0] == a[1] && a[1] == a[2]; };
  if (set.skew_id != 0 && !(uniform(set.translation) && uniform(set.rotation)))
    context.unsupported(line.error(31, 10, "skew_IDi",
                                   "0 (a skew orients partial Trarot_Mi codes, which Crumple does not support in a "
                                   "skew; with 111 or 000 in each triple it changes nothing)"));
  set.node_group_id = line.id(41, 10, "grnod_IDi", IdKind::Other);
  if (set.node_group_id <= 0) line.fail(41, 10, "grnod_IDi", "a positive node group id (the independent nodes)");
}

void read_rbe3(CardReader& reader, DeckContext& context) {
  InterpolationConstraint c;
  c.where = reader.card().where;
  c.user_id = card_id(reader, 1);
  c.title = read_title(reader);
  const Line line = reader.next("Node_IDr, Trarot_ref, N_set, I_modif, Iform").as_written();
  c.dependent_node_id = line.id(1, 10, "Node_IDr", IdKind::Node);
  if (c.dependent_node_id <= 0) line.fail(1, 10, "Node_IDr", "a positive dependent node id");
  const DofCodes codes = read_trarot(line, 14, "Trarot_ref");
  for (std::size_t d = 0; d < 3; ++d) c.reference_dofs[d] = codes.translation[d], c.reference_dofs[3 + d] = codes.rotation[d];
  const std::int64_t sets = line.integer(21, 10, "N_set");
  if (sets < 1 || sets > 1000) line.fail(21, 10, "N_set", "the number of independent node sets, 1 to 1000");
  c.i_modif = read_flag(line, 31, "I_modif", 1, 1, 3, "1 (weights made to carry each translation alike, default), "
                                                     "2 (as given) or 3 (all 1)");
  const std::int64_t iform = line.integer(41, 10, "Iform");
  if (iform != 0 && iform != 1)
    context.unsupported(line.error(41, 10, "Iform", "0 or 1 (the formulation the reference prints as IFORM 1)"));
  for (std::int64_t k = 0; k < sets; ++k) {
    InterpolationSet set;
    read_interpolation_set(reader.next("WT_i, Trarot_Mi, skew_IDi, grnod_IDi").as_written(), set, context);
    c.sets.push_back(set);
  }
  reader.finish();
  context.model.interpolation_constraints.push_back(std::move(c));
}

}  // namespace

void register_rigid_keywords(KeywordTable& table) {
  // /RWALL is registered whole so that other types get a clear "not supported" rather than "unknown keyword".
  table.push_back({"/RWALL", DeckPart::Starter, read_rigid_wall});
  table.push_back({"/RBODY", DeckPart::Starter, read_rigid_body});
  table.push_back({"/RBE2", DeckPart::Starter, read_rbe2});
  table.push_back({"/RBE3", DeckPart::Starter, read_rbe3});
}

}  // namespace crumple::deck
