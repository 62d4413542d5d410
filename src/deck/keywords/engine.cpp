// Engine deck (NAME_0001.rad): run control. Layouts: docs/cards/loads-output-engine.md §7.
// Engine data lines are free format (values separated by blanks or commas, in any columns) and blank lines are
// skipped. Times are kept in input units here and converted to working units in resolve_output.cpp: in the
// Radioss single-file form the engine cards come before /BEGIN, whose units are not known yet when they are read.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <array>
#include <optional>
#include <span>

#include "../context.hpp"
#include "../keyword_catalog.hpp"

namespace crumple::deck {
namespace {

// What each /ANIM result name writes into the field frames of NAME.h5 (results_file.cpp, docs/output-format.md):
// a field every frame has (flag nullptr) or the request flag that adds its field. `kinds` says which element
// kinds have the value. Any other result is an output request Crumple does not write: a named warning.
enum AnimKinds : unsigned { kShells = 1, kBricks = 2, kAllKinds = 3 };
struct AnimResult {
  std::string_view name;
  bool FrameRequests::*flag;  // nullptr: in every frame
  unsigned kinds = kAllKinds;
};
using F = FrameRequests;
constexpr std::array<AnimResult, 14> kElementResults{{
    {"EPSP", nullptr},  {"OFF", nullptr},   {"SIGX", nullptr},  {"SIGY", nullptr},
    {"SIGXY", nullptr}, {"THIC", nullptr, kShells}, {"SIGZ", nullptr, kBricks}, {"SIGYZ", nullptr, kBricks},
    {"SIGZX", nullptr, kBricks}, {"VONM", nullptr}, {"P", &F::pressure}, {"ENER", &F::energy_density},
    {"HOURG", &F::hourglass_energy}, {"DT", &F::time_step}}};
constexpr std::array<AnimResult, 8> kVectorResults{{{"VEL", nullptr},
                                                    {"DISP", nullptr},
                                                    {"CONT", &F::contact_force},
                                                    {"ACC", &F::acceleration},
                                                    {"ACCEL", &F::acceleration},
                                                    {"FINT", &F::internal_force},
                                                    {"FEXT", &F::external_force},
                                                    {"VROT", &F::angular_velocity}}};
constexpr std::array<AnimResult, 1> kNodalResults{{{"DMAS", &F::added_mass}}};

// The results the reference manual lists for each kind of /ANIM request (its /ANIM/Eltyp/Restype,
// /ANIM/SHELL/Restype, /ANIM/BRICK/..., /ANIM/VECT and /ANIM/NODA pages) that Crumple does not write: a named
// warning. A name on no list is a typo: an error with the nearest name (or --skip-unknown).
constexpr std::string_view kManualElementResults[] = {
    "AMS",   "BFRAC", "BULK",  "DAM1",  "DAM2",   "DAM3",  "DAMA",  "DENS",  "EINT",  "ENERGY", "EPSD",  "ERROR",
    "ESPN",  "FAIL",  "FLAY",  "FLDF",  "FLDZ",   "FORC",  "IDPLY", "K",     "MACH",  "NL_EPSP", "PHI",  "PLY",
    "QVIS",  "SCHLIEREN", "SIGEQ", "SSP", "TDEL", "TDET",  "TEMP",  "THIN",  "THKERR", "TVIS",  "VDAM1", "VDAM2",
    "VDAM3", "VFRAC", "VOLU",  "VORT",  "VORTX",  "VORTY", "VORTZ", "WPLA"};
constexpr std::string_view kManualVectorResults[] = {"AROT", "CLUST", "CONT2", "DROT", "DXANI", "FOPT",
                                                     "FREAC", "FVEL", "MREAC", "PCONT", "VFLU"};
constexpr std::string_view kManualTensors[] = {"STRESS", "STRAIN", "EPSDOT", "EPSDO", "DAMA", "EPSP"};
constexpr std::string_view kManualNodalResults[] = {"DAMA2", "DENS", "DINER", "DT", "GPS", "NDMAS", "P", "SSP",
                                                    "TEMP", "VFRAC"};

// Whether `name` is a result the manual lists (`manual`, or a user variable USR1 to USR18 or a LAW51 phase).
bool manual_lists(std::span<const std::string_view> manual, std::string_view name) {
  for (const std::string_view m : manual)
    if (name == m) return true;
  const auto numbered = [&](std::string_view prefix) {
    return name.size() > prefix.size() && name.substr(0, prefix.size()) == prefix &&
           std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '_'; });
  };
  return numbered("USR") || numbered("LAW51") || name.rfind("LAW51_", 0) == 0;
}

// Path part `index` of the keyword line as written (Card::path is upper-cased; a run name keeps its case).
std::string written_part(const Card& card, std::size_t index) {
  std::string_view rest(card.keyword);
  for (std::size_t k = 0; k <= index; ++k) {
    const auto slash = rest.find('/');
    if (slash == std::string_view::npos) return {};
    rest.remove_prefix(slash + 1);
  }
  return std::string(trim(rest.substr(0, rest.find('/'))));
}

std::string path_prefix(const Card& card, std::size_t count) {
  std::string out;
  for (std::size_t k = 0; k < count && k < card.path.size(); ++k) out.append("/").append(card.path[k]);
  return out;
}

// More path parts than `count` is another form of the keyword, which Crumple does not read.
void path_at_most(CardReader& reader, std::size_t count) {
  const Card& card = reader.card();
  if (card.path.size() > count)
    reader.fail("keyword", fmt::format("nothing after {}", path_prefix(card, count)), in_quotes(card.path[count]));
}

// An integer path part (may be negative: /PRINT/-100); nullopt when absent.
std::optional<std::int64_t> path_integer(CardReader& reader, std::size_t index, std::string_view name) {
  const Card& card = reader.card();
  if (index >= card.path.size() || card.path[index].empty()) return std::nullopt;
  if (auto v = parse_integer(card.path[index])) return *v;
  reader.fail(name, "an integer in the keyword line", in_quotes(card.path[index]));
}

void output_only(CardReader& reader, DeckContext& context, const std::string& what) {
  context.note(reader.card().where, reader.card().keyword, "", "output-only: " + what, SkipKind::OutputOnly);
}

void note_without_effect(DeckContext& context, const Card& card) {
  auto& list = context.report.accepted_without_effect;
  const std::string name = fmt::format("/{}", card.path[0]);
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

// The next data line. A '/' inside it would end Radioss list-directed input and drop the rest of the line
// silently: reject it.
std::optional<Line> next_line(CardReader& reader) {
  auto line = reader.next_nonblank();
  if (line && line->content().find('/') != std::string::npos)
    line->fail_value("data line", "values separated by blanks or commas (a '/' ends the line's input in Radioss)",
                     in_quotes(trim(line->content())));
  return line;
}

Line required_line(CardReader& reader, std::string_view what) {
  if (auto line = next_line(reader)) return *line;
  reader.fail(what, fmt::format("a data line with {}", what), "end of card");
}

void at_most(const Line& line, std::size_t count, std::string_view fields) {
  if (line.token_count() > count)
    line.fail_value(fields, fmt::format("at most {} value{} ({})", count, count == 1 ? "" : "s", fields),
                    fmt::format("{} values", line.token_count()));
}

bool positive(double v) { return v > 0.0; }
bool not_negative(double v) { return v >= 0.0; }
bool unit_interval(double v) { return v >= 0.0 && v <= 1.0; }

// A real of a free-format line that must lie in a range; the message names the field and its position.
double checked_real(const Line& line, std::size_t index, std::string_view name, std::optional<double> fallback,
                    bool (*ok)(double), std::string_view expected) {
  const double value = line.token_real(index, name, dim::none, fallback);
  if (!ok(value)) line.fail_value(fmt::format("{} (value {})", name, index + 1), expected, fmt::format("{}", value));
  return value;
}

// ---------------------------------------------------------------------------------------------------------------
// /RUN, /TFILE, /PRINT, /VERS, /TITLE

void read_run(CardReader& reader, DeckContext& context) {
  const Card& card = reader.card();
  RunControl& run = context.model.run;
  if (context.run_seen) reader.fail("", "a single /RUN card", "a second /RUN");
  context.run_seen = true;  // even if the card is malformed below: its own error says what is wrong with it
  path_at_most(reader, 4);
  run.run_name = written_part(card, 1);
  if (run.run_name.empty() || parse_integer(run.run_name))
    reader.fail("Runname", "/RUN/Runname/run_number with a run name", in_quotes(card.keyword));
  // Run k is the engine deck NAME_000k.rad: a continued run carries on from the run before (the restart letter
  // would start from a restart file, which Crumple does not read). Left out (/RUN/name, the reference QA deck
  // INTERF/INT_7/fpenmax), it is this deck's, as the reference runs it.
  const auto number = path_integer(reader, 2, "run_number").value_or(context.engine_deck);
  if (number != context.engine_deck)
    reader.fail("run_number", fmt::format("{} (the number of this engine deck, NAME_{:04d}.rad)", context.engine_deck,
                                          context.engine_deck),
                fmt::format("{}", number));
  if (card.path.size() > 3)
    reader.fail("restart letter", "nothing (restart files are not read)", in_quotes(card.path[3]));
  const Line line = required_line(reader, "Tstop");
  at_most(line, 1, "Tstop");
  run.end_time = checked_real(line, 0, "Tstop", std::nullopt, positive, "a positive end time");
  reader.finish();
  run.run_number = context.engine_deck;
  run.present = true;
  run.where = card.where;
}

void read_tfile(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  if (run.history_format != 0) reader.fail("", "a single /TFILE card", "a second /TFILE");
  path_at_most(reader, 2);
  const std::int64_t format = path_integer(reader, 1, "type").value_or(0);
  if (format < 0 || format > 4)
    reader.fail("type", "0 to 4 (1 binary, 2 coded ASCII, 3 ASCII, 4 IEEE binary)", fmt::format("{}", format));
  const Line line = required_line(reader, "dT_his");
  at_most(line, 1, "dT_his");
  // 0: a row every cycle (the reference's, measured: its T01 file has one record per cycle).
  run.history_interval = checked_real(line, 0, "dT_his", std::nullopt, not_negative,
                                      "a time-history interval >= 0 (0: every cycle)");
  reader.finish();
  run.history_format = format == 0 ? 4 : static_cast<int>(format);  // blank or 0: IEEE binary (manual)
  if (format != 0)
    context.note(reader.card().where, reader.card().keyword, "type",
                 "output-only: the time histories go to NAME.h5 (HDF5) at dT_his, in no Radioss file format",
                 SkipKind::OutputOnly);
}

void read_print(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  path_at_most(reader, 3);
  const auto every = path_integer(reader, 1, "Nprint");
  if (!every || *every == 0) reader.fail("Nprint", "/PRINT/n with n a non-zero number of cycles", "none or 0");
  const std::int64_t lines = path_integer(reader, 2, "Nline").value_or(0);
  if (lines < 0 || lines > 1000000) reader.fail("Nline", "0 to 1000000 lines", fmt::format("{}", lines));
  reader.finish();
  run.print_every = *every;
  run.print_header_lines = static_cast<int>(lines);
  if (lines != 0)
    context.note(reader.card().where, reader.card().keyword, "Nline",
                 "output-only: Crumple's listing prints its column header once", SkipKind::OutputOnly);
}

void read_engine_version(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 2);
  const auto version = path_integer(reader, 1, "version");
  if (!version || *version <= 0 || *version > 100000)
    reader.fail("version", "/VERS/n with n a positive input version", "none");
  reader.finish();
  context.model.run.engine_version = static_cast<int>(*version);
  note_without_effect(context, reader.card());
}

void read_engine_title(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 1);
  reader.next_nonblank();  // the title: free text, a '/' is allowed here
  reader.finish();
  note_without_effect(context, reader.card());
}

// ---------------------------------------------------------------------------------------------------------------
// /ANIM/...

void read_anim_dt(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  path_at_most(reader, 2);
  if (run.anim_interval > 0.0) reader.fail("", "a single /ANIM/DT card", "a second /ANIM/DT");
  const Line line = required_line(reader, "Tstart, Tfreq");
  at_most(line, 2, "Tstart, Tfreq");
  run.anim_start = checked_real(line, 0, "Tstart", std::nullopt, not_negative, "a non-negative start time");
  run.anim_interval = checked_real(line, 1, "Tfreq", std::nullopt, positive, "a positive interval");
  reader.finish();
}

// The names of a table, without the second name of a field (ACCEL for ACC).
std::string result_names(std::span<const AnimResult> results) {
  std::vector<std::string_view> names;
  for (auto r = results.begin(); r != results.end(); ++r)
    if (r->flag == nullptr || std::none_of(results.begin(), r, [&](const AnimResult& o) { return o.flag == r->flag; }))
      names.push_back(r->name);
  return fmt::format("{}", fmt::join(names, " "));
}

std::string_view kind_words(unsigned kinds) { return kinds == kShells ? "shells" : "bricks"; }

// A result name on neither list: a typo, an error naming the nearest result of either list.
void unknown_result(CardReader& reader, DeckContext& context, std::span<const AnimResult> results,
                    std::span<const std::string_view> manual, std::string_view name) {
  std::string nearest;
  std::size_t best = std::max<std::size_t>(2, name.size() / 3) + 1;
  const auto consider = [&](std::string_view candidate) {
    const std::size_t d = edit_distance(name, candidate);
    if (d < best) best = d, nearest = std::string(candidate);
  };
  for (const AnimResult& r : results) consider(r.name);
  for (const std::string_view m : manual) consider(m);
  const std::string hint = nearest.empty() ? std::string() : fmt::format(" (nearest: {})", nearest);
  context.unsupported(
      DeckError(reader.card().where, reader.card().keyword, "restype",
                fmt::format("a result the Radioss manual lists for this request{} (or --skip-unknown)", hint),
                fmt::format("'{}', which is no result of {}", name, path_prefix(reader.card(), 2))),
      fmt::format("unknown result {} skipped (--skip-unknown){}", name, hint));
}

// Result `name` of a table: its flag set, or a named warning when Crumple does not write it for `kinds` (a result
// the manual lists for it, `manual`), or an error when the manual does not list it either (a typo).
void request_result(CardReader& reader, DeckContext& context, std::span<const AnimResult> results,
                    std::span<const std::string_view> manual, std::string_view name, unsigned kinds) {
  const auto found = std::find_if(results.begin(), results.end(), [&](const AnimResult& r) { return r.name == name; });
  if (found == results.end() && !manual_lists(manual, name)) return unknown_result(reader, context, results, manual, name);
  if (found == results.end())
    return output_only(reader, context,
                       fmt::format("result {} is not written by Crumple (its frames hold {})", name,
                                   results.empty() ? std::string("no result of this kind") : result_names(results)));
  if ((found->kinds & kinds) == 0)
    return output_only(reader, context,
                       fmt::format("result {} is written for {} only", name, kind_words(found->kinds)));
  if (found->flag != nullptr) context.model.run.anim.*found->flag = true;
}

// /ANIM/ELEM/restype, /ANIM/VECT/restype, /ANIM/NODA/restype: each name kept once in `fields`.
void read_anim_fields(CardReader& reader, DeckContext& context, std::span<const AnimResult> results,
                      std::span<const std::string_view> manual) {
  const Card& card = reader.card();
  if (card.path.size() < 3 || card.path[2].empty())
    reader.fail("restype", fmt::format("{}/<result name>", path_prefix(card, 2)), "no result name");
  path_at_most(reader, 3);
  const std::string& name = card.path[2];
  reader.finish();
  request_result(reader, context, results, manual, name, kAllKinds);
}

// /ANIM/[SHELL/|BRICK/]TENS/restype[/location]: the tensor at path part `at`. Frames hold the stress tensor
// (shell membrane stress, brick mean stress) and, on request, the shell bending and surface stresses.
void read_anim_tensor(CardReader& reader, DeckContext& context, std::size_t at, unsigned kinds) {
  const Card& card = reader.card();
  if (card.path.size() <= at || card.path[at].empty())
    reader.fail("restype", fmt::format("{}/<tensor name, e.g. STRESS>", path_prefix(card, at)), "no tensor name");
  reader.finish();
  const std::string& tensor = card.path[at];
  const std::string location = card.path.size() > at + 1 ? card.path[at + 1] : "";
  FrameRequests& anim = context.model.run.anim;
  std::string missing;
  if (!manual_lists(kManualTensors, tensor)) return unknown_result(reader, context, {}, kManualTensors, tensor);
  if (tensor != "STRESS")
    missing = fmt::format("tensor {} is not written by Crumple (its frames hold the stress tensors)", tensor);
  else if (card.path.size() > at + 2)
    missing = "stress per composite layer point is not written by Crumple";
  else if (location == "BEND" || location == "UPPER" || location == "LOWER") {
    if ((kinds & kShells) == 0) missing = fmt::format("stress {} is written for shells only", location);
    else (location == "BEND" ? anim.bending_stress : anim.surface_stress) = true;
  } else if (location == "MEMB" && (kinds & kShells) == 0)
    missing = "stress MEMB is written for shells only";
  else if (!location.empty() && location != "0" && location != "MEMB")
    missing = fmt::format("stress at integration point {} is not written by Crumple (its frames hold the shell "
                          "membrane, bending, upper and lower stresses and the brick mean stress)",
                          location);
  if (!missing.empty()) output_only(reader, context, missing);
}

// /ANIM/SHELL/..., /ANIM/BRICK/...: the element results of one kind, or its tensors (/ANIM/SHELL/TENS/...).
void read_anim_kind(CardReader& reader, DeckContext& context, unsigned kinds) {
  const Card& card = reader.card();
  if (card.path.size() > 2 && card.path[2] == "TENS") return read_anim_tensor(reader, context, 3, kinds);
  if (card.path.size() < 3 || card.path[2].empty())
    reader.fail("restype", fmt::format("{}/<result name>", path_prefix(card, 2)), "no result name");
  reader.finish();
  const std::string& name = card.path[2];
  const bool written = std::any_of(kElementResults.begin(), kElementResults.end(),
                                   [&](const AnimResult& r) { return r.name == name; });
  if (card.path.size() > 3 && (written || manual_lists(kManualElementResults, name)))
    return output_only(reader, context, fmt::format("result {} per layer or point is not written by Crumple", name));
  request_result(reader, context, kElementResults, kManualElementResults, name, kinds);
}

void read_anim_mass(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 2);
  reader.finish();
  context.model.run.anim.nodal_mass = true;
}

void read_anim_gzip(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 2);
  reader.finish();
  context.model.run.anim_gzip = true;
  output_only(reader, context, "Crumple writes its frames to NAME.h5 (HDF5), not gzipped animation files");
}

// /TH/VERS/n (engine, old decks): the version of the Radioss time-history file the engine writes; Crumple writes its
// histories to NAME.h5 whatever it says.
void read_th_version(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 3);
  const auto version = path_integer(reader, 2, "n");
  if (version && (*version <= 0 || *version > 100000))
    reader.fail("n", "a time-history file version (a positive integer)", std::to_string(*version));
  reader.finish();
  output_only(reader, context, "the time-history file's version; Crumple writes its histories to NAME.h5 (HDF5)");
}

void read_anim_version(CardReader& reader, DeckContext& context) {
  path_at_most(reader, 3);
  const auto version = path_integer(reader, 2, "n");
  if (!version || *version <= 0 || *version > 100000)
    reader.fail("n", "/ANIM/VERS/n with n a positive format version", "none");
  reader.finish();
  context.model.run.anim_version = static_cast<int>(*version);
  output_only(reader, context, "Crumple writes its frames to NAME.h5 (HDF5), in no animation format version");
}

// ---------------------------------------------------------------------------------------------------------------
// /DT family

// `DTsca DTmin` on one line. `minimum_required`: cards that act only through DTmin (/DT/NODA/CST, /DT/INTER/...)
// would do nothing without it, which is almost certainly not what the deck's author meant.
void read_dt_values(CardReader& reader, TimeStepControl& target, TimeStepAction action, bool minimum_required) {
  const Card& card = reader.card();
  if (target.given)
    reader.fail("", fmt::format("a single {} card", path_prefix(card, card.path.size())), "a second one");
  const Line line = required_line(reader, "DTsca, DTmin");
  at_most(line, 2, "DTsca, DTmin");
  target.scale = checked_real(line, 0, "DTsca", 0.0, unit_interval, "a time-step scale in (0, 1] (0: default 0.9)");
  target.minimum = checked_real(line, 1, "DTmin", 0.0, not_negative, "a non-negative time step");
  if (minimum_required && target.minimum <= 0.0)
    line.fail_value("DTmin (value 2)", fmt::format("a positive minimum time step (without it {} has no effect)",
                                                   path_prefix(card, card.path.size())),
                    fmt::format("{}", target.minimum));
  reader.finish();
  target.action = action;
  target.given = true;
  target.where = card.where;
}

// Iflag (path part 3) selects extra input lines that Crumple does not read.
void no_iflag(CardReader& reader) {
  if (path_integer(reader, 3, "Iflag").value_or(0) != 0)
    reader.fail("Iflag", "0 or nothing (the extra Iflag = 1 input is not supported)", in_quotes(reader.card().path[3]));
  path_at_most(reader, 4);
}

void read_dt_element(CardReader& reader, TimeStepControl& target, bool small_strain_allowed) {
  const Card& card = reader.card();
  TimeStepAction action = TimeStepAction::Default;
  const std::string keyword3 = card.path.size() > 2 ? card.path[2] : std::string();
  if (keyword3 == "STOP") action = TimeStepAction::Stop;
  else if (keyword3 == "DEL") action = TimeStepAction::Delete;
  else if (keyword3 == "CST" && small_strain_allowed) action = TimeStepAction::SmallStrain;
  else if (!keyword3.empty())
    reader.fail("Keyword3", small_strain_allowed ? "STOP, DEL or CST" : "STOP or DEL", in_quotes(keyword3));
  no_iflag(reader);
  read_dt_values(reader, target, action, false);
}

// /DT/AMS/Iflag: DTsca DTmin; with Iflag 1 or 2 a line Tol_AMS; with Iflag 2 a line Niter Nprint. Nprint only
// prints the solve's iterations: output-only (Crumple reports them in the summary).
void read_dt_ams(CardReader& reader, DeckContext& context) {
  SelectiveMassControl& ams = context.model.run.dt_ams;
  const Card& card = reader.card();
  if (ams.given) reader.fail("", "a single /DT/AMS card", "a second one");
  const std::int64_t iflag = path_integer(reader, 2, "Iflag").value_or(0);
  if (iflag < 0 || iflag > 2) reader.fail("Iflag", "0, 1 or 2 (the number of extra lines)", fmt::format("{}", iflag));
  path_at_most(reader, 3);
  const Line line = required_line(reader, "DTsca, DTmin");
  at_most(line, 2, "DTsca, DTmin");
  ams.scale = checked_real(line, 0, "DTsca", 0.0, unit_interval, "a time-step scale in (0, 1] (0: default 0.9)");
  ams.minimum = checked_real(line, 1, "DTmin", 0.0, not_negative, "a non-negative time step");
  if (iflag >= 1) {
    const Line tol = required_line(reader, "Tol_AMS");
    at_most(tol, 1, "Tol_AMS");
    ams.tolerance = checked_real(tol, 0, "Tol_AMS", 0.0, unit_interval, "a relative tolerance in [0, 1] (0: default 1e-3)");
  }
  if (iflag == 2) {
    const Line iterations = required_line(reader, "Niter, Nprint");
    at_most(iterations, 2, "Niter, Nprint");
    ams.max_iterations = iterations.token_integer(0, "Niter", 0);
    if (ams.max_iterations < 0)
      iterations.fail_value("Niter (value 1)", "a non-negative iteration count (0: default 1000)",
                            fmt::format("{}", ams.max_iterations));
    if (iterations.token_integer(1, "Nprint", 0) != 0)
      output_only(reader, context, "Nprint: Crumple reports the solve's iterations in the summary, not every Nprint cycles");
  }
  reader.finish();
  ams.given = true;
  ams.where = card.where;
}

void read_dt(CardReader& reader, DeckContext& context) {
  const Card& card = reader.card();
  RunControl& run = context.model.run;
  if (card.path.size() == 1) return read_dt_values(reader, run.dt, TimeStepAction::Default, false);
  const std::string& type = card.path[1];
  const std::string keyword3 = card.path.size() > 2 ? card.path[2] : std::string();
  for (const ElementKindDescription& kind : kElementKindTable)
    if (type == kind.step_card || (kind.kind == ElementKind::Shell3 && type == "SH3N"))
      return read_dt_element(reader, run.*kind.step_control, true);
  if (type == "NODA") {
    // CST is Radioss' name for CST2 (mass added to keep DTmin); CST1, SET and STOP are other methods.
    if (keyword3 != "CST" && keyword3 != "CST2")
      reader.fail("Keyword3", "/DT/NODA/CST (added mass; the other nodal time-step methods are not supported)",
                  in_quotes(card.keyword));
    no_iflag(reader);
    return read_dt_values(reader, run.dt_nodal_cst, TimeStepAction::Default, true);
  }
  if (type == "AMS") return read_dt_ams(reader, context);
  if (type == "INTER") {
    path_at_most(reader, 3);
    if (keyword3 == "DEL") return read_dt_values(reader, run.dt_inter_del, TimeStepAction::Default, true);
    if (keyword3 == "CST" || keyword3 == "CST2")
      return read_dt_values(reader, run.dt_inter_cst, TimeStepAction::Default, true);
    reader.fail("Keyword3", "/DT/INTER/DEL or /DT/INTER/CST", in_quotes(card.keyword));
  }
  reader.fail("Eltyp", "/DT, /DT/SHELL, /DT/BRICK, /DT/SH_3N, /DT/NODA/CST, /DT/AMS, /DT/INTER/DEL or /DT/INTER/CST",
              in_quotes(card.keyword));
}

// ---------------------------------------------------------------------------------------------------------------
// Switches, /STOP, /RFILE, /RBODY/ON|OFF

// `/PARITH/ON|OFF`, `/MON/ON|OFF`.
bool read_switch(CardReader& reader) {
  const Card& card = reader.card();
  path_at_most(reader, 2);
  const std::string value = card.path.size() > 1 ? card.path[1] : std::string();
  if (value != "ON" && value != "OFF")
    reader.fail("keyword", fmt::format("/{}/ON or /{}/OFF", card.path[0], card.path[0]), in_quotes(card.keyword));
  reader.finish();
  return value == "ON";
}

bool zero_or_one(const Line& line, std::size_t index, std::string_view name) {
  const std::int64_t v = line.token_integer(index, name, 0);
  if (v != 0 && v != 1) line.fail_value(fmt::format("{} (value {})", name, index + 1), "0 or 1", fmt::format("{}", v));
  return v == 1;
}

void read_stop(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  path_at_most(reader, 1);  // /STOP/LSENSOR (sensor stop) is another card
  const Line line = required_line(reader, "Emax, Mmax, Nmax, NTH, NANIM, NERR_POSIT");
  at_most(line, 6, "Emax, Mmax, Nmax, NTH, NANIM, NERR_POSIT");
  auto limit = [&](std::size_t index, std::string_view name) {
    return checked_real(line, index, name, 0.0, not_negative, "a non-negative limit (0: none)");
  };
  run.stop_energy_error = limit(0, "Emax");
  run.stop_mass_error = limit(1, "Mmax");
  run.stop_node_mass_error = limit(2, "Nmax");
  run.stop_write_history = zero_or_one(line, 3, "NTH");
  run.stop_write_animation = zero_or_one(line, 4, "NANIM");
  run.stop_positive_error_only = zero_or_one(line, 5, "NERR_POSIT");
  reader.finish();
  // The solver stops on Emax (|energy error|) and Mmax (added mass); the other limits are not implemented.
  if (run.stop_node_mass_error != 0.0) {
    context.unsupported(DeckError(line.where(), reader.card().keyword, "Nmax (value 3)",
                                  default_only("a stop on the largest nodal added mass is"),
                                  fmt::format("{}", run.stop_node_mass_error)));
    run.stop_node_mass_error = 0.0;
  }
  if (run.stop_positive_error_only && run.stop_energy_error > 0.0) {
    context.unsupported(DeckError(line.where(), reader.card().keyword, "NERR_POSIT (value 6)",
                                  default_only("counting only a positive energy error is"), "1"));
    run.stop_positive_error_only = false;
  }
  if (run.stop_write_history || run.stop_write_animation)
    context.note(line.where(), reader.card().keyword, run.stop_write_history ? "NTH (value 4)" : "NANIM (value 5)",
                 "output-only: Crumple writes no extra time-history or frame when a /STOP limit ends the run",
                 SkipKind::OutputOnly);
}

void read_rfile(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  const Card& card = reader.card();
  path_at_most(reader, 2);
  if (card.path.size() > 1 && card.path[1] == "OFF") {  // OpenRadioss form: no restart files at all
    reader.finish();
    run.restart_every = 0;
    run.restart_sets = 0;
    return;
  }
  const std::int64_t sets = path_integer(reader, 1, "n").value_or(0);
  if (sets < 0 || sets > 26) reader.fail("n", "0 to 26 rotating restart sets", fmt::format("{}", sets));
  std::int64_t every = 1000000;  // the manual's default when no cycle count is given
  if (auto line = next_line(reader)) {
    // Before input version 110 the line also held Iread and Iwrite, flags of the old restart files: 0 there is
    // what every later version means.
    at_most(*line, 3, "Ncycle, Iread, Iwrite");
    for (std::size_t k = 1; k < line->token_count(); ++k)
      if (line->token_integer(k, k == 1 ? "Iread (value 2)" : "Iwrite (value 3)", 0) != 0)
        line->fail_value(k == 1 ? "Iread (value 2)" : "Iwrite (value 3)",
                         "0 (the restart read and write flags of input versions before 110 are not supported by Crumple)",
                         line->content());
    every = line->token_integer(0, "Ncycle", 0);
    if (every < 0) line->fail_value("Ncycle (value 1)", "a positive number of cycles", fmt::format("{}", every));
    if (every == 0) every = 1000000;
  }
  reader.finish();
  run.restart_every = every;
  run.restart_sets = static_cast<int>(sets);
  // Crumple writes the snapshot into NAME.rst (docs/output-format.md, "Restart file"); it keeps the last one.
  if (sets > 1)
    output_only(reader, context, fmt::format("{} rotating restart sets asked: Crumple keeps the last snapshot only", sets));
}

// /VEL/TRA/dirs[/skew_ID]: dirs a combination of X, Y and Z (each once); then node ids, any number per line.
void read_velocity_link(CardReader& reader, DeckContext& context) {
  const Card& card = reader.card();
  path_at_most(reader, 4);
  if (card.path.size() < 2 || card.path[1] != "TRA")
    return context.unsupported(reader.error(
        "Keyword2", "TRA in /VEL/TRA/dirs (the rotational and grid links are not supported by Crumple)",
        in_quotes(card.path.size() > 1 ? card.path[1] : "")));
  RunControl::VelocityLink link;
  link.where = card.where;
  const std::string dirs = card.path.size() > 2 ? card.path[2] : "";
  for (char c : dirs) {
    const std::size_t axis = c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : 3;
    if (axis > 2 || link.along[axis])
      reader.fail("Keyword3", "X, Y and Z, each at most once (XY, XYZ, ...)", in_quotes(dirs));
    link.along[axis] = true;
  }
  if (dirs.empty()) reader.fail("Keyword3", "X, Y and Z, each at most once (XY, XYZ, ...)", "none");
  if (card.path.size() > 3) {
    const auto skew = parse_integer(card.path[3]);
    if (!skew || *skew < 0) reader.fail("skew_ID", "a skew id (blank: the global axes)", in_quotes(card.path[3]));
    link.skew_id = *skew;
  }
  while (auto line = next_line(reader))
    for (std::size_t k = 0; k < line->token_count(); ++k) {
      const std::int64_t id = line->token_integer(k, "node_ID", std::nullopt);
      if (id <= 0) line->fail_value(fmt::format("node_ID (value {})", k + 1), "a node id", fmt::format("{}", id));
      link.node_ids.push_back(id);
    }
  if (link.node_ids.size() < 2) reader.fail("node_ID", "at least two node ids (the nodes linked)", "fewer");
  context.model.run.velocity_links.push_back(std::move(link));
}

void read_rbody_switch(CardReader& reader, std::vector<std::int64_t>& ids, std::vector<SourceLocation>& where) {
  path_at_most(reader, 2);
  bool any = false;
  while (auto line = next_line(reader)) {
    for (std::size_t k = 0; k < line->token_count(); ++k) {
      // The main node ids of the bodies (the engine manual's node_ID list); 0 names none, as a blank field would.
      const std::int64_t id = line->token_integer(k, "node_ID", std::nullopt);
      if (id < 0)
        line->fail_value(fmt::format("node_ID (value {})", k + 1), "a rigid body's main node id (0: none)",
                         fmt::format("{}", id));
      if (id == 0) continue;
      ids.push_back(id);
      where.push_back(line->where());
    }
    any = true;
  }
  if (!any) reader.fail("node_ID", "a line of rigid body main node ids", "none");
}

// /DTIX: DTini DTmax. The first step of this engine deck is at most DTini, every step at most DTmax.
void read_dtix(CardReader& reader, DeckContext& context) {
  RunControl& run = context.model.run;
  path_at_most(reader, 1);
  const Line line = required_line(reader, "DTini, DTmax");
  at_most(line, 2, "DTini, DTmax");
  run.dt_initial = checked_real(line, 0, "DTini", 0.0, not_negative, "a non-negative time step (0: none)");
  run.dt_max = checked_real(line, 1, "DTmax", 0.0, not_negative, "a non-negative time step (0: none)");
  reader.finish();
}

}  // namespace

void register_engine_keywords(KeywordTable& table) {
  auto fields = [](std::span<const AnimResult> results, std::span<const std::string_view> manual) {
    return [results, manual](CardReader& r, DeckContext& c) { read_anim_fields(r, c, results, manual); };
  };
  const DeckPart E = DeckPart::Engine;
  table.push_back({"/RUN", E, read_run});
  table.push_back({"/TFILE", E, read_tfile});
  table.push_back({"/PRINT", E, read_print});
  table.push_back({"/VERS", E, read_engine_version});
  table.push_back({"/TITLE", E, read_engine_title});
  table.push_back({"/ANIM/DT", E, read_anim_dt});
  table.push_back({"/ANIM/ELEM", E, fields(kElementResults, kManualElementResults)});
  table.push_back({"/ANIM/VECT", E, fields(kVectorResults, kManualVectorResults)});
  table.push_back({"/ANIM/NODA", E, fields(kNodalResults, kManualNodalResults)});
  table.push_back({"/ANIM/SHELL", E, [](CardReader& r, DeckContext& c) { read_anim_kind(r, c, kShells); }});
  table.push_back({"/ANIM/BRICK", E, [](CardReader& r, DeckContext& c) { read_anim_kind(r, c, kBricks); }});
  table.push_back({"/ANIM/TENS", E, [](CardReader& r, DeckContext& c) { read_anim_tensor(r, c, 2, kAllKinds); }});
  table.push_back({"/ANIM/MASS", E, read_anim_mass});
  table.push_back({"/ANIM/GZIP", E, read_anim_gzip});
  table.push_back({"/TH/VERS", E, read_th_version});
  table.push_back({"/ANIM/VERS", E, read_anim_version});
  // Every other /ANIM request the manual lists (/ANIM/BEAM/..., /ANIM/GPS/..., /ANIM/SENSOR) is an output-only
  // warning, anything else (/ANIM/TD) an unknown keyword with the nearest one (data/radioss_keywords.txt).
  table.push_back({"/DT", E, read_dt});
  table.push_back({"/DTIX", E, read_dtix});
  table.push_back({"/PARITH", E, [](CardReader& r, DeckContext& c) {
                     c.model.run.parith = read_switch(r);
                     // Crumple always sums in the model's fixed order (docs/parallel.md): /PARITH/OFF would trade
                     // that for speed, and the order costs under 1 % of a cycle (docs/performance.md, "Parallel
                     // runs"), so there is nothing to trade.
                     c.note(r.card().where, r.card().keyword, "",
                            c.model.run.parith ? "performance hint: no effect on Crumple's results"
                                               : "performance hint: Crumple always assembles in a fixed order, the "
                                                 "same answer for any rank count (its cost is under 1 % of a cycle)",
                            SkipKind::PerformanceHint);
                   }});
  table.push_back({"/MON", E, [](CardReader& r, DeckContext& c) {
                     c.model.run.monitor = read_switch(r);
                     output_only(r, c, "Crumple's listing ends with its own time profile, whatever /MON says");
                   }});
  table.push_back({"/STOP", E, read_stop});
  table.push_back({"/RFILE", E, read_rfile});
  table.push_back({"/VEL", E, read_velocity_link});
  table.push_back({"/RBODY/ON", E, [](CardReader& r, DeckContext& c) {
                     read_rbody_switch(r, c.model.run.rbody_on, c.model.run.rbody_on_where);
                   }});
  table.push_back({"/RBODY/OFF", E, [](CardReader& r, DeckContext& c) {
                     read_rbody_switch(r, c.model.run.rbody_off, c.model.run.rbody_off_where);
                   }});
}

}  // namespace crumple::deck
