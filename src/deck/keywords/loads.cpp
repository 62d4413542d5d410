// /BCS, /IMPVEL, /IMPDISP, /CLOAD, /INIVEL/TRA, /GRAV, /ADMAS. Layouts, defaults and checks:
// docs/cards/loads-output-engine.md sections 1 and 4. References (groups, functions) are resolved in
// resolve_loads.cpp; unsupported options (skew, sensor, frame) are rejected there.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

#include "../context.hpp"

namespace crumple::deck {
namespace {

constexpr double kNever = 1e30;  // Tstop blank or 0: the condition never stops


template <class Record>
Record begin_record(CardReader& reader, std::size_t id_index) {
  Record r;
  r.where = reader.card().where;
  r.user_id = card_id(reader, id_index);
  r.title = read_title(reader);
  return r;
}

// An id that must be given (> 0).
std::int64_t required_id(const Line& line, int column, std::string_view name, std::string_view what, int width = 10) {
  const std::int64_t id = line.id(column, width, name, IdKind::Other);
  if (id <= 0) line.fail(column, width, name, fmt::format("a positive {} id", what));
  return id;
}

// Columns that Radioss 2019-2021 leave blank but newer versions use for an option Crumple lacks (a frame, a
// function type): blank or 0, as Radioss 2021 reads them, or an option not supported by Crumple.
void require_blank_newer_field(const Line& line, DeckContext& context, int column, std::string_view newer_field) {
  const std::string text = line.text(column, 10);
  if (text.empty() || parse_integer(text) == std::optional<std::int64_t>(0)) return;
  context.unsupported(line.error(column, 10, newer_field,
                                 fmt::format("blank or 0 (columns {}-{} are blank in the Radioss 2021 layout; newer "
                                             "versions read {} there, which is not supported by Crumple)",
                                             column, column + 9, newer_field)));
}

// A scale factor where blank or 0 means 1 (in input units, hence the conversion factor).
double scale_or_one(const CardReader& reader, const Line& line, int column, std::string_view name, Dimension d,
                    int width = 20) {
  const double value = line.real(column, width, name, d);
  return value == 0.0 ? reader.units().factor(d) : value;
}

// The abscissa (time) scale of a function: blank or 0 means 1; negative would run the function backwards.
double time_scale(const CardReader& reader, const Line& line, int column) {
  const double value = scale_or_one(reader, line, column, "Ascale_x", dim::time);
  if (value < 0.0) line.fail(column, 20, "Ascale_x", "a positive time scale (0 or blank: 1)");
  return value;
}

// Case-insensitive, like the keyword paths: "y" cannot mean anything but Y.
std::optional<Dof> parse_dof(std::string_view text) {
  std::string upper(text);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  constexpr std::pair<std::string_view, Dof> kNames[] = {{"X", Dof::X},   {"Y", Dof::Y},   {"Z", Dof::Z},
                                                         {"XX", Dof::XX}, {"YY", Dof::YY}, {"ZZ", Dof::ZZ}};
  for (const auto& [name, dof] : kNames)
    if (upper == name) return dof;
  return std::nullopt;
}

// Dir, columns 11-20, written right-justified and read trimmed.
Dof read_direction(const Line& line, bool rotations) {
  const std::optional<Dof> dof = parse_dof(line.text(11, 10));
  if (!dof || (!rotations && is_rotation(*dof)))
    line.fail(11, 10, "Dir", rotations ? "X, Y, Z (translation) or XX, YY, ZZ (rotation)" : "X, Y or Z");
  return *dof;
}

// ---------------------------------------------------------------------------------------------------------------
// /BCS: single-digit codes, translations in columns 4-6 and rotations in 8-10.

bool read_bcs_code(const Line& line, int column, std::string_view name) {
  const char code = line.raw(column, 1)[0];
  if (code == '1') return true;
  if (code != ' ' && code != '0')
    line.fail(column, 1, name, "0, 1 or blank (1 fixes the degree of freedom; codes in columns 4-6 and 8-10)");
  return false;
}

void require_blank(const Line& line, int column, int width, std::string_view name, std::string_view expected) {
  if (!line.text(column, width).empty()) line.fail(column, width, name, expected);
}

// The /BCS line: the codes in columns 4-6 and 8-10, skew 11-20, group 21-30; in input versions 41 to 44 the codes
// in 2-4 and 6-8, skew 9-16, group 17-24 (the 8-column field " 111 111").
struct BcsColumns {
  int translations, rotations, skew, group, width;
};
constexpr BcsColumns kBcsColumns{4, 8, 11, 21, 10}, kNarrowBcsColumns{2, 6, 9, 17, 8};

void read_bcs(CardReader& reader, DeckContext& context) {
  auto bc = begin_record<BoundaryCondition>(reader, 1);
  const Line line = reader.next("Tra rot, skew_ID, grnod_ID").as_written();
  const BcsColumns c = reader.narrow() ? kNarrowBcsColumns : kBcsColumns;
  require_blank(line, 1, c.translations - 1, "leading blank",
                fmt::format("blank (the translation codes TX TY TZ are in columns {}-{})", c.translations,
                            c.translations + 2));
  require_blank(line, c.translations + 3, 1, "separator",
                fmt::format("blank (between translation codes {}-{} and rotation codes {}-{})", c.translations,
                            c.translations + 2, c.rotations, c.rotations + 2));
  constexpr const char* kNames[2][3] = {{"TX", "TY", "TZ"}, {"RX", "RY", "RZ"}};
  for (int k = 0; k < 3; ++k) {
    bc.fixed_translation[static_cast<std::size_t>(k)] = read_bcs_code(line, c.translations + k, kNames[0][k]);
    bc.fixed_rotation[static_cast<std::size_t>(k)] = read_bcs_code(line, c.rotations + k, kNames[1][k]);
  }
  bc.skew_id = line.optional_id(c.skew, c.width, "skew_ID");
  bc.node_group_id = required_id(line, c.group, "grnod_ID", "node group", c.width);
  reader.finish();
  const auto fixed = [](const std::array<bool, 3>& a) { return std::count(a.begin(), a.end(), true); };
  if (fixed(bc.fixed_translation) + fixed(bc.fixed_rotation) == 0)
    context.warn(line.where(), reader.card().keyword, "no degree of freedom fixed (all codes blank or 0)");
  context.model.boundary_conditions.push_back(std::move(bc));
}

// /ALE/BCS fixes the ALE grid's motion of ALE nodes. Crumple has no ALE material (each is refused), so the card acts
// on nothing: a named warning, as the reference runs a Lagrangian model with it (measured by a helper on the QA deck
// LOIS/LOI2/BESH: its result with the cards and without them is the same).
void read_ale_bcs(CardReader& reader, DeckContext& context) {
  const SourceLocation where = reader.card().where;
  card_id(reader, 2);
  read_title(reader);
  const Line line = reader.next("Tra rot, skew_ID, grnod_ID");
  line.text(1, 10);  // the grid's codes
  line.optional_id(11, 10, "skew_ID"), line.optional_id(21, 10, "grnod_ID");
  reader.finish();
  context.note(where, reader.card().keyword, "grnod_ID",
               "fixes the ALE grid of ALE parts only; the model has none (Crumple has no ALE material), so it acts on "
               "nothing, as in the reference",
               SkipKind::Unsupported);
}

// ---------------------------------------------------------------------------------------------------------------
// /IMPVEL, /IMPDISP, /CLOAD

Dimension ordinate_dimension(ImposedKind kind, Dof dof) {
  const bool rotation = is_rotation(dof);
  switch (kind) {
    case ImposedKind::Velocity: return rotation ? dim::angular_velocity : dim::velocity;
    case ImposedKind::Displacement: return rotation ? dim::none : dim::length;
    case ImposedKind::Force: return rotation ? dim::moment : dim::force;
  }
  return dim::none;
}

void read_imposed_motion(CardReader& reader, DeckContext& context, ImposedKind kind) {
  auto im = begin_record<ImposedMotion>(reader, 1);
  im.kind = kind;
  const Line line = reader.next("funct_IDT, Dir, skew_ID, sensor_ID, grnod_ID, frame_ID, Icoor");
  im.function_id = required_id(line, 1, "funct_IDT", "function");
  im.dof = read_direction(line, true);
  im.skew_id = line.optional_id(21, 10, "skew_ID");
  im.sensor_id = line.optional_id(31, 10, "sensor_ID");
  // grnod_ID 0 names no node: the card acts on nothing, as the reference runs it (measured: a deck with such an
  // /IMPVEL and /IMPDISP gives the same energies as without them; generated decks leave such cards).
  im.node_group_id = line.optional_id(41, 10, "grnod_ID");
  if (kind == ImposedKind::Velocity) {
    im.frame_id = line.optional_id(51, 10, "frame_ID");
    if (im.frame_id != 0 && im.skew_id != 0)
      line.fail(51, 10, "frame_ID", "0 when skew_ID is given (a skew and a frame exclude each other)");
  } else {
    require_blank_newer_field(line, context, 51, "frame_ID");
  }
  im.icoor = static_cast<int>(line.integer(61, 10, "Icoor"));
  if (im.icoor != 0 && im.icoor != 1) line.fail(61, 10, "Icoor", "0 (Cartesian) or 1 (cylindrical)");

  if (reader.narrow()) {  // input versions 41 to 44: Fscale_Y 1-16, Tstart 17-32, Tstop 33-48, no Ascale_x
    const Line scales = reader.next("Fscale_Y, Tstart, Tstop").as_written();
    im.scale_x = reader.units().factor(dim::time);
    im.scale_y = scale_or_one(reader, scales, 1, "Fscale_Y", ordinate_dimension(kind, im.dof), 16);
    im.t_start = scales.real(17, 16, "Tstart", dim::time);
    const double stop = scales.real(33, 16, "Tstop", dim::time);
    im.t_stop = stop == 0.0 ? kNever : stop;
    if (im.t_stop < im.t_start) scales.fail(33, 16, "Tstop", "a stop time not before Tstart (0 or blank: never)");
  } else {
    const Line scales = reader.next("Ascale_x, Fscale_Y, Tstart, Tstop");
    im.scale_x = time_scale(reader, scales, 1);
    im.scale_y = scale_or_one(reader, scales, 21, "Fscale_Y", ordinate_dimension(kind, im.dof));
    im.t_start = scales.real(41, 20, "Tstart", dim::time);
    const double stop = scales.real(61, 20, "Tstop", dim::time);
    im.t_stop = stop == 0.0 ? kNever : stop;
    if (im.t_stop < im.t_start) scales.fail(61, 20, "Tstop", "a stop time not before Tstart (0 or blank: never)");
  }
  reader.finish();
  if (im.node_group_id == 0) {
    context.note(line.where(), reader.card().keyword, "grnod_ID", "0: the card acts on no node, as in the reference",
                 SkipKind::Unsupported);
    return;
  }
  context.model.imposed.push_back(std::move(im));
}

// /IMPDISP/FGEO/id[/unit_ID]: title; fct_ID, part_ID, (blank), sens_ID; Ascale, (blank), Tstart, Tstop; then one line
// per node: node_ID, X, Y, Z (its final position). part_ID names a spring part the reference builds between the nodes
// and their final positions, which Crumple does not have.
void read_final_geometry(CardReader& reader, DeckContext& context) {
  auto g = begin_record<FinalGeometry>(reader, 2);
  const Line line = reader.next("fct_ID, part_ID, sens_ID");
  g.function_id = required_id(line, 1, "fct_ID", "function");
  if (line.id(11, 10, "part_ID", IdKind::Part) != 0)
    context.unsupported(line.error(11, 10, "part_ID", default_only("a spring part between the nodes and their "
                                                                   "final positions is")));
  if (line.integer(21, 10, "(unused)") != 0) line.fail(21, 10, "(unused)", "blank or 0 in columns 21-30");
  g.sensor_id = line.optional_id(31, 10, "sens_ID");
  const Line times = reader.next("Ascale, Tstart, Tstop");
  g.scale_x = scale_or_one(reader, times, 1, "Ascale", dim::time);
  if (g.scale_x < 0.0) times.fail(1, 20, "Ascale", "a positive time scale (0 or blank: 1)");
  if (times.real(21, 20, "(unused)", dim::none) != 0.0) times.fail(21, 20, "(unused)", "blank or 0 in columns 21-40");
  g.t_start = times.real(41, 20, "Tstart", dim::time);
  const double stop = times.real(61, 20, "Tstop", dim::time);
  g.t_stop = stop == 0.0 ? kNever : stop;
  if (g.t_stop < g.t_start) times.fail(61, 20, "Tstop", "a stop time not before Tstart (0 or blank: never)");
  while (auto node = reader.next_nonblank()) {
    const std::int64_t id = node->id(1, 10, "node_ID", IdKind::Node);
    if (id <= 0) node->fail(1, 10, "node_ID", "a positive node id");
    g.node_ids.push_back(id);
    g.node_where.push_back(node->where());
    g.final_positions.push_back({node->real(11, 20, "X", dim::length), node->real(31, 20, "Y", dim::length),
                                 node->real(51, 20, "Z", dim::length)});
  }
  if (g.node_ids.empty()) reader.fail("node_ID", "at least one node and its final position", "none");
  context.model.final_geometries.push_back(std::move(g));
}

void read_concentrated_load(CardReader& reader, DeckContext& context) {
  auto load = begin_record<ImposedMotion>(reader, 1);
  load.kind = ImposedKind::Force;
  const Line line = reader.next("funct_IDT, Dir, skew_ID, sensor_ID, grnod_ID, Ascale_x, Fscale_Y");
  // Radioss gives fct_IDT = 0 no constant-load meaning: a missing function is an error, not a guess.
  load.function_id = required_id(line, 1, "funct_IDT", "function");
  load.dof = read_direction(line, true);
  load.skew_id = line.optional_id(21, 10, "skew_ID");
  load.sensor_id = line.optional_id(31, 10, "sensor_ID");
  if (reader.narrow()) {  // input versions 41 to 44: Fscale_Y 33-48, grnod_ID 49-56, no Ascale_x
    const Line w = line.as_written();
    load.scale_y = scale_or_one(reader, w, 33, "Fscale_Y", ordinate_dimension(load.kind, load.dof), 16);
    load.node_group_id = required_id(w, 49, "grnod_ID", "node group", 8);
    load.scale_x = reader.units().factor(dim::time);
    reader.finish();
    context.model.imposed.push_back(std::move(load));
    return;
  }
  load.node_group_id = required_id(line, 41, "grnod_ID", "node group");
  require_blank_newer_field(line, context, 51, "Itypfun");
  load.scale_x = time_scale(reader, line, 61);
  load.scale_y = scale_or_one(reader, line, 81, "Fscale_Y", ordinate_dimension(load.kind, load.dof));
  reader.finish();
  context.model.imposed.push_back(std::move(load));
}

// ---------------------------------------------------------------------------------------------------------------
// /INIVEL/TRA, /GRAV, /ADMAS

// /INIVEL/TRA, /INIVEL/T+G (translation and grid: the same on Crumple's Lagrangian nodes) and /INIVEL/ROT (the
// nodes' angular velocity), in the global axes or a skew's. From input version 2025 a second line may give Tstart
// and sens_ID: Crumple starts every velocity at time 0, so they must be blank or 0.
void read_initial_velocity(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const std::string type = path.size() < 2 ? "" : path[1];
  if (type != "TRA" && type != "T+G" && type != "ROT")
    reader.fail("type", "TRA, T+G or ROT in /INIVEL/type/id (the other initial velocity types, AXIS, GRID, FVM, "
                "are not supported by Crumple)", in_quotes(type));
  auto iv = begin_record<InitialVelocity>(reader, 2);
  iv.rotation = type == "ROT";
  const Line line = reader.next(iv.rotation ? "Wx, Wy, Wz, grnod_ID, Skew_ID" : "Vx, Vy, Vz, grnod_ID, Skew_ID");
  constexpr const char* kNames[2][3] = {{"Vx", "Vy", "Vz"}, {"Wx", "Wy", "Wz"}};
  for (int k = 0; k < 3; ++k)
    iv.velocity[static_cast<std::size_t>(k)] = line.real(1 + 20 * k, 20, kNames[iv.rotation ? 1 : 0][k],
                                                         iv.rotation ? dim::angular_velocity : dim::velocity);
  iv.node_group_id = required_id(line, 61, "grnod_ID", "node group");
  iv.skew_id = line.optional_id(71, 10, "Skew_ID");
  if (reader.has_data()) {
    const Line start = reader.next("Tstart, sens_ID");
    if (start.real(1, 20, "Tstart", dim::time) != 0.0)
      context.unsupported(start.error(1, 20, "Tstart", default_only("an initial velocity set at a later time is")));
    if (start.integer(21, 10, "sens_ID") != 0)
      context.unsupported(start.error(21, 10, "sens_ID", default_only("sensors are")));
  }
  reader.finish();
  context.model.initial_velocities.push_back(std::move(iv));
}

void read_gravity(CardReader& reader, DeckContext& context) {
  auto g = begin_record<Gravity>(reader, 1);
  const Line line = reader.next("funct_IDT, Dir, skew_ID, sensor_ID, grnod_ID, Ascale_x, Fscale_Y");
  g.function_id = line.optional_id(1, 10, "funct_IDT");  // 0: constant acceleration
  g.dof = line.text(11, 10).empty() ? Dof::Z : read_direction(line, false);
  g.skew_id = line.optional_id(21, 10, "skew_ID");
  g.sensor_id = line.optional_id(31, 10, "sensor_ID");
  // Input versions 41 to 44: Fscale_Y 33-48, grnod_ID 49-56, no Ascale_x.
  const bool narrow = reader.narrow();
  const Line w = line.as_written();
  const int scale_column = narrow ? 33 : 81, scale_width = narrow ? 16 : 20;
  if (narrow) {
    g.node_group_id = w.optional_id(49, 8, "grnod_ID");  // 0: every node
    g.scale_x = reader.units().factor(dim::time);
  } else {
    g.node_group_id = line.optional_id(41, 10, "grnod_ID");  // 0: every node
    require_blank_newer_field(line, context, 51, "Itypfun");
    g.scale_x = time_scale(reader, line, 61);
  }
  g.scale_y = scale_or_one(reader, w, scale_column, "Fscale_Y", dim::acceleration, scale_width);
  // Radioss reads a blank scale as 1: an acceleration of 1 in input units, rarely what was meant.
  if (w.real(scale_column, scale_width, "Fscale_Y", dim::none) == 0.0)
    context.warn(line.where(), reader.card().keyword,
                 "Fscale_Y blank or 0: acceleration 1 in input units (the Radioss default)");
  reader.finish();
  context.model.gravity.push_back(std::move(g));
}

// /ADMAS/type/id: the type comes first in the path. Types 2-7 (surface, part and per-item lists) have other
// layouts and are not supported.
void read_added_mass(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const std::int64_t type = reader.path_id(1, "type", true);
  if (path.size() < 3 || path[2].empty())
    reader.fail("admas_ID", "/ADMAS/type/id (the type comes first; a single number is ambiguous)",
                in_quotes(reader.card().keyword));
  if (type > 7) reader.fail("type", "an /ADMAS type: 0 (mass per node) or 1 (total mass)", in_quotes(path[1]));
  if (type > 1)
    reader.fail("type",
                "0 (mass per node) or 1 (total mass shared by the nodes); type 2-7 are not supported by Crumple",
                in_quotes(path[1]));
  auto a = begin_record<AddedMass>(reader, 2);
  a.type = static_cast<int>(type);
  const Line line = reader.next("Mass, grnod_ID");
  a.mass = line.real(1, 20, "Mass", dim::mass);
  if (a.mass < 0.0) line.fail(1, 20, "Mass", "a non-negative added mass");
  a.node_group_id = required_id(line, 21, "grnod_ID", "node group");
  reader.finish();
  context.model.added_masses.push_back(std::move(a));
}

}  // namespace

void register_load_keywords(KeywordTable& table) {
  table.push_back({"/BCS", DeckPart::Starter, read_bcs});
  table.push_back({"/ALE/BCS", DeckPart::Starter, read_ale_bcs});
  table.push_back({"/IMPVEL", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_imposed_motion(r, c, ImposedKind::Velocity); }});
  table.push_back({"/IMPDISP", DeckPart::Starter,
                   [](CardReader& r, DeckContext& c) { read_imposed_motion(r, c, ImposedKind::Displacement); }});
  table.push_back({"/IMPDISP/FGEO", DeckPart::Starter, read_final_geometry});
  table.push_back({"/CLOAD", DeckPart::Starter, read_concentrated_load});
  // /INIVEL is registered whole so that other types get a clear "not supported" rather than "unknown keyword".
  table.push_back({"/INIVEL", DeckPart::Starter, read_initial_velocity});
  table.push_back({"/GRAV", DeckPart::Starter, read_gravity});
  table.push_back({"/ADMAS", DeckPart::Starter, read_added_mass});
}

}  // namespace crumple::deck
