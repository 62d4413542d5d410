#include "resolve.hpp"

#include <fmt/format.h>

#include <cmath>

#include "crumple/model/mass.hpp"

namespace crumple::deck {
namespace {

// rho t A (or rho V) and the sums of masses can overflow although every input value is finite: a model whose
// mass is not finite is refused rather than handed to the solver.
void check_mass(Resolver& r) {
  const Model& m = r.model;
  for (const ElementGroup& g : m.element_groups) {
    const ElementTable& table = m.elements[static_cast<int>(g.kind)];
    for (std::int32_t e = g.begin; e < g.end; ++e) {
      const double mass = element_mass(m, g.kind, static_cast<std::size_t>(e));
      if (std::isfinite(mass)) continue;
      const Part& part = m.parts[static_cast<std::size_t>(g.part)];
      r.error(part.where, fmt::format("/PART/{}", part.user_id), "",
              "elements of finite mass (density x thickness x area, or density x volume)",
              fmt::format("{} {} of mass {}", element_kind_name(g.kind), table.user_id[static_cast<std::size_t>(e)],
                          mass));
      break;  // one error per group
    }
  }
  if (!r.errors.empty()) return;
  for (std::size_t i = 0; i < m.nodal_mass.size(); ++i)
    if (!std::isfinite(m.nodal_mass[i])) {
      r.error(r.context.node_where[i], "/NODE", "", "a finite nodal mass (element and added masses)",
              fmt::format("node {} of mass {}", m.nodes.user_id[i], m.nodal_mass[i]));
      return;
    }
  if (!std::isfinite(m.total_mass()))
    r.error(SourceLocation{r.context.report.files.front(), 0}, "", "", "a finite total mass",
            fmt::format("{}", m.total_mass()));
}

}  // namespace

void Resolver::throw_if_errors() {
  if (!errors.empty()) throw DeckErrors(std::move(errors));
}

void resolve_model(DeckContext& context, std::vector<RunControl>& continued_runs) {
  Resolver r(context);
  resolve_definitions(r);
  r.throw_if_errors();  // later stages need valid nodes, parts, materials and properties
  resolve_elements(r);
  r.throw_if_errors();
  resolve_sets(r);
  resolve_load_references(r);
  resolve_output_references(r, continued_runs);
  r.throw_if_errors();
  compute_mass(context.model);
  check_mass(r);
  r.throw_if_errors();
}

}  // namespace crumple::deck
