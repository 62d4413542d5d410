#include "resolve.hpp"

#include <fmt/format.h>

#include <cmath>
#include <random>

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

// An /RBE2 group without mass has nothing to carry its force: the reference stops (its error 804); so does
// `crumple check`, before the solver's own guard (docs/theory/rigid-bodies.md, RE-6).
void refuse_massless_rigid_elements(Resolver& r) {
  const Model& m = r.model;
  for (const RigidElement& e : m.rigid_elements) {
    double mass = m.nodal_mass[static_cast<std::size_t>(e.main_node)];
    for (std::int32_t n : e.secondary_nodes) mass += m.nodal_mass[static_cast<std::size_t>(n)];
    if (!(mass > 0.0))
      r.error(e.where, fmt::format("/RBE2/{}", e.user_id), "grnod_ID",
              "a group with mass (its main node's or its secondary nodes'), as the reference requires", "no mass");
  }
}

// /RANDOM (docs/deck-format.md): after /TRANSFORM (the reference's order, measured), each coordinate of each node
// moved by Xalea (2 u - 1), u uniform in [0, 1) from a 64-bit Mersenne twister seeded by Seed, so that the same
// deck gives the same model everywhere. The reference moves its nodes the same way (each axis within +-Xalea,
// measured in its starter listing) with its own sequence.
void apply_random_noise(Model& m) {
  if (!(m.random_noise > 0.0)) return;
  std::mt19937_64 engine(static_cast<std::uint64_t>(m.random_seed * 9007199254740992.0) ^ 0x9e3779b97f4a7c15ULL);
  const auto uniform = [&] { return static_cast<double>(engine() >> 11) * 0x1.0p-53; };
  for (std::size_t k = 0; k < m.nodes.size(); ++k)
    for (std::vector<double>* axis : {&m.nodes.x, &m.nodes.y, &m.nodes.z})
      (*axis)[k] += m.random_noise * (2.0 * uniform() - 1.0);
}

}  // namespace

void Resolver::throw_if_errors() {
  if (!errors.empty()) throw DeckErrors(std::move(errors));
}

// One-point bricks written as tetrahedra or pyramids integrate 3/4 of their volume, as in the reference (docs/theory/
// brick8.md, eq. B-2b): their mass and stiffness follow. Said once per part, since a user may not expect it.
void warn_degenerate_one_point_bricks(Resolver& r) {
  const Model& m = r.model;
  std::vector<long long> count(m.parts.size(), 0);
  for (const ElementGroup& g : m.element_groups)
    if (g.kind == ElementKind::Brick8)
      for (std::int32_t e = g.begin; e < g.end; ++e)
        if (one_point_volume_scale(m, static_cast<std::size_t>(e)) != 1.0) ++count[static_cast<std::size_t>(g.part)];
  for (std::size_t i = 0; i < m.parts.size(); ++i)
    if (count[i] > 0)
      r.context.warn(m.parts[i].where, fmt::format("/PART/{}", m.parts[i].user_id),
                     fmt::format("{} one-point bricks written as tetrahedra or pyramids integrate 3/4 of their "
                                 "volume, as in the reference: their mass and stiffness follow (Isolid 14 to 18 "
                                 "integrate all of it)",
                                 count[i]));
}

// /DEF_SHELL and /DEF_SOLID set the defaults of the elements of their kind: a model without such elements takes
// nothing from them.
void warn_defaults_without_elements(Resolver& r) {
  const Model& m = r.model;
  const bool shells = m.elements[static_cast<int>(ElementKind::Shell4)].size() + m.elements[static_cast<int>(ElementKind::Shell3)].size() > 0;
  const bool bricks = m.elements[static_cast<int>(ElementKind::Brick8)].size() > 0;
  const ShellDefaults& ds = m.shell_defaults;
  const SolidDefaults& dv = m.solid_defaults;
  if (!shells && (ds.ishell || ds.ismstr || ds.ithick || ds.iplas || ds.istrain || ds.ish3n || ds.idrill))
    r.context.warn(ds.where, "/DEF_SHELL", "no shell in the model: its defaults act on nothing");
  if (!bricks && (dv.isolid || dv.ismstr || dv.icpre || dv.istrain || dv.iframe))
    r.context.warn(dv.where, "/DEF_SOLID", "no brick in the model: its defaults act on nothing");
}

void resolve_model(DeckContext& context, std::vector<RunControl>& continued_runs) {
  Resolver r(context);
  resolve_definitions(r);
  r.throw_if_errors();  // later stages need valid nodes, parts, materials and properties
  resolve_elements(r);
  r.throw_if_errors();
  // The order of the positions, as the reference's (docs/deck-format.md, "Transformations", measured):
  //  1. the deck's coordinates: element checks, boxes and the box groups (/GRNOD/BOX, /GRSHEL/BOX...);
  //  2. /TRANSFORM, in deck order, on the nodes of their groups (box groups included);
  //  3. /RANDOM noise, on the transformed positions;
  //  4. everything after: skews, rigid walls (D_search), rigid bodies, sections, mass.
  resolve_sets(r);
  if (r.errors.empty()) apply_transforms(r);  // they need their groups (any error is thrown below)
  apply_random_noise(context.model);
  resolve_load_references(r);
  resolve_output_references(r, continued_runs);
  if (r.errors.empty()) resolve_rigid_elements(r);  // needs the ties and the walls' node sets
  if (r.errors.empty()) refuse_joints_off_bodies(r);
  r.throw_if_errors();
  compute_mass(context.model);
  check_mass(r);
  refuse_massless_rigid_elements(r);
  warn_degenerate_one_point_bricks(r);
  warn_defaults_without_elements(r);
  r.throw_if_errors();
}

}  // namespace crumple::deck
