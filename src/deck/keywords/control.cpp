// /BEGIN, /TITLE, /DEF_SHELL, /DEF_SOLID and the control keywords accepted without effect.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "../context.hpp"

namespace crumple::deck {
namespace {

void read_begin(CardReader& reader, DeckContext& context) {
  if (context.begin_seen) reader.fail("", "a single /BEGIN", "a second /BEGIN");
  context.begin_seen = true;
  Model& model = context.model;
  model.run_name = reader.next("Runname").text(1, 80);
  const Line version = reader.next("Invers, Irun");
  model.input_version = static_cast<int>(version.integer(1, 10, "Invers"));
  version.integer(11, 10, "Irun");
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
  // Every conversion factor (up to the cube of a unit, as in a density) must stay finite and non-zero: with an
  // infinite factor a blank field (0 x inf) reads as NaN and passes every range check of its card.
  const UnitSystem u = model.units;
  for (int mass = -3; mass <= 3; ++mass)
    for (int length = -3; length <= 3; ++length)
      for (int time = -3; time <= 3; ++time)
        if (const double f = u.factor(Dimension{mass, length, time}); !std::isfinite(f) || f == 0.0) {
          model.units = UnitSystem{};  // the rest of the deck is read in SI rather than reporting every field
          reader.fail("units", "input and working units whose conversion factors stay finite and non-zero",
                      fmt::format("input/working size ratios {:g} (mass), {:g} (length), {:g} (time)",
                                  u.input[0] / u.work[0], u.input[1] / u.work[1], u.input[2] / u.work[2]));
        }
  reader.finish();
}

void read_title_card(CardReader& reader, DeckContext& context) {
  context.model.title = read_title(reader);
}

void read_def_shell(CardReader& reader, DeckContext& context) {
  ShellDefaults& d = context.model.shell_defaults;
  if (reader.at_end()) return;
  const Line line = reader.next("Ishell, Ismstr, Ithick, Iplas, Istrain, Ish3n, Idrill");
  d.ishell = static_cast<int>(line.integer(1, 10, "Ishell"));
  d.ismstr = static_cast<int>(line.integer(11, 10, "Ismstr"));
  d.ithick = static_cast<int>(line.integer(21, 10, "Ithick"));
  d.iplas = static_cast<int>(line.integer(31, 10, "Iplas"));
  d.istrain = static_cast<int>(line.integer(41, 10, "Istrain"));
  d.ish3n = static_cast<int>(line.integer(71, 10, "Ish3n"));
  d.idrill = static_cast<int>(line.integer(81, 10, "Idrill"));
  reader.finish();
}

// /DEF_SOLID: Isolid 1-10, Ismstr 11-20, Icpre 21-30 (blank in the 2019 layout), Istrain 31-40 (2019 layout),
// Itetra4 41-50, Itetra10 51-60, Imas 61-70, Iframe 71-80. The tetrahedron fields concern /TETRA4 and /TETRA10
// elements, which Crumple does not read; Istrain is an output flag.
void read_def_solid(CardReader& reader, DeckContext& context) {
  SolidDefaults& d = context.model.solid_defaults;
  if (reader.at_end()) return;
  const Line line = reader.next("Isolid, Ismstr, Icpre, Istrain, Itetra4, Itetra10, Imas, Iframe");
  d.isolid = static_cast<int>(line.integer(1, 10, "Isolid"));
  d.ismstr = static_cast<int>(line.integer(11, 10, "Ismstr"));
  if (d.ismstr < 0 || d.ismstr > 4)
    line.fail(11, 10, "Ismstr",
              "0 (default, 4), 1 or 3 (small strain from t = 0), 2 (switchable by /DT/BRICK/CST) or 4 (large "
              "strain); the automatic -1, -2 and the total-strain 10, 11, 12 are not supported by Crumple");
  d.icpre = static_cast<int>(line.integer(21, 10, "Icpre"));
  if (d.icpre != 0 && d.icpre != 1 && d.icpre != 3)
    line.fail(21, 10, "Icpre",
              "0 (default), 1 (constant pressure) or 3 (none); 2 (plasticity-dependent pressure) and the automatic "
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
  table.push_back({"/BEGIN", DeckPart::Starter, read_begin});
  table.push_back({"/TITLE", DeckPart::Starter, read_title_card});
  table.push_back({"/DEF_SHELL", DeckPart::Starter, read_def_shell});
  table.push_back({"/DEF_SOLID", DeckPart::Starter, read_def_solid});
  // Accepted with no effect on results (deck.md); /RANDOM in particular must not perturb: runs stay deterministic.
  for (std::string_view name : {"/ANALY", "/IOFLAG", "/SPMD", "/PROC", "/RANDOM", "/SHFRA", "/VERS", "/MEMORY"})
    table.push_back({name, DeckPart::Starter, {}});
}

}  // namespace crumple::deck
