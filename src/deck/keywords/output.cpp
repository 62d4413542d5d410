// Output requests: time histories (/TH/...) and cut sections (/SECT). Layouts: docs/cards/loads-output-engine.md
// §6. Object ids and groups are resolved in resolve_output.cpp.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <span>

#include "../context.hpp"

namespace crumple::deck {
namespace {

// How a /TH card lists its objects.
enum class ObjectLines : std::uint8_t {
  Ids,          // up to 10 ids of 10 columns per line
  IdSkewName,   // one object per line: id 1-10, skew 11-20 (must be 0), name 21-100
  IdBlankName,  // one object per line: id 1-10, columns 11-20 blank, name 21-100
};

struct HistoryKind {
  HistoryObject object;
  ObjectLines lines;
  std::span<const std::string_view> variables;  // the manual's names for what Crumple computes (DEF... included)
  std::span<const std::string_view> written;    // the names whose values NAME.h5 records
};

// Variable names Crumple can record, per object kind: the manual's variables for the quantities Crumple computes
// (no thermal, user, fluid or per-integration-point values) and its group names. Anything else is an error, so
// that a curve the user asked for is never silently missing from the results.
constexpr std::array<std::string_view, 34> kNodeVariables{
    "DEF",  "D",     "V",     "A",     "VR",     "AR",     "XYZ",    "DX",  "DY",  "DZ", "VX", "VY",
    "VZ",   "AX",    "AY",    "AZ",    "VRX",    "VRY",    "VRZ",    "ARX", "ARY", "ARZ", "X", "Y",
    "Z",    "DRX",   "DRY",   "DRZ",   "REACX",  "REACY",  "REACZ",  "REACXX", "REACYY", "REACZZ"};
constexpr std::array<std::string_view, 24> kPartVariables{
    "DEF", "IE",  "KE",  "XMOM", "YMOM", "ZMOM", "MASS", "HE",  "XCG", "YCG",   "ZCG",   "XXMOM",
    "YYMOM", "ZZMOM", "IXX", "IYY", "IZZ", "IXY", "IYZ", "IZX", "RIE", "KERB", "RKERB", "RKE"};
constexpr std::array<std::string_view, 27> kShellVariables{
    "DEF", "STRESS", "STRAIN", "PLAS", "F1",   "F2",   "F12", "Q1",  "Q2",  "M1",  "M2",  "M12", "IEM", "IEB",
    "OFF", "THIC",   "EMIN",   "EMAX", "EPSD", "E1",   "E2",  "E12", "SH1", "SH2", "K1",  "K2",  "K12"};
constexpr std::array<std::string_view, 20> kBrickVariables{
    "DEF",  "OFF", "SX",  "SY",   "SZ",    "SXY",   "SYZ",   "SXZ",   "IE",    "DENS",
    "BULK", "VOL", "PLAS", "PLSR", "EPSXX", "EPSYY", "EPSZZ", "EPSXY", "EPSXZ", "EPSYZ"};
constexpr std::array<std::string_view, 21> kInterfaceVariables{
    "DEF",  "FNX",  "FNY",  "FNZ",   "FTX", "FTY", "FTZ", "|FNX|", "|FNY|",    "|FNZ|",   "||FN||",
    "|FX|", "|FY|", "|FZ|", "||F||", "MX",  "MY",  "MZ",  "CE_ELAST", "CE_FRIC", "CE_DAMP"};
constexpr std::array<std::string_view, 7> kWallVariables{"DEF", "FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"};
constexpr std::array<std::string_view, 13> kRigidBodyVariables{"DEF", "F",  "M",  "R",  "FX", "FY", "FZ",
                                                               "MX",  "MY", "MZ", "RX", "RY", "RZ"};
// Interface values NAME.h5 records by these names (history/interface_values).
constexpr std::array<std::string_view, 8> kInterfaceWritten{"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "CE_ELAST",
                                                            "CE_FRIC"};
constexpr std::array<std::string_view, 19> kSectionVariables{
    "DEF", "FN", "FT", "M",  "CENTER", "FNX", "FNY", "FNZ", "FTX",  "FTY",
    "FTZ", "M1", "M2", "M3", "CX",     "CY",  "CZ",  "WORK", "WORKR"};

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
  std::size_t end = index + 1;
  if (unit_allowed) {
    if (reader.path_id(end, "unit_ID", false) != 0)
      reader.fail("unit_ID", "0 or nothing after the id (/UNIT systems are not supported by Crumple)",
                  in_quotes(card.path[end]));
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

// What NAME.h5 records for each kind of /TH card (results_file.cpp, docs/output-format.md): the energies always,
// and the rigid walls, rigid bodies and interfaces whatever the cards ask. A request for anything else is
// output Crumple does not write: a named warning, never an error (it changes no result).
void note_what_is_written(const TimeHistoryRequest& th, const HistoryKind& kind, DeckContext& context) {
  std::vector<std::string> missing;
  for (const std::string& v : th.variables)
    if (std::find(kind.written.begin(), kind.written.end(), v) == kind.written.end()) missing.push_back(v);
  if (missing.empty()) return;
  const std::string variables = fmt::format("{}", fmt::join(missing, " "));
  std::string what;
  switch (th.object) {
    case HistoryObject::RigidWall:
      what = fmt::format("variables {} not written by name: NAME.h5 holds the total force of every rigid wall "
                         "(history/rigid_wall_force)", variables);
      break;
    case HistoryObject::RigidBody:
      what = fmt::format("variables {} not written: NAME.h5 holds the position, velocity and angular velocity of "
                         "every rigid body (history/rigid_body_values)", variables);
      break;
    case HistoryObject::Interface:
      what = fmt::format("variables {} not written: NAME.h5 holds the normal and friction forces, elastic energy, "
                         "friction work and absorbed energy of every interface (history/interface_values)",
                         variables);
      break;
    default:
      what = "time history not written by Crumple (NAME.h5 holds the energies, rigid walls, rigid bodies and "
             "interfaces only)";
  }
  std::vector<std::string> unknown;
  for (const std::string& v : missing)
    if (std::find(kind.variables.begin(), kind.variables.end(), v) == kind.variables.end()) unknown.push_back(v);
  if (!unknown.empty())
    what += fmt::format(" ({} not among the variables of {} in the manual that Crumple computes)",
                        fmt::join(unknown, " "), th.keyword);
  context.note(th.where, th.keyword, "", "output-only: " + what, SkipKind::OutputOnly);
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

void read_object_line(const Line& line, const HistoryKind& kind, TimeHistoryRequest& th, DeckContext& context) {
  if (kind.lines == ObjectLines::Ids) {
    check_width(line, "Obj_ID");
    for (int column = 1; column <= 91; column += 10) {
      const std::int64_t id = line.integer(column, 10, "Obj_ID");
      if (id < 0) line.fail(column, 10, "Obj_ID", "a positive object id");
      if (id != 0) add_object(th, line, id, std::nullopt, context);
    }
    return;
  }
  check_width(line, "name");
  const std::int64_t id = line.integer(1, 10, "Obj_ID");
  if (id <= 0) line.fail(1, 10, "Obj_ID", "a positive object id (one object per line)");
  if (kind.lines == ObjectLines::IdSkewName) {
    if (line.integer(11, 10, "skew_ID") != 0)
      line.fail(11, 10, "skew_ID",
                "0 or blank (one object per line; output in skew or frame systems is not supported by Crumple)");
  } else if (!line.text(11, 10).empty()) {
    line.fail(11, 10, "(blank)", "blank columns 11-20 (the name starts at column 21)");
  }
  add_object(th, line, id, line.text(21, 80), context);
}

void read_history(CardReader& reader, DeckContext& context, const HistoryKind& kind) {
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
  note_what_is_written(th, kind, context);
  context.model.histories.push_back(std::move(th));
}

// ---------------------------------------------------------------------------------------------------------------
// /SECT/sect_ID[/unit_ID]

void read_section_frame(const Line& line, Section& s) {
  for (int k = 0; k < 3; ++k) {
    const std::string name = fmt::format("node_ID{}", k + 1);
    s.node_ids[k] = line.integer(1 + 10 * k, 10, name);
    if (s.node_ids[k] < 0) line.fail(1 + 10 * k, 10, name, "a node id or blank");
  }
  s.node_group_id = line.integer(31, 10, "grnod_ID");
  if (s.node_group_id < 0) line.fail(31, 10, "grnod_ID", "a node group id or blank");
  s.isave = static_cast<int>(line.integer(41, 10, "ISAVE"));
  if (s.isave != 0) line.fail(41, 10, "ISAVE", "0 (saving or imposing cut motions is not supported by Crumple)");
  s.frame_id = line.integer(51, 10, "frame_ID");
  if (s.frame_id != 0) line.fail(51, 10, "frame_ID", "0 or blank (moving frames are not supported by Crumple)");
  s.dt = line.real(61, 20, "Dt", dim::time);
  s.alpha = line.real(81, 20, "alpha", dim::none);
  if (s.dt < 0.0) line.fail(61, 20, "Dt", "a non-negative sampling interval");
  if (s.alpha < 0.0) line.fail(81, 20, "alpha", "a non-negative filter coefficient");
}

// Element groups: only 4-node shell groups exist in Crumple's keyword set (/GRSHEL).
void read_section_groups(const Line& line, Section& s) {
  struct Field { int column; std::string_view name; std::string_view missing; };
  constexpr std::array<Field, 6> unsupported{{
      {1, "grbric_ID", "brick groups (/GRBRIC) are"},
      {11, "grquad_ID", "2-D quad groups are"},
      {31, "grtrus_ID", "truss groups are"},
      {41, "grbeam_ID", "beam groups are"},
      {51, "grsprg_ID", "spring groups are"},
      {61, "grtria_ID", "3-node shell groups (/GRSH3N) are"},
  }};
  for (const Field& f : unsupported) {
    const std::int64_t id = line.integer(f.column, 10, f.name);
    if (id != 0) line.fail(f.column, 10, f.name, fmt::format("0 or blank ({} not supported by Crumple)", f.missing));
  }
  s.shell_group_id = line.integer(21, 10, "grshel_ID");
  if (s.shell_group_id < 0) line.fail(21, 10, "grshel_ID", "a shell group id or blank");
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
    const std::int64_t id = line.integer(1 + 10 * k, 10, name);
    if (k < s.ninter && id <= 0)
      line.fail(1 + 10 * k, 10, name, fmt::format("a positive interface id (Ninter = {})", s.ninter));
    if (k >= s.ninter && id != 0)
      line.fail(1 + 10 * k, 10, name, fmt::format("blank: only Ninter = {} ids", s.ninter));
    if (id > 0) s.interface_ids.push_back(id);
  }
}

void read_section(CardReader& reader, DeckContext& context) {
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
  if (s.shell_group_id == 0 && s.ninter == 0)
    context.warn(s.where, kw, "no element group and no interface: the section records nothing");
  context.note(s.where, kw, "", "output-only: cut-section forces are not written by Crumple", SkipKind::OutputOnly);
  context.model.sections.push_back(std::move(s));
}

}  // namespace

void register_output_keywords(KeywordTable& table) {
  auto history = [](HistoryObject object, ObjectLines lines, std::span<const std::string_view> variables,
                    std::span<const std::string_view> written = {}) {
    return [kind = HistoryKind{object, lines, variables, written}](CardReader& r, DeckContext& c) {
      read_history(r, c, kind);
    };
  };
  using H = HistoryObject;
  using L = ObjectLines;
  table.push_back({"/TH/NODE", DeckPart::Starter, history(H::Node, L::IdSkewName, kNodeVariables)});
  table.push_back({"/TH/PART", DeckPart::Starter, history(H::Part, L::Ids, kPartVariables)});
  table.push_back({"/TH/SUBS", DeckPart::Starter, history(H::Subset, L::Ids, kPartVariables)});
  table.push_back({"/TH/RWALL", DeckPart::Starter, history(H::RigidWall, L::Ids, kWallVariables)});
  table.push_back(
      {"/TH/INTER", DeckPart::Starter, history(H::Interface, L::Ids, kInterfaceVariables, kInterfaceWritten)});
  // /TH/SHELL is not in the manual but HyperCrash writes it (QA box_crush) and Radioss reads it as /TH/SHEL.
  table.push_back({"/TH/SHEL", DeckPart::Starter, history(H::Shell, L::IdSkewName, kShellVariables)});
  table.push_back({"/TH/SHELL", DeckPart::Starter, history(H::Shell, L::IdSkewName, kShellVariables)});
  table.push_back({"/TH/SH3N", DeckPart::Starter, history(H::Sh3n, L::IdSkewName, kShellVariables)});
  table.push_back({"/TH/BRIC", DeckPart::Starter, history(H::Brick, L::IdBlankName, kBrickVariables)});
  table.push_back({"/TH/SECTIO", DeckPart::Starter, history(H::Section, L::Ids, kSectionVariables)});
  table.push_back({"/TH/RBODY", DeckPart::Starter, history(H::RigidBody, L::Ids, kRigidBodyVariables)});
  table.push_back({"/SECT", DeckPart::Starter, read_section});
}

}  // namespace crumple::deck
