// What the domains of a run of several exchange at the named points of a cycle (docs/parallel.md): each function
// is called by every domain at the same point of the loop.
#include "solver/domain_sharing.hpp"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "crumple/solver/snapshot.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {

namespace {

// The per-type step controls and the nodal step read every element's critical step; otherwise only the groups'
// smallest steps matter, which travel anyway.
bool critical_steps_needed(const RunControl& rc) {
  bool per_type = false;
  for (const ElementKindDescription& kind : kElementKindTable) per_type = per_type || (rc.*kind.step_control).minimum > 0.0;
  return rc.dt_nodal_cst.given || rc.dt_ams.given || per_type;
}

// Every domain's elements' conditions from their owners (an element that failed in its kernel is deleted
// everywhere).
void share_conditions(SolverState& s, Exchange& exchange) {
  for (int k = 0; k < kElementKinds; ++k) {
    const std::vector<std::int32_t>& owner = s.domain.owner[static_cast<std::size_t>(k)];
    std::vector<std::uint8_t>& status = element_state(s, static_cast<ElementKind>(k)).deleted;
    exchange.share(status, 1, owner);  // the owner's condition, without the flag
    for (std::size_t e = 0; e < owner.size(); ++e)
      if (owner[e] != s.domain.index) status[e] = static_cast<std::uint8_t>(status[e] | kElementElsewhere);
  }
}

// The groups' results as one domain finds them (GroupStepResult over all of a group's elements): the smallest step
// with the first element that has it, the last inverted and the last non-finite element, the failed count. The
// energies are not combined here: the balance takes each element's running energy when it is checked
// (update_energies, docs/theory/energy.md).
void share_group_results(const Model& m, SolverState& s, Exchange& exchange) {
  DomainScratch::GroupShare& w = s.domain_scratch.group_share;
  const std::size_t groups = m.element_groups.size();
  for (auto* v : {&w.controlling, &w.last_inverted, &w.last_non_finite, &w.failed, &w.inverted_count}) v->resize(groups);
  w.min_dt.resize(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    const GroupStepResult& r = s.group_results[g];
    w.min_dt[g] = r.min_dt, w.controlling[g] = r.controlling;
    w.last_inverted[g] = r.inverted, w.last_non_finite[g] = r.non_finite, w.failed[g] = r.failed;
    w.inverted_count[g] = r.inverted_count;
  }
  exchange.min_with_index(w.min_dt, w.controlling);
  exchange.max(w.last_inverted);
  exchange.max(w.last_non_finite);
  exchange.sum(w.failed);
  exchange.sum(w.inverted_count);
  bool failed = false;
  for (std::size_t g = 0; g < groups; ++g) {
    GroupStepResult r;
    if (w.controlling[g] >= 0) r.min_dt = w.min_dt[g], r.controlling = w.controlling[g];
    r.inverted = w.last_inverted[g], r.non_finite = w.last_non_finite[g], r.failed = w.failed[g];
    r.inverted_count = w.inverted_count[g];
    failed = failed || r.failed > 0;
    s.group_results[g] = r;
  }
  if (failed) share_conditions(s, exchange);
}

}  // namespace

// What one domain computed of its own elements reaches the domains that need it (docs/parallel.md, "Exchange"): the
// loads of the elements at shared nodes, the critical steps when a step control reads them, then the groups' results as one domain finds them, then the local shared nodes' sums in model order.
void share_element_results(const Model& m, SolverState& s, Exchange& exchange) {
  const Domain& d = s.domain;
  const bool critical_steps = critical_steps_needed(m.run);
  exchange.halo_finish();  // the records' halo, started by run_element_kernels
  for (int k = 0; k < kElementKinds; ++k) {
    ElementKindState& state = element_state(s, static_cast<ElementKind>(k));
    if (critical_steps) exchange.share(state.critical_dt, 1, d.owner[static_cast<std::size_t>(k)]);
    if (nodal_stiffness_on(m))
      exchange.share(s.interface_stiffness[static_cast<std::size_t>(k)], 1, d.owner[static_cast<std::size_t>(k)]);
  }
  share_group_results(m, s, exchange);
  std::array<const ElementRecords*, kElementKinds> records{};
  for (ElementKind kind : kAllElementKinds) records[static_cast<std::size_t>(kind)] = &element_state(s, kind).records;
  assemble_element_loads(d, records, s.nodes);
}

namespace {

// Every field of one kind's element state from the elements' owners: point fields by the points' owners, element
// fields (one or more values per element) by the elements'. The status is shared every cycle already.
template <class State, class Visit>
void share_kind_state(Exchange& exchange, State& state, Visit visit, const std::vector<std::int32_t>& owner,
                      const std::vector<std::int32_t>& point_owner, std::initializer_list<std::string_view> point_fields) {
  const std::size_t n = owner.size();
  auto share = [&](const std::string& name, auto& values) {
    using Values = std::remove_reference_t<decltype(values)>;
    if constexpr (std::is_same_v<Values, std::vector<double>> || std::is_same_v<Values, std::vector<float>> ||
                  std::is_same_v<Values, std::vector<std::uint8_t>>) {
      if (values.empty() || name == "deleted") return;
      if (std::find(point_fields.begin(), point_fields.end(), name) != point_fields.end()) {
        exchange.share(values, 1, point_owner);
      } else {
        if (n == 0 || values.size() % n != 0) throw std::logic_error("element field " + name + " is not per element");
        exchange.share(values, static_cast<int>(values.size() / n), owner);
      }
    }
  };
  visit(share, std::string(), state);
}

}  // namespace

bool histories_read_nodes(const Model& m) {
  for (const TimeHistoryRequest& th : m.histories) {
    const HistoryObject o = th.object;
    if (o == HistoryObject::Node || o == HistoryObject::Part || o == HistoryObject::Subset || o == HistoryObject::Section ||
        o == HistoryObject::Accelerometer)
      return true;
  }
  return false;
}

ElementStateNeed history_needs(const Model& m) {
  ElementStateNeed need = ElementStateNeed::None;
  for (const TimeHistoryRequest& th : m.histories) {
    const HistoryObject o = th.object;
    if (o == HistoryObject::Shell || o == HistoryObject::Sh3n || o == HistoryObject::Brick || o == HistoryObject::Spring || o == HistoryObject::Truss || o == HistoryObject::Beam ||
        o == HistoryObject::Section)
      return ElementStateNeed::All;
    if (o == HistoryObject::Part || o == HistoryObject::Subset) need = ElementStateNeed::Energies;
  }
  return need;
}

void share_element_state(SolverState& s, Exchange& exchange, ElementStateNeed need) {
  if (need == ElementStateNeed::None) return;
  if (need == ElementStateNeed::Energies) {
    for (int k = 0; k < kElementKinds; ++k) {
      ElementKindState& state = element_state(s, static_cast<ElementKind>(k));
      const auto& owner = s.domain.owner[static_cast<std::size_t>(k)];
      exchange.share(state.internal_energy, 1, owner), exchange.share(state.hourglass_energy, 1, owner);
    }
    return;
  }
  const auto& owner = s.domain.owner;
  const auto& points = s.domain_scratch.point_owner;
  auto shells = [](auto& v, const std::string& at, ShellState& st) { snapshot_detail::visit_shells(v, at, st); };
  auto bricks = [](auto& v, const std::string& at, BrickState& st) { snapshot_detail::visit_bricks(v, at, st); };
  const auto shell_points = {std::string_view("sxx"), std::string_view("syy"), std::string_view("sxy"),
                             std::string_view("eps_p"), std::string_view("eps_rate"), std::string_view("hardening_term")};
  const auto brick_points = {std::string_view("sxx"), std::string_view("syy"), std::string_view("szz"),
                             std::string_view("sxy"), std::string_view("syz"), std::string_view("szx"),
                             std::string_view("eps_p"), std::string_view("eps_rate")};
  share_kind_state(exchange, s.shells, shells, owner[0], points[0], shell_points);
  share_kind_state(exchange, s.shells3, shells, owner[1], points[1], shell_points);
  share_kind_state(exchange, s.bricks, bricks, owner[2], points[2], brick_points);
  auto springs = [](auto& v, const std::string& at, SpringState& st) { snapshot_detail::visit_springs(v, at, st); };
  share_kind_state(exchange, s.springs, springs, owner[3], points[3], std::initializer_list<std::string_view>{});
  auto trusses = [](auto& v, const std::string& at, TrussState& st) { snapshot_detail::visit_trusses(v, at, st); };
  share_kind_state(exchange, s.trusses, trusses, owner[4], points[4], std::initializer_list<std::string_view>{});
  auto beams = [](auto& v, const std::string& at, BeamState& st) { snapshot_detail::visit_beams(v, at, st); };
  share_kind_state(exchange, s.beams, beams, owner[5], points[5], std::initializer_list<std::string_view>{});
}

namespace {

// Before a restart snapshot: the contact state each domain keeps for the secondary nodes it owns and for their
// pairs (docs/parallel.md, "Contact"), from those domains.
void share_contact_state(SolverState& s, Exchange& exchange) {
  DomainScratch::GroupShare& w = s.domain_scratch.group_share;
  w.secondary_owner.resize(s.contact.interfaces.size()), w.pair_owner.resize(s.contact.interfaces.size());
  for (std::size_t f = 0; f < s.contact.interfaces.size(); ++f) {
    ContactInterface& in = s.contact.interfaces[f];
    std::vector<std::int32_t>& node = w.secondary_owner[f];
    if (node.empty())
      for (std::int32_t k : in.secondary_nodes) node.push_back(s.domain.node_owner[static_cast<std::size_t>(k)]);
    std::vector<std::int32_t>& pair = w.pair_owner[f];
    pair.clear();
    for (std::int32_t i : in.candidate_node) pair.push_back(node[static_cast<std::size_t>(i)]);
    exchange.renew(pair);
    for (auto* v : {&in.friction_x, &in.friction_y, &in.friction_z}) exchange.share(*v, 1, pair);
    for (auto* v : {&in.gap_reduction, &in.gap_clearance}) exchange.share(*v, 1, node);
    exchange.share(in.node_impacted, 1, node);
    if (!in.friction_mu.empty()) {
      exchange.share(in.friction_mu, 1, node);
      std::vector<double> pass(in.friction_mu_pass.begin(), in.friction_mu_pass.end());
      exchange.share(pass, 1, node);
      for (std::size_t i = 0; i < pass.size(); ++i) in.friction_mu_pass[i] = static_cast<long long>(pass[i]);
    }
  }
}

}  // namespace

void share_node_state(const Model& m, SolverState& s, Exchange& exchange, bool restart) {
  NodalState& n = s.nodes;
  const std::vector<std::int32_t>& owner = s.domain.node_owner;
  // The mass and rotational inertia too: /DT/INTER/CST adds mass where the node's pairs are computed, /DT/NODA/CST
  // both where the node is advanced (time-step.md, T-3, T-3a).
  for (auto* v : {&n.x, &n.y, &n.z, &n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz, &n.fx, &n.fy, &n.fz, &n.mx, &n.my, &n.mz,
                  &n.mass, &n.inertia})
    exchange.share(*v, 1, owner);
  // Tied walls keep which nodes they hold, where the node is local.
  DomainScratch::GroupShare& w = s.domain_scratch.group_share;
  if (w.wall_node_owner.size() != s.walls.size()) {
    w.wall_node_owner.assign(s.walls.size(), {});
    for (std::size_t i = 0; i < s.walls.size(); ++i)
      for (std::int32_t k : s.walls[i].nodes) w.wall_node_owner[i].push_back(owner[static_cast<std::size_t>(k)]);
  }
  for (std::size_t i = 0; i < s.walls.size(); ++i) exchange.share(s.walls[i].tied, 1, w.wall_node_owner[i]);
  if (!s.contact.interfaces.empty()) {
    // The contact force field: each node's from its owner; every node with one is then to be cleared by the next
    // pass (so that a restart starts with the same list everywhere).
    ContactState& c = s.contact;
    for (auto* v : {&c.fx, &c.fy, &c.fz}) exchange.share(*v, 1, owner);
    c.touched.clear();
    for (std::size_t k = 0; k < c.fx.size(); ++k)
      if (c.fx[k] != 0.0 || c.fy[k] != 0.0 || c.fz[k] != 0.0) c.touched.push_back(static_cast<std::int32_t>(k));
    if (restart) share_contact_state(s, exchange);
  }
  // /DAMP beta: each node's element force of the last cycle, whose rate the next cycle takes (damping.md, D-5).
  if (s.damping.stiffness()) exchange.share(s.damping.element_force_before, 6, owner);
  RecordedNodalResults& r = s.recorded;
  for (auto* v : {&r.acceleration, &r.internal_force, &r.external_force})
    if (!v->empty()) exchange.share(*v, 3, owner);
  // Output-only integrals of the cycle, kept right by the domain their node is local to.
  HistoryIntegrals& h = s.histories;
  if (!m.accelerometers.empty()) {
    if (w.accelerometer_owner.empty())
      for (const Accelerometer& a : m.accelerometers) w.accelerometer_owner.push_back(owner[static_cast<std::size_t>(a.node)]);
    exchange.share(h.accel_filtered, 3, w.accelerometer_owner), exchange.share(h.accel_velocity, 3, w.accelerometer_owner);
    exchange.share(h.accel_memory, 18, w.accelerometer_owner);
  }
  if (!h.rotation_nodes.empty()) {
    if (w.rotation_owner.empty())
      for (std::int32_t k : h.rotation_nodes) w.rotation_owner.push_back(owner[static_cast<std::size_t>(k)]);
    exchange.share(h.rotation, 3, w.rotation_owner);
  }
}

}  // namespace crumple::solver
