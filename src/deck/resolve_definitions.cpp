// Nodes, functions, materials, properties and parts: indices, duplicates, cross-references, formulations.
#include <fmt/format.h>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

bool one_of(int value, std::initializer_list<int> allowed) {
  for (int a : allowed)
    if (value == a) return true;
  return false;
}

std::string keyword_of(const Property& p) {
  return fmt::format("/PROP/{}/{}", p.kind == PropertyKind::Shell ? "SHELL" : "SOLID", p.user_id);
}

// Icpre of a brick property (docs/theory/brick8.md, "Constant pressure"): 1 constant pressure, 3 none. Blank or
// 0 takes the formulation's default: 3 for Isolid 14 and 24, 1 for 17; Radioss takes Isolid 18's from the material
// law, which Crumple does not guess. Isolid 1, 2 (one pressure per element anyway) and 12 (bulk always at one
// point) have no such option: Radioss sets it to 0 there and Crumple warns that the value is ignored.
int solid_icpre(Resolver& r, const Property& p, int isolid, int icpre) {
  if (one_of(isolid, {1, 2, 12})) {
    if (icpre != 0)
      r.context.warn(p.where, keyword_of(p),
                     fmt::format("Icpre {} is used only with Isolid 14, 17, 18 and 24; ignored for Isolid {}", icpre,
                                 isolid));
    return 0;
  }
  if (icpre != 0) return icpre;  // the readers accept 0, 1 and 3 only
  if (isolid == 18)
    r.error(p.where, keyword_of(p), "Icpre",
            "1 or 3 for Isolid 18 (its default depends on the material law in Radioss; Crumple needs it given)",
            "0");
  return isolid == 17 ? 1 : 3;
}

// Ismstr of a brick property (docs/theory/brick8.md, eq. B-14): 1, 3 small strain from t = 0, 2 switchable by
// /DT/BRICK/CST, 4 never (the default). Isolid 12 runs with 4 only (Radioss switches it); Isolid 18 takes its
// default from the material law in Radioss, which Crumple does not guess.
int solid_ismstr(Resolver& r, const Property& p, int isolid, int ismstr) {
  if (isolid == 12 && ismstr != 0 && ismstr != 4) {
    r.context.warn(p.where, keyword_of(p), fmt::format("Ismstr {} is not available with Isolid 12; set to 4", ismstr));
    return 4;
  }
  if (isolid == 18 && ismstr == 0)
    r.error(p.where, keyword_of(p), "Ismstr",
            "1 to 4 for Isolid 18 (its default depends on the material law in Radioss; Crumple needs it given)", "0");
  return ismstr == 0 ? 4 : ismstr;  // the readers accept 0 to 4 only
}

// Property flag, else /DEF_SHELL or /DEF_SOLID, else the built-in default (Radioss defaults).
ResolvedFormulation formulation_of(Resolver& r, const Property& p) {
  const ShellDefaults& ds = r.model.shell_defaults;
  const SolidDefaults& dv = r.model.solid_defaults;
  auto pick = [](int property_value, int global_value, int builtin) {
    return property_value != 0 ? property_value : global_value != 0 ? global_value : builtin;
  };
  ResolvedFormulation f;
  if (p.kind == PropertyKind::Shell) {
    f.ishell = pick(p.shell.ishell, ds.ishell, 24);
    f.ish3n = pick(p.shell.ish3n, ds.ish3n, 2);
    f.ismstr = pick(p.shell.ismstr, ds.ismstr, 0);
    f.n_points = p.shell.n_points;
    if (!one_of(f.ishell, {1, 24}))
      r.error(p.where, keyword_of(p), "Ishell", "a supported 4-node shell formulation: 1 (Belytschko-Tsay) or 24 (QEPH)",
              std::to_string(f.ishell));
    if (!one_of(f.ish3n, {1, 2}))
      r.error(p.where, keyword_of(p), "Ish3n", "a supported 3-node shell formulation: 1 or 2 (C0 triangle)",
              std::to_string(f.ish3n));
  } else {
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
  r.index(m.materials, m.index.materials, "/MAT");
  r.index(m.properties, m.index.properties, "/PROP");
  r.index(m.parts, m.index.parts, "/PART");

  m.formulations.clear();
  for (const Property& p : m.properties) m.formulations.push_back(formulation_of(r, p));

  for (Part& part : m.parts) {
    const std::string keyword = fmt::format("/PART/{}", part.user_id);
    part.property = r.find(m.index.properties, part.property_id, part.where, keyword, "prop_ID", "property");
    part.material = r.find(m.index.materials, part.material_id, part.where, keyword, "mat_ID", "material");
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
