// Builds the solver state from the model once, before the first cycle (docs/theory/time-loop.md, "Start").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "crumple/contact/contact.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/model/mass.hpp"
#include "crumple/solver/accelerometers.hpp"
#include "crumple/solver/sections.hpp"
#include "crumple/solver/node_rotations.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

constexpr double kDefaultHourglass = 0.01;    // Radioss default hm, hf, hr for 4-node shells
constexpr double kDefaultElastoplasticHourglass = 0.1;  // Radioss default hm, hf of Ishell 3

void setup_nodes(const Model& m, SolverState& s) {
  const std::size_t n = m.nodes.size();
  s.nodes.resize(n);
  s.nodes.x = m.nodes.x, s.nodes.y = m.nodes.y, s.nodes.z = m.nodes.z;
  s.x0 = m.nodes.x, s.y0 = m.nodes.y, s.z0 = m.nodes.z;
  s.nodes.mass = m.nodal_mass;
  s.fixed.assign(n, 0);
  s.rigid_owner.assign(n, -1);
  // /INIVEL: a velocity written in a skew is its components along the skew's axes at the start (SK-6).
  for (const InitialVelocity& iv : m.initial_velocities) {
    const Vec3 v = iv.skew < 0 ? iv.velocity
                               : to_global(skew_axes(m.skews[static_cast<std::size_t>(iv.skew)], m.nodes.x, m.nodes.y,
                                                     m.nodes.z),
                                           iv.velocity);
    auto [vx, vy, vz] = iv.rotation ? std::tie(s.nodes.wx, s.nodes.wy, s.nodes.wz)
                                     : std::tie(s.nodes.vx, s.nodes.vy, s.nodes.vz);
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(iv.node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      vx[k] = v.x, vy[k] = v.y, vz[k] = v.z;
    }
  }
  for (const BoundaryCondition& bc : m.boundary_conditions) {
    if (bc.skew >= 0) continue;  // its codes fix the skew's axes, not the global ones (eq. SK-5, loads.cpp)
    std::uint8_t mask = 0;
    for (int d = 0; d < 3; ++d) {
      if (bc.fixed_translation[static_cast<std::size_t>(d)]) mask |= static_cast<std::uint8_t>(1u << d);
      if (bc.fixed_rotation[static_cast<std::size_t>(d)]) mask |= static_cast<std::uint8_t>(1u << (d + 3));
    }
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(bc.node_group)].nodes)
      s.fixed[static_cast<std::size_t>(node)] |= mask;
  }
}

// Shell state and group parameters for the 4-node (kind Shell4) or 3-node (kind Shell3) shells.
void setup_shells(const Model& m, SolverState& s, ElementKind kind) {
  const ElementTable& table = m.elements[static_cast<int>(kind)];
  const int nodes_per = nodes_per_element(kind);
  const std::size_t n = table.size();
  ShellState& st = shell_state(s, kind);
  st.resize_elements(n, 0.0);
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);

  std::size_t total_points = 0;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != kind) continue;
    const Property& prop = m.properties[static_cast<std::size_t>(group.property)];
    const ResolvedFormulation& f = m.formulations[static_cast<std::size_t>(group.property)];
    const Material& mat = m.materials[static_cast<std::size_t>(group.material)];
    ShellGroupParameters& p = s.shell_groups[g];
    p.hardening = materials::Hardening::of(mat, m.functions);
    p.young = mat.young, p.poisson = mat.poisson, p.density = mat.density;
    // Ashear (default 5/6); a membrane (N = 1) has no transverse shear, as in the reference solver.
    p.shear_factor = f.n_points == 1 ? 0.0 : prop.shell.ashear > 0.0 ? prop.shell.ashear : 5.0 / 6.0;
    // Ishell 3: hm and hf default to 0.1 (hr to 0.01), as the reference's starter resolves them (shell4.md, S-18);
    // the other formulations to 0.01.
    const double elastoplastic_default = f.ishell == 3 ? kDefaultElastoplasticHourglass : kDefaultHourglass;
    p.hm = prop.shell.hm > 0.0 ? prop.shell.hm : elastoplastic_default;
    p.hf = prop.shell.hf > 0.0 ? prop.shell.hf : elastoplastic_default;
    p.hr = prop.shell.hr > 0.0 ? prop.shell.hr : kDefaultHourglass;
    // Ishell 2 never orthogonalises its hourglass vector (eq. S-17); the reference's Ishell 1 does not either with
    // Ismstr 1 (small strain from t = 0, eq. S-15).
    p.orthogonal_hourglass = f.ishell != 2 && !(f.ishell == 1 && f.ismstr == 1);
    p.elastoplastic_hourglass = f.ishell == 3;
    // N = 0: stress-resultant (global) plasticity, one membrane point plus the element's bending stress.
    const int np = f.n_points == 0 ? 1 : f.n_points;
    p.resultant_plasticity = f.n_points == 0;
    p.radial_return = f.iplas == 2;
    if (p.resultant_plasticity && st.bending_stress.empty()) st.bending_stress.assign(3 * table.size(), 0.0);
    p.physical_hourglass = kind == ElementKind::Shell4 && f.ishell == 24;
    p.fully_integrated = kind == ElementKind::Shell4 && f.ishell == 12;
    p.small_strain = f.ismstr == 1;  // Ismstr 3 was resolved to 2 (or refused) by the reader
    p.small_strain_switchable = f.ismstr == 2;  // eq. S-16; Ismstr 4 never switches
    if ((p.small_strain || p.small_strain_switchable) && st.initial_shape.empty())
      st.initial_shape.assign(2 * static_cast<std::size_t>(nodes_per) * n, 0.0);
    const ShellDamping damping = shell_damping(kind == ElementKind::Shell3, prop.shell, f);
    p.membrane_damping = damping.membrane, p.numerical_damping = damping.numerical;
    // Ishell 12 keeps a section per Gauss point (docs/theory/shell4.md, eq. Q-2).
    const int sections = p.fully_integrated ? 4 : 1;
    if (p.fully_integrated && st.gauss_shear.empty()) st.gauss_shear.assign(8 * n, 0.0);
    if (p.fully_integrated && p.resultant_plasticity && st.gauss_bending.empty()) st.gauss_bending.assign(12 * n, 0.0);
    p.points = np;
    const auto at = static_cast<std::size_t>(np) * 11;
    p.zeta = &s.shell_zeta[at];
    p.membrane_weight = &s.shell_membrane_weight[at];
    p.bending_weight = &s.shell_bending_weight[at];
    const int ithick = prop.shell.ithick != 0 ? prop.shell.ithick : m.shell_defaults.ithick;
    p.thickness_update = ithick == 1;
    p.failure_strain = p.hardening.failure_strain() >= 1e20 ? 0.0 : p.hardening.failure_strain();
    p.first_point = total_points;
    st.point_offset[g] = total_points;
    st.points[g] = sections * np;
    total_points += static_cast<std::size_t>(group.end - group.begin) * static_cast<std::size_t>(sections * np);
    // The step the elements' rotations must be stable at: the shells' own /DT scale, else the run's.
    const TimeStepControl& type = m.run.*describe(kind).step_control;
    const double scale = type.given && type.scale > 0.0 ? type.scale : m.run.dt.scale > 0.0 ? m.run.dt.scale : 0.9;
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const double thickness = shell_thickness(m, kind, static_cast<std::size_t>(e));
      st.thickness[static_cast<std::size_t>(e)] = thickness;
      // Lumped rotational inertia of the shell's nodes: m (t^2/12 + A/9) / 4 (docs/theory/shell4.md, eq. S-8), for
      // a triangle m (t^2/12 + 2A/9) shared by the corner angles (eq. S-9c), raised where the element's
      // transverse-shear mode would not be stable at its step (eq. S-8a).
      const double mass = element_mass(m, kind, static_cast<std::size_t>(e));
      st.mass[static_cast<std::size_t>(e)] = mass;
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(e));
      Vec3 x[4];
      for (int a = 0; a < nodes_per; ++a) {
        const auto k = static_cast<std::size_t>(nodes[a]);
        x[a] = {s.nodes.x[k], s.nodes.y[k], s.nodes.z[k]};
      }
      const double share = shell_rotational_inertia_share(p, nodes_per, x, thickness, scale);
      const std::array<double, 8> corner = corner_mass_fractions(m, kind, nodes);
      for (int a = 0; a < nodes_per; ++a)
        s.nodes.inertia[static_cast<std::size_t>(nodes[a])] += mass * corner[static_cast<std::size_t>(a)] * share;
    }
  }
  st.resize_points(total_points);
}

void setup_through_thickness_rules(SolverState& s) {
  s.shell_zeta.assign(11 * 11, 0.0);
  s.shell_membrane_weight.assign(11 * 11, 0.0);
  s.shell_bending_weight.assign(11 * 11, 0.0);
  for (int np = 1; np <= 10; ++np) {
    const auto at = static_cast<std::size_t>(np) * 11;
    through_thickness_rule(np, &s.shell_zeta[at], &s.shell_membrane_weight[at], &s.shell_bending_weight[at]);
  }
}

}  // namespace

}  // namespace crumple::solver

namespace crumple {

void mark_domain(SolverState& s) {
  if (!s.domain.several()) return;
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    std::vector<std::uint8_t>& status = element_state(s, kind).deleted;
    for (std::size_t e = 0; e < status.size(); ++e)
      status[e] = static_cast<std::uint8_t>(element_condition(status[e]) | (s.domain.mine(kind, e) ? 0 : kElementElsewhere));
  }
}

}  // namespace crumple

namespace crumple::solver {
namespace {

// One domain of a run of several (docs/parallel.md): the elements of the other domains are marked as computed
// elsewhere (the kernels skip them), and the groups whose loads other domains need are recorded: the groups with an
// element at a shared node (its loads travel, Domain::record_halo).
void take_domain(const Model& m, SolverState& s, Domain domain) {
  s.domain = std::move(domain);
  if (!s.domain.several()) return;
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    const std::size_t size = m.elements[static_cast<std::size_t>(k)].size();
    ElementRecords& records = element_state(s, kind).records;
    records.start(size, nodes_per_element(kind), describe(kind).values_per_node);
    std::vector<std::uint8_t> sent(size, 0);
    for (const auto& list : s.domain.record_halo[static_cast<std::size_t>(k)].send)
      for (std::uint32_t e : list) sent[e] = 1;
    records.only.assign(size, 0);
    for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
      const ElementGroup& group = m.element_groups[g];
      if (group.kind != kind) continue;
      const bool needed = std::any_of(sent.begin() + group.begin, sent.begin() + group.end, [](std::uint8_t x) { return x != 0; });
      if (needed) records.only[static_cast<std::size_t>(group.begin)] = 1;
    }
  }
  mark_domain(s);
  for (auto& owner : s.domain_scratch.point_owner) owner.clear();
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {  // groups are kind by kind, points group by group
    const ElementGroup& group = m.element_groups[g];
    const int points = element_state(s, group.kind).points[g];
    auto& owner = s.domain_scratch.point_owner[static_cast<std::size_t>(group.kind)];
    for (std::int32_t e = group.begin; e < group.end; ++e)
      owner.insert(owner.end(), static_cast<std::size_t>(points),
                   s.domain.owner[static_cast<std::size_t>(group.kind)][static_cast<std::size_t>(e)]);
  }
}

}  // namespace

void rebind_domain(const Model& m, SolverState& s, Domain domain) {
  take_domain(m, s, std::move(domain));
  // What was made of the old domain: the exchange scratch's owner arrays, the contact pass's division of its pairs
  // and its node scratch, the cut sections' owners and recorded groups.
  DomainScratch::GroupShare& w = s.domain_scratch.group_share;
  w.accelerometer_owner.clear(), w.rotation_owner.clear(), w.interface_node_owner.clear();
  w.secondary_owner.clear(), w.pair_owner.clear(), w.wall_node_owner.clear();
  for (ContactInterface& in : s.contact.interfaces) {
    in.divided = false;
    std::fill(in.node_touched.begin(), in.node_touched.end(), 0);
    for (auto* v : {&in.node_tangent_sum, &in.node_reach_stiffness, &in.node_unresolved_stiffness, &in.node_entry_stiffness,
                    &in.node_friction_viscosity})
      std::fill(v->begin(), v->end(), 0.0);
    in.touched_list.clear();
  }
  bind_sections(m, s, true);
  bind_ties_to_domain(s);
}

SolverState make_state(const Model& m, std::vector<std::string>& notes, Domain domain) {
  SolverState s;
  setup_nodes(m, s);
  if (!m.type7_interfaces.empty()) {
    // Inacti 3 moves initially penetrated nodes: the run starts from the moved coordinates.
    s.contact = contact::setup_contact(m, s.nodes, notes);
    s.x0 = s.nodes.x, s.y0 = s.nodes.y, s.z0 = s.nodes.z;
  }
  setup_through_thickness_rules(s);
  s.shell_groups.assign(m.element_groups.size(), ShellGroupParameters{});
  setup_shells(m, s, ElementKind::Shell4);
  setup_shells(m, s, ElementKind::Shell3);
  setup_bricks(m, s);
  setup_beams(m, s);  // before the springs, whose steps take their nodes' inertia (SP-19)
  setup_springs(m, s);
  setup_trusses(m, s);
  for (const RayleighDamping& d : m.dampings) s.damping.alpha.push_back(d.alpha), s.damping.beta.push_back(d.beta);
  setup_damping(m, s);
  s.group_results.assign(m.element_groups.size(), GroupStepResult{});
  take_domain(m, s, std::move(domain));
  setup_ties(m, s);  // after every mass is lumped and the springs' steps have their nodes' own (SP-19)
  setup_sections(m, s);  // /TH/SECTIO: after the domain, whose records it may restrict or read
  update_skew_axes(m, s);  // every domain holds every node here
  setup_rigid_bodies(m, s);
  setup_rigid_elements(m, s);
  setup_interpolation_constraints(m, s);
  setup_rigid_walls(m, s);
  if (selective_mass_on(m)) size_selective_mass(m, s);  // before a restart reads what the last cycle left
  setup_accelerometers(m.accelerometers.size(), s.histories);
  setup_node_rotations(m, s.histories);
  s.mass_initial = 0.0;
  for (double mass : s.nodes.mass) s.mass_initial += mass;
  // A rigid body's initial spin is rotational (RB-7); every domain holds every node here.
  const auto [translational, rotational] = kinetic_energy(s, true);
  // E_0 holds the energy a pretensioner stores from the start (docs/theory/spring.md, SP-22).
  double stored = 0.0;
  for (double e : s.springs.internal_energy) stored += e;
  s.energy.initial_kinetic = translational + rotational + stored;
  return s;
}

}  // namespace crumple::solver
