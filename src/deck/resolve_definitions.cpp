// Nodes, functions, materials, properties and parts: indices, duplicates, cross-references, formulations.
#include <fmt/format.h>

#include <algorithm>

#include <vector>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

// Points through the thickness the reference solver gives a /MAT/PLAS_JOHNS shell property with N = 0.
constexpr int kJohnsonCookPointsForGlobalIntegration = 3;

bool one_of(int value, std::initializer_list<int> allowed) {
  for (int a : allowed)
    if (value == a) return true;
  return false;
}

std::string keyword_of(const Property& p) {
  if (p.kind == PropertyKind::Spring) return fmt::format("/PROP/{}/{}", p.spring.card(), p.user_id);
  return fmt::format("/PROP/{}/{}", describe(p.kind).name, p.user_id);
}

// Shell flags: the property's, else /DEF_SHELL's, else the defaults (docs/theory/shell4.md, "Formulation flags";
// the values Crumple lacks were refused at their fields while reading).
void shell_formulation(Resolver& r, const Property& p, ResolvedFormulation& f) {
  const ShellDefaults& ds = r.model.shell_defaults;
  const auto pick = [](int property_value, int global_value, int builtin) {
    return property_value != 0 ? property_value : global_value != 0 ? global_value : builtin;
  };
  f.ishell = pick(p.shell.ishell, ds.ishell, 1);  // the manual: 1 without /IMPLICIT (the QA listings print 1)
  f.ish3n = pick(p.shell.ish3n, ds.ish3n, 2);
  f.ismstr = pick(p.shell.ismstr, ds.ismstr, 2);
  f.iplas = pick(p.shell.iplas, ds.iplas, 2);  // the manual: 2 (radial return) without /IMPLICIT
  f.n_points = p.shell.n_points;
  // Ishell 2 needs bending points: with N = 1 the reference solver runs Ishell 1 and says so.
  if (f.ishell == 2 && f.n_points == 1) {
    r.context.warn(p.where, keyword_of(p), "Ishell 2 with N = 1 runs as Ishell 1 (the reference solver does the same)");
    f.ishell = 1;
  }
  // Ismstr 3, the old small-strain formulation, exists for Ishell 2 only; the reference runs the others with
  // Ismstr 2 (and says so).
  if (f.ismstr == 3) {
    const bool own = p.shell.ismstr != 0;
    if (f.ishell == 2)
      r.error(own ? p.shell.flags_where : ds.where, own ? keyword_of(p) : "/DEF_SHELL", "Ismstr (columns 11-20)",
              "1, 2 or 4 with Ishell 2: the old small-strain formulation (Ismstr 3) is not supported by Crumple", "'3'");
    else
      r.context.warn(p.where, keyword_of(p), "Ismstr 3 is for Ishell 2 only: runs with Ismstr 2, as the reference");
    f.ismstr = 2;
  }
}

// Whether a part that uses property `property` has a plastic material (every law Crumple has but the elastic one).
// Isolid 18 takes its Icpre default from it, as the reference does (docs/deck-format.md, "Defaults that matter").
bool used_with_plastic_law(const Model& m, const Property& property) {
  const auto index = static_cast<std::int32_t>(&property - m.properties.data());
  return std::any_of(m.parts.begin(), m.parts.end(), [&](const Part& part) {
    return part.property == index && part.material >= 0 &&
           m.materials[static_cast<std::size_t>(part.material)].law != MaterialLaw::Elastic;
  });
}

// Icpre of a brick property (docs/theory/brick8.md, "Constant pressure"): 1 constant pressure, 2 a constant share
// that follows plasticity (eq. B-9c), 3 none. Blank or 0 takes the formulation's default: 3 for Isolid 14 and 24,
// 1 for 17. Isolid 18 takes 3 with an elastic law and 2 with a plastic one, as the reference resolves them
// (measured: its starter listing's element groups, with LAW1 and with LAW2). Icpre 2 is built for the 2x2x2-point
// bricks; Isolid 24 refuses it. Isolid 1, 2 (one pressure per element anyway) and 12 (bulk always at one point)
// have no such option: Radioss sets it to 0 there and Crumple warns that the value is ignored.
int solid_icpre(Resolver& r, const Property& p, int isolid, int icpre) {
  if (one_of(isolid, {1, 2, 12})) {
    if (icpre != 0)
      r.context.warn(p.where, keyword_of(p),
                     fmt::format("Icpre {} is used only with Isolid 14, 17, 18 and 24; ignored for Isolid {}", icpre,
                                 isolid));
    return 0;
  }
  // Icpre 2 is measured for Isolid 14 and 18 (within 1.1 % of the reference's cantilevers); the reference's H8C
  // (Isolid 17) takes a smaller share (measured: Crumple's share was 17 % low in internal energy) and HEPH (24) is
  // not built: refused, not approximated.
  if (icpre == 2 && (isolid == 17 || isolid == 24)) {
    r.context.unsupported(DeckError(p.where, keyword_of(p), "Icpre",
                                    fmt::format("1 or 3 with Isolid {} (the plasticity-following pressure is built for "
                                                "Isolid 14 and 18 only in Crumple)",
                                                isolid),
                                    "2"));
    return isolid == 17 ? 1 : 3;  // --skip-unknown: the formulation's default
  }
  if (icpre != 0) return icpre;  // the readers accept 0 to 3
  if (isolid == 18 && used_with_plastic_law(r.model, p)) return 2;
  return isolid == 17 ? 1 : 3;
}

// Ismstr of a brick property (docs/theory/brick8.md, eq. B-14): 1, 3 small strain from t = 0, 2 switchable by
// /DT/BRICK/CST, 4 never (the default). Isolid 12 runs with 4 only (Radioss switches it); Isolid 18 takes 2, as the
// reference resolves it for the elastic and the plastic laws (measured, as Icpre).
int solid_ismstr(Resolver& r, const Property& p, int isolid, int ismstr) {
  if (isolid == 12 && ismstr != 0 && ismstr != 4) {
    r.context.warn(p.where, keyword_of(p), fmt::format("Ismstr {} is not available with Isolid 12; set to 4", ismstr));
    return 4;
  }
  if (isolid == 18 && ismstr == 0) return 2;
  return ismstr == 0 ? 4 : ismstr;  // the readers accept 0 to 4 only
}

// Property flag, else /DEF_SHELL or /DEF_SOLID, else the built-in default (Radioss defaults).
ResolvedFormulation formulation_of(Resolver& r, const Property& p) {
  const SolidDefaults& dv = r.model.solid_defaults;
  auto pick = [](int property_value, int global_value, int builtin) {
    return property_value != 0 ? property_value : global_value != 0 ? global_value : builtin;
  };
  ResolvedFormulation f;
  if (p.kind == PropertyKind::Shell) {
    shell_formulation(r, p, f);
  } else if (p.kind == PropertyKind::Solid) {
    f.isolid = pick(p.solid.isolid, dv.isolid, 1);
    f.ismstr = solid_ismstr(r, p, f.isolid, pick(p.solid.ismstr, dv.ismstr, 0));
    if (!one_of(f.isolid, {1, 2, 12, 14, 17, 18, 24}))
      r.error(p.where, keyword_of(p), "Isolid",
              "a brick formulation supported by Crumple: 1, 2 (one point, viscous hourglass), 24 (one point, "
              "physically stabilised), 12, 14, 17, 18 (2x2x2 points)",
              std::to_string(f.isolid));
    if (p.solid.inpts != 0 && !(f.isolid == 14 && p.solid.inpts == 222))
      r.error(p.where, keyword_of(p), "Inpts",
              "0 or, for Isolid 14, 222 (other numbers of integration points are not supported by Crumple)",
              std::to_string(p.solid.inpts));
    f.icpre = solid_icpre(r, p, f.isolid, pick(p.solid.icpre, dv.icpre, 0));
    // Iframe: Isolid 14, 18 and 24 are always co-rotational; the others take the flag (default 1).
    f.iframe = one_of(f.isolid, {14, 18, 24}) ? 2 : pick(p.solid.iframe, dv.iframe, 1);
  }
  return f;
}

// Which properties 4-node and 3-node shells use: a formulation flag acts only on the elements it is meant for,
// so a property without triangles may carry an Ish3n Crumple lacks (it has nothing to act on).
struct PropertyUse {
  bool quads = false, triangles = false;
};
std::vector<PropertyUse> property_use(const Resolver& r) {
  const Model& m = r.model;
  std::vector<PropertyUse> use(m.properties.size());
  for (const ElementKind kind : {ElementKind::Shell4, ElementKind::Shell3})
    for (const std::int64_t part_id : r.context.raw_elements[static_cast<int>(kind)].part_id) {
      const auto it = m.index.parts.find(part_id);
      if (it == m.index.parts.end()) continue;
      const std::int32_t property = m.parts[static_cast<std::size_t>(it->second)].property;
      if (property < 0) continue;
      (kind == ElementKind::Shell4 ? use[static_cast<std::size_t>(property)].quads
                                   : use[static_cast<std::size_t>(property)].triangles) = true;
    }
  return use;
}

// Ish3n of a property its triangles use: its own field, else /DEF_SHELL's (the line that gave the value).
void check_triangle_formulation(Resolver& r, const Property& p, const ResolvedFormulation& f) {
  if (one_of(f.ish3n, {1, 2})) return;
  const bool own = p.shell.ish3n != 0;
  r.error(own ? p.shell.flags_where : r.model.shell_defaults.where, own ? keyword_of(p) : "/DEF_SHELL",
          own ? "Ish3n (columns 21-30)" : "I_SH3N (columns 71-80)",
          fmt::format("a 3-node shell formulation supported by Crumple for the triangles of {}: 1 or 2 (C0 triangle); "
                      "30 (DKT18), 31 (DKT_S3) and other values are not supported by Crumple",
                      keyword_of(p)),
          fmt::format("'{}'", f.ish3n));
}

// Iplas of a plastic section. At points through the thickness both returns exist: 1, the iterative plane-stress
// projection (run to convergence, materials.md PS-3), and 2, the radial return (PS-5), the default. On the
// resultants (N = 0) the return is radial (RP-1 to RP-3): the iterative one, 1, is an option Crumple lacks.
void check_plasticity_algorithm(Resolver& r, const Property& p, const ResolvedFormulation& f) {
  if (f.n_points >= 1 || f.iplas == 2) return;
  const bool own = p.shell.iplas != 0;
  r.error(own ? p.shell.section_where : r.model.shell_defaults.where, own ? keyword_of(p) : "/DEF_SHELL",
          own ? "Iplas (columns 81-90)" : "Iplas (columns 31-40)",
          fmt::format("0 or 2 for the plastic resultants of {} (N = 0): the iterative return, 1, is not supported by "
                      "Crumple",
                      keyword_of(p)),
          fmt::format("'{}'", f.iplas));
}

// Flags whose effect depends on the material of a part that uses the property (docs/theory/shell4.md,
// "Formulation flags"): membrane damping dm, the default P_thick_fail and the default Iplas.
void check_shell_material(Resolver& r, const Property& p, const ResolvedFormulation& f, const Material& mat,
                          const PropertyUse& use) {
  const ShellSection& s = p.shell;
  const bool tabulated = mat.law == MaterialLaw::Tabulated, plastic = mat.law != MaterialLaw::Elastic;
  // A given dm acts on every 4-node shell of the reference (Ishell 1 with /MAT/PLAS_JOHNS: measured, shell4.md
  // "Probes"); Crumple has it for the triangles, the Belytschko-Tsay shells and Ishell 24 (eq. S-9d), not for the
  // fully integrated Ishell 12.
  if (s.dm != 0.0 && use.quads && f.ishell == 12)
    r.error(s.damping_where, keyword_of(p), "dm (columns 61-80)",
            "0: membrane damping is not supported by Crumple for the fully integrated shell (Ishell 12)",
            fmt::format("'{}'", s.dm));
  // P_thick_fail 0: the reference deletes an element when all its points failed, Crumple at the first one; the
  // same with one point (N = 0, 1), not with several.
  const double failure = mat.law == MaterialLaw::JohnsonCook ? mat.johnson_cook.eps_p_max
                         : tabulated                         ? mat.tabulated.eps_p_max
                                                             : 0.0;
  // (N = 0 with /MAT/PLAS_JOHNS runs 3 points, as in the reference: integrate_johnson_cook_through_points.)
  const bool switched = s.n_points == 0 && f.n_points >= 2;
  if (f.n_points >= 2 && failure > 0.0 && failure < 1e20)
    r.error(s.flags_where, keyword_of(p), "P_thick_fail (columns 61-80)",
            fmt::format("N = {} with the failure strain of material {}: with N = {}{} the reference deletes an "
                        "element when all its points failed, Crumple at the first (not supported by Crumple)",
                        switched ? "1" : "0 or 1", mat.user_id, f.n_points,
                        switched ? " (N = 0 runs 3 points for /MAT/PLAS_JOHNS)" : ""),
            "'0'");
  if (plastic) check_plasticity_algorithm(r, p, f);
}

// N = 0 asks for global (resultant) integration through the thickness. The reference solver does not integrate
// /MAT/PLAS_JOHNS globally: it switches such a property to 3 points and says so (its starter warning 1912, in the
// listings of the QA decks ball_on_wall, contact_idel and friction). Crumple does the same, so that the fully
// plastic moment is the 3-point one, sigma_y t^2 / 6, not the resultant surface's sigma_y t^2 / 4
// (docs/theory/materials.md, "Which laws run on the resultants").
void integrate_johnson_cook_through_points(Resolver& r) {
  Model& m = r.model;
  for (const Part& part : m.parts) {
    if (part.property < 0 || part.material < 0) continue;
    const Property& p = m.properties[static_cast<std::size_t>(part.property)];
    ResolvedFormulation& f = m.formulations[static_cast<std::size_t>(part.property)];
    const Material& mat = m.materials[static_cast<std::size_t>(part.material)];
    if (p.kind != PropertyKind::Shell || f.n_points != 0 || mat.law != MaterialLaw::JohnsonCook) continue;
    f.n_points = kJohnsonCookPointsForGlobalIntegration;
    r.context.warn(p.shell.section_where, keyword_of(p),
                   fmt::format("N = 0 (global integration) with /MAT/PLAS_JOHNS/{}: the reference solver does not "
                               "integrate this law globally and runs {} points through the thickness; so does Crumple",
                               mat.user_id, kJohnsonCookPointsForGlobalIntegration));
  }
}

void check_shell_formulations(Resolver& r) {
  integrate_johnson_cook_through_points(r);
  const Model& m = r.model;
  const std::vector<PropertyUse> use = property_use(r);
  for (std::size_t i = 0; i < m.properties.size(); ++i) {
    const Property& p = m.properties[i];
    if (p.kind == PropertyKind::Shell && use[i].triangles) check_triangle_formulation(r, p, m.formulations[i]);
    // dn damps QEPH's hourglass modes (S-14) and QBAT's (Ishell 12) step and deformation rates: the other
    // formulations leave it, as the reference does (measured: box_crush, Ishell 1, dn 0.3, the same energies).
    const bool dn_acts = use[i].quads && (m.formulations[i].ishell == 24 || m.formulations[i].ishell == 12);
    if (p.kind == PropertyKind::Shell && p.shell.dn > 0.0 && !dn_acts)
      r.context.warn(p.where, keyword_of(p), "dn acts only on 4-node shells with Ishell 24 or 12: ignored");
    // hm, hf, hr scale the hourglass forces of the one-point shells Ishell 1 to 4; QEPH (24) is stabilised by
    // its own physics, QBAT (12) integrated fully (docs/theory/shell4.md).
    const bool hourglass_given = p.shell.hm > 0.0 || p.shell.hf > 0.0 || p.shell.hr > 0.0;
    if (p.kind == PropertyKind::Shell && hourglass_given && use[i].quads && m.formulations[i].ishell >= 12)
      r.context.warn(p.where, keyword_of(p),
                     fmt::format("hm, hf and hr act only with Ishell 1 to 4: ignored with Ishell {}",
                                 m.formulations[i].ishell));
    // 3-node shells have no hourglass modes: the reference ignores hm, hf, hr on a property of triangles alone
    // (measured: a bent plate of 50 triangles, hm = hf = hr 0.01 and 0.5, the same listing to the last digit).
    if (p.kind == PropertyKind::Shell && hourglass_given && use[i].triangles && !use[i].quads)
      r.context.warn(p.where, keyword_of(p),
                     "hm, hf and hr act only on 4-node shells (3-node shells have no hourglass modes): ignored, the "
                     "property has 3-node shells alone");
    // h is the viscous hourglass coefficient of Isolid 1 and 2; dn damps Isolid 24's stabilisation (B-6, B-8).
    if (p.kind == PropertyKind::Solid) {
      const int isolid = m.formulations[i].isolid;
      if (p.solid.h > 0.0 && isolid != 1 && isolid != 2)
        r.context.warn(p.where, keyword_of(p),
                       fmt::format("h acts only with Isolid 1 and 2 (viscous hourglass): ignored with Isolid {}",
                                   isolid));
      if (p.solid.dn > 0.0 && isolid != 24)
        r.context.warn(p.where, keyword_of(p),
                       fmt::format("dn acts only with Isolid 24: ignored with Isolid {}", isolid));
    }
  }
  std::vector<std::uint8_t> checked(m.properties.size() * m.materials.size(), 0);
  for (const Part& part : m.parts) {
    if (part.property < 0 || part.material < 0) continue;
    const auto ip = static_cast<std::size_t>(part.property), im = static_cast<std::size_t>(part.material);
    const Property& p = m.properties[ip];
    if (p.kind != PropertyKind::Shell || !(use[ip].quads || use[ip].triangles) || checked[ip * m.materials.size() + im])
      continue;
    checked[ip * m.materials.size() + im] = 1;
    check_shell_material(r, p, m.formulations[ip], m.materials[im], use[ip]);
  }
}

// A truss or beam part's material (docs/theory/truss.md, beam.md): LAW1 or LAW2, as the reference, which refuses
// the others on them (its starter errors 3046 and 3047 for LAW36, measured); LAW2's strain-rate terms do nothing on
// a truss there (measured: c 0.05 gives the runs of c 0), and a beam's rate is not filtered (measured: Fsmooth 1
// with F_cut 100 Hz gives the run without).
void check_line_element_materials(Resolver& r) {
  const Model& m = r.model;
  for (const Part& part : m.parts) {
    if (part.property < 0 || part.material < 0) continue;
    const PropertyKind kind = m.properties[static_cast<std::size_t>(part.property)].kind;
    if (kind != PropertyKind::Truss && kind != PropertyKind::Beam) continue;
    const bool truss = kind == PropertyKind::Truss;
    const std::string_view what = truss ? "trusses" : "beams";
    const Material& mat = m.materials[static_cast<std::size_t>(part.material)];
    const std::string keyword = fmt::format("/PART/{}", part.user_id);
    if (mat.law != MaterialLaw::Elastic && mat.law != MaterialLaw::JohnsonCook) {
      r.error(part.where, keyword, "mat_ID",
              fmt::format("a LAW1 or LAW2 material for {} (the reference refuses LAW{} on them)", what,
                          static_cast<int>(mat.law)),
              std::to_string(mat.user_id));
      continue;
    }
    if (mat.law != MaterialLaw::JohnsonCook) continue;
    const JohnsonCookParameters& jc = mat.johnson_cook;
    if (jc.c != 0.0 && truss)
      r.context.warn(mat.where, fmt::format("/MAT/LAW2/{}", mat.user_id),
                     fmt::format("c (strain rate) does nothing on the trusses of part {}, as in the reference",
                                 part.user_id));
    if (jc.c != 0.0 && !truss && jc.fsmooth != 0)
      r.context.warn(mat.where, fmt::format("/MAT/LAW2/{}", mat.user_id),
                     fmt::format("Fsmooth, F_cut: the beams of part {} take their strain rate unfiltered, as in the "
                                 "reference",
                                 part.user_id));
  }
}

// /MOVE_FUNCT, in deck order, before anything reads a function (docs/deck-format.md, "Functions").
void move_functions(Resolver& r) {
  for (const FunctionMove& move : r.context.function_moves) {
    const auto k = r.find(r.model.index.functions, move.function_id, move.where, move.keyword, "fct_ID", "/FUNCT");
    if (k < 0) continue;
    Function& f = r.model.functions[static_cast<std::size_t>(k)];
    for (double& x : f.x) x = move.scale_x * x + move.shift_x;
    for (double& y : f.y) y = move.scale_y * y + move.shift_y;
  }
}

// A pretensioner's functions f1 and f2 (docs/theory/spring.md, SP-22b), by their ids.
void resolve_pretension_functions(Resolver& r, Property& p) {
  SpringPretension& pre = p.spring.pretension;
  const auto find = [&](std::int64_t id, std::string_view field) {
    return r.find_optional(r.model.index.functions, id, p.where, keyword_of(p), std::string(field), "function");
  };
  pre.stroke_function = find(pre.stroke_function_id, "fct_ID1");
  pre.time_function = find(pre.time_function_id, "fct_ID2");
}

// A spring law's functions (docs/theory/spring.md): the force or yield curve, H 4's lower curve and the rate
// functions g and h (SP-23), by their ids.
void resolve_spring_functions(Resolver& r, Property& p, int d) {
  SpringLaw& law = p.spring.dof[static_cast<std::size_t>(d)];
  const bool six = p.spring.dofs() > 1;
  const std::string i = six ? std::to_string(d + 1) : "1";
  Model& m = r.model;
  const auto find = [&](std::int64_t id, std::string_view field) {
    return r.find_optional(m.index.functions, id, p.where, keyword_of(p), std::string(field) + i, "function");
  };
  law.rate_force_function = find(law.rate_force_function_id, "fct_ID4");
  if (law.function_id == 0) return;
  law.function = find(law.function_id, "fct_ID1");
  law.lower_function = find(law.lower_function_id, "fct_ID3");
  law.rate_factor_function = find(law.rate_factor_function_id, "fct_ID2");
  if (law.function < 0) return;  // an unknown id: already an error
  // SP-4c: a hardening spring unloads at no less than its curve's steepest slope, as the reference runs it.
  const double slope =
      m.functions[static_cast<std::size_t>(law.function)].steepest_slope() * law.function_scale / law.abscissa_scale;
  if (law.hardening != 0 && law.stiffness < slope)
    r.context.warn(p.where, keyword_of(p),
                   fmt::format("K{} = {:g} is below the steepest slope of its yield curve fct_ID1{}, {:g}: the spring "
                               "unloads at that slope, as the reference runs it",
                               six ? i : "", law.stiffness, i, slope));
  // H 1: the yield force is the curve's in both directions (SP-6), as the reference runs a curve that is odd about 0;
  // the reference's answer to another curve is not Crumple's.
  if (law.hardening != 1) return;
  // A TYPE25 radial law (SP-20) is a law of the magnitude, never below 0: its curve's negative side is not read.
  if (p.spring.radial && (d == 1 || d == 2 || d == 4 || d == 5)) return;
  const Function& f = m.functions[static_cast<std::size_t>(law.function)];
  for (double x : f.x)
    if (std::abs(f(-x) + f(x)) > 1e-9 * (std::abs(f(x)) + 1.0)) {
      r.context.unsupported(DeckError(p.where, keyword_of(p), "fct_ID1" + i,
                                      "a yield curve odd about 0, f(-x) = -f(x), for isotropic hardening (H 1; "
                                      "another curve is not supported by Crumple)",
                                      fmt::format("f({:g}) = {:g}, f({:g}) = {:g}", x, f(x), -x, f(-x))));
      return;
    }
}

}  // namespace

void resolve_definitions(Resolver& r) {
  Model& m = r.model;
  // Nodes: duplicates named with both lines.
  m.index.nodes.reserve(m.nodes.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const auto [it, inserted] = m.index.nodes.emplace(m.nodes.user_id[i], static_cast<std::int32_t>(i));
    if (!inserted) {
      const auto& first = r.context.node_where[static_cast<std::size_t>(it->second)];
      r.error(r.context.node_where[i], "/NODE", "node_ID", "a node id not used by another node",
              fmt::format("node {} already defined at {}:{}", m.nodes.user_id[i], first.file, first.line));
    }
  }
  r.index(m.functions, m.index.functions, "/FUNCT");
  move_functions(r);
  r.index(m.materials, m.index.materials, "/MAT");
  r.index(m.properties, m.index.properties, "/PROP");
  r.index(m.parts, m.index.parts, "/PART");

  for (Part& part : m.parts) {
    const std::string keyword = fmt::format("/PART/{}", part.user_id);
    part.property = r.find(m.index.properties, part.property_id, part.where, keyword, "prop_ID", "property");
    if (part.material_id != 0) {
      part.material = r.find(m.index.materials, part.material_id, part.where, keyword, "mat_ID", "material");
      continue;
    }
    part.material = -1;  // mat_ID 0: the property carries the law
    if (part.property >= 0 && !describe(m.properties[static_cast<std::size_t>(part.property)].kind).carries_law)
      r.error(part.where, keyword, "mat_ID",
              "a positive material id (only a part whose property carries the law, a spring, takes mat_ID 0)", "0");
  }
  // After the parts: a default may depend on the material the property is used with (Isolid 18).
  m.formulations.clear();
  for (const Property& p : m.properties) m.formulations.push_back(formulation_of(r, p));
  check_shell_formulations(r);
  check_line_element_materials(r);
  for (Property& p : m.properties)
    if (p.kind == PropertyKind::Spring) {
      for (int d = 0; d < p.spring.dofs(); ++d) resolve_spring_functions(r, p, d);
      if (p.spring.pretension.on) resolve_pretension_functions(r, p);
    }
  for (Material& mat : m.materials) {
    if (mat.law != MaterialLaw::Tabulated) continue;
    const std::string keyword = fmt::format("/MAT/PLAS_TAB/{}", mat.user_id);
    for (std::size_t k = 0; k < mat.tabulated.function_id.size(); ++k)
      mat.tabulated.function.push_back(r.find(m.index.functions, mat.tabulated.function_id[k], mat.where, keyword,
                                              fmt::format("fct_ID{}", k + 1), "function"));
  }
}

}  // namespace crumple::deck
