// /INTER/TYPE7: node-to-surface contact. Fields: ../shared/spec/type7.md §1; exact columns, defaults and the
// conditional lines: docs/cards/loads-output-engine.md §5. The node group and the surface are resolved in
// resolve_output.cpp. Options the contact module does not implement are errors naming the field: a deck that
// asks for them would otherwise run with a different contact than the one its author set up.
#include <fmt/format.h>

#include <array>
#include <initializer_list>
#include <optional>

#include "../context.hpp"

namespace crumple::deck {
namespace {

constexpr int kDefaultCode = 1000;  // the manual's explicit "default" value of Istf, Igap, Idel and Inacti

// Dimensions of the friction-law coefficients (docs of Type7Interface::friction_c).
constexpr Dimension kPerPressure{-1, 1, 2};
constexpr Dimension kPerPressureSquared{-2, 2, 4};
constexpr Dimension kPerVelocity{0, -1, 1};
constexpr Dimension kPerVelocitySquared{0, -2, 2};
constexpr Dimension kPerPressureVelocity{-1, 0, 3};

std::array<Dimension, 6> friction_dimensions(int ifric) {
  switch (ifric) {
    case 1: return {kPerPressure, kPerVelocity, kPerPressureVelocity, kPerPressureSquared, kPerVelocitySquared,
                    dim::none};
    case 2: return {kPerPressureSquared, kPerVelocity, kPerPressure, kPerVelocity, dim::none, kPerVelocity};
    default: return {dim::none, dim::none, dim::none, dim::none, dim::velocity, dim::velocity};
  }
}

// Xfreq is a factor for the simple filter, a period for Ifiltr = 2 and a frequency for Ifiltr = 3.
Dimension filter_dimension(int ifiltr) {
  return ifiltr == 2 ? dim::time : ifiltr == 3 ? dim::rate : dim::none;
}

// A flag that must take one of `allowed`; the manual's 1000 (explicit default) is stored as 0.
int flag(const Line& line, int column, std::string_view name, std::initializer_list<int> allowed,
         std::string_view expected) {
  const std::int64_t value = line.integer(column, 10, name);
  for (int a : allowed)
    if (value == a) return a == kDefaultCode ? 0 : a;
  line.fail(column, 10, name, expected);
}

double non_negative(const Line& line, int column, std::string_view name, Dimension d) {
  const double value = line.real(column, 20, name, d);
  if (value < 0.0) line.fail(column, 20, name, "a non-negative value");
  return value;
}

// A field whose option the contact module does not implement: only 0 (blank) is accepted (--skip-unknown: the
// value is recorded as skipped; the contact then runs without the option).
void require_zero(DeckContext& context, const Line& line, bool non_zero, int column, int width,
                  std::string_view name, std::string_view feature) {
  if (non_zero) context.unsupported(line.error(column, width, name, default_only(feature)));
}

// `/INTER/TYPE7/id[/unit_ID]`
std::int64_t interface_id(CardReader& reader) {
  const std::int64_t id = object_id(reader, 2);
  if (reader.narrow()) {  // input versions 41 to 44: the title follows the id
    reader.title_after(3);
    return id;
  }
  read_unit_id(reader, 3);
  if (reader.card().path.size() > 4)
    reader.fail("keyword", "nothing after the unit id", fmt::format("'{}'", reader.card().path[4]));
  return id;
}

// The data lines, kept so that fields rejected once the whole card is read can be named with their columns.
struct Type7Lines {
  std::optional<Line> flags, gap, stiffness, contact, damping, friction;
};

void read_flags(const Line& line, Type7Interface& i) {
  i.secondary_group_id = line.id(1, 10, "Slav_id", IdKind::Other);
  if (i.secondary_group_id <= 0) line.fail(1, 10, "Slav_id", "a positive node group id (secondary nodes)");
  i.main_surface_id = line.id(11, 10, "Mast_id", IdKind::Other);
  if (i.main_surface_id <= 0) line.fail(11, 10, "Mast_id", "a positive surface id (main surface)");
  i.istf = flag(line, 21, "Istf", {0, 1, 2, 3, 4, 5, kDefaultCode}, "0 to 5, or 1000 (default)");
  i.ithe = flag(line, 31, "Ithe", {0, 1}, "0 or 1");
  i.igap = flag(line, 41, "Igap", {0, 1, 2, kDefaultCode},
                "0, 1, 2 or 1000 (Igap = 3, the mesh-size gap, is not supported by Crumple)");
  line.integer(51, 10, "Multimp");  // checked for a number here, reported by warn_unused
  i.ibag = flag(line, 61, "Ibag", {0, 1, 2}, "0, 1 or 2");
  i.idel = flag(line, 71, "Idel", {0, 1, 2, kDefaultCode},
                "0, 1, 2 or 1000 (negative Idel, keeping orphan secondary nodes, is not supported by Crumple)");
  i.icurv = flag(line, 81, "Icurv", {0, 1, 2, 3}, "0 to 3");
  i.iadm = flag(line, 91, "Iadm", {0, 1, 2}, "0 to 2");
}

void read_gap_line(const Line& line, Type7Interface& i) {
  i.fscale_gap = non_negative(line, 1, "Fscale_gap", dim::none);
  i.gap_max = non_negative(line, 21, "Gap_max", dim::length);
  i.fpenmax = non_negative(line, 41, "Fpenmax", dim::none);
  i.itied = static_cast<int>(line.integer(81, 10, "Itied"));
}

void read_stiffness_line(const Line& line, Type7Interface& i) {
  i.stmin = non_negative(line, 1, "Stmin", dim::stiffness);
  i.stmax = non_negative(line, 21, "Stmax", dim::stiffness);
  if (i.stmax != 0.0 && i.stmax < i.stmin) line.fail(21, 20, "Stmax", "a maximum stiffness not below Stmin");
  i.mesh_size_percent = non_negative(line, 41, "%mesh_size", dim::none);
  i.dtmin = non_negative(line, 61, "dtmin", dim::time);
  i.irem_gap = flag(line, 81, "Irem_gap", {0, 1, 2}, "0, 1 or 2");
  i.irem_i2 = flag(line, 91, "Irem_i2", {0, 1, 3}, "0, 1 or 3");
}

void read_curvature_line(const Line& line, Type7Interface& i) {
  for (int k = 0; k < 2; ++k) {
    const std::string name = fmt::format("node_ID{}", k + 1);
    const std::int64_t id = line.id(1 + 10 * k, 10, name, IdKind::Node);
    if (id < 0) line.fail(1 + 10 * k, 10, name, "a node id or blank");
    i.curvature_node_ids[static_cast<std::size_t>(k)] = id;
  }
}

void read_contact_line(const Line& line, Type7Interface& i) {
  // With Istf = 1 Stfac is the stiffness itself, otherwise a factor on the computed one.
  i.stfac = non_negative(line, 1, "Stfac", i.istf == 1 ? dim::stiffness : dim::none);
  i.fric = non_negative(line, 21, "Fric", dim::none);
  i.gapmin = non_negative(line, 41, "Gapmin", dim::length);
  i.tstart = non_negative(line, 61, "Tstart", dim::time);
  i.tstop = non_negative(line, 81, "Tstop", dim::time);
  if (i.tstop != 0.0 && i.tstop < i.tstart)
    line.fail(81, 20, "Tstop", "a stop time not before Tstart (or blank: never stops)");
}

// IBC is three one-digit flags in columns 8, 9 and 10; Inacti starts at column 31.
void read_damping_line(const Line& line, Type7Interface& i) {
  if (!line.text(1, 7).empty())
    line.fail(1, 7, "IBC", "blank columns 1-7 (the three IBC flags are in columns 8, 9 and 10)");
  constexpr std::array<std::string_view, 3> names{"IBC x", "IBC y", "IBC z"};
  for (std::size_t k = 0; k < 3; ++k) {
    const int column = 8 + static_cast<int>(k);
    const char c = line.raw(column, 1)[0];
    if (c != ' ' && c != '0' && c != '1') line.fail(column, 1, names[k], "0, 1 or blank");
    i.ibc[k] = c == '1';
  }
  if (!line.text(11, 20).empty()) line.fail(11, 20, "Inacti", "blank columns 11-30 (Inacti is in columns 31-40)");
  i.inacti = flag(line, 31, "Inacti", {0, 1, 2, 3, 5, 6, kDefaultCode}, "0, 1, 2, 3, 5, 6 or 1000");
  i.viss = non_negative(line, 41, "VisS", dim::none);
  i.visf = non_negative(line, 61, "VisF", dim::none);
  i.bumult = non_negative(line, 81, "Bumult", dim::none);
}

void read_friction_line(const Line& line, Type7Interface& i) {
  i.ifric = flag(line, 1, "Ifric", {0, 1, 2, 3}, "0 (Coulomb), 1 (generalized viscous), 2 (Darmstad) or 3 (Renard)");
  i.ifiltr = flag(line, 11, "Ifiltr", {0, 1, 2, 3}, "0 (no filter), 1, 2 or 3");
  i.xfreq = non_negative(line, 21, "Xfreq", filter_dimension(i.ifiltr));
  // Radioss quietly drops the filter when Xfreq is 0; asking for a filter without its value is a deck error.
  if (i.ifiltr > 0 && i.xfreq == 0.0) line.fail(21, 20, "Xfreq", "a positive filter coefficient when Ifiltr > 0");
  if (i.ifiltr == 1 && i.xfreq > 1.0) line.fail(21, 20, "Xfreq", "a filter factor in (0, 1] when Ifiltr = 1");
  i.iform = flag(line, 41, "Iform", {0, 1, 2}, "0 (default), 1 (viscous) or 2 (stiffness)");
  i.sensor_id = line.id(51, 10, "sens_ID", IdKind::Other);
  i.friction_function_id = line.id(61, 10, "fct_IDf", IdKind::Other);
  i.ascale_f = line.real(71, 20, "AscaleF", dim::none);
  i.friction_id = line.id(91, 10, "fric_ID", IdKind::Other);
}

// C1..C5 when Ifric > 0, C6 on its own line when Ifric > 1 (the layout the Radioss reader uses).
void read_friction_law(CardReader& reader, Type7Interface& i) {
  if (i.ifric == 0) return;
  const auto dims = friction_dimensions(i.ifric);
  const Line first = reader.next(fmt::format("C1..C5 (Ifric = {})", i.ifric));
  for (std::size_t k = 0; k < 5; ++k)
    i.friction_c[k] = first.real(1 + 20 * static_cast<int>(k), 20, fmt::format("C{}", k + 1), dims[k]);
  if (i.ifric == 1) return;
  const Line second = reader.next(fmt::format("C6 (Ifric = {})", i.ifric));
  i.friction_c[5] = second.real(1, 20, "C6", dims[5]);
  // Renard (eq. C-9c): the curve is defined between the critical speeds 0 < C5 < C6.
  if (i.ifric == 3 && !(i.friction_c[4] > 0.0))
    first.fail(81, 20, "C5", "a positive first critical speed Vcr1 when Ifric = 3");
  if (i.ifric == 3 && !(i.friction_c[5] > i.friction_c[4]))
    second.fail(1, 20, "C6", "a second critical speed Vcr2 above C5 when Ifric = 3");
}

void read_adaptive_line(const Line& line, Type7Interface& i) {
  i.nradm = static_cast<int>(line.integer(1, 10, "NRadm"));
  i.padm = line.real(11, 20, "Padm", dim::none);
  i.angladm = line.real(31, 20, "Angladm", dim::none);
}

void reject_unsupported(const Type7Lines& l, Type7Interface& i, DeckContext& context) {
  auto reject = [&](const Line& line, auto& value, int column, int width, std::string_view name,
                    std::string_view feature) {
    require_zero(context, line, value != 0, column, width, name, feature);
    value = 0;
  };
  reject(*l.flags, i.ithe, 31, 10, "Ithe", "thermal contact is");
  // Ibag closes airbag vents on contact; Crumple has no airbags (/MONVOL), so any value asks for something absent.
  reject(*l.flags, i.ibag, 61, 10, "Ibag", "airbag vent closure is");
  reject(*l.flags, i.icurv, 81, 10, "Icurv", "curved gap envelopes are");
  reject(*l.flags, i.iadm, 91, 10, "Iadm", "adaptive meshing is");
  if (l.gap) {  // input versions 41 to 44 have neither the gap nor the stiffness line
    reject(*l.gap, i.fpenmax, 41, 20, "Fpenmax", "deactivation by initial penetration depth is");
    reject(*l.gap, i.itied, 81, 10, "Itied", "tied contact is");
  }
  if (l.stiffness) {
    reject(*l.stiffness, i.mesh_size_percent, 41, 20, "%mesh_size", "the mesh-size gap (Igap = 3) is");
    if (i.irem_gap == 2) {
      require_zero(context, *l.stiffness, true, 81, 10, "Irem_gap",
                   "removing nodes whose elements are smaller than the gap (Irem_gap = 2) is");
      i.irem_gap = 0;
    }
  }
  // Irem_i2 1 takes the /INTER/TYPE2 tied nodes out of this contact's secondary nodes (contact/setup.cpp); 0 and 3
  // keep them (measured: the reference's starter resolves 0 to 3 in an explicit run).
  if (!l.friction) return;  // input version 41 has no friction line
  reject(*l.friction, i.friction_function_id, 61, 10, "fct_IDf", "friction-temperature functions are");
  // AscaleF only scales fct_IDf; 1 is its default and changes nothing.
  if (i.ascale_f != 0.0 && i.ascale_f != 1.0) {
    require_zero(context, *l.friction, true, 71, 20, "AscaleF", "friction-temperature functions (AscaleF) are");
    i.ascale_f = 0.0;
  }
  reject(*l.friction, i.friction_id, 91, 10, "fric_ID", "/FRICTION definitions are");
}

// Values that Radioss reads but does not use with the other flags given: say so rather than drop them quietly.
void warn_unused(const Type7Lines& l, const Type7Interface& i, DeckContext& context, const std::string& keyword) {
  auto warn = [&](const Line& line, std::string message) { context.warn(line.where(), keyword, std::move(message)); };
  // Columns 51-60 held Multimp, a memory-sizing hint of old decks that Radioss itself no longer reads.
  if (l.flags->integer(51, 10, "Multimp") != 0)
    context.note(l.flags->where(), keyword, "Multimp (columns 51-60)",
                 "performance hint: an obsolete memory-sizing hint, no effect on Crumple's results",
                 SkipKind::PerformanceHint);
  if (l.gap && i.fscale_gap != 0.0 && i.igap != 2) warn(*l.gap, "Fscale_gap is used only with Igap = 2; ignored");
  if (l.gap && i.gap_max != 0.0 && i.igap == 0)
    warn(*l.gap, "Gap_max is used only with a variable gap (Igap = 1, 2); ignored");
  if (l.stiffness && (i.stmin != 0.0 || i.stmax != 0.0) && i.istf == 1)
    warn(*l.stiffness, "Stmin and Stmax are not used when Istf = 1 (Stfac is the stiffness); ignored");
  if (i.visf != 0.0 && i.iform == 2) warn(*l.damping, "VisF is not used with Iform = 2 (stiffness friction); ignored");
  if (i.visf != 0.0 && i.fric == 0.0) warn(*l.damping, "VisF acts only with friction (Fric > 0); ignored");
  if (l.friction && i.xfreq != 0.0 && i.ifiltr == 0)
    warn(*l.friction, "Xfreq acts only with a friction filter (Ifiltr > 0); ignored");
  // Bumult sizes the search's buckets: how fast the pairs are found, not which.
  if (i.bumult != 0.0)
    context.note(l.damping->where(), keyword, "Bumult",
                 "performance hint: the search's bucket size, no effect on the pairs found", SkipKind::PerformanceHint);
}

// Input versions 41 to 44 (docs/deck-format.md, "Input versions") write the flags, contact, damping and (44) friction
// lines only, narrowed: the gap and stiffness lines' fields keep their defaults.
void read_type7(CardReader& reader, DeckContext& context) {
  Type7Interface i;
  i.where = reader.card().where;
  i.user_id = interface_id(reader);
  i.title = read_title(reader);
  Type7Lines l;
  l.flags = reader.next("Slav_id, Mast_id, Istf, Ithe, Igap, Ibag, Idel, Icurv, Iadm");
  read_flags(*l.flags, i);
  if (!reader.narrow()) {
    l.gap = reader.next("Fscale_gap, Gap_max, Fpenmax");
    read_gap_line(*l.gap, i);
    l.stiffness = reader.next("Stmin, Stmax, %mesh_size, dtmin, Irem_gap, Irem_i2");
    read_stiffness_line(*l.stiffness, i);
  }
  if (i.icurv == 1 || i.icurv == 2) read_curvature_line(reader.next("node_ID1, node_ID2 (Icurv = 1, 2)"), i);
  l.contact = reader.next("Stfac, Fric, Gapmin, Tstart, Tstop");
  read_contact_line(*l.contact, i);
  l.damping = reader.next("IBC, Inacti, VisS, VisF, Bumult");
  read_damping_line(*l.damping, i);
  if (!(reader.narrow() && reader.at_end())) {
    l.friction = reader.next("Ifric, Ifiltr, Xfreq, Iform, sens_ID, fct_IDf, AscaleF, fric_ID");
    read_friction_line(*l.friction, i);
    // Version 44's friction line has no coefficient lines after it: a friction law there is refused.
    if (reader.narrow() && i.ifric != 0)
      l.friction->fail(1, 10, "Ifric", "0 (the friction laws' coefficients of input versions 41 to 44 are not read by "
                                       "Crumple)");
    read_friction_law(reader, i);
  }
  if (i.iadm == 2) read_adaptive_line(reader.next("NRadm, Padm, Angladm (Iadm = 2)"), i);
  // Checked once every line is placed, so that an option with extra lines (Ithe's thermal lines) is reported
  // by its name rather than as a stray data line.
  reject_unsupported(l, i, context);
  reader.finish();
  warn_unused(l, i, context, reader.card().keyword);
  context.model.type7_interfaces.push_back(std::move(i));
}

// /INTER/TYPE2 line 1 (docs/cards/loads-output-engine.md §5b). Input versions before 110 have no Ignore field:
// its columns are blank in their layout and are not read.
void read_type2_line(const Line& line, Type2Interface& i, int input_version, DeckContext& context) {
  i.secondary_group_id = line.id(1, 10, "grnd_IDs", IdKind::Other);
  if (i.secondary_group_id <= 0) line.fail(1, 10, "grnd_IDs", "a positive node group id (the tied nodes)");
  i.main_surface_id = line.id(11, 10, "surf_IDm", IdKind::Other);
  if (i.main_surface_id <= 0) line.fail(11, 10, "surf_IDm", "a positive surface id (the main surface)");
  if (input_version >= 110 || input_version == 0)
    i.ignore = flag(line, 21, "Ignore", {0, 1, 2, 3, kDefaultCode}, "0, 1, 2, 3 or 1000");
  else
    line.raw(21, 10);  // blank in these layouts; the reference does not read it
  const std::int64_t spotflag = line.integer(31, 10, "Spotflag");
  if (spotflag != 0 && spotflag != 1 && spotflag != 2 && spotflag != 4 && spotflag != 5)
    context.unsupported(line.error(31, 10, "Spotflag",
                                   "0, 1, 2, 4 or 5 (the formulations with failure, 20 to 22, and the penalty ones, "
                                   "25 to 28 and 30, are not supported by Crumple)"));
  else
    i.spotflag = static_cast<int>(spotflag);
  // Level orders the solution of chained ties; the reference refuses chained kinematic ties whatever their levels
  // and gives the others the same answer at every Level (measured): a named warning.
  if (line.integer(41, 10, "Level") != 0)
    context.warn(line.where(), "/INTER/TYPE2", "Level: no effect (ties of ties are refused; every other tie is solved "
                                               "alike at any hierarchy level, as in the reference)");
  i.isearch = flag(line, 51, "Isearch", {0, 1, 2}, "0, 1 or 2");
  require_zero(context, line, i.isearch == 1, 51, 10, "Isearch", "the old search (Isearch 1) is");
  i.idel2 = flag(line, 61, "Idel2", {0, 1, 2, kDefaultCode}, "0, 1, 2 or 1000");
  if (i.idel2 != 0 && i.spotflag == 2) {  // measured: the reference sets it to 1000 with Spotflag 2, and says nothing
    context.warn(line.where(), "/INTER/TYPE2", "Idel2: no effect with Spotflag 2 (the reference keeps such ties when "
                                               "their main elements are deleted)");
    i.idel2 = 0;
  }
  i.dsearch = non_negative(line, 81, "dsearch", dim::length);
}

// `/INTER/TYPE2/id[/unit_ID]`: a tie of nodes to a surface (docs/theory/tied-interfaces.md).
void read_type2(CardReader& reader, DeckContext& context) {
  Type2Interface i;
  i.where = reader.card().where;
  i.user_id = interface_id(reader);
  i.title = read_title(reader);
  read_type2_line(reader.next("grnd_IDs, surf_IDm, Ignore, Spotflag, Level, Isearch, Idel2, dsearch"), i,
                  context.model.input_version, context);
  // The optional heat-transfer line (Ithe, Kthe, Iproj): thermal ties are not supported.
  if (reader.has_data()) {
    const Line heat = reader.next("Ithe, Kthe, Iproj");
    require_zero(context, heat, heat.integer(1, 10, "Ithe") != 0, 1, 10, "Ithe", "heat transfer through ties is");
    require_zero(context, heat, heat.real(11, 20, "Kthe", dim::none) != 0.0, 11, 20, "Kthe",
                 "heat transfer through ties is");
    heat.integer(91, 10, "Iproj");  // where a thermal tie projects its nodes: nothing without heat transfer
  }
  reader.finish();
  context.model.type2_interfaces.push_back(std::move(i));
}

}  // namespace

void register_interface_keywords(KeywordTable& table) {
  table.push_back({"/INTER/TYPE7", DeckPart::Starter, read_type7});
  table.push_back({"/INTER/TYPE2", DeckPart::Starter, read_type2});
}

}  // namespace crumple::deck
