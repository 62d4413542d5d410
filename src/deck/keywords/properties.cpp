// /PROP/TYPE1 (SHELL), /PROP/TYPE14 (SOLID), the springs (/PROP/TYPE4, TYPE8, TYPE13), /PROP/TYPE2 (TRUSS) and
// /PROP/TYPE3 (BEAM). Layouts: docs/cards/starter-model.md.
#include <fmt/format.h>

#include <cmath>
#include <utility>
#include <tuple>

#include "../context.hpp"
#include "shell_flags.hpp"

namespace crumple::deck {
namespace {

using namespace shell_flags;

Property begin_property(CardReader& reader, PropertyKind kind) {
  Property p;
  p.where = reader.card().where;
  p.kind = kind;
  p.user_id = object_id(reader, 2);
  read_unit_id(reader, 3);
  p.title = read_title(reader);
  return p;
}

void read_shell_flags(const Line& flags, ShellSection& s) {
  s.ishell = static_cast<int>(flags.integer(1, 10, "Ishell"));
  s.ismstr = static_cast<int>(flags.integer(11, 10, "Ismstr"));
  s.ish3n = static_cast<int>(flags.integer(21, 10, "Ish3n"));
  s.idrill = static_cast<int>(flags.integer(31, 10, "Idrill"));
  check_ishell(flags, 1, s.ishell);
  check_ismstr(flags, 11, s.ismstr);
  if (!one_of(s.ish3n, {0, 1, 2, 30, 31}))
    flags.fail(21, 10, "Ish3n", "a 3-node shell formulation: 0 (/DEF_SHELL), 1, 2, 30 or 31");
  check_idrill(flags, 31, s.idrill);
  require_blank_or_zero(flags, 41, "Ipinch", "the pinching degree of freedom");
  // P_thick_fail 0 means "every point": an element goes when all its points failed (resolve_definitions.cpp
  // refuses the cases where Crumple, which deletes at the first failed point, would differ).
  if (flags.real(61, 20, "P_thick_fail", dim::none) != 0.0)
    flags.fail(61, 20, "P_thick_fail", "0 (an element is deleted when its points fail; another fraction of failed "
                                       "points is not supported by Crumple)");
}

void read_shell_section(const Line& section, ShellSection& s) {
  s.n_points = static_cast<int>(section.integer(1, 10, "N"));
  s.istrain = static_cast<int>(section.integer(11, 10, "Istrain"));  // strain output only
  check_istrain(section, 11, s.istrain);
  s.thickness = section.real(21, 20, "Thick", dim::length);
  s.ashear = section.real(41, 20, "Ashear", dim::none);
  s.ithick = static_cast<int>(section.integer(71, 10, "Ithick"));
  s.iplas = static_cast<int>(section.integer(81, 10, "Iplas"));
  if (s.n_points < 0 || s.n_points > 10) section.fail(1, 10, "N", "0 (default) to 10 integration points");
  if (s.thickness <= 0.0) section.fail(21, 20, "Thick", "a positive shell thickness");
  if (s.ashear < 0.0) section.fail(41, 20, "Ashear", "a non-negative shear factor");
  check_ithick(section, 71, s.ithick);
  check_iplas(section, 81, s.iplas);
  require_blank_or_zero(section, 91, "Ipos", "a shell offset");
}

void read_shell_property(CardReader& reader, DeckContext& context) {
  Property p = begin_property(reader, PropertyKind::Shell);
  ShellSection& s = p.shell;
  const Line flags = reader.next("Ishell, Ismstr, Ish3n, Idrill, P_thick_fail");
  s.flags_where = flags.where();
  read_shell_flags(flags, s);
  const Line hourglass = reader.next("hm, hf, hr, dm, dn");
  s.damping_where = hourglass.where();
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
  s.section_where = section.where();
  read_shell_section(section, s);
  if (s.istrain == 1)
    context.warn(section.where(), reader.card().keyword,
                 "Istrain 1 (strain output) has no effect: Crumple writes no strain output");
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

constexpr const char* kIcpreChoices =
    "0 (default), 1 (constant pressure), 2 (a share that follows plasticity) or 3 (none); the automatic -1, -2 are "
    "not supported by Crumple";
constexpr const char* kIsmstrChoices =
    "0 (default, 4), 1 or 3 (small strain from t = 0), 2 (switchable by /DT/BRICK/CST) or 4 (large strain); the "
    "automatic -1, -2 and the total-strain 10, 11, 12 are not supported by Crumple";

// A field that only matters for elements Crumple does not read (tetrahedra) or only for output: a named warning
// when it is set.
void note_if_set(const Line& line, DeckContext& context, const CardReader& reader, std::int64_t value,
                 std::string_view name, std::string_view why) {
  if (value != 0)
    context.warn(line.where(), reader.card().keyword, fmt::format("{} = {}: {}", name, value, why));
}

// /PROP/SOLID line 1 in input versions 41 to 44: Isolid 1-8, Ismstr 9-16, then (44) Iplas 17-24, Icpre 25-32,
// Icstr 33-40, dn 41-56. Iplas and Icstr have no field in later versions: anything but 0 is refused.
void read_narrow_solid_flags(CardReader& reader, DeckContext& context, SolidSection& s) {
  const Line flags = reader.next("Isolid, Ismstr, Iplas, Icpre, Icstr, dn").as_written();
  s.isolid = static_cast<int>(flags.integer(1, 8, "Isolid"));
  s.ismstr = static_cast<int>(flags.integer(9, 8, "Ismstr"));
  if (s.ismstr < 0 || s.ismstr > 4) flags.fail(9, 8, "Ismstr", kIsmstrChoices);
  for (const auto& [column, name] : {std::pair{17, "Iplas"}, std::pair{33, "Icstr"}})
    if (flags.integer(column, 8, name) != 0)
      context.unsupported(flags.error(column, 8, name, default_only("this option of input version 44 is")));
  s.icpre = static_cast<int>(flags.integer(25, 8, "Icpre"));
  if (s.icpre < 0 || s.icpre > 3) flags.fail(25, 8, "Icpre", kIcpreChoices);
  s.dn = flags.real(41, 16, "dn", dim::none);
  if (s.dn < 0.0) flags.fail(41, 16, "dn", "a non-negative numerical damping");
}

// /PROP/SOLID line 1 (2019 layout): Isolid, Ismstr, -, Icpre, Itetra10, Inpts, Itetra4, Iframe, dn.
void read_solid_flags(CardReader& reader, DeckContext& context, SolidSection& s) {
  if (reader.narrow()) return read_narrow_solid_flags(reader, context, s);
  const Line flags = reader.next("Isolid, Ismstr, Icpre, Itetra10, Inpts, Itetra4, Iframe, dn");
  s.isolid = static_cast<int>(flags.integer(1, 10, "Isolid"));
  s.ismstr = static_cast<int>(flags.integer(11, 10, "Ismstr"));
  if (s.ismstr < 0 || s.ismstr > 4) flags.fail(11, 10, "Ismstr", kIsmstrChoices);
  s.icpre = static_cast<int>(flags.integer(31, 10, "Icpre"));
  if (s.icpre < 0 || s.icpre > 3) flags.fail(31, 10, "Icpre", kIcpreChoices);
  note_if_set(flags, context, reader, flags.integer(41, 10, "Itetra10"), "Itetra10",
              "applies to /TETRA10 elements only; no effect on bricks");
  s.inpts = static_cast<int>(flags.integer(51, 10, "Inpts"));
  note_if_set(flags, context, reader, flags.integer(61, 10, "Itetra4"), "Itetra4",
              "applies to /TETRA4 elements only; no effect on bricks");
  s.iframe = static_cast<int>(flags.integer(71, 10, "Iframe"));
  if (s.iframe < 0 || s.iframe > 2) flags.fail(71, 10, "Iframe", "0 (default), 1 (non co-rotational) or 2 (co-rotational)");
  s.dn = flags.real(81, 20, "dn", dim::none);
  if (s.dn < 0.0) flags.fail(81, 20, "dn", "a non-negative numerical damping");
}

// Line 2: q_a, q_b, h, LAMBDA_v, MU_v. The numerical Navier-Stokes viscosity is not implemented.
void read_solid_viscosity(CardReader& reader, SolidSection& s) {
  const Line viscosity = reader.next("q_a, q_b, h, LAMBDA_v, MU_v");
  s.qa = viscosity.real(1, 20, "q_a", dim::none);
  s.qb = viscosity.real(21, 20, "q_b", dim::none);
  s.h = viscosity.real(41, 20, "h", dim::none);
  if (s.qa < 0.0) viscosity.fail(1, 20, "q_a", "a non-negative bulk viscosity coefficient");
  if (s.qb < 0.0) viscosity.fail(21, 20, "q_b", "a non-negative bulk viscosity coefficient");
  if (s.h < 0.0) viscosity.fail(41, 20, "h", "a non-negative hourglass coefficient");
  if (viscosity.real(61, 20, "LAMBDA_v", dim::none) != 0.0)
    viscosity.fail(61, 20, "LAMBDA_v", "0 (the numerical Navier-Stokes viscosity is not supported by Crumple)");
  if (viscosity.real(81, 20, "MU_v", dim::none) != 0.0)
    viscosity.fail(81, 20, "MU_v", "0 (the numerical Navier-Stokes viscosity is not supported by Crumple)");
}

// Line 3: dt_min, Istrain, IHKT.
void read_solid_step_line(CardReader& reader, DeckContext& context, SolidSection& s) {
  const Line step = reader.next("dt_min, Istrain, IHKT");
  if (step.real(1, 20, "dt_min", dim::time) != 0.0)
    step.fail(1, 20, "dt_min", "0 (a per-property minimum brick step is not supported by Crumple; use /DT/BRICK)");
  note_if_set(step, context, reader, step.integer(21, 10, "Istrain"), "Istrain",
              "strain output flag; Crumple's output does not depend on it");
  s.ihkt = static_cast<int>(step.integer(31, 10, "IHKT"));
  if (s.ihkt != 0 && s.ihkt != 1)
    step.fail(31, 10, "IHKT",
              "0 or 1 (elastic hourglass modulus); 2 (tangent modulus) is not supported by Crumple");
}

void read_solid_property(CardReader& reader, DeckContext& context) {
  Property p = begin_property(reader, PropertyKind::Solid);
  SolidSection& s = p.solid;
  if (!reader.at_end()) read_solid_flags(reader, context, s);
  if (!reader.at_end()) read_solid_viscosity(reader, s);
  if (!reader.at_end()) read_solid_step_line(reader, context, s);
  if (reader.has_data()) {  // the optional Sol2SPH line
    const Line sph = reader.next("Ndir, sphpart_ID");
    if (sph.integer(1, 10, "Ndir") != 0 || sph.integer(11, 10, "sphpart_ID") != 0)
      sph.fail(1, 20, "Ndir, sphpart_ID", "blank (the solid-to-SPH option is not supported by Crumple)");
  }
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// A field of /PROP/TYPE4 that acts only with an option Crumple lacks: its default (0, or `neutral`) or an error.
void spring_default_only(const Line& line, DeckContext& context, int column, int width, std::string_view name,
                         double value, double neutral, std::string_view feature) {
  if (value != 0.0 && value != neutral)
    context.unsupported(line.error(column, width, name, default_only(feature)));
}

// Per unit length (SP-21): a mass per length [M / L], an inertia per length [M L]; `power` 1 for a
// stiffness per unit strain.
Dimension per_length(Dimension d, int power = -1) { return {d.mass, d.length + power, d.time}; }

// The names of a spring law's fields in messages: /PROP/TYPE4's (K, fct_ID11, H, ...) or the i-th degree of
// freedom's of /PROP/TYPE8 (K1, fct_ID11, H1, ... for X; K4 and fct_ID14 for XX).
struct SpringLawNames {
  std::string k, c, a, b, d, curve, h, rate_factor, lower, rate_force, delta_min, delta_max, f, e, ascale, hscale;
  // A rotation's law (XX, YY, ZZ) is a moment against an angle in radians; `rate` the unit of D and F.
  Dimension stiffness = dim::stiffness, damping = dim::viscous_damping, force = dim::force, displacement = dim::length,
            rate = dim::velocity;
  int dof = 0;  // 0: TYPE4's law; 1 to 6: a TYPE8 law's degree of freedom (1 to 4 for TYPE25's)
  bool axisymmetric = false;  // TYPE25's layout of the law's last two lines (SP-20)
  Dimension limit = dim::length;  // delta_min, delta_max: an elongation, or with Ifail2 a force or an energy (SP-5b)
  bool rotation = false;
  // `first_rotation`: the first degree of freedom that is a rotation (4 for TYPE8 and TYPE13, 3 for TYPE25).
  explicit SpringLawNames(int index, int first_rotation = 4) : dof(index) {
    rotation = dof >= first_rotation;
    if (rotation)
      stiffness = dim::moment, damping = Dimension{1, 2, -1}, force = dim::moment, displacement = dim::none,
      rate = dim::angular_velocity, limit = dim::none;
    const std::string i = dof == 0 ? "" : std::to_string(dof), j = dof == 0 ? "1" : std::to_string(dof);
    k = "K" + i, c = "C" + i, a = "A" + i, b = "B" + i, d = "D" + i, h = "H" + i;
    curve = "fct_ID1" + j, rate_factor = "fct_ID2" + j, lower = "fct_ID3" + j, rate_force = "fct_ID4" + j;
    delta_min = "delta_min" + i, delta_max = "delta_max" + i, f = "F" + i, e = "E" + i;
    ascale = "Ascale" + i, hscale = "Hscale" + i;
  }
  // Ileng 1 (SP-21): the stiffness and damping per unit length (times a length), the curve's abscissa a strain;
  // `limits`: the elongation limits a strain too (a beam-type spring's; a 1-D spring's stay lengths, and force and
  // energy limits are not scaled, measured).
  void per_unit_length(bool limits) {
    stiffness = per_length(stiffness, 1), damping = per_length(damping, 1), displacement = per_length(displacement);
    rate = per_length(rate);
    if (limits) limit = per_length(limit);
  }
};

// Ileng (TYPE4, TYPE13 and TYPE25): 0, or 1 for the input per unit length (SP-21), which changes the dimensions of
// the mass, inertia, stiffnesses and dampings, read after it.
bool read_unit_length_flag(const Line& line, int column) {
  const std::int64_t ileng = line.integer(column, 10, "Ileng");
  if (ileng != 0 && ileng != 1) line.fail(column, 10, "Ileng", "0 (the values as given) or 1 (per unit length)");
  return ileng == 1;
}

// sens_ID and Isflag at columns 51-60, 61-70 of line 1 (SP-24): Isflag 0, 1 or 2; without a sensor, a warning.
void read_spring_switch(const Line& first, DeckContext& context, SpringSection& s) {
  s.sensor.sensor_id = first.optional_id(51, 10, "sens_ID", IdKind::Other);
  const std::int64_t flag = first.integer(61, 10, "Isflag");
  if (flag < 0 || flag > 2)
    first.fail(61, 10, "Isflag", "0 (on when the sensor comes on), 1 (off then) or 2 (on while the sensor is)");
  s.sensor.flag = static_cast<int>(flag);
  if (s.sensor.sensor_id == 0 && flag != 0) {
    const DeckError at = first.error(61, 10, "Isflag", "");
    context.note(at.where(), at.keyword(), "Isflag", "acts with a sensor (sens_ID) only; ignored", SkipKind::Unsupported);
  }
}

// Line 1 of /PROP/TYPE4: Mass, sens_ID, Isflag, Ileng.
void read_spring_mass(CardReader& reader, DeckContext& context, SpringSection& s) {
  const Line first = reader.next("Mass, sens_ID, Isflag, Ileng");
  s.per_unit_length = read_unit_length_flag(first, 71);
  s.mass = first.real(1, 20, "Mass", s.per_unit_length ? per_length(dim::mass) : dim::mass);
  if (!(s.mass > 0.0)) first.fail(1, 20, "Mass", "a positive spring mass (the reference refuses a spring without mass)");
  read_spring_switch(first, context, s);
}

// A law's rate fields as written (SP-23), checked once the whole law is read (resolve_rate_effects): B and D on its
// first line, F, E and Hscale on the later ones (where, for the messages).
struct RateFields {
  SourceLocation first, scales;
  double a = 1.0;  // A, resolved (0 or blank: 1)
  double b = 0.0, d = 0.0, f = 0.0, e = 0.0, hscale = 0.0;
  bool lower_curve_given = false;  // fct_ID3 as written, before the hardening flag drops it
};

// A rate scale D or F [n.rate]: its magnitude (a negative D acts as |D|, measured), 0 or blank 1.
double rate_reference(double value, const CardReader& reader, const SpringLawNames& n) {
  return (value == 0.0 ? 1.0 : std::abs(value)) * reader.units().factor(n.rate);
}

// A law's first line: K, C, A, B, D.
void read_spring_stiffness(CardReader& reader, SpringLaw& s, const SpringLawNames& n, RateFields& rate) {
  const Line second = reader.next("K, C, A, B, D");
  s.stiffness = second.real(1, 20, n.k, n.stiffness);
  s.damping = second.real(21, 20, n.c, n.damping);
  if (s.stiffness < 0.0) second.fail(1, 20, n.k, "a non-negative stiffness");
  if (s.damping < 0.0) second.fail(21, 20, n.c, "a non-negative damping");
  // A scales the function fct_ID1 (read_spring_law checks it against one); blank or 0: 1.
  const double a = second.real(41, 20, n.a, dim::none);
  if (a < 0.0) second.fail(41, 20, n.a, "a positive function scale (0 or blank: 1)");
  rate.a = a == 0.0 ? 1.0 : a;
  s.function_scale = rate.a * reader.units().factor(n.force);
  rate.first = second.where();
  rate.b = second.real(61, 20, n.b, dim::none), rate.d = second.real(81, 20, n.d, dim::none);
}

// A rate field that acts on nothing in this law (SP-23; the reference ignores it there, measured): a named warning.
void rate_field_ignored(DeckContext& context, const CardReader& reader, const SourceLocation& where,
                        const std::string& field, double value, std::string_view why) {
  if (value != 0.0 && value != 1.0)
    context.note(where, reader.card().keyword, field, std::string(why), SkipKind::Unsupported);
}

// SP-23: the rate factor R (B, D, fct_ID2, E) scales the curve fct_ID1 and acts with it only: a linear spring drops
// it, as the reference does (measured: its starter prints B = 0 and E = 0, and a /PROP/TYPE25 deck with B 50 on its
// linear laws runs to the same time history as with B 0); the rate force (fct_ID4, Hscale) acts on every law.
// The curve A f is scaled by R / A: B and E are kept over A.
void resolve_rate_effects(const RateFields& rate, SpringLaw& s, const CardReader& reader, DeckContext& context,
                          const SpringLawNames& n) {
  s.log_rate = rate.b / rate.a, s.log_rate_reference = rate_reference(rate.d, reader, n);
  s.rate_factor_scale = (rate.e == 0.0 ? 1.0 : rate.e) / rate.a, s.rate_scale = rate_reference(rate.f, reader, n);
  s.rate_force_scale = (rate.hscale == 0.0 ? 1.0 : rate.hscale) * reader.units().factor(n.force);
  if (s.function_id == 0) {
    if (rate.b != 0.0)
      context.note(rate.first, reader.card().keyword, n.b,
                   "the logarithmic rate effect acts on the force function only; a linear spring ignores it, as the "
                   "reference does",
                   SkipKind::Unsupported);
    if (s.rate_factor_function_id != 0)
      context.note(rate.scales, reader.card().keyword, n.rate_factor,
                   "the rate factor function acts on the force function only; a linear spring ignores it, as the "
                   "reference does",
                   SkipKind::Unsupported);
    s.log_rate = 0.0, s.rate_factor_function_id = 0;
  }
  // Measured: a /PROP/TYPE4 law with fct_ID3 given reads g and h at a rate scale that is not F (it follows the rank
  // of fct_ID3's id among the deck's functions); Crumple reads them at r / F, as the manual defines them.
  if (n.dof == 0 && rate.lower_curve_given && (s.rate_factor_function_id != 0 || s.rate_force_function_id != 0))
    context.warn(rate.scales, reader.card().keyword,
                 fmt::format("{} and {} are read at the rate over {}, as the manual defines them; beside {} the "
                             "reference reads them at another scale, so its rate effects differ from Crumple's",
                             n.rate_factor, n.rate_force, n.f, n.lower));
  if (s.log_rate == 0.0)
    rate_field_ignored(context, reader, rate.first, n.d, rate.d, "the rate D acts with the logarithmic rate effect B only");
  if (s.rate_factor_function_id == 0)
    rate_field_ignored(context, reader, rate.scales, n.e, rate.e, "E scales the rate factor function fct_ID2 only");
  if (s.rate_factor_function_id == 0 && s.rate_force_function_id == 0)
    rate_field_ignored(context, reader, rate.scales, n.f, rate.f, "F scales the rate of the functions fct_ID2 and fct_ID4 only");
  if (s.rate_force_function_id == 0)
    rate_field_ignored(context, reader, rate.scales, n.hscale, rate.hscale, "Hscale scales the rate force fct_ID4 only");
}

// The hardening flag and its curves (line 2 of a law): every flag needs fct_ID1, most an unloading K; H 4 to 7 take
// a second curve fct_ID3 (lower yield curve, residual elongation, unloading curve), which no other flag takes.
void check_spring_hardening(const Line& third, CardReader& reader, DeckContext& context, SpringLaw& s,
                            const SpringLawNames& n) {
  if (s.hardening < 0 || s.hardening == 3 || s.hardening > 8)
    context.unsupported(third.error(11, 10, n.h, "0 (elastic), 1 (isotropic), 2 (uncoupled), 4 (kinematic), 5 "
                                                 "(residual), 6 (unloading curve), 7 (hysteresis) or 8 (total length) "
                                                 "hardening (3 is not supported by Crumple)"));
  // The reference's errors 231, 1057 and 1058 (measured, /PROP/TYPE4): H 4 to 8 need their curve.
  if (s.hardening >= 4 && s.hardening <= 8 && s.function_id == 0)
    third.fail(1, 10, n.curve, fmt::format("the force curve of hardening H {} (H 4 to 8 need one)", s.hardening));
  if (s.hardening != 0 && s.function_id == 0) {  // measured: H 1 and 2 without a curve run as the linear spring
    context.warn(third.where(), reader.card().keyword,
                 fmt::format("{} {} without a curve ({}): the spring is linear at {}, as the reference runs it", n.h,
                             s.hardening, n.curve, n.k));
    s.hardening = 0;
  }
  if (s.hardening != 0 && s.hardening != 6 && s.hardening != 8 && !(s.stiffness > 0.0))
    throw DeckError(third.where(), reader.card().keyword, n.k,
                    "a positive unloading stiffness for a hardening spring (H 1, 2, 4, 5, 7)", fmt::format("{:g}", s.stiffness));
  if (s.hardening == 4 && s.lower_function_id == 0)
    context.unsupported(third.error(31, 10, n.lower, "the lower yield curve of kinematic hardening (H 4; without "
                                                     "it, not supported by Crumple)"));
  if ((s.hardening == 5 || s.hardening == 6) && s.lower_function_id == 0)  // the reference's errors 231 and 1057
    third.fail(31, 10, n.lower, "the residual elongation (H 5) or unloading curve (H 6) function");
  if (s.hardening == 7 && s.lower_function_id == 0) {  // the reference's warning 1059: it runs as H 2
    context.warn(third.where(), reader.card().keyword,
                 fmt::format("{}: hysteresis (H 7) without its unloading curve runs as uncoupled hardening (H 2), as "
                             "the reference runs it", n.lower));
    s.hardening = 2;
  }
  if ((s.hardening < 4 || s.hardening > 7) && s.lower_function_id != 0) {  // measured with H 0: no effect
    context.warn(third.where(), reader.card().keyword,
                 fmt::format("{} acts only with H 4 to 7: ignored with H {}, as the reference ignores it", n.lower,
                             s.hardening));
    s.lower_function_id = 0;
  }
}

void read_abscissa_scale(const Line& line, int column, const CardReader& reader, SpringLaw& s, const SpringLawNames& n) {
  const double ascale = line.real(column, 20, n.ascale, dim::none);
  if (ascale < 0.0) line.fail(column, 20, n.ascale, "a positive abscissa scale (0 or blank: 1)");
  s.abscissa_scale = (ascale == 0.0 ? 1.0 : ascale) * reader.units().factor(n.displacement);
}

// F of a law (SP-23), the rate g and h read in: positive, 0 or blank 1.
void read_rate_scale(const Line& line, int column, const SpringLawNames& n, RateFields& rate) {
  rate.f = line.real(column, 20, n.f, dim::none);
  if (rate.f < 0.0) line.fail(column, 20, n.f, "a positive rate scale (0 or blank: 1)");
}

// E and Hscale of a law (SP-23), the scales of g and h.
void read_rate_function_scales(const Line& line, int e_column, int hscale_column, const SpringLawNames& n,
                               RateFields& rate) {
  rate.e = line.real(e_column, 20, n.e, dim::none), rate.hscale = line.real(hscale_column, 20, n.hscale, dim::none);
}

// A law's second and third lines: fct_ID1, H, fct_ID2, fct_ID3, fct_ID4, delta_min, delta_max; F, E, Ascale, Hscale.
// TYPE25's (SP-20): fct_ID1, H, fct_ID2, fct_ID3, F, delta_min, delta_max; Ascale, E, fct_ID4, Hscale.
void read_spring_law(CardReader& reader, DeckContext& context, SpringLaw& s, const SpringLawNames& n, RateFields& rate) {
  const Line third = reader.next("fct_ID1, H, fct_ID2, fct_ID3, fct_ID4, delta_min, delta_max");
  s.function_id = third.optional_id(1, 10, n.curve, IdKind::Other);
  s.lower_function_id = third.optional_id(31, 10, n.lower, IdKind::Other);
  s.rate_factor_function_id = third.optional_id(21, 10, n.rate_factor, IdKind::Other);
  rate.scales = third.where();
  rate.lower_curve_given = s.lower_function_id != 0;
  if (n.axisymmetric)
    read_rate_scale(third, 41, n, rate);
  else
    s.rate_force_function_id = third.optional_id(41, 10, n.rate_force, IdKind::Other);
  // A scales the function only: the reference prints A = 1 for a spring without one (measured, /PROP/SPRING with
  // K 1000 and A 2: the same energies as A 1), so a linear spring ignores it, as the reference does.
  if (s.function_id == 0 && s.function_scale != reader.units().factor(n.force))
    context.note(third.where(), reader.card().keyword, n.a,
                 "the function scale factor acts on the force function only; a linear spring ignores it, as the "
                 "reference does",
                 SkipKind::Unsupported);
  s.hardening = static_cast<int>(third.integer(11, 10, n.h));
  check_spring_hardening(third, reader, context, s, n);
  if (s.hardening == 8 && n.dof > 0)  // a six-law spring's law: its total length is not measured
    context.unsupported(third.error(11, 10, n.h, "0 to 7 for a spring of six laws (H 8, the total length's curve, is "
                                                 "not supported by Crumple on /PROP/TYPE8 and TYPE13)"));
  const double low = third.real(61, 20, n.delta_min, n.limit);
  const double high = third.real(81, 20, n.delta_max, n.limit);
  if (low > 0.0) third.fail(61, 20, n.delta_min, "a negative failure limit (0 or blank: none)");
  if (high < 0.0) third.fail(81, 20, n.delta_max, "a positive failure limit (0 or blank: none)");
  if (low < 0.0) s.delta_min = low;
  if (high > 0.0) s.delta_max = high;
  if (!reader.has_data()) return;
  if (n.axisymmetric) {
    const Line last = reader.next("Ascale, E, fct_ID4, Hscale");
    read_abscissa_scale(last, 1, reader, s, n);
    s.rate_force_function_id = last.optional_id(41, 10, n.rate_force, IdKind::Other);
    read_rate_function_scales(last, 21, 51, n, rate);
    return;
  }
  const Line fourth = reader.next("F, E, Ascale, Hscale");
  rate.scales = fourth.where();
  read_rate_scale(fourth, 1, n, rate);
  read_rate_function_scales(fourth, 21, 61, n, rate);
  read_abscissa_scale(fourth, 41, reader, s, n);
}

void read_spring_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  read_spring_mass(reader, context, p.spring);
  SpringLawNames names(0);
  if (p.spring.per_unit_length) names.per_unit_length(false);
  RateFields rate;
  read_spring_stiffness(reader, p.spring.dof[0], names, rate);
  read_spring_law(reader, context, p.spring.dof[0], names, rate);
  resolve_rate_effects(rate, p.spring.dof[0], reader, context, names);
  if (p.spring.per_unit_length && p.spring.dof[0].hardening == 8)
    context.unsupported(DeckError(p.where, reader.card().keyword, "Ileng",
                                  "0 with H 8 (the total length's curve per unit length is not supported by Crumple)", "1"));
  if (!p.spring.dof[0].acts())
    throw DeckError(p.where, reader.card().keyword, "K, C, fct_ID11", "a stiffness, a damping or a force function",
                    "none of them");
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// The rate filter of /PROP/TYPE8 and TYPE13 (Fsmooth, an integer at `smooth`; Fcut, a real at `cut`). The reference
// runs a general spring's rate effects with and without it to the same forces (measured, /PROP/TYPE8 on a velocity
// step, every rate term: the largest difference 0): there it is a warning. On TYPE13, whose failure reads the rate
// too, blank, 0 or the reference's default 1e30 only.
void read_rate_filter(const Line& line, const CardReader& reader, DeckContext& context, int smooth, int cut,
                      bool without_effect) {
  const auto fsmooth = static_cast<double>(line.integer(smooth, 10, "Fsmooth"));
  const double frequency = line.real(cut, 20, "Fcut", dim::rate);
  if (without_effect) {
    if (fsmooth != 0.0 || (frequency != 0.0 && frequency < 1e29))
      context.note(line.where(), reader.card().keyword, "Fsmooth, Fcut",
                   "the rate filter changes none of a general spring's forces in the reference (measured); ignored",
                   SkipKind::Unsupported);
    return;
  }
  spring_default_only(line, context, smooth, 10, "Fsmooth", fsmooth, 0.0, "the rate filter is");
  if (frequency != 0.0 && frequency < 1e29)
    context.unsupported(line.error(cut, 20, "Fcut", default_only("the rate filter's cut-off frequency is")));
}

// Line 1's fields that /PROP/TYPE8 and /PROP/TYPE13 share: Mass, Inertia (> 0 where `inertia_required`), sens_ID,
// Isflag, Ifail (the skew at 41-50 and the last fields are each card's own).
void read_six_law_spring_line(const Line& first, DeckContext& context, SpringSection& s, bool inertia_required) {
  s.mass = first.real(1, 20, "Mass", s.per_unit_length ? per_length(dim::mass) : dim::mass);
  if (!(s.mass > 0.0)) first.fail(1, 20, "Mass", "a positive spring mass (the reference refuses a spring without mass)");
  s.inertia = first.real(21, 20, "Inertia", s.per_unit_length ? per_length(dim::inertia) : dim::inertia);
  if (inertia_required ? !(s.inertia > 0.0) : s.inertia < 0.0)
    first.fail(21, 20, "Inertia", inertia_required ? "a positive rotational inertia" : "a non-negative rotational inertia");
  read_spring_switch(first, context, s);
  const std::int64_t ifail = first.integer(71, 10, "Ifail");
  // The reference runs a general spring's Ifail 2 as 1 (measured); a beam-type spring's other values are unknown.
  const bool general = !inertia_required;
  if (general && ifail == 2)
    context.warn(first.where(), "/PROP/SPR_GENE", "Ifail 2: the laws combined (Ifail 1), as the reference runs it");
  else if (ifail != 0 && ifail != 1)
    first.fail(71, 10, "Ifail", "0 (each law on its own) or 1 (the laws combined)");
  s.failure.combined = ifail == 1 || (general && ifail == 2);
}

// The limits' dimension of a failure measure (SP-5b): an elongation, a force or an energy.
void set_limit_dimension(SpringLawNames& n, SpringFailureMeasure measure) {
  if (measure == SpringFailureMeasure::Force) n.limit = n.rotation ? dim::moment : dim::force;
  if (measure == SpringFailureMeasure::Energy) n.limit = dim::moment;  // an energy
}

// The six laws of a /PROP/TYPE8 or /PROP/TYPE13 spring, three lines each, X to ZZ.
void read_six_laws(CardReader& reader, DeckContext& context, SpringSection& s) {
  for (int d = 0; d < kSpringDofs; ++d) {
    SpringLawNames names(d + 1);
    set_limit_dimension(names, s.failure.measure);
    if (s.per_unit_length) names.per_unit_length(s.failure.measure == SpringFailureMeasure::Elongation);
    SpringLaw& law = s.dof[static_cast<std::size_t>(d)];
    RateFields rate;
    read_spring_stiffness(reader, law, names, rate);
    read_spring_law(reader, context, law, names, rate);
    resolve_rate_effects(rate, law, reader, context, names);
  }
}

// Line 1 of /PROP/TYPE8: Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ifail2, Iequil.
void read_general_spring_mass(CardReader& reader, DeckContext& context, SpringSection& s) {
  const Line first = reader.next("Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ifail2, Iequil");
  read_six_law_spring_line(first, context, s, false);
  s.skew_id = first.optional_id(41, 10, "skew_ID", IdKind::Other);  // the axes of its laws (SP-9b); 0: global
  // Ifail2: 0 the elongation, 1 the force, 2 the energy; the reference runs other values as 0 (measured: 3, 5).
  const std::int64_t ifail2 = first.integer(81, 10, "Ifail2");
  if (ifail2 == 1 || ifail2 == 2)
    s.failure.measure = ifail2 == 1 ? SpringFailureMeasure::Force : SpringFailureMeasure::Energy;
  else if (ifail2 != 0)
    context.warn(first.where(), "/PROP/SPR_GENE", fmt::format("Ifail2 {}: the elongation criterion, as the reference "
                                                              "runs it (0 elongation, 1 force, 2 energy)", ifail2));
  spring_default_only(first, context, 91, 10, "Iequil", static_cast<double>(first.integer(91, 10, "Iequil")), 0.0,
                      "the moment equilibrium option is");
}

// /PROP/TYPE8 (/PROP/SPR_GENE): the general spring, one law per degree of freedom in the global axes (X, Y, Z, XX,
// YY, ZZ), then the rate filter line (docs/theory/spring.md, "General springs").
void read_general_spring_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  p.spring.frame = SpringFrame::Global;
  read_general_spring_mass(reader, context, p.spring);
  read_six_laws(reader, context, p.spring);
  if (reader.has_data()) {
    const Line last = reader.next("Fsmooth, Fcut");
    read_rate_filter(last, reader, context, 1, 11, true);
  }
  if (p.spring.dof[3].acts() || p.spring.dof[4].acts() || p.spring.dof[5].acts())
    if (!(p.spring.inertia > 0.0))
      throw DeckError(p.where, reader.card().keyword, "Inertia",
                      "a positive rotational inertia for a spring with rotational stiffness or damping", "0");
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// Line 1 of /PROP/TYPE13: Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ileng, Ifail2.
void read_beam_spring_mass(CardReader& reader, DeckContext& context, SpringSection& s) {
  const Line first = reader.next("Mass, Inertia, skew_ID, sens_ID, Isflag, Ifail, Ileng, Ifail2");
  s.per_unit_length = read_unit_length_flag(first, 81);
  read_six_law_spring_line(first, context, s, true);
  s.skew_id = first.optional_id(41, 10, "skew_ID", IdKind::Other);
  // Ifail2 (SP-5b): 0 the elongation; 1 the elongation, 2 the force, 3 the energy, each limit raised by the rate.
  const std::int64_t ifail2 = first.integer(91, 10, "Ifail2");
  if (ifail2 < 0 || ifail2 > 3)
    first.fail(91, 10, "Ifail2", "0 (elongation), 1 (elongation and rate), 2 (force and rate) or 3 (energy and rate)");
  s.failure.rate_effect = ifail2 >= 1;
  s.failure.measure = ifail2 == 2 ? SpringFailureMeasure::Force
                    : ifail2 == 3 ? SpringFailureMeasure::Energy : SpringFailureMeasure::Elongation;
}

// The rate line's reference velocities Vo, Wo of the failure's rate term (0 or blank: 1, measured).
void read_failure_rates(const Line& line, SpringFailure& f) {
  const double vo = line.real(1, 20, "Vo", dim::velocity), wo = line.real(21, 20, "Wo", dim::angular_velocity);
  f.translation_rate = vo > 0.0 ? vo : 1.0;
  f.rotation_rate = wo > 0.0 ? wo : 1.0;
}

// A failure line of a degree of freedom (SP-5b): c (in the limit's unit), n, alpha, beta; they act with Ifail2 >= 1
// only (measured), where 0 or blank is n 1, alpha 1, beta 2. `first_rotation` as SpringLawNames's.
void read_failure_line(const Line& line, const SpringSection& s, SpringLaw& law, int dof, int first_rotation = 4) {
  SpringLawNames names(dof, first_rotation);
  set_limit_dimension(names, s.failure.measure);
  const std::string i = std::to_string(dof);
  const double c = line.real(1, 20, "c" + i, names.limit), n = line.real(21, 20, "n" + i, dim::none);
  const double alpha = line.real(41, 20, "alpha" + i, dim::none), beta = line.real(61, 20, "beta" + i, dim::none);
  if (!s.failure.rate_effect) return;
  if (c < 0.0 || n < 0.0 || alpha < 0.0 || beta < 0.0)
    line.fail(1, 80, "c, n, alpha, beta", "non-negative values (0 or blank: c 0, n 1, alpha 1, beta 2)");
  law.rate_c = c, law.rate_n = n > 0.0 ? n : 1.0, law.alpha = alpha > 0.0 ? alpha : 1.0, law.beta = beta > 0.0 ? beta : 2.0;
}

// /PROP/TYPE13 (/PROP/SPR_BEAM): the beam-type spring, one law per degree of freedom of its own turning frame
// (tension, shear XY, shear XZ, torsion, bending Y, bending Z), the rate line (Vo, Wo: the rate effects' reference
// velocities, which act on nothing without them; Fcut, Fsmooth), then the six lines of the rate-dependent failure
// (c, n, alpha, beta: used by Ifail2 only) (docs/theory/spring.md, "Beam-type springs").
void read_beam_spring_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  p.spring.frame = SpringFrame::Beam;
  read_beam_spring_mass(reader, context, p.spring);
  read_six_laws(reader, context, p.spring);
  if (reader.has_data()) {
    const Line rate = reader.next("Vo, Wo, Fcut, Fsmooth");
    read_failure_rates(rate, p.spring.failure);
    read_rate_filter(rate, reader, context, 61, 41, false);
  }
  // Blank lines between them are skipped (measured: a deck with one before each is the reference's deck as written).
  for (int d = 0; d < kSpringDofs && reader.has_data(); ++d)
    read_failure_line(*reader.next_nonblank(), p.spring, p.spring.dof[static_cast<std::size_t>(d)], d + 1);
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// /PROP/TYPE25 (/PROP/SPR_AXI): the beam-type spring whose shear and bending are each one law of the radial magnitude
// (docs/theory/spring.md, SP-20). Line 1 as TYPE13's; four laws (tension, shear, torsion, bending) in TYPE25's layout,
// held as TYPE13's six with shear Y = Z and bending Y = Z; the rate line (Vo, Wo) and four lines c, n, alpha, beta
// (Ifail2 >= 1 only, SP-5b), each optional (measured: the reference reads them so, not as its manual's four lines c,
// n).
void read_axisymmetric_spring_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  p.spring.frame = SpringFrame::Beam;
  p.spring.radial = true;
  read_beam_spring_mass(reader, context, p.spring);
  constexpr std::size_t kSlot[4] = {0, 1, 3, 4};  // tension, shear, torsion, bending in TYPE13's order
  for (int d = 0; d < 4; ++d) {
    SpringLawNames names(d + 1, 3);
    names.axisymmetric = true;
    set_limit_dimension(names, p.spring.failure.measure);
    if (p.spring.per_unit_length) names.per_unit_length(false);  // SP-21: its elongation limits stay lengths
    SpringLaw& law = p.spring.dof[kSlot[d]];
    RateFields rate;
    read_spring_stiffness(reader, law, names, rate);
    read_spring_law(reader, context, law, names, rate);
    resolve_rate_effects(rate, law, reader, context, names);
  }
  if (reader.has_data()) read_failure_rates(reader.next("Vo, Wo"), p.spring.failure);
  for (int d = 0; d < 4 && reader.has_data(); ++d)  // SP-5b on the radial magnitudes and their rates (measured)
    read_failure_line(*reader.next_nonblank(), p.spring, p.spring.dof[kSlot[d]], d + 1, 3);
  p.spring.dof[2] = p.spring.dof[1], p.spring.dof[5] = p.spring.dof[4];
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// The pretension's F1, E1, K1 from the two of F1, D1, E1, K1 the card gives (SP-22, the reference's starter,
// measured): F1 = K1 D1, E1 = F1 D1 / 2; a K1 left at 0 is 1e-20 (F1 alone is a constant pull without a stroke);
// more than two is the reference's error 408.
void resolve_pretension(const Line& line, double stroke, SpringPretension& p) {
  int given = 0;
  for (double v : {p.force, stroke, p.energy, p.stiffness}) given += v != 0.0;
  if (given > 2)
    line.fail(21, 80, "F1, D1, E1, K1", "at most two of F1, D1, E1 and K1 (the others follow from them)");
  double& f = p.force;
  double d = std::abs(stroke);
  double& e = p.energy;
  double& k = p.stiffness;
  if (k == 0.0) k = 1e-20;
  if (f != 0.0 && d != 0.0) k = f / d, e = 0.5 * f * d;
  else if (f != 0.0 && e != 0.0) d = 2.0 * e / f, k = f / d;
  else if (d != 0.0 && e != 0.0) f = 2.0 * e / d, k = f / d;
  else if (f != 0.0) e = 0.5 * f * f / k;
  else if (d != 0.0) f = k * d, e = 0.5 * f * d;
  else if (e != 0.0) f = std::sqrt(2.0 * e * k);
}

// Line 3 of /PROP/TYPE32 (SP-22b): fct_ID1 (the pretension of the elongation), fct_ID2 (of the time since the
// sensor's Tdelay), their abscissa scales Scale_t, Scale_d and the force scale Scale_f (0 or blank: 1); without
// either function the scales act on nothing (a warning, as in the reference).
void read_pretension_functions(const Line& third, const CardReader& reader, DeckContext& context, SpringPretension& pre) {
  pre.stroke_function_id = third.optional_id(1, 10, "fct_ID1", IdKind::Other);
  pre.time_function_id = third.optional_id(11, 10, "fct_ID2", IdKind::Other);
  const auto scale = [&](int column, const char* name, Dimension d) {
    const double value = third.real(column, 20, name, d);
    if (value < 0.0) third.fail(column, 20, name, "a positive scale (0 or blank: 1)");
    if (value != 0.0 && value != reader.units().factor(d) && !pre.by_functions())
      context.note(third.where(), reader.card().keyword, name,
                   "the scale of a pretension function; without one it does nothing, as in the reference",
                   SkipKind::Unsupported);
    return value == 0.0 ? reader.units().factor(d) : value;
  };
  pre.time_scale = scale(41, "Scale_t", dim::time);
  pre.stroke_scale = scale(61, "Scale_d", dim::length);
  pre.force_scale = scale(81, "Scale_f", dim::force);
}

// /PROP/TYPE32 (/PROP/SPR_PRE): the pretensioner (docs/theory/spring.md, SP-22). Line 1 M, sens_ID, Ilock; line 2
// K0, F1, D1, E1, K1; line 3 the force functions of the stroke and of time and their scales (columns measured on
// the reference's starter echo, input versions 100 to 2019).
void read_pretension_spring_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  SpringSection& s = p.spring;
  SpringPretension& pre = s.pretension;
  pre.on = true;
  const Line first = reader.next("M, sens_ID, Ilock");
  s.mass = first.real(1, 20, "M", dim::mass);
  if (!(s.mass > 0.0)) first.fail(1, 20, "M", "a positive spring mass");
  pre.sensor_id = first.optional_id(51, 10, "sens_ID", IdKind::Other);
  const std::int64_t ilock = first.integer(61, 10, "Ilock");
  pre.lock = ilock == 2;  // measured: 0, 1, 3 and -1 run alike
  const Line second = reader.next("K0, F1, D1, E1, K1");
  SpringLaw& law = s.dof[0];
  law.stiffness = second.real(1, 20, "K0", dim::stiffness);
  if (!(law.stiffness > 0.0)) second.fail(1, 20, "K0", "a positive stiffness before the sensor (and to unload)");
  pre.force = second.real(21, 20, "F1", dim::force);
  const double stroke = second.real(41, 20, "D1", dim::length);
  pre.energy = second.real(61, 20, "E1", dim::moment);
  pre.stiffness = second.real(81, 20, "K1", dim::stiffness);
  if (reader.has_data()) read_pretension_functions(reader.next("fct_ID1, fct_ID2, Scale_t, Scale_d, Scale_f"), reader,
                                                   context, pre);
  if (!pre.by_functions()) {
    resolve_pretension(second, stroke, pre);
  } else {  // SP-22b: D1 the stroke; F1, E1 and K1 act on nothing (measured: any of them changes no force)
    pre.stroke = std::abs(stroke);
    for (const auto& [column, name, value] : {std::tuple{21, "F1", pre.force}, {61, "E1", pre.energy}, {81, "K1", pre.stiffness}})
      if (value != 0.0)
        context.note(second.where(), reader.card().keyword, name,
                     "acts only without the pretension functions; ignored, as by the reference", SkipKind::Unsupported);
  }
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// A joint's free degree of freedom (SP-25g), its three lines: K, fct_K, S-, S+, Icomb; C, fct_C; Kf, F, fct_F, named
// as the manual names them for a translation (Kt1, SD1-, FF1, ...) or a rotation (Kr1, SA1-, FM1, ...) about `axis`.
// Its linear stiffness and damping act (SP-25); the functions, stops and friction are refused with the field named.
void read_joint_free_dof(CardReader& reader, DeckContext& context, SpringLaw& law, bool rotation,
                         const std::string& axis) {
  const std::string t = rotation ? "r" : "t", stop = rotation ? "SA" : "SD", push = rotation ? "FM" : "FF";
  const std::string_view what = rotation ? "rotational" : "translational";
  const Line stiffness = reader.next("K, fct_K, S-, S+, Icomb");
  law.stiffness = stiffness.real(1, 20, "K" + t + axis, rotation ? dim::moment : dim::stiffness);
  if (law.stiffness < 0.0) stiffness.fail(1, 20, "K" + t + axis, fmt::format("a non-negative {} stiffness", what));
  const auto refuse_id = [&context](const Line& line, int column, const std::string& name, std::string_view field) {
    if (line.optional_id(column, 10, name, IdKind::Other) != 0)
      context.unsupported(line.error(column, 10, name, default_only(field)));
  };
  const auto refuse_real = [&context](const Line& line, int column, const std::string& name, std::string_view field) {
    if (line.real(column, 20, name, dim::none) != 0.0)
      context.unsupported(line.error(column, 20, name, default_only(field)));
  };
  refuse_id(stiffness, 21, "fct_K" + t + axis, "a joint's stiffness function is");
  refuse_real(stiffness, 31, stop + axis + "-", "a joint's stop is");
  refuse_real(stiffness, 51, stop + axis + "+", "a joint's stop is");
  refuse_id(stiffness, 71, "Icomb_" + t + axis, "a joint's combined stop is");
  const Line damping = reader.next("C, fct_C");
  law.damping = damping.real(1, 20, "C" + t + axis, rotation ? Dimension{1, 2, -1} : Dimension{1, 0, -1});
  if (law.damping < 0.0) damping.fail(1, 20, "C" + t + axis, fmt::format("a non-negative {} damping", what));
  refuse_id(damping, 21, "fct_C" + t + axis, "a joint's damping function is");
  const Line friction = reader.next("Kf, F, fct_F");
  refuse_real(friction, 1, "Kf" + t + axis, "a joint's stop and friction stiffness is");
  refuse_real(friction, 21, push + axis, "a joint's friction is");
  refuse_id(friction, 41, "fct_" + push + axis, "a joint's friction function is");
}

// /PROP/TYPE45 (/PROP/KJOINT2): the joint (docs/theory/spring.md, SP-25). Line 1 Type, Kn, ScF, Cr, sens_ID,
// Skew_ID1, Skew_ID2; then three lines per free degree of freedom (SP-25g), the translations' first, each group in
// the order of its axes. A general spring of no mass whose other degrees of freedom the engine blocks.
void read_joint_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Spring);
  SpringSection& s = p.spring;
  s.frame = SpringFrame::Global, s.joint.on = true;
  const Line first = reader.next("Type, Kn, ScF, Cr, sens_ID, Skew_ID1, Skew_ID2");
  s.joint.type = static_cast<int>(first.integer(1, 10, "Type"));
  if (!SpringJoint::supported(s.joint.type))
    first.fail(1, 10, "Type",
               "1 to 9 (spherical, revolute, cylindrical, planar, universal, translational, Oldham, rigid, free; the "
               "reference refuses any other, its error 938)");
  s.joint.blocking_stiffness = first.real(11, 20, "Kn", dim::stiffness);
  if (s.joint.blocking_stiffness < 0.0)
    first.fail(11, 20, "Kn", "a non-negative blocking stiffness (0 or blank: the automatic one)");
  const double scale = first.real(31, 20, "ScF", dim::none);
  if (scale < 0.0)
    first.fail(31, 20, "ScF", "a positive scale of the blocking stiffness (0 or blank: 1, or 10 with a given Kn)");
  s.joint.stiffness_scale = scale != 0.0 ? scale : s.joint.blocking_stiffness > 0.0 ? 10.0 : 1.0;
  const double critical = first.real(51, 20, "Cr", dim::none);
  if (critical < 0.0) first.fail(51, 20, "Cr", "a non-negative fraction of critical damping (0 or blank: 0.05)");
  s.joint.critical_damping = critical == 0.0 ? 0.05 : critical;
  s.joint.skew_id = first.optional_id(81, 10, "Skew_ID1", IdKind::Other);  // the frame's (SP-25f)
  for (const auto& [column, name, what] :
       {std::tuple{71, "sens_ID", "a joint switched by a sensor is"},
        {91, "Skew_ID2", "a joint's second skew (which the reference checks against the first) is"}})
    if (first.optional_id(column, 10, name, IdKind::Other) != 0)
      context.unsupported(first.error(column, 10, name, default_only(what)));
  constexpr const char* kAxes[3] = {"1", "2", "3"};
  // A line group per free degree of freedom, numbered by its axis; a card that ends after line 1 leaves every free
  // one without stiffness or damping (the reference's layout makes the groups optional; measured on a Type 3).
  const bool groups = reader.has_data();
  for (std::size_t d = 0; d < s.dof.size() && groups; ++d)
    if (s.joint.free(d)) read_joint_free_dof(reader, context, s.dof[d], d >= 3, kAxes[d % 3]);
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// /PROP/TYPE2 (/PROP/TRUSS): the truss's initial cross-section and gap (docs/theory/truss.md).
void read_truss_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Truss);
  const Line line = reader.next("Area, Gap_ini");
  p.truss.area = line.real(1, 20, "Area", dim::area);
  if (!(p.truss.area > 0.0)) line.fail(1, 20, "Area", "a positive cross-section");
  p.truss.gap = line.real(21, 20, "Gap_ini", dim::length);  // negative: 0, as the manual says (TR-5)
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

// /PROP/TYPE3 (/PROP/BEAM): Ismstr, the numerical dampings, the section, the rotation releases and Ishear
// (docs/theory/beam.md).
void read_beam_property(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  Property p = begin_property(reader, PropertyKind::Beam);
  BeamSection& b = p.beam;
  const Line flags = reader.next("Ismstr");
  b.ismstr = static_cast<int>(flags.integer(11, 10, "Ismstr"));
  if (!one_of(b.ismstr, {0, 1}))
    flags.fail(11, 10, "Ismstr", "0 (the axial strain logarithmic, the step on the current length) or 1 (on L0); "
                                 "other values are not supported by Crumple");
  const Line damping = reader.next("dm, df");
  b.dm = damping.real(1, 20, "dm", dim::none), b.df = damping.real(21, 20, "df", dim::none);
  const Line section = reader.next("Area, Iyy, Izz, Ixx");
  b.area = section.real(1, 20, "Area", dim::area);
  b.iyy = section.real(21, 20, "Iyy", dim::area_moment), b.izz = section.real(41, 20, "Izz", dim::area_moment);
  b.ixx = section.real(61, 20, "Ixx", dim::area_moment);
  for (const auto& [column, name, value] : {std::tuple{1, "Area", b.area}, {21, "Iyy", b.iyy}, {41, "Izz", b.izz},
                                            {61, "Ixx", b.ixx}})
    if (!(value > 0.0)) section.fail(column, 20, name, "a positive section value (the reference refuses 0)");
  if (reader.has_data()) {
    const Line releases = reader.next("rotation releases, Ishear");
    const char* names[6] = {"Wx1", "Wy1", "Wz1", "Wx2", "Wy2", "Wz2"};
    for (int k = 0; k < 6; ++k) {
      const int column = k < 3 ? 4 + k : 8 + (k - 3);
      if (releases.integer(column, 1, names[k]) != 0)
        context.unsupported(releases.error(column, 1, names[k], default_only("a beam's rotation release is")));
    }
    b.ishear = static_cast<int>(releases.integer(11, 10, "Ishear"));
    if (!one_of(b.ishear, {0, 1})) releases.fail(11, 10, "Ishear", "0 (Timoshenko's shear) or 1 (none)");
  }
  reader.finish();
  context.model.properties.push_back(std::move(p));
}

}  // namespace

void register_property_keywords(KeywordTable& table) {
  table.push_back({"/PROP/TYPE3", DeckPart::Starter, read_beam_property});
  table.push_back({"/PROP/BEAM", DeckPart::Starter, read_beam_property});
  table.push_back({"/PROP/TYPE2", DeckPart::Starter, read_truss_property});
  table.push_back({"/PROP/TRUSS", DeckPart::Starter, read_truss_property});
  table.push_back({"/PROP/TYPE1", DeckPart::Starter, read_shell_property});
  table.push_back({"/PROP/SHELL", DeckPart::Starter, read_shell_property});
  table.push_back({"/PROP/TYPE14", DeckPart::Starter, read_solid_property});
  table.push_back({"/PROP/SOLID", DeckPart::Starter, read_solid_property});
  table.push_back({"/PROP/TYPE4", DeckPart::Starter, read_spring_property});
  table.push_back({"/PROP/SPRING", DeckPart::Starter, read_spring_property});
  table.push_back({"/PROP/TYPE8", DeckPart::Starter, read_general_spring_property});
  table.push_back({"/PROP/SPR_GENE", DeckPart::Starter, read_general_spring_property});
  table.push_back({"/PROP/TYPE13", DeckPart::Starter, read_beam_spring_property});
  table.push_back({"/PROP/SPR_BEAM", DeckPart::Starter, read_beam_spring_property});
  table.push_back({"/PROP/TYPE25", DeckPart::Starter, read_axisymmetric_spring_property});
  table.push_back({"/PROP/SPR_AXI", DeckPart::Starter, read_axisymmetric_spring_property});
  table.push_back({"/PROP/TYPE32", DeckPart::Starter, read_pretension_spring_property});
  table.push_back({"/PROP/SPR_PRE", DeckPart::Starter, read_pretension_spring_property});
  table.push_back({"/PROP/TYPE45", DeckPart::Starter, read_joint_property});
  table.push_back({"/PROP/KJOINT2", DeckPart::Starter, read_joint_property});
}

}  // namespace crumple::deck
