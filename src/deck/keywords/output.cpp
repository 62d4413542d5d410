// Output requests: time histories (/TH/...), cut sections (/SECT) and accelerometers (/ACCEL). Layouts:
// docs/cards/loads-output-engine.md §6. Object ids and groups are resolved in resolve_output.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <span>

#include "../context.hpp"
#include "crumple/model/history_variables.hpp"

namespace crumple::deck {
namespace {

// How a /TH card lists its objects.
enum class ObjectLines : std::uint8_t {
  Ids,          // up to 10 ids of 10 columns per line
  IdSkewName,   // one object per line: id 1-10, skew 11-20 (nodes only), name 21-100
  IdBlankName,  // one object per line: id 1-10, columns 11-20 blank, name 21-100
};

struct HistoryCard {
  HistoryObject object;
  ObjectLines lines;
};

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}


// Radioss ignores columns past 100; text there is almost always a shifted field, so it is an error here.
void check_width(const Line& line, std::string_view name) {
  const std::string& s = line.content();
  if (s.size() > 100 && !trim(std::string_view(s).substr(100)).empty())
    line.fail(101, static_cast<int>(s.size()) - 100, name, "nothing after column 100");
}

// `/TH/<type>/id` or `/SECT/id`: the id at path part `index`, nothing after it except (for /SECT) a unit id.
std::int64_t card_id(CardReader& reader, std::size_t index, bool unit_allowed) {
  const Card& card = reader.card();
  if (index < card.path.size() && !card.path[index].empty() && !parse_integer(card.path[index]))
    reader.fail("id",
                fmt::format("a numeric id (the /{}/{} form is not supported by Crumple)", card.path[0],
                            card.path[index]),
                in_quotes(card.path[index]));
  const std::int64_t id = object_id(reader, index);
  if (reader.narrow()) {  // versions 41 to 44: the title follows the id
    reader.title_after(index + 1);
    return id;
  }
  std::size_t end = index + 1;
  if (unit_allowed) {
    read_unit_id(reader, end);
    ++end;
  }
  if (card.path.size() > end) reader.fail("keyword", "nothing after the id", in_quotes(card.path[end]));
  return id;
}

// A variable line starts with a name, an object line with an id: the first non-blank 10-column field decides.
bool is_variable_line(const Line& line) {
  for (int column = 1; column <= 91; column += 10) {
    const std::string field = line.text(column, 10);
    if (!field.empty()) return !parse_integer(field).has_value();
  }
  return false;
}


void read_variables(const Line& line, TimeHistoryRequest& th) {
  check_width(line, "var_ID");
  for (int column = 1; column <= 91; column += 10) {
    const std::string name = upper(line.text(column, 10));
    if (name.empty()) continue;
    if (std::find(th.variables.begin(), th.variables.end(), name) == th.variables.end()) th.variables.push_back(name);
  }
}

// What NAME.h5 does not record of a /TH card (docs/output-format.md, "/history/th"): the variables Crumple does
// not compute and the names that are no variable of the kind in the manual. Output Crumple does not write is a
// named warning, never an error (it changes no result).
void note_what_is_written(const TimeHistoryRequest& th, DeckContext& context) {
  const HistorySelection selection = select_history_variables(th.object, th.variables);
  std::vector<std::string_view> missing;
  std::size_t written = 0;
  for (const HistoryVariable* v : selection.variables) {
    if (v->written) ++written;
    else missing.push_back(v->name);
  }
  if (missing.empty() && selection.unknown.empty()) return;
  std::vector<std::string> parts;
  if (written == 0) parts.push_back("time history not written by Crumple");
  if (!missing.empty())
    parts.push_back(fmt::format("variables {} not written{}", fmt::join(missing, " "),
                                written > 0 ? " (NAME.h5 records the others)" : ""));
  if (!selection.unknown.empty())
    parts.push_back(fmt::format("{} not among the variables of {} in the manual that Crumple computes",
                                fmt::join(selection.unknown, " "), th.keyword));
  context.note(th.where, th.keyword, "", fmt::format("output-only: {}", fmt::join(parts, "; ")),
               SkipKind::OutputOnly);
}

// Adds one object (with its name for the one-per-line kinds); an object listed twice would record the same curve
// twice, so it is kept once with a warning.
void add_object(TimeHistoryRequest& th, const Line& line, std::int64_t id, std::optional<std::string> name,
                DeckContext& context) {
  if (std::find(th.object_ids.begin(), th.object_ids.end(), id) != th.object_ids.end()) {
    context.warn(line.where(), th.keyword, fmt::format("object {} listed twice; recorded once", id));
    return;
  }
  th.object_ids.push_back(id);
  if (name) th.object_names.push_back(std::move(*name));
}

// The kind of id a /TH card lists: nodes, elements and parts by their own kinds, every other object by off_def.
IdKind object_id_kind(HistoryObject object) {
  switch (object) {
    case HistoryObject::Node: return IdKind::Node;
    case HistoryObject::Part: return IdKind::Part;
    case HistoryObject::Shell:
    case HistoryObject::Sh3n:
    case HistoryObject::Brick:
    case HistoryObject::Spring:
    case HistoryObject::Truss:
    case HistoryObject::Beam: return IdKind::Element;
    default: return IdKind::Other;
  }
}

void read_object_line(const Line& line, const HistoryCard& kind, TimeHistoryRequest& th, DeckContext& context) {
  if (kind.lines == ObjectLines::Ids) {
    check_width(line, "Obj_ID");
    for (int column = 1; column <= 91; column += 10) {
      const std::int64_t id = line.id(column, 10, "Obj_ID", object_id_kind(th.object));
      if (id < 0) line.fail(column, 10, "Obj_ID", "a positive object id");
      if (id != 0) add_object(th, line, id, std::nullopt, context);
    }
    return;
  }
  check_width(line, "name");
  const std::int64_t id = line.id(1, 10, "Obj_ID", object_id_kind(th.object));
  if (id <= 0) line.fail(1, 10, "Obj_ID", "a positive object id (one object per line)");
  std::int64_t skew = 0;
  if (kind.lines == ObjectLines::IdSkewName) {
    skew = line.id(11, 10, "skew_ID", IdKind::Other);
    if (skew < 0) line.fail(11, 10, "skew_ID", "a non-negative skew id (0 or blank: the global axes)");
    // A node's vectors can be written in a skew (SK-4); an element's stresses in a skew are not.
    if (skew != 0 && th.object != HistoryObject::Node)
      line.fail(11, 10, "skew_ID",
                "0 or blank (element results in a skew or frame system are not supported by Crumple)");
  } else if (!line.text(11, 10).empty()) {
    line.fail(11, 10, "(blank)", "blank columns 11-20 (the name starts at column 21)");
  }
  const auto listed = std::find(th.object_ids.begin(), th.object_ids.end(), id);
  if (listed != th.object_ids.end() && th.object == HistoryObject::Node &&
      th.object_skew_ids[static_cast<std::size_t>(listed - th.object_ids.begin())] != skew)
    line.fail(11, 10, "skew_ID", "the skew the node has on its first line in this card (one curve per node and "
                                 "card; a second skew takes a second /TH/NODE)");
  const std::size_t before = th.object_ids.size();
  add_object(th, line, id, line.text(21, 80), context);
  if (th.object == HistoryObject::Node && th.object_ids.size() > before) th.object_skew_ids.push_back(skew);
}

void read_history(CardReader& reader, DeckContext& context, const HistoryCard& kind) {
  TimeHistoryRequest th;
  th.where = reader.card().where;
  th.keyword = reader.card().keyword;
  th.object = kind.object;
  th.user_id = card_id(reader, 2, false);
  th.title = read_title(reader);
  // Blank lines carry nothing here (no names, no ids), so they are skipped like comments.
  std::optional<Line> line = reader.next_nonblank();
  for (; line && is_variable_line(*line); line = reader.next_nonblank()) read_variables(*line, th);
  if (th.variables.empty()) {
    if (line) line->fail(1, 10, "var_ID1", "at least one variable line before the objects (e.g. DEF)");
    reader.fail("var_ID1", "a line of variable names (e.g. DEF) after the title", "end of card");
  }
  for (; line; line = reader.next_nonblank()) read_object_line(*line, kind, th, context);
  if (th.object_ids.empty()) context.warn(th.where, th.keyword, "no objects listed: the group records nothing");
  note_what_is_written(th, context);
  context.model.histories.push_back(std::move(th));
}

// ---------------------------------------------------------------------------------------------------------------
// /SECT/sect_ID[/unit_ID]

void read_section_frame(const Line& line, Section& s) {
  for (int k = 0; k < 3; ++k) {
    const std::string name = fmt::format("node_ID{}", k + 1);
    s.node_ids[k] = line.id(1 + 10 * k, 10, name, IdKind::Node);
    if (s.node_ids[k] < 0) line.fail(1 + 10 * k, 10, name, "a node id or blank");
  }
  s.node_group_id = line.id(31, 10, "grnod_ID", IdKind::Other);
  if (s.node_group_id < 0) line.fail(31, 10, "grnod_ID", "a node group id or blank");
  s.isave = static_cast<int>(line.integer(41, 10, "ISAVE"));
  if (s.isave != 0) line.fail(41, 10, "ISAVE", "0 (saving or imposing cut motions is not supported by Crumple)");
  s.frame_id = line.id(51, 10, "frame_ID", IdKind::Other);
  if (s.frame_id != 0) line.fail(51, 10, "frame_ID", "0 or blank (moving frames are not supported by Crumple)");
  s.dt = line.real(61, 20, "Dt", dim::time);
  s.alpha = line.real(81, 20, "alpha", dim::none);
  if (s.dt < 0.0) line.fail(61, 20, "Dt", "a non-negative sampling interval");
  if (s.alpha < 0.0) line.fail(81, 20, "alpha", "a non-negative filter coefficient");
}

// Element groups: 4-node shells (/GRSHEL), 3-node shells (/GRSH3N) and bricks (/GRBRIC); Crumple has no 2-D
// quads, trusses, beams or springs.
void read_section_groups(const Line& line, Section& s) {
  struct Field { int column; std::string_view name; std::string_view missing; };
  constexpr std::array<Field, 4> unsupported{{
      {11, "grquad_ID", "2-D quad groups are"},
      {31, "grtrus_ID", "truss groups are"},
      {41, "grbeam_ID", "beam groups are"},
      {51, "grsprg_ID", "spring groups are"},
  }};
  for (const Field& f : unsupported) {
    const std::int64_t id = line.integer(f.column, 10, f.name);
    if (id != 0) line.fail(f.column, 10, f.name, fmt::format("0 or blank ({} not supported by Crumple)", f.missing));
  }
  s.brick_group_id = line.id(1, 10, "grbric_ID", IdKind::Other);
  if (s.brick_group_id < 0) line.fail(1, 10, "grbric_ID", "a brick group id or blank");
  s.shell_group_id = line.id(21, 10, "grshel_ID", IdKind::Other);
  if (s.shell_group_id < 0) line.fail(21, 10, "grshel_ID", "a shell group id or blank");
  s.sh3n_group_id = line.id(61, 10, "grtria_ID", IdKind::Other);
  if (s.sh3n_group_id < 0) line.fail(61, 10, "grtria_ID", "a 3-node shell group id or blank");
  s.ninter = static_cast<int>(line.integer(71, 10, "Ninter"));
  if (s.ninter < 0 || s.ninter > 10) line.fail(71, 10, "Ninter", "a number of interfaces from 0 to 10");
  if (line.integer(81, 10, "(unused)") != 0)
    line.fail(81, 10, "(unused)", "blank or 0 in columns 81-90 (Iframe is in columns 91-100)");
  s.iframe = static_cast<int>(line.integer(91, 10, "Iframe"));
  if (!((s.iframe >= 0 && s.iframe <= 3) || (s.iframe >= 10 && s.iframe <= 13)))
    line.fail(91, 10, "Iframe", "0, 1, 2, 3 (local frame) or 10, 11, 12, 13 (global frame)");
}

void read_section_interfaces(const Line& line, Section& s) {
  for (int k = 0; k < 10; ++k) {
    const std::string name = fmt::format("int_ID{}", k + 1);
    const std::int64_t id = line.id(1 + 10 * k, 10, name, IdKind::Other);
    if (k < s.ninter && id <= 0)
      line.fail(1 + 10 * k, 10, name, fmt::format("a positive interface id (Ninter = {})", s.ninter));
    if (k >= s.ninter && id != 0)
      line.fail(1 + 10 * k, 10, name, fmt::format("blank: only Ninter = {} ids", s.ninter));
    if (id > 0) s.interface_ids.push_back(id);
  }
}

void read_section(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Section s;
  s.where = reader.card().where;
  s.user_id = card_id(reader, 1, true);
  s.title = read_title(reader);
  read_section_frame(reader.next("node_ID1, node_ID2, node_ID3, grnod_ID, ISAVE, frame_ID, Dt, alpha"), s);
  // The file-name line is always there, blank when ISAVE = 0 (QA decks): it is consumed as a line of its own.
  s.file_name = reader.next("file_name (may be blank)").text(1, 100);
  read_section_groups(
      reader.next("grbric_ID, grshel_ID, grtrus_ID, grbeam_ID, grsprg_ID, grtria_ID, Ninter, Iframe"), s);
  if (s.ninter > 0) read_section_interfaces(reader.next(fmt::format("int_ID1..int_ID{}", s.ninter)), s);
  reader.finish();
  const std::string& kw = reader.card().keyword;
  if (s.node_group_id == 0) context.warn(s.where, kw, "no node group (grnod_ID): the cut has no nodes");
  if (s.shell_group_id == 0 && s.sh3n_group_id == 0 && s.brick_group_id == 0 && s.ninter == 0)
    context.warn(s.where, kw, "no element group and no interface: the section records nothing");
  context.model.sections.push_back(std::move(s));
}

// ---------------------------------------------------------------------------------------------------------------
// /ACCEL/accel_ID[/unit_ID]: node_ID 1-10, skew_ID 11-20, Fcut 31-50 (docs/cards/loads-output-engine.md §6.3)

void read_accelerometer(CardReader& reader, DeckContext& context) {
  Accelerometer a;
  a.where = reader.card().where;
  a.user_id = card_id(reader, 1, true);
  a.title = read_title(reader);
  const Line line = reader.next("node_ID, skew_ID, Fcut");
  a.node_id = line.id(1, 10, "node_ID", IdKind::Node);
  if (a.node_id <= 0) line.fail(1, 10, "node_ID", "a positive node id");
  a.skew_id = line.id(11, 10, "skew_ID", IdKind::Other);
  if (a.skew_id < 0) line.fail(11, 10, "skew_ID", "a non-negative skew id (0 or blank: the global axes)");
  // Input versions 41 to 44 put Fcut in columns 27-42, after a 10-column gap.
  const Line cut = reader.narrow() ? line.as_written() : line;
  const int column = reader.narrow() ? 27 : 31, width = reader.narrow() ? 16 : 20;
  a.cutoff = cut.real(column, width, "Fcut", dim::rate);
  if (a.cutoff < 0.0) cut.fail(column, width, "Fcut", "a non-negative cutoff frequency (0 or blank: no filter)");
  reader.finish();
  context.model.accelerometers.push_back(std::move(a));
}

}  // namespace

void register_output_keywords(KeywordTable& table) {
  auto history = [](HistoryObject object, ObjectLines lines) {
    return [card = HistoryCard{object, lines}](CardReader& r, DeckContext& c) { read_history(r, c, card); };
  };
  using H = HistoryObject;
  using L = ObjectLines;
  table.push_back({"/TH/NODE", DeckPart::Starter, history(H::Node, L::IdSkewName)});
  table.push_back({"/TH/PART", DeckPart::Starter, history(H::Part, L::Ids)});
  table.push_back({"/TH/SUBS", DeckPart::Starter, history(H::Subset, L::Ids)});
  table.push_back({"/TH/RWALL", DeckPart::Starter, history(H::RigidWall, L::Ids)});
  table.push_back({"/TH/INTER", DeckPart::Starter, history(H::Interface, L::Ids)});
  // /TH/SHELL is not in the manual but HyperCrash writes it (QA box_crush) and Radioss reads it as /TH/SHEL.
  table.push_back({"/TH/SHEL", DeckPart::Starter, history(H::Shell, L::IdSkewName)});
  table.push_back({"/TH/SHELL", DeckPart::Starter, history(H::Shell, L::IdSkewName)});
  table.push_back({"/TH/SH3N", DeckPart::Starter, history(H::Sh3n, L::IdSkewName)});
  table.push_back({"/TH/BRIC", DeckPart::Starter, history(H::Brick, L::IdBlankName)});
  table.push_back({"/TH/SPRING", DeckPart::Starter, history(H::Spring, L::IdBlankName)});
  table.push_back({"/TH/TRUSS", DeckPart::Starter, history(H::Truss, L::IdBlankName)});
  table.push_back({"/TH/BEAM", DeckPart::Starter, history(H::Beam, L::IdBlankName)});
  table.push_back({"/TH/SECTIO", DeckPart::Starter, history(H::Section, L::Ids)});
  table.push_back({"/TH/RBODY", DeckPart::Starter, history(H::RigidBody, L::Ids)});
  table.push_back({"/TH/ACCEL", DeckPart::Starter, history(H::Accelerometer, L::Ids)});
  table.push_back({"/SECT", DeckPart::Starter, read_section});
  table.push_back({"/ACCEL", DeckPart::Starter, read_accelerometer});
}

}  // namespace crumple::deck
