// Nodes, functions, materials, properties and parts: indices, duplicates, cross-references, formulations.
#include <fmt/format.h>

#include <vector>

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
    // Ishell 2 needs bending points: with N = 1 the reference solver runs Ishell 1 and says so.
    if (f.ishell == 2 && f.n_points == 1) {
      r.context.warn(p.where, keyword_of(p), "Ishell 2 with N = 1 runs as Ishell 1 (the reference solver does the same)");
      f.ishell = 1;
    }
    if (!one_of(f.ishell, {1, 2, 3, 12, 24}))
      r.error(p.where, keyword_of(p), "Ishell",
              "a supported 4-node shell formulation: 1 (Belytschko-Tsay), 2 (without orthogonality), 3 "
              "(elasto-plastic hourglass), 12 (QBAT) or 24 (QEPH)",
              std::to_string(f.ishell));
  } else {
    f.isolid = pick(p.solid.isolid, dv.isolid, 1);
    f.ismstr = pick(p.solid.ismstr, dv.ismstr, 0);
    if (!one_of(f.isolid, {1, 14, 24}))
      r.error(p.where, keyword_of(p), "Isolid",
              "a supported brick formulation: 1 (one point), 14 (fully integrated) or 24 (physically stabilised)",
              std::to_string(f.isolid));
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
          "a 3-node shell formulation supported by Crumple for the triangles of this property: 1 or 2 (C0 "
          "triangle); 30 (DKT18), 31 (DKT_S3) and other values are not supported by Crumple",
          fmt::format("'{}'", f.ish3n));
}

void check_shell_formulations(Resolver& r) {
  const std::vector<PropertyUse> use = property_use(r);
  for (std::size_t i = 0; i < r.model.properties.size(); ++i) {
    const Property& p = r.model.properties[i];
    if (p.kind == PropertyKind::Shell && use[i].triangles) check_triangle_formulation(r, p, r.model.formulations[i]);
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
  check_shell_formulations(r);
  for (Material& mat : m.materials) {
    if (mat.law != MaterialLaw::Tabulated) continue;
    const std::string keyword = fmt::format("/MAT/PLAS_TAB/{}", mat.user_id);
    for (std::size_t k = 0; k < mat.tabulated.function_id.size(); ++k)
      mat.tabulated.function.push_back(r.find(m.index.functions, mat.tabulated.function_id[k], mat.where, keyword,
                                              fmt::format("fct_ID{}", k + 1), "function"));
  }
}

}  // namespace crumple::deck
