// /MAT/LAW1 (ELAST), /MAT/LAW2 (PLAS_JOHNS), /MAT/LAW36 (PLAS_TAB). Layouts: docs/cards/starter-model.md.
#include <fmt/format.h>

#include <cmath>

#include "../context.hpp"

namespace crumple::deck {
namespace {

Material begin_material(CardReader& reader, MaterialLaw law) {
  Material m;
  m.where = reader.card().where;
  m.law = law;
  m.user_id = object_id(reader, 2);
  read_unit_id(reader, 3);
  m.title = read_title(reader);
  return m;
}

void read_density(CardReader& reader, DeckContext& context, Material& m) {
  const Line line = reader.next("RHO_I, RHO_0");
  m.density = line.real(1, 20, "RHO_I", dim::density);
  if (m.density <= 0.0) line.fail(1, 20, "RHO_I", "a positive density");
  // RHO_0, the reference density of an equation of state: blank, 0 or RHO_I mean no initial compression.
  const double reference = line.real(21, 20, "RHO_0", dim::density);
  if (reference != 0.0 && reference != m.density)
    context.unsupported(line.error(21, 20, "RHO_0", default_only("a reference density other than RHO_I is")));
}

// A field whose non-default value is an option of the law Crumple does not implement.
void reject_if(DeckContext& context, const Line& line, bool non_default, int column, int width, std::string_view name,
               std::string_view feature) {
  if (non_default) context.unsupported(line.error(column, width, name, default_only(feature)));
}

void check_elastic(const Line& line, const Material& m, int e_column, int nu_column) {
  if (m.young <= 0.0) line.fail(e_column, 20, "E", "a positive Young's modulus");
  if (!(m.poisson > -1.0 && m.poisson < 0.5)) line.fail(nu_column, 20, "Nu", "a Poisson ratio in (-1, 0.5)");
}

void read_elastic(CardReader& reader, DeckContext& context) {
  Material m = begin_material(reader, MaterialLaw::Elastic);
  read_density(reader, context, m);
  const Line line = reader.next("E, Nu");
  m.young = line.real(1, 20, "E", dim::pressure);
  m.poisson = line.real(21, 20, "Nu", dim::none);
  check_elastic(line, m, 1, 21);
  reader.finish();
  context.model.materials.push_back(std::move(m));
}

void read_johnson_cook(CardReader& reader, DeckContext& context) {
  Material m = begin_material(reader, MaterialLaw::JohnsonCook);
  JohnsonCookParameters& jc = m.johnson_cook;
  read_density(reader, context, m);
  const Line elastic = reader.next("E, Nu, Iflag");
  m.young = elastic.real(1, 20, "E", dim::pressure);
  m.poisson = elastic.real(21, 20, "Nu", dim::none);
  const std::int64_t iflag = elastic.integer(41, 10, "Iflag");
  check_elastic(elastic, m, 1, 21);
  if (iflag != 0 && iflag != 1) elastic.fail(41, 10, "Iflag", "0 (a, b, n given) or 1 (yield, UTS, strain at UTS)");

  const Line hardening = reader.next("a, b, n, EPS_p_max, SIG_max0");
  jc.eps_p_max = hardening.real(61, 20, "EPS_p_max", dim::none);
  jc.sig_max0 = hardening.real(81, 20, "SIG_max0", dim::pressure);
  if (iflag == 0) {
    jc.a = hardening.real(1, 20, "a", dim::pressure);
    jc.b = hardening.real(21, 20, "b", dim::pressure);
    jc.n = hardening.real(41, 20, "n", dim::none, 1.0);
    if (jc.a <= 0.0) hardening.fail(1, 20, "a", "a positive yield stress");
    if (jc.b < 0.0) hardening.fail(21, 20, "b", "a non-negative hardening modulus");
    if (jc.n <= 0.0 || jc.n > 1.0) hardening.fail(41, 20, "n", "a hardening exponent in (0, 1]");
  } else {
    // Iflag = 1: yield stress, ultimate tensile stress and engineering strain at UTS. With true stress and
    // strain at necking (eps_u = ln(1 + e_uts), sigma_u = UTS (1 + e_uts)) Considere's condition
    // d(sigma)/d(eps) = sigma gives n = b n eps^(n-1)... solved as in docs/theory/materials.md.
    const double yield = hardening.real(1, 20, "sigma_Y", dim::pressure);
    const double uts = hardening.real(21, 20, "UTS", dim::pressure);
    const double e_uts = hardening.real(41, 20, "EPS_UTS", dim::none);
    if (yield <= 0.0) hardening.fail(1, 20, "sigma_Y", "a positive yield stress");
    if (uts <= yield) hardening.fail(21, 20, "UTS", "an ultimate tensile stress above the yield stress");
    if (e_uts <= 0.0) hardening.fail(41, 20, "EPS_UTS", "a positive engineering strain at UTS");
    const double eps_u = std::log1p(e_uts);
    const double sigma_u = uts * (1.0 + e_uts);
    // sigma = a + b eps^n with sigma(eps_u) = sigma_u and sigma'(eps_u) = sigma_u: n b eps_u^(n-1) = sigma_u.
    // => (sigma_u - a) n / eps_u = sigma_u  => n = sigma_u eps_u / (sigma_u - a).
    jc.a = yield;
    jc.n = sigma_u * eps_u / (sigma_u - yield);
    jc.b = (sigma_u - yield) / std::pow(eps_u, jc.n);
    if (!(jc.n > 0.0 && jc.n <= 1.0))
      hardening.fail_value("EPS_UTS", "a strain at UTS that gives a hardening exponent in (0, 1]",
                           fmt::format("n = {:.4g}", jc.n));
  }
  if (jc.eps_p_max < 0.0) hardening.fail(61, 20, "EPS_p_max", "a non-negative failure plastic strain");
  if (jc.sig_max0 < 0.0) hardening.fail(81, 20, "SIG_max0", "a non-negative maximum stress");

  if (!reader.at_end()) {
    const Line rate = reader.next("c, EPS_DOT_0, ICC, Fsmooth, F_cut, Chard");
    jc.c = rate.real(1, 20, "c", dim::none);
    jc.eps_dot_0 = rate.real(21, 20, "EPS_DOT_0", dim::rate);
    jc.icc = static_cast<int>(rate.integer(41, 10, "ICC"));
    jc.fsmooth = static_cast<int>(rate.integer(51, 10, "Fsmooth"));
    jc.f_cut = rate.real(61, 20, "F_cut", dim::rate);
    jc.chard = rate.real(81, 20, "Chard", dim::none);
    if (jc.c < 0.0) rate.fail(1, 20, "c", "a non-negative strain-rate coefficient");
    if (jc.c > 0.0 && jc.eps_dot_0 <= 0.0)
      rate.fail(21, 20, "EPS_DOT_0", "a positive reference strain rate when c > 0");
    if (jc.chard < 0.0 || jc.chard > 1.0) rate.fail(81, 20, "Chard", "a hardening mix in [0, 1]");
    if (jc.fsmooth != 0 && jc.fsmooth != 1) rate.fail(51, 10, "Fsmooth", "0 (no smoothing) or 1 (smoothed strain rate)");
    // docs/cards/starter-model.md, /MAT/PLAS_JOHNS reader checks: ICC in {0, 1, 2}.
    if (jc.icc < 0 || jc.icc > 2)
      rate.fail(41, 10, "ICC", "0 or 1 (the rate factor also scales SIG_max0) or 2 (SIG_max0 not rate dependent)");
    if (jc.c == 0.0 && jc.eps_dot_0 != 0.0)
      context.warn(rate.where(), reader.card().keyword,
                   "EPS_DOT_0 acts only with a strain-rate coefficient c > 0: ignored with c = 0");
    if (jc.fsmooth == 0 && jc.f_cut != 0.0)
      context.warn(rate.where(), reader.card().keyword, "F_cut acts only with Fsmooth = 1: ignored");
    reject_if(context, rate, jc.chard != 0.0, 81, 20, "Chard", "kinematic hardening (Chard > 0) is");
    if (jc.chard != 0.0) jc.chard = 0.0;  // --skip-unknown: isotropic hardening
  }
  if (!reader.at_end()) {
    const Line thermal = reader.next("m, T_melt, rhoC_p, T_r");
    jc.m = thermal.real(1, 20, "m", dim::none);
    jc.t_melt = thermal.real(21, 20, "T_melt", dim::none);
    jc.rho_cp = thermal.real(41, 20, "rhoC_p", dim::none);
    jc.t_r = thermal.real(61, 20, "T_r", dim::none);
    // With m = 0 the temperature does not enter the yield stress: T_melt, rhoC_p and T_r then change nothing.
    reject_if(context, thermal, jc.m != 0.0, 1, 20, "m", "thermal softening (m > 0) is");
    if (jc.m == 0.0 && (jc.t_melt != 0.0 || jc.rho_cp != 0.0 || jc.t_r != 0.0))
      context.warn(thermal.where(), reader.card().keyword,
                   "T_melt, rhoC_p and T_r act only with thermal softening (m > 0): ignored with m = 0");
    jc.m = 0.0;
  }
  reader.finish();
  context.model.materials.push_back(std::move(m));
}

// Law 36: yield stress tabulated against plastic strain, one curve per strain rate.
void read_tabulated_pressure_line(CardReader& reader, DeckContext& context);
void read_tabulated_curves(CardReader& reader, TabulatedHardening& tab, std::int64_t n_funct);

// Input versions 41 to 44: the control line ends with Ipfun 49-56 and Eps_f 57-72 (44; blank in 41 and 42) and
// there is no pressure line; the rest is the 2017 card narrowed.
void read_tabulated_plasticity(CardReader& reader, DeckContext& context) {
  Material m = begin_material(reader, MaterialLaw::Tabulated);
  TabulatedHardening& tab = m.tabulated;
  read_density(reader, context, m);
  const Line elastic = reader.next("E, Nu, EPS_p_max, EPS_t, EPS_m");
  m.young = elastic.real(1, 20, "E", dim::pressure);
  m.poisson = elastic.real(21, 20, "Nu", dim::none);
  check_elastic(elastic, m, 1, 21);
  if (m.poisson < 0.0) elastic.fail(21, 20, "Nu", "a Poisson ratio in [0, 0.5) for law 36");
  tab.eps_p_max = elastic.real(41, 20, "EPS_p_max", dim::none);
  tab.eps_t1 = elastic.real(61, 20, "EPS_t", dim::none);
  tab.eps_t2 = elastic.real(81, 20, "EPS_m", dim::none);
  if (tab.eps_p_max < 0.0) elastic.fail(41, 20, "EPS_p_max", "a non-negative failure plastic strain");
  // Tensile failure (stress reduced from EPS_t, zero at EPS_m): blank, 0 or the manual's 1E20 defaults mean none.
  constexpr double kNoTensileFailure = 1e20;
  reject_if(context, elastic, tab.eps_t1 != 0.0 && tab.eps_t1 < kNoTensileFailure, 61, 20, "EPS_t",
            "tensile failure softening is");
  reject_if(context, elastic, tab.eps_t2 != 0.0 && tab.eps_t2 < 2.0 * kNoTensileFailure, 81, 20, "EPS_m",
            "tensile failure softening is");
  tab.eps_t1 = tab.eps_t2 = 0.0;

  const Line control = reader.next("N_funct, Fsmooth, Chard, Fcut, Eps_f, VP");
  const std::int64_t n_funct = control.integer(1, 10, "N_funct");
  if (n_funct < 1 || n_funct > 100) control.fail(1, 10, "N_funct", "a number of curves between 1 and 100");
  tab.fsmooth = static_cast<int>(control.integer(11, 10, "Fsmooth"));
  tab.chard = control.real(21, 20, "Chard", dim::none);
  tab.f_cut = control.real(41, 20, "Fcut", dim::rate);
  if (tab.chard < 0.0 || tab.chard > 1.0) control.fail(21, 20, "Chard", "a hardening mix in [0, 1]");
  reject_if(context, control, tab.chard != 0.0, 21, 20, "Chard", "kinematic hardening (Chard > 0) is");
  tab.chard = 0.0;
  if (reader.narrow()) {
    const Line old = control.as_written();
    reject_if(context, old, old.integer(49, 8, "Ipfun") != 0, 49, 8, "Ipfun", "pressure-dependent yield is");
    reject_if(context, old, old.real(57, 16, "Eps_f", dim::none) != 0.0, 57, 16, "Eps_f", "the failure strain Eps_f is");
  } else {
    reject_if(context, control, control.real(61, 20, "Eps_f", dim::none) != 0.0, 61, 20, "Eps_f",
              "the failure strain Eps_f is");
    // VP chooses the strain rate of the curves: 0, the total strain rate, is what Crumple uses.
    reject_if(context, control, control.integer(81, 10, "VP") != 0, 81, 10, "VP",
              "a strain rate other than the total one (VP > 0) is");
    read_tabulated_pressure_line(reader, context);
  }
  read_tabulated_curves(reader, tab, n_funct);
  reader.finish();
  context.model.materials.push_back(std::move(m));
}

void read_tabulated_pressure_line(CardReader& reader, DeckContext& context) {
  const Line pressure = reader.next("fct_IDp, Fscale, fct_IDE, Einf, CE");
  reject_if(context, pressure, pressure.integer(1, 10, "fct_IDp") != 0, 1, 10, "fct_IDp",
            "pressure-dependent yield is");
  reject_if(context, pressure, pressure.integer(31, 10, "fct_IDE") != 0, 31, 10, "fct_IDE",
            "Young's modulus evolution is");
  pressure.real(11, 20, "Fscale", dim::none);  // scales fct_IDp only
  pressure.real(41, 20, "Einf", dim::pressure);  // used only with CE
  // E(eps_p) = E - (E - Einf)(1 - exp(-CE eps_p)) when CE > 0: a modulus evolution too.
  reject_if(context, pressure, pressure.real(61, 20, "CE", dim::none) != 0.0, 61, 20, "CE",
            "Young's modulus evolution is");
}

// The curves: function ids, their scales and their strain rates, five a line each.
void read_tabulated_curves(CardReader& reader, TabulatedHardening& tab, std::int64_t n_funct) {
  const auto n = static_cast<std::size_t>(n_funct);
  const std::size_t lines = (n + 4) / 5;
  for (std::size_t l = 0; l < lines; ++l) {
    const Line ids = reader.next("fct_ID1..fct_ID5");
    for (std::size_t k = 0; k < 5 && tab.function_id.size() < n; ++k) {
      const int column = 1 + 10 * static_cast<int>(k);
      const std::string name = fmt::format("fct_ID{}", tab.function_id.size() + 1);
      const std::int64_t id = ids.id(column, 10, name, IdKind::Other);
      if (id <= 0) ids.fail(column, 10, name, "a positive function id");
      tab.function_id.push_back(id);
    }
  }
  for (std::size_t l = 0; l < lines; ++l) {
    const Line scales = reader.next("Fscale1..Fscale5");
    for (std::size_t k = 0; k < 5 && tab.scale.size() < n; ++k) {
      const std::string name = fmt::format("Fscale{}", tab.scale.size() + 1);
      double scale = scales.real(1 + 20 * static_cast<int>(k), 20, name, dim::pressure);
      if (scale == 0.0) scale = reader.units().factor(dim::pressure);  // blank or zero: 1 (in input units)
      tab.scale.push_back(scale);
    }
  }
  for (std::size_t l = 0; l < lines; ++l) {
    if (reader.at_end() && n == 1) {
      tab.strain_rate.push_back(0.0);
      break;
    }
    const Line rates = reader.next("Eps_dot1..Eps_dot5");
    for (std::size_t k = 0; k < 5 && tab.strain_rate.size() < n; ++k) {
      const int column = 1 + 20 * static_cast<int>(k);
      const std::string name = fmt::format("Eps_dot{}", tab.strain_rate.size() + 1);
      const double rate = rates.real(column, 20, name, dim::rate);
      if (!tab.strain_rate.empty() && rate <= tab.strain_rate.back())
        rates.fail(column, 20, name, "strain rates in increasing order");
      tab.strain_rate.push_back(rate);
    }
  }
}

}  // namespace

void register_material_keywords(KeywordTable& table) {
  table.push_back({"/MAT/LAW1", DeckPart::Starter, read_elastic});
  table.push_back({"/MAT/ELAST", DeckPart::Starter, read_elastic});
  table.push_back({"/MAT/LAW2", DeckPart::Starter, read_johnson_cook});
  table.push_back({"/MAT/PLAS_JOHNS", DeckPart::Starter, read_johnson_cook});
  table.push_back({"/MAT/LAW36", DeckPart::Starter, read_tabulated_plasticity});
  table.push_back({"/MAT/PLAS_TAB", DeckPart::Starter, read_tabulated_plasticity});
}

}  // namespace crumple::deck
