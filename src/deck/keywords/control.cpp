// /BEGIN, /TITLE, /DEF_SHELL, /DEF_SOLID and the control keywords accepted without effect.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>

#include "../context.hpp"
#include "shell_flags.hpp"

namespace crumple::deck {
namespace {

// Every conversion factor (up to the cube of a unit, as in a density) must stay finite and non-zero: with an
// infinite factor a blank field (0 x inf) reads as NaN and passes every range check of its card.
bool finite_factors(const UnitSystem& u) {
  for (int mass = -3; mass <= 3; ++mass)
    for (int length = -3; length <= 3; ++length)
      for (int time = -3; time <= 3; ++time)
        if (const double f = u.factor(Dimension{mass, length, time}); !std::isfinite(f) || f == 0.0) return false;
  return true;
}

void read_begin(CardReader& reader, DeckContext& context) {
  if (context.begin_seen) reader.fail("", "a single /BEGIN", "a second /BEGIN");
  if (reader.card().path.size() > 1 && reader.card().path[1] != "0")
    reader.fail("keyword", "/BEGIN (or /BEGIN/0, as old decks write it)", in_quotes(reader.card().path[1]));
  context.begin_seen = true;
  Model& model = context.model;
  model.run_name = reader.next("Runname").text(1, 80);
  const Line version = reader.next("Invers, Irun");
  model.input_version = static_cast<int>(version.integer(1, 10, "Invers"));
  // Input versions 51 to 140 write every card Crumple reads with the widths and title lines of 2017; they lack
  // only fields added later, which are blank there. Versions 41 to 44 write 8- and 16-column fields with the title
  // on the keyword line: the cards after /BEGIN are read in that narrow layout (docs/deck-format.md, "Input
  // versions").
  if (model.input_version < 41)
    version.fail(1, 10, "Invers", "an input version of 41 or later (41 to 44, 51 to 140, 2017 and later)");
  // Irun numbers the starter run in Radioss' file names; Crumple names its files after the run name.
  if (version.integer(11, 10, "Irun") != 0)
    context.note(version.where(), reader.card().keyword, "Irun (columns 11-20)",
                 "output-only: the starter run number names no Crumple file", SkipKind::OutputOnly);
  // Unit lines: mass, length, time in 20-column fields, a code or a real (SI size). A blank working unit is
  // the SI unit; a blank input unit is the working unit.
  const char* names[2][3] = {{"Input_mass_unit", "Input_length_unit", "Input_time_unit"},
                             {"Work_mass_unit", "Work_length_unit", "Work_time_unit"}};
  std::optional<Line> lines[2];
  for (auto& line : lines)
    if (!reader.at_end()) line = reader.next("units");
  for (int system : {1, 0}) {
    for (int base = 0; base < 3; ++base) {
      const int column = 1 + 20 * base;
      double& target = system == 0 ? model.units.input[base] : model.units.work[base];
      if (!lines[system] || lines[system]->text(column, 20).empty()) {
        target = system == 0 ? model.units.work[base] : 1.0;
        continue;
      }
      const auto size = parse_unit(lines[system]->raw(column, 20), base);
      if (!size)
        lines[system]->fail(column, 20, names[system][base],
                            "a unit code (kg, g, Mg, m, mm, s, ms, lb, in...) or a positive real");
      target = *size;
    }
  }
  const UnitSystem u = model.units;
  if (!finite_factors(u)) {
    model.units = UnitSystem{};  // the rest of the deck is read in SI rather than reporting every field
    reader.fail("units", "input and working units whose conversion factors stay finite and non-zero",
                fmt::format("input/working size ratios {:g} (mass), {:g} (length), {:g} (time)", u.input[0] / u.work[0],
                            u.input[1] / u.work[1], u.input[2] / u.work[2]));
  }
  reader.finish();
}

// Before input version 100, /UNIT/LENGTH/code, /UNIT/MASS/code and /UNIT/TIME/code set the input unit of one
// base quantity, with no data line. Code 1 leaves it as /BEGIN's (measured: the reference's listing of the QA deck
// RESSORT/prop_type25/input_51, which writes all three with code 1, prints the input unit system 1, 1, 1); the other
// codes' units are not known to Crumple.
void read_old_unit(CardReader& reader, DeckContext& context) {
  const std::vector<std::string>& path = reader.card().path;
  const bool base = path.size() == 3 && (path[1] == "LENGTH" || path[1] == "MASS" || path[1] == "TIME");
  if (!base)
    reader.fail("keyword", "/UNIT/LENGTH/code, /UNIT/MASS/code or /UNIT/TIME/code (the /UNIT card of input versions "
                "before 100)", in_quotes(reader.card().keyword));
  if (path[2] != "1")
    reader.fail("code", "1 (the unit of /BEGIN; the other codes of the /UNIT card of input versions before 100 are "
                "not supported by Crumple)", in_quotes(path[2]));
  reader.finish();
  context.note(reader.card().where, reader.card().keyword, "code",
               "code 1: the input unit stays /BEGIN's, as the reference reads it", SkipKind::Unsupported);
}

// /UNIT/unit_ID: title; mass, length, time units in 20-column fields (codes or SI sizes, as in /BEGIN). A blank one
// is /BEGIN's input unit (measured on the reference: a blank mass read a density in grams under /BEGIN g mm ms).
// The cards that name it read their values in it, converted to the working units (docs/deck-format.md, "Units").
// Read right after /BEGIN, whose units it needs.
void read_unit(CardReader& reader, DeckContext& context) {
  if (context.model.input_version < 100) return read_old_unit(reader, context);
  refuse_narrow_layout(reader);
  const std::int64_t id = object_id(reader, 1);
  if (reader.card().path.size() > 2) reader.fail("keyword", "nothing after the unit id", in_quotes(reader.card().path[2]));
  read_title(reader);
  const Line line = reader.next("mass_unit, length_unit, time_unit");
  UnitSystem u = context.model.units;
  constexpr const char* kNames[3] = {"mass_unit", "length_unit", "time_unit"};
  for (int base = 0; base < 3; ++base) {
    const int column = 1 + 20 * base;
    if (line.text(column, 20).empty()) continue;  // /BEGIN's input unit
    const auto size = parse_unit(line.raw(column, 20), base);
    if (!size) line.fail(column, 20, kNames[base], "a unit code (kg, g, Mg, m, mm, s, ms, lb, in...) or a positive real");
    u.input[base] = *size;
  }
  reader.finish();
  if (!finite_factors(u))
    reader.fail("units", "units whose conversion factors to the working units stay finite and non-zero",
                fmt::format("size ratios {:g} (mass), {:g} (length), {:g} (time)", u.input[0] / u.work[0],
                            u.input[1] / u.work[1], u.input[2] / u.work[2]));
  if (const auto seen = context.local_units_where.find(id); seen != context.local_units_where.end())
    reader.fail("unit_ID", "an id no other /UNIT has", fmt::format("{} is also the id of the /UNIT at {}:{}", id, seen->second.file, seen->second.line));
  context.local_units[id] = u;
  context.local_units_where[id] = reader.card().where;
}

void read_title_card(CardReader& reader, DeckContext& context) {
  context.model.title = read_title(reader);
}

// ---------------------------------------------------------------------------------------------------------------
// Control cards with no model data: each field either acts, is a named warning (output, performance) or, when
// non-default, an option Crumple lacks.

// The card's single optional data line (blank or absent: every field at its default).
std::optional<Line> optional_line(CardReader& reader, std::string_view what) {
  if (!reader.has_data()) return std::nullopt;
  auto line = reader.next_nonblank();
  if (line) return *line;
  reader.fail(what, "a data line", "none");
}

void output_only_card(CardReader& reader, DeckContext& context, std::string_view why) {
  context.note(reader.card().where, reader.card().keyword, "", fmt::format("output-only card: {}", why),
               SkipKind::OutputOnly);
}

void performance_card(CardReader& reader, DeckContext& context) {
  context.note(reader.card().where, reader.card().keyword, "",
               "performance hint: no effect on Crumple's results (Crumple chooses its own parallel layout and memory)",
               SkipKind::PerformanceHint);
}

// A 10-column field no input version gives a meaning here: blank, or the 0 that decks written by other tools
// put in every field; anything else is refused (issue 27).
void unused_columns(const Line& line, int column, std::string_view expected) {
  const std::string text = line.text(column, 10);
  if (!text.empty() && line.integer(column, 10, "(unused)") != 0) line.fail(column, 10, "(unused)", std::string(expected));
}

// /ANALY in input versions 41 to 44: N2D3D 1-8, Iparith 19-26, Isubcycle 27-34.
void read_narrow_analy(CardReader& reader, DeckContext& context) {
  if (const auto read = optional_line(reader, "N2D3D, Iparith, Isubcycle")) {
    const Line line = read->as_written();
    if (line.integer(1, 8, "N2D3D") != 0)
      context.unsupported(line.error(1, 8, "N2D3D", default_only("2-D analysis (axisymmetric, plane strain) is")));
    for (const auto& [column, name] : {std::pair{19, "Iparith"}, std::pair{27, "Isubcycle"}})
      if (line.integer(column, 8, name) != 0)
        context.note(line.where(), reader.card().keyword, name, "performance hint: no effect on Crumple's results",
                     SkipKind::PerformanceHint);
  }
}

// /ANALY: N2D3D (1-10), Iparith (21-30), Isubcycle (31-40).
void read_analy(CardReader& reader, DeckContext& context) {
  if (reader.narrow()) return read_narrow_analy(reader, context);
  if (const auto line = optional_line(reader, "N2D3D, Iparith, Isubcycle")) {
    const std::int64_t n2d3d = line->integer(1, 10, "N2D3D");
    if (n2d3d < 0 || n2d3d > 2) line->fail(1, 10, "N2D3D", "0 (3-D), 1 (axisymmetric) or 2 (plane strain)");
    if (n2d3d != 0)
      context.unsupported(line->error(1, 10, "N2D3D", default_only("2-D analysis (axisymmetric, plane strain) is")));
    unused_columns(*line, 11, "blank or 0 in columns 11-20 (Iparith is in columns 21-30)");
    const std::int64_t iparith = line->integer(21, 10, "Iparith");
    if (iparith < 0 || iparith > 2) line->fail(21, 10, "Iparith", "0 or 1 (parallel arithmetic on) or 2 (off)");
    const std::int64_t isub = line->integer(31, 10, "Isubcycle");
    if (isub != 0 && isub != 2) line->fail(31, 10, "Isubcycle", "0 (no subcycling) or 2 (memory for /SHSUB)");
    // Iparith and Isubcycle = 2 only choose reproducible sums and reserve memory; /SHSUB (engine) would subcycle.
    if (iparith == 2 || isub == 2)
      context.note(line->where(), reader.card().keyword,
                   iparith == 2 ? "Iparith (columns 21-30)" : "Isubcycle (columns 31-40)",
                   "performance hint: no effect on Crumple's results", SkipKind::PerformanceHint);
  }
}

// /IOFLAG: Ipri (1-10), Igtyp (21-30, obsolete), Ioutp (31-40), OutyyFMT (41-50), Irootyy (51-60), Idrot (61-70).
void read_ioflag(CardReader& reader, DeckContext& context) {
  if (const auto line = optional_line(reader, "Ipri, Ioutp, OutyyFMT, Irootyy, Idrot")) {
    line->integer(1, 10, "Ipri");
    unused_columns(*line, 11, "blank or 0 in columns 11-20");
    line->integer(21, 10, "Igtyp");
    line->integer(31, 10, "Ioutp");
    line->integer(41, 10, "OutyyFMT");
    line->integer(51, 10, "Irootyy");
    // Idrot forces rotational degrees of freedom on nodes that have none (solid-only nodes): a model option.
    const std::int64_t idrot = line->integer(61, 10, "Idrot");
    if (idrot != 0 && idrot != 1) line->fail(61, 10, "Idrot", "0 or 1");
    if (idrot == 1)
      context.unsupported(
          line->error(61, 10, "Idrot", default_only("forcing rotational degrees of freedom (Idrot = 1) is")));
  }
  output_only_card(reader, context, "the starter printout level and the STY model file are Crumple's own");
}

// /SPMD: Domdec (1-10), Nproc (11-20), Dkword (31-40), Nthread (51-60): domain decomposition and threads.
void read_spmd(CardReader& reader, DeckContext& context) {
  if (const auto line = optional_line(reader, "Domdec, Nproc, Dkword, Nthread")) {
    line->integer(1, 10, "Domdec");
    line->integer(11, 10, "Nproc");
    line->integer(31, 10, "Dkword");
    line->integer(51, 10, "Nthread");
  }
  performance_card(reader, context);
}

// /PROC (starter or engine, /PROC/n/...): processor counts. /MEMORY: memory sizes.
void read_performance_card(CardReader& reader, DeckContext& context) {
  // The values only size the run on the machine: read as text, whatever they are.
  while (auto line = reader.next_nonblank()) line->text(1, static_cast<int>(line->content().size()));
  performance_card(reader, context);
}

// /RANDOM: Xalea (1-20), Seed (21-40): every node moved by up to Xalea along each axis (resolve.cpp). The
// /RANDOM/GRNOD/id form, noise on one group's nodes, is refused with a noise.
void read_random(CardReader& reader, DeckContext& context) {
  const bool on_group = reader.card().path.size() > 1;
  if (const auto line = optional_line(reader, "Xalea, Seed")) {
    const double noise = line->real(1, 20, "Xalea", dim::length);
    if (noise < 0.0) line->fail(1, 20, "Xalea", "a noise amplitude >= 0");
    const double seed = line->real(21, 20, "Seed", dim::none);
    if (seed < 0.0 || seed >= 1.0) line->fail(21, 20, "Seed", "a seed in [0, 1)");
    if (noise != 0.0 && on_group)
      context.unsupported(line->error(1, 20, "Xalea", default_only("random noise on a node group (/RANDOM/GRNOD) is")));
    context.model.random_noise = noise, context.model.random_seed = seed;
  }
}

// /SHFRA/V4 or /SHFRA/V5: how the shell local frame is built. It orients orthotropic materials (none in Crumple)
// and the element-frame stress output (Crumple writes its own element frame).
void read_shfra(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  if (path.size() != 2 || (path[1] != "V4" && path[1] != "V5"))
    reader.fail("keyword", "/SHFRA/V4 or /SHFRA/V5", in_quotes(reader.card().keyword));
  reader.finish();
  output_only_card(reader, context,
                   "the shell frame orients only orthotropic materials (none in Crumple) and element-frame output");
}

// /AMS: grpart_ID (1-10), the part group advanced mass scaling acts on when the engine deck has /DT/AMS; 0 or
// blank: the whole model. Without /DT/AMS the card does nothing, as in the reference solver.
void read_ams(CardReader& reader, DeckContext& context) {
  if (context.model.ams_selected) reader.fail("", "a single /AMS card", "a second one");
  if (const auto line = optional_line(reader, "grpart_ID")) {
    const std::int64_t group = line->id(1, 10, "grpart_ID", IdKind::Other);
    if (group < 0) line->fail(1, 10, "grpart_ID", "a non-negative part group id (0 or blank: the whole model)");
    if (group != 0)
      context.unsupported(line->error(1, 10, "grpart_ID", default_only("selective mass scaling on a part group is")));
  }
  context.model.ams_selected = true;
  context.model.ams_where = reader.card().where;
}

// /DEF_SHELL (docs/cards/starter-model.md §3): only the first card counts, as in the reference solver.
void read_def_shell(CardReader& reader, DeckContext& context) {
  ShellDefaults& d = context.model.shell_defaults;
  if (reader.at_end()) return;
  const Line line = reader.next("Ishell, Ismstr, Ithick, Iplas, Istrain, Ish3n, Idrill");
  if (d.where.line != 0) {
    context.warn(line.where(), "/DEF_SHELL",
                 fmt::format("ignored: only the first /DEF_SHELL counts ({}:{})", d.where.file, d.where.line));
    while (reader.has_data()) reader.next("ignored /DEF_SHELL line");
    return;
  }
  using namespace shell_flags;
  d.where = line.where();
  d.ishell = static_cast<int>(line.integer(1, 10, "Ishell"));
  d.ismstr = static_cast<int>(line.integer(11, 10, "Ismstr"));
  d.ithick = static_cast<int>(line.integer(21, 10, "Ithick"));
  d.iplas = static_cast<int>(line.integer(31, 10, "Iplas"));
  d.istrain = static_cast<int>(line.integer(41, 10, "Istrain"));
  d.ish3n = static_cast<int>(line.integer(71, 10, "I_SH3N"));
  d.idrill = static_cast<int>(line.integer(81, 10, "Idrill"));
  check_ishell(line, 1, d.ishell);
  check_ismstr(line, 11, d.ismstr);
  check_ithick(line, 21, d.ithick);
  check_iplas(line, 31, d.iplas);
  check_istrain(line, 41, d.istrain);
  require_blank_or_zero(line, 51, "Ioffset", "a shell offset");
  if (!one_of(d.ish3n, {0, 1, 2, 30, 31})) line.fail(71, 10, "I_SH3N", "a 3-node shell formulation: 0, 1, 2, 30 or 31");
  check_idrill(line, 81, d.idrill);
  require_blank_or_zero(line, 91, "Islice", "drape thinning");
  if (d.istrain == 1)
    context.warn(line.where(), "/DEF_SHELL", "Istrain 1 (strain output) has no effect: Crumple writes no strain output");
  reader.finish();
}

// /DEF_SOLID: Isolid 1-10, Ismstr 11-20, Icpre 21-30 (blank in the 2019 layout), Istrain 31-40 (2019 layout),
// Itetra4 41-50, Itetra10 51-60, Imas 61-70, Iframe 71-80. The tetrahedron fields concern /TETRA4 and /TETRA10
// elements, which Crumple does not read; Istrain is an output flag.
void read_def_solid(CardReader& reader, DeckContext& context) {
  SolidDefaults& d = context.model.solid_defaults;
  if (reader.at_end()) return;
  const Line line = reader.next("Isolid, Ismstr, Icpre, Istrain, Itetra4, Itetra10, Imas, Iframe");
  d.where = line.where();
  d.isolid = static_cast<int>(line.integer(1, 10, "Isolid"));
  d.ismstr = static_cast<int>(line.integer(11, 10, "Ismstr"));
  if (d.ismstr < 0 || d.ismstr > 4)
    line.fail(11, 10, "Ismstr",
              "0 (default, 4), 1 or 3 (small strain from t = 0), 2 (switchable by /DT/BRICK/CST) or 4 (large "
              "strain); the automatic -1, -2 and the total-strain 10, 11, 12 are not supported by Crumple");
  d.icpre = static_cast<int>(line.integer(21, 10, "Icpre"));
  if (d.icpre < 0 || d.icpre > 3)
    line.fail(21, 10, "Icpre",
              "0 (default), 1 (constant pressure), 2 (a share that follows plasticity) or 3 (none); the automatic "
              "-1, -2 are not supported by Crumple");
  d.istrain = static_cast<int>(line.integer(31, 10, "Istrain"));
  const auto warn_if = [&](int column, std::string_view name, std::string_view why) {
    if (const auto value = line.integer(column, 10, name); value != 0)
      context.warn(line.where(), reader.card().keyword, fmt::format("{} = {}: {}", name, value, why));
  };
  warn_if(31, "Istrain", "strain output flag; Crumple's output does not depend on it");
  warn_if(41, "Itetra4", "applies to /TETRA4 elements only; no effect on bricks");
  warn_if(51, "Itetra10", "applies to /TETRA10 elements only; no effect on bricks");
  warn_if(61, "Imas", "nodal mass distribution of tetrahedra only; no effect on bricks");
  d.iframe = static_cast<int>(line.integer(71, 10, "Iframe"));
  if (d.iframe < 0 || d.iframe > 2) line.fail(71, 10, "Iframe", "0 (default), 1 (non co-rotational) or 2 (co-rotational)");
  reader.finish();
}

}  // namespace

void register_control_keywords(KeywordTable& table) {
  table.push_back({"/BEGIN", DeckPart::Starter, read_begin, true});
  table.push_back({"/UNIT", DeckPart::Starter, read_unit, true});
  table.push_back({"/TITLE", DeckPart::Starter, read_title_card});
  table.push_back({"/DEF_SHELL", DeckPart::Starter, read_def_shell, true});
  table.push_back({"/DEF_SOLID", DeckPart::Starter, read_def_solid});
  table.push_back({"/ANALY", DeckPart::Starter, read_analy});
  table.push_back({"/IOFLAG", DeckPart::Starter, read_ioflag});
  table.push_back({"/SPMD", DeckPart::Starter, read_spmd});
  table.push_back({"/PROC", DeckPart::Starter, read_performance_card});
  table.push_back({"/PROC", DeckPart::Engine, read_performance_card});
  table.push_back({"/MEMORY", DeckPart::Starter, read_performance_card});
  table.push_back({"/RANDOM", DeckPart::Starter, read_random, true});
  table.push_back({"/SHFRA", DeckPart::Starter, read_shfra, true});
  table.push_back({"/AMS", DeckPart::Starter, read_ams, true});
  // A version stamp without data: accepted without effect (listed by `crumple check`).
  table.push_back({"/VERS", DeckPart::Starter, {}});
}

}  // namespace crumple::deck
