// /PROP/TYPE1 (SHELL) and /PROP/TYPE14 (SOLID). Layouts: docs/cards/starter-model.md.
#include "../context.hpp"

namespace crumple::deck {
namespace {

Property begin_property(CardReader& reader, PropertyKind kind) {
  Property p;
  p.where = reader.card().where;
  p.kind = kind;
  p.user_id = object_id(reader, 2);
  require_no_unit_id(reader, 3);
  p.title = read_title(reader);
  return p;
}

void read_shell_property(CardReader& reader, DeckContext& context) {
  Property p = begin_property(reader, PropertyKind::Shell);
  ShellSection& s = p.shell;
  const Line flags = reader.next("Ishell, Ismstr, Ish3n, Idrill");
  s.ishell = static_cast<int>(flags.integer(1, 10, "Ishell"));
  s.ismstr = static_cast<int>(flags.integer(11, 10, "Ismstr"));
  s.ish3n = static_cast<int>(flags.integer(21, 10, "Ish3n"));
  s.idrill = static_cast<int>(flags.integer(31, 10, "Idrill"));
  flags.real(61, 20, "P_thick_fail", dim::none);
  const Line hourglass = reader.next("hm, hf, hr, dm, dn");
  s.hm = hourglass.real(1, 20, "hm", dim::none);
  s.hf = hourglass.real(21, 20, "hf", dim::none);
  s.hr = hourglass.real(41, 20, "hr", dim::none);
  s.dm = hourglass.real(61, 20, "dm", dim::none);
  s.dn = hourglass.real(81, 20, "dn", dim::none);
  for (auto [value, column, name] : {std::tuple{s.hm, 1, "hm"}, std::tuple{s.hf, 21, "hf"},
                                     std::tuple{s.hr, 41, "hr"}, std::tuple{s.dm, 61, "dm"},
                                     std::tuple{s.dn, 81, "dn"}})
    if (value < 0.0) hourglass.fail(column, 20, name, "a non-negative coefficient");
  const Line section = reader.next("N, Istrain, Thick, Ashear, Ithick, Iplas");
  s.n_points = static_cast<int>(section.integer(1, 10, "N"));
  s.istrain = static_cast<int>(section.integer(11, 10, "Istrain"));
  s.thickness = section.real(21, 20, "Thick", dim::length);
  s.ashear = section.real(41, 20, "Ashear", dim::none);
  s.ithick = static_cast<int>(section.integer(61, 10, "Ithick"));
  s.iplas = static_cast<int>(section.integer(71, 10, "Iplas"));
  if (s.n_points < 0 || s.n_points > 10) section.fail(1, 10, "N", "0 (default) to 10 integration points");
  if (s.thickness <= 0.0) section.fail(21, 20, "Thick", "a positive shell thickness");
  if (s.ashear < 0.0) section.fail(41, 20, "Ashear", "a non-negative shear factor");
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

constexpr const char* kIcpreChoices =
    "0 (default), 1 (constant pressure) or 3 (none); 2 (plasticity-dependent pressure) and the automatic -1, -2 are "
    "not supported by Crumple";

void read_solid_property(CardReader& reader, DeckContext& context) {
  Property p = begin_property(reader, PropertyKind::Solid);
  SolidSection& s = p.solid;
  if (!reader.at_end()) {
    const Line flags = reader.next("Isolid, Ismstr, Icpre, Itetra4, Itetra10, Imass, Iframe");
    s.isolid = static_cast<int>(flags.integer(1, 10, "Isolid"));
    s.ismstr = static_cast<int>(flags.integer(11, 10, "Ismstr"));
    s.icpre = static_cast<int>(flags.integer(31, 10, "Icpre"));
    if (s.icpre != 0 && s.icpre != 1 && s.icpre != 3)
      flags.fail(31, 10, "Icpre", kIcpreChoices);
    s.inpts = static_cast<int>(flags.integer(51, 10, "Inpts"));
    s.iframe = static_cast<int>(flags.integer(71, 10, "Iframe"));
  }
  if (!reader.at_end()) {
    const Line viscosity = reader.next("q_a, q_b, h, LAMBDA_v, MU_v");
    s.qa = viscosity.real(1, 20, "q_a", dim::none);
    s.qb = viscosity.real(21, 20, "q_b", dim::none);
    s.h = viscosity.real(41, 20, "h", dim::none);
    if (s.qa < 0.0) viscosity.fail(1, 20, "q_a", "a non-negative bulk viscosity coefficient");
    if (s.qb < 0.0) viscosity.fail(21, 20, "q_b", "a non-negative bulk viscosity coefficient");
    if (s.h < 0.0) viscosity.fail(41, 20, "h", "a non-negative hourglass coefficient");
  }
  while (reader.has_data()) reader.next("optional solid property line");  // time-step and Ndir lines: unused
  context.model.properties.push_back(std::move(p));
}

}  // namespace

void register_property_keywords(KeywordTable& table) {
  table.push_back({"/PROP/TYPE1", DeckPart::Starter, read_shell_property});
  table.push_back({"/PROP/SHELL", DeckPart::Starter, read_shell_property});
  table.push_back({"/PROP/TYPE14", DeckPart::Starter, read_solid_property});
  table.push_back({"/PROP/SOLID", DeckPart::Starter, read_solid_property});
}

}  // namespace crumple::deck
