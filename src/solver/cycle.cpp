// The phases of one cycle (docs/theory/time-loop.md, "One cycle"); time_loop.cpp calls them in this order.
#include "solver/cycle.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "crumple/contact/contact.hpp"
#include "crumple/solver/snapshot.hpp"
#include "crumple/solver/accelerometers.hpp"
#include "crumple/solver/node_rotations.hpp"
#include "crumple/solver/sections.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

std::array<std::vector<double>*, 6> velocities(NodalState& n) { return {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz}; }

// /DT/SHELL, /DT/SH_3N, /DT/BRICK: the step control of an element kind.
const TimeStepControl& type_control(const RunControl& rc, ElementKind kind) {
  return kind == ElementKind::Shell4 ? rc.dt_shell : kind == ElementKind::Shell3 ? rc.dt_sh3n : rc.dt_brick;
}

GroupStepResult group_forces(const Model& m, SolverState& s, std::size_t g) {
  const ElementGroup& group = m.element_groups[g];
  const ElementTable& table = m.elements[static_cast<int>(group.kind)];
  switch (group.kind) {
    case ElementKind::Shell4: return shell4_forces(table, group, s.shell_groups[g], s.nodes, s.shells, s.dt);
    case ElementKind::Shell3: return shell3_forces(table, group, s.shell_groups[g], s.nodes, s.shells3, s.dt);
    case ElementKind::Brick8: return brick8_forces(table, group, s.brick_groups[g], s.nodes, s.bricks, s.dt);
  }
  return {};
}

StopReason element_stop(StopReason::Kind kind, ElementKind element_kind, std::int32_t element, const SolverState& s) {
  StopReason stop;
  stop.kind = kind, stop.cycle = s.cycle, stop.time = s.time;
  stop.element_kind = element_kind, stop.index = element;
  return stop;
}

// /DT/<type>/DEL (the default for shells): the group's elements whose scaled step is below the minimum are
// deleted; the group's bound is then taken over the others (docs/theory/time-step.md, "Element minimum").
// Returns how many were deleted.
long long delete_below_minimum(const ElementGroup& group, SolverState& s, RunEvents& events, double type_scale,
                          double minimum, GroupStepResult& r) {
  const bool brick = group.kind == ElementKind::Brick8;
  ShellState& shells = group.kind == ElementKind::Shell4 ? s.shells : s.shells3;
  auto& deleted = brick ? s.bricks.deleted : shells.deleted;
  const auto& critical_dt = brick ? s.bricks.critical_dt : shells.critical_dt;
  r.min_dt = std::numeric_limits<double>::infinity();
  long long count = 0;
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (element_condition(deleted[ue]) != kElementActive) continue;
    if (type_scale * critical_dt[ue] < minimum) {
      deleted[ue] = static_cast<std::uint8_t>((deleted[ue] & kElementElsewhere) | kElementDeleted);
      ++count;
      RunEvent event{RunEvent::Kind::ElementDeletedBelowMinimumStep, s.cycle, s.time, group.kind, e};
      event.value = type_scale * critical_dt[ue];
      events.pending.push_back(event);
    } else if (critical_dt[ue] < r.min_dt) {
      r.min_dt = critical_dt[ue], r.controlling = e;
    }
  }
  events.deleted_below_minimum_step += count;
  return count;
}

// Switches element e of group g to small strain; false when its formulation cannot (shells: shell4.md S-16;
// bricks: brick8.md B-14, only Ismstr 2 switches).
bool switch_element(const Model& m, std::size_t g, SolverState& s, std::int32_t e) {
  const ElementGroup& group = m.element_groups[g];
  const ElementTable& table = m.elements[static_cast<int>(group.kind)];
  if (group.kind != ElementKind::Brick8) {
    ShellState& shells = group.kind == ElementKind::Shell4 ? s.shells : s.shells3;
    return shell_switch_to_small_strain(table, s.shell_groups[g], s.nodes, shells, e);
  }
  if (s.brick_groups[g].ismstr != 2 || s.bricks.small_strain[static_cast<std::size_t>(e)] != 0) return false;
  brick8_switch_to_small_strain(table, e, s.nodes, s.bricks);
  return true;
}

// /DT/<type>/CST: the group's elements whose scaled step is below the minimum switch to the small-strain
// formulation (Ismstr 2), which freezes their shape and with it their step (docs/theory/time-step.md, "Element
// minimum"); elements that cannot switch (Ismstr 1, 3, 4) go on as they are.
void switch_below_minimum(const Model& m, std::size_t g, SolverState& s, RunEvents& events, double type_scale,
                          double minimum) {
  const ElementGroup& group = m.element_groups[g];
  const bool brick = group.kind == ElementKind::Brick8;
  const ShellState& shells = group.kind == ElementKind::Shell4 ? s.shells : s.shells3;
  const auto& status = brick ? s.bricks.deleted : shells.deleted;
  const auto& critical_dt = brick ? s.bricks.critical_dt : shells.critical_dt;
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    if (element_condition(status[ue]) != kElementActive || !(type_scale * critical_dt[ue] < minimum)) continue;
    if (!switch_element(m, g, s, e)) continue;
    ++events.switched_to_small_strain;
    RunEvent event{RunEvent::Kind::ElementSwitchedToSmallStrain, s.cycle, s.time, group.kind, e};
    event.value = type_scale * critical_dt[ue];
    events.pending.push_back(event);
  }
}

// Per-type step control of one group's result: stop the run, switch the elements below the minimum to small
// strain, or delete them (their count is returned: deleted elements leave the contact interfaces like failed
// ones).
long long control_group_step(const Model& m, std::size_t g, SolverState& s, RunEvents& events, double type_scale,
                             GroupStepResult& r) {
  const ElementGroup& group = m.element_groups[g];
  const TimeStepControl& type = type_control(m.run, group.kind);
  if (r.controlling < 0 || !(type.minimum > 0.0) || !(type_scale * r.min_dt < type.minimum) || events.stop.stopped())
    return 0;
  if (type.action == TimeStepAction::SmallStrain) {
    switch_below_minimum(m, g, s, events, type_scale, type.minimum);
    return 0;
  }
  const bool stop = type.action == TimeStepAction::Stop ||
                    (type.action == TimeStepAction::Default && group.kind == ElementKind::Brick8);
  if (!stop) return delete_below_minimum(group, s, events, type_scale, type.minimum, r);
  events.stop = element_stop(StopReason::Kind::ElementStepBelowMinimum, group.kind, r.controlling, s);
  events.stop.dt = type_scale * r.min_dt, events.stop.minimum = type.minimum;
  return 0;
}

// Power of the /CLOAD and /GRAV loads on the mid-step velocities, times the step, into `work`: each node's terms
// from the domain that owns it.
// Work of the kinematic conditions: the impulse that changed the free velocity, on the mid-step velocity, into
// `work` (owned nodes).
void add_constraint_work(SolverState& s, const VelocityScratch& scratch, ExactSum& work) {
  NodalState& n = s.nodes;
  auto v = velocities(n);
  for_each_owned_node(s.domain, n.size(), [&](std::size_t k) {
    for (std::size_t d = 0; d < 3; ++d) {
      const double dv = (*v[d])[k] - scratch.free[d][k];
      if (dv != 0.0) work.add(n.mass[k] * dv * 0.5 * ((*v[d])[k] + scratch.before[d][k]));
    }
    if (n.inertia[k] > 0.0)
      for (std::size_t d = 3; d < 6; ++d) {
        const double dv = (*v[d])[k] - scratch.free[d][k];
        if (dv != 0.0) work.add(n.inertia[k] * dv * 0.5 * ((*v[d])[k] + scratch.before[d][k]));
      }
  });
}

// Hourglass energy above 10 % of the internal energy is a mesh or formulation problem the user must see
// (docs/theory/energy.md): one event, the first time it happens once the energy counts (above 0.1 % of the
// balance's scale, so that the first cycles' round-off does not raise it).
void warn_hourglass_share(const SolverState& s, RunEvents& events) {
  const EnergyBalanceState& e = s.energy;
  const double scale = std::abs(e.initial_kinetic) + std::abs(e.external_work);
  if (events.hourglass_warned || !(e.hourglass > 0.1 * std::abs(e.internal)) || !(e.hourglass > 1e-3 * scale)) return;
  events.hourglass_warned = true;
  RunEvent event{RunEvent::Kind::HourglassShare, s.cycle, s.time};
  event.value = e.internal != 0.0 ? e.hourglass / std::abs(e.internal) : std::numeric_limits<double>::infinity();
  events.pending.push_back(event);
}

// An energy error beyond 10 % (5 % under a preset) means the balance is not kept: an instability growing, or a
// remedy (mass scaling, a contact released deep in its gap) adding or taking energy. A run must not end "normal"
// without saying so (docs/theory/energy.md): one event, the first time, unless /STOP Emax stops the run before.
void warn_energy_error(const RunControl& rc, const SolverState& s, RunEvents& events) {
  const double error = s.energy.error_percent();
  if (events.energy_error_warned || !(std::abs(error) > rc.energy_error_warning)) return;
  events.energy_error_warned = true;
  RunEvent event{RunEvent::Kind::EnergyErrorLarge, s.cycle, s.time};
  event.value = error, event.second_value = rc.energy_error_warning;
  events.pending.push_back(event);
}

// The elements' forces on the nodes, before contact and loads add theirs (field frames, /ANIM/VECT/FINT).
void record_internal_forces(SolverState& s) {
  std::vector<double>& out = s.recorded.internal_force;
  if (out.empty()) return;
  const NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(),
                      [&](std::size_t k) { out[3 * k] = n.fx[k], out[3 * k + 1] = n.fy[k], out[3 * k + 2] = n.fz[k]; });
}

// a^n from the velocity change of the step, after the kinematic conditions (field frames, /ANIM/VECT/ACC).
void record_acceleration(SolverState& s, const VelocityScratch& scratch, double dt_average) {
  std::vector<double>& out = s.recorded.acceleration;
  if (out.empty() || !(dt_average > 0.0)) return;
  const NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(), [&](std::size_t k) {
    out[3 * k] = (n.vx[k] - scratch.before[0][k]) / dt_average;
    out[3 * k + 1] = (n.vy[k] - scratch.before[1][k]) / dt_average;
    out[3 * k + 2] = (n.vz[k] - scratch.before[2][k]) / dt_average;
  });
}

}  // namespace

double step_scale(const RunControl& run) { return run.dt.scale > 0.0 ? run.dt.scale : 0.9; }

namespace {

// The per-type step controls and the nodal step read every element's critical step; otherwise only the groups'
// smallest steps matter, which travel anyway.
bool critical_steps_needed(const RunControl& rc) {
  return rc.dt_nodal_cst.given || rc.dt_ams.given || rc.dt_shell.minimum > 0.0 || rc.dt_sh3n.minimum > 0.0 ||
         rc.dt_brick.minimum > 0.0;
}

// Every domain's elements' conditions from their owners (an element that failed in its kernel is deleted
// everywhere).
void share_conditions(SolverState& s, Exchange& exchange) {
  for (int k = 0; k < kElementKinds; ++k) {
    const std::vector<std::int32_t>& owner = s.domain.owner[static_cast<std::size_t>(k)];
    std::vector<std::uint8_t>& status = element_view(s, static_cast<ElementKind>(k)).status;
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
  SolverState::GroupShare& w = s.group_share;
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
    ElementStateView v = element_view(s, static_cast<ElementKind>(k));
    if (critical_steps) exchange.share(v.critical_dt, 1, d.owner[static_cast<std::size_t>(k)]);
    if (nodal_stiffness_on(m))
      exchange.share(s.interface_stiffness[static_cast<std::size_t>(k)], 1, d.owner[static_cast<std::size_t>(k)]);
  }
  share_group_results(m, s, exchange);
  assemble_element_loads(d, s.shells, s.shells3, s.bricks, s.nodes);
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
    if (o == HistoryObject::Shell || o == HistoryObject::Sh3n || o == HistoryObject::Brick || o == HistoryObject::Section)
      return ElementStateNeed::All;
    if (o == HistoryObject::Part || o == HistoryObject::Subset) need = ElementStateNeed::Energies;
  }
  return need;
}

void share_element_state(SolverState& s, Exchange& exchange, ElementStateNeed need) {
  if (need == ElementStateNeed::None) return;
  if (need == ElementStateNeed::Energies) {
    const auto& owner = s.domain.owner;
    for (auto* state : {&s.shells, &s.shells3}) {
      const auto& o = owner[state == &s.shells ? 0 : 1];
      exchange.share(state->internal_energy, 1, o), exchange.share(state->hourglass_energy, 1, o);
    }
    exchange.share(s.bricks.internal_energy, 1, owner[2]), exchange.share(s.bricks.hourglass_energy, 1, owner[2]);
    return;
  }
  const auto& owner = s.domain.owner;
  const auto& points = s.point_owner;
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
}

namespace {

// Before a restart snapshot: the contact state each domain keeps for the secondary nodes it owns and for their
// pairs (docs/parallel.md, "Contact"), from those domains.
void share_contact_state(SolverState& s, Exchange& exchange) {
  SolverState::GroupShare& w = s.group_share;
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
  SolverState::GroupShare& w = s.group_share;
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

void run_element_kernels(const Model& m, SolverState& s, Exchange* exchange) {
  NodalState& n = s.nodes;
  if (!s.domain.several()) n.clear_forces();
  else
    for_each_local_node(s.domain, n.size(), [&n](std::size_t k) { n.fx[k] = n.fy[k] = n.fz[k] = n.mx[k] = n.my[k] = n.mz[k] = 0.0; });
  // Several domains: the records' halo starts as soon as the last group with a sent element is computed, and the
  // groups after it are computed while it travels (share_element_results completes it). The groups keep their
  // model order, so every node's sum does too.
  const std::int32_t last_sending = s.domain.last_sending_group;
  auto start_halo = [&] {
    for (int k = 0; k < kElementKinds; ++k) {
      ElementStateView v = element_view(s, static_cast<ElementKind>(k));
      exchange->halo_start(v.records.load, v.records.nodes_per_element * v.records.values_per_node,
                           s.domain.record_halo[static_cast<std::size_t>(k)]);
    }
  };
  if (exchange != nullptr && last_sending < 0) start_halo();
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    s.group_results[g] = group_forces(m, s, g);
    if (exchange != nullptr && static_cast<std::int32_t>(g) == last_sending) start_halo();
  }
}

namespace {

// An inverted brick ends the run; inverted shells were deleted by their kernel and are named in the listing
// (docs/theory/shell4.md, "Inverted elements").
void report_inverted(ElementKind kind, const GroupStepResult& r, const SolverState& s, RunEvents& events) {
  if (kind == ElementKind::Brick8) {
    events.stop = element_stop(StopReason::Kind::InvertedElement, kind, r.inverted, s);
    return;
  }
  RunEvent event{RunEvent::Kind::ShellDeletedInverted, s.cycle, s.time, kind, r.inverted};
  event.value = r.inverted_count;
  events.pending.push_back(event);
  events.deleted_inverted += r.inverted_count;
}

}  // namespace

StepBound combine_group_results(const Model& m, SolverState& s, RunEvents& events, bool& elements_deleted) {
  StepBound bound;
  const double scale = step_scale(m.run);
  const bool selective = selective_mass_on(m);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    GroupStepResult& r = s.group_results[g];  // r.min_dt: the unscaled critical step
    elements_deleted = elements_deleted || r.failed > 0;
    if (r.non_finite >= 0 && !events.stop.stopped())
      events.stop = element_stop(StopReason::Kind::NonFiniteForces, group.kind, r.non_finite, s);
    if (r.inverted >= 0) report_inverted(group.kind, r, s, events);
    const TimeStepControl& type = type_control(m.run, group.kind);
    const double type_scale = type.given && type.scale > 0.0 ? type.scale : scale;
    if (control_group_step(m, g, s, events, type_scale, r) > 0) elements_deleted = true;
    // A group whose elements are all deleted or inverted has no controlling element (controlling = -1). Under
    // selective mass scaling the smallest element is held at dt_min (eq. SM-0).
    const double group_step = selective ? selective_mass_step(m, r.min_dt) : type_scale * r.min_dt;
    if (r.controlling >= 0 && group_step < bound.dt) bound = {group_step, StepControl::element(group.kind, r.controlling)};
  }
  record_internal_forces(s);
  return bound;
}

StepBound compute_element_forces(const Model& m, SolverState& s, RunEvents& events, bool& elements_deleted,
                                  Exchange* exchange) {
  run_element_kernels(m, s, s.domain.several() ? exchange : nullptr);
  const bool nodal_stiffness = nodal_stiffness_on(m);
  if (nodal_stiffness) element_interface_stiffness(m, s);
  if (s.domain.several()) share_element_results(m, s, *exchange);
  if (nodal_stiffness) nodal_interface_stiffness(m, s);
  if (selective_mass_on(m)) {  // every element's added mass from its step (SM-1), which the contact step reads
    scale_selective_mass(m, s);
    s.contact.selective_mass_added = &s.selective_mass.node_added;
  }
  return combine_group_results(m, s, events, elements_deleted);
}

namespace {

// The contact pass's view of the other domains (contact/contact.hpp, ContactDomains), over the run's exchange.
class ContactExchange final : public contact::ContactDomains {
 public:
  ContactExchange(SolverState& s, Exchange& exchange) : s_(s), exchange_(exchange) {
    scope_.node_owner = &s.domain.node_owner, scope_.me = s.domain.index;
    scope_.local = &s.domain.local, scope_.multi_local = &s.domain.multi_local;
  }
  const contact::ContactScope& scope() const override { return scope_; }
  double max(double value) override {
    values_.assign(1, value);
    exchange_.max(values_);
    return values_[0];
  }
  void sum(std::vector<ExactSum>& sums) override { exchange_.sum(sums); }
  void min_with_index(double& value, std::int32_t& index) override {
    values_.assign(1, value), indices_.assign(1, index);
    exchange_.min_with_index(values_, indices_);
    value = values_[0], index = indices_[0];
  }
  void union_of(std::vector<std::int32_t>& flags) override { exchange_.max(flags); }
  void gather_positions(const ContactInterface& in) override {
    const std::vector<std::int32_t>& owner = interface_owner(in);
    NodalState& n = s_.nodes;
    for (auto* v : {&n.x, &n.y, &n.z}) exchange_.share(*v, 1, owner);
  }
  void share_ghosts(const ContactInterface& in, bool changed) override {
    if (changed) exchange_.renew(in.ghost_owner);
    NodalState& n = s_.nodes;
    for (auto* v : {&n.x, &n.y, &n.z, &n.vx, &n.vy, &n.vz}) exchange_.share(*v, 1, in.ghost_owner);
  }
  void gather(const std::vector<double>& mine, std::vector<double>& all) override { exchange_.gather(mine, all); }

 private:
  // Per node, its owner when it is one of the interface's nodes, else -1 (kept: the exchange's layouts use it).
  const std::vector<std::int32_t>& interface_owner(const ContactInterface& in) {
    const auto f = static_cast<std::size_t>(&in - s_.contact.interfaces.data());
    std::vector<std::vector<std::int32_t>>& owners = s_.group_share.interface_node_owner;
    if (owners.size() <= f) owners.resize(s_.contact.interfaces.size());
    std::vector<std::int32_t>& owner = owners[f];
    if (owner.empty()) {
      owner.assign(s_.nodes.size(), -1);
      for (std::int32_t k : in.secondary_nodes) owner[static_cast<std::size_t>(k)] = s_.domain.node_owner[static_cast<std::size_t>(k)];
      for (std::int32_t k : in.main_nodes) owner[static_cast<std::size_t>(k)] = s_.domain.node_owner[static_cast<std::size_t>(k)];
    }
    return owner;
  }

  SolverState& s_;
  Exchange& exchange_;
  contact::ContactScope scope_;
  std::vector<double> values_;
  std::vector<std::int32_t> indices_;
};

}  // namespace

void compute_contact_forces(const Model& m, SolverState& s, RunEvents& events, bool elements_deleted,
                            StepBound& bound) {
  if (elements_deleted)
    contact::remove_deleted_elements(s.contact, {&s.shells.deleted, &s.shells3.deleted, &s.bricks.deleted});
  std::optional<ContactExchange> domains;
  if (s.domain.several()) domains.emplace(s, *s.reducer.exchange());
  const contact::ContactStep step = contact::contact_forces(m, s.contact, s.nodes, s.time, s.dt, bound.dt,
                                                            step_scale(m.run), s.mass_added,
                                                            domains ? &*domains : nullptr);
  // IBC: boundary conditions of secondary nodes released at their first impact.
  for (const auto& [node, dofs] : s.contact.bc_releases) {
    s.fixed[static_cast<std::size_t>(node)] &= static_cast<std::uint8_t>(~dofs);
    RunEvent released{RunEvent::Kind::ContactBoundaryReleased, s.cycle, s.time};
    released.index = node, released.value = dofs;
    events.pending.push_back(released);
  }
  s.contact.bc_releases.clear();
  // The deck as written's step (T-3c): the elements' (the bound so far) and the contacts' without the nodal mass.
  bound.as_written_dt = bound.dt, bound.as_written_control = bound.control;
  if (step.dt_as_written < bound.as_written_dt)
    bound.as_written_dt = step.dt_as_written,
    bound.as_written_control = StepControl::contact(step.interface_as_written, step.node_as_written);
  bound.contact_dt = step.dt, bound.contact_control = StepControl::contact(step.interface, step.node);
  if (step.dt < bound.dt) bound.dt = step.dt, bound.control = bound.contact_control;
}

void apply_loads(const Model& m, SolverState& s) {
  add_external_forces(m, s, s.time);
  if (!s.recorded.external_force.empty()) record_external_forces(m, s, s.time);
  gather_rigid_body_forces(s);
}

double choose_time_step(const Model& m, SolverState& s, RunEvents& events, StepBound& bound) {
  const RunControl& rc = m.run;
  if (rc.dt_nodal_cst.given) {
    const NodalStep nodal = nodal_time_step(m, s);
    if (nodal.node >= 0) {
      StepBound scaled{nodal.dt, StepControl::node(nodal.node)};
      if (bound.contact_dt < scaled.dt) scaled.dt = bound.contact_dt, scaled.control = bound.contact_control;
      // The deck as written's step is stable for any added mass (mass only lowers the frequencies), eq. T-3c;
      // without contact it is the elements' (the bound so far).
      const StepBound written = s.contact.interfaces.empty() ? StepBound{bound.dt, bound.control}
                                                             : StepBound{bound.as_written_dt, bound.as_written_control};
      const StepBound& chosen = rc.nodal_step_at_least_as_written && written.dt > scaled.dt ? written : scaled;
      bound.dt = chosen.dt, bound.control = chosen.control;
    }
  } else if (interface_nodal_step_on(m)) {
    // With a TYPE7 interface the reference also bounds the step by its nodal one (eq. T-4).
    const NodalStep nodal = interface_nodal_step(m, s);
    if (nodal.node >= 0 && nodal.dt < bound.dt) bound.dt = nodal.dt, bound.control = StepControl::node(nodal.node);
  }
  // /DTIX: never above DTmax; the first cycle of the engine deck at most DTini.
  if (rc.dt_max > 0.0 && !(bound.dt <= rc.dt_max)) bound = {rc.dt_max, {StepControl::Source::MaximumStep}};
  if (rc.dt_initial > 0.0 && s.cycle == 0 && rc.dt_initial < bound.dt)
    bound = {rc.dt_initial, {StepControl::Source::InitialStep}};
  // Nothing bounds the step (docs/theory/time-step.md, "No stable step"): at the start that is a model the
  // explicit scheme cannot advance (point masses and rigid bodies alone); once every element has been deleted
  // the run goes on with its last step.
  if (!std::isfinite(bound.dt)) {
    if (s.cycle + s.cycles_done == 0) {
      events.stop.kind = StopReason::Kind::NoStableStep, events.stop.cycle = 0, events.stop.time = s.time;
      return bound.dt;
    }
    bound.dt = s.dt;
    bound.control.source = StepControl::Source::LastStep;
  }
  if (rc.dt.minimum > 0.0 && bound.dt < rc.dt.minimum) {
    events.stop.kind = StopReason::Kind::StepBelowMinimum, events.stop.cycle = s.cycle, events.stop.time = s.time;
    events.stop.dt = bound.dt, events.stop.minimum = rc.dt.minimum, events.stop.control = bound.control;
    return bound.dt;
  }
  return s.time + bound.dt > rc.end_time ? std::max(rc.end_time - s.time, 0.0) : bound.dt;
}

void solve_accelerations(const Model& m, SolverState& s, RunEvents& events, double dt_average, double dt_next) {
  if (s.domain.several()) {
    // Every domain solves the whole model, the same way (docs/parallel.md, "Selective mass scaling"): the nodes'
    // forces, velocities and positions from their owners.
    NodalState& n = s.nodes;
    Exchange& exchange = *s.reducer.exchange();
    for (auto* v : {&n.fx, &n.fy, &n.fz, &n.vx, &n.vy, &n.vz, &n.x, &n.y, &n.z}) exchange.share(*v, 1, s.domain.node_owner);
  }
  predict_wall_holds(m, s, dt_average, dt_next);
  const SelectiveSolve solve = solve_selective_mass(m, s, dt_average, dt_next);
  if (solve.converged || events.stop.stopped()) return;
  StopReason& stop = events.stop;
  stop.kind = StopReason::Kind::MassScalingDiverged, stop.cycle = s.cycle, stop.time = s.time;
  stop.index = static_cast<std::int32_t>(solve.iterations), stop.value = solve.residual;
  stop.minimum = m.run.dt_ams.tolerance_or_default();
}

// One pass over the local nodes: the velocities before the step into scratch.before, the update (CD-2), the free
// velocities into scratch.free. One read of each array instead of three: the update is bound by memory traffic.
void integrate(SolverState& s, VelocityScratch& scratch, double dt_average, bool selective) {
  NodalState& n = s.nodes;
  const SelectiveMassState& sm = s.selective_mass;
  auto& before = scratch.before;
  auto& free = scratch.free;
  for_each_local_node(s.domain, n.size(), [&](std::size_t k) {
    before[0][k] = n.vx[k], before[1][k] = n.vy[k], before[2][k] = n.vz[k];
    before[3][k] = n.wx[k], before[4][k] = n.wy[k], before[5][k] = n.wz[k];
    if (selective) {  // the accelerations of (M + dM) a = F (eq. SM-5)
      n.vx[k] += dt_average * sm.ax[k], n.vy[k] += dt_average * sm.ay[k], n.vz[k] += dt_average * sm.az[k];
    } else {
      const double inverse_mass = n.mass[k] > 0.0 ? 1.0 / n.mass[k] : 0.0;
      n.vx[k] += dt_average * n.fx[k] * inverse_mass;
      n.vy[k] += dt_average * n.fy[k] * inverse_mass;
      n.vz[k] += dt_average * n.fz[k] * inverse_mass;
    }
    if (n.inertia[k] > 0.0) {
      const double factor = selective ? selective_inertia_factor(s, k) : 1.0;
      if (selective) {  // the scaled inertia changed: the angular momentum is kept through the change (SM-5b)
        const double kept = selective_inertia_factor_before(s, k) / factor;
        n.wx[k] *= kept, n.wy[k] *= kept, n.wz[k] *= kept;
      }
      const double inverse_inertia = 1.0 / (n.inertia[k] * factor);
      n.wx[k] += dt_average * n.mx[k] * inverse_inertia;
      n.wy[k] += dt_average * n.my[k] * inverse_inertia;
      n.wz[k] += dt_average * n.mz[k] * inverse_inertia;
    }
    free[0][k] = n.vx[k], free[1][k] = n.vy[k], free[2][k] = n.vz[k];
    free[3][k] = n.wx[k], free[4][k] = n.wy[k], free[5][k] = n.wz[k];
  });
}

void apply_constraints(const Model& m, SolverState& s, VelocityScratch& scratch, double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  const double body_work = update_rigid_bodies(m, s, dt_average, dt_next);
  link_velocities(m, s);
  auto v = velocities(n);
  // A link's sharing of momentum is internal to its nodes, as the reference counts it: what it dissipates shows in
  // the energy error, not in the external work (L-8).
  for (const auto& link : m.run.velocity_links)
    for (std::int32_t node : link.nodes)
      for (std::size_t d = 0; d < 3; ++d)
        scratch.free[d][static_cast<std::size_t>(node)] = (*v[d])[static_cast<std::size_t>(node)];
  for (std::size_t d = 0; d < 6; ++d)  // rigid-body motion is internal to the body: not a constraint's work
    for (const auto& b : s.bodies) {
      for (std::int32_t node : b.secondary)
        scratch.free[d][static_cast<std::size_t>(node)] = (*v[d])[static_cast<std::size_t>(node)];
      scratch.free[d][static_cast<std::size_t>(b.main_node)] = (*v[d])[static_cast<std::size_t>(b.main_node)];
    }
  impose_kinematics(m, s, s.time, dt_next);
  apply_rigid_walls(m, s, dt_average, dt_next);
  // The works of the step as exact sums over the owned nodes, combined over the domains (docs/parallel.md): the
  // loads' and conditions' work, then each interface's contact work.
  std::vector<ExactSum>& work = s.reducer.sums;
  work.assign(1 + s.contact.interfaces.size(), ExactSum{});
  add_load_work(m, s, scratch.before, s.time, dt_average, work[0]);
  add_constraint_work(s, scratch, work[0]);
  if (!s.contact.interfaces.empty())
    contact::add_contact_work(s.contact, n, scratch.before.data(), s.domain.node_owner, s.domain.index, work.data() + 1);
  // Under selective mass scaling, the held dofs' reactions (SM-4b): every domain has them all, the first adds them.
  if (s.selective_mass.solved_cycle == s.cycle && s.domain.index == 0) work[0].add(s.selective_mass.reaction_work);
  s.reducer.sum(work);
  s.energy.external_work += work[0].value() + body_work;
  if (!s.contact.interfaces.empty()) s.energy.contact = contact::absorb_contact_work(s.contact, work.data() + 1, dt_average);
  record_acceleration(s, scratch, dt_average);
  // /ACCEL: only a deck with accelerometers has any (a loop over them, not over the nodes).
  update_accelerometers(m.accelerometers, n, {&scratch.before[0], &scratch.before[1], &scratch.before[2]}, dt_average,
                        s.skew_axes, s.histories);
  // /TH/SECTIO WORK: only a deck that asks it (a loop over the sections' elements, not over the model).
  add_section_work(m, s, scratch.before, dt_average);
}

void advance_positions(SolverState& s, double dt_next) {
  NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(), [&n, dt_next](std::size_t k) {
    n.x[k] += dt_next * n.vx[k];
    n.y[k] += dt_next * n.vy[k];
    n.z[k] += dt_next * n.vz[k];
  });
  // /TH/NODE DRX DRY DRZ: only the nodes a request asks them of (none: no loop).
  integrate_node_rotations(n, dt_next, s.histories);
  s.time += dt_next;
  s.dt = dt_next;
  ++s.cycle;
}

// A continued run's outputs follow its own /ANIM/DT and /TFILE from where it starts (the one at its first time
// was written by the run before).
OutputSchedule::OutputSchedule(const RunControl& rc, double time, long long max)
    : next_frame(std::numeric_limits<double>::infinity()),
      next_history(std::numeric_limits<double>::infinity()),
      print_every(rc.print_every != 0 ? std::llabs(rc.print_every) : 100),
      max_cycles(max) {
  if (rc.anim_interval > 0.0)
    next_frame = time > rc.anim_start ? next_output_time(time, rc.anim_start, rc.anim_interval) : rc.anim_start;
  if (rc.history_interval > 0.0) next_history = time > 0.0 ? next_output_time(time, 0.0, rc.history_interval) : 0.0;
  if (rc.history_every_cycle()) next_history = 0.0;  // due at every cycle
}

void keep_requested_results(const RunControl& rc, SolverState& s) {
  const std::size_t values = 3 * s.nodes.size();
  RecordedNodalResults& r = s.recorded;
  r.acceleration.assign(rc.anim.acceleration ? values : 0, 0.0);
  r.internal_force.assign(rc.anim.internal_force ? values : 0, 0.0);
  r.external_force.assign(rc.anim.external_force ? values : 0, 0.0);
}

bool frame_due(const SolverState& s, const OutputSchedule& schedule) {
  return s.time >= schedule.next_frame * (1.0 - 1e-12);
}

bool MonitorDue::energies() const { return print || frame || history || cycle % 64 == 0; }

MonitorDue outputs_due(const Model& m, const SolverState& s, const OutputSchedule& schedule, double dt_next) {
  MonitorDue due{};
  due.cycle = s.cycle;
  due.finished = s.time >= m.run.end_time * (1.0 - 1e-12) || dt_next <= 0.0 ||
                 (schedule.max_cycles >= 0 && s.cycle >= schedule.max_cycles);
  due.print = s.cycle % schedule.print_every == 0 || due.finished;
  due.frame = frame_due(s, schedule);
  due.history = s.time >= schedule.next_history * (1.0 - 1e-12);
  return due;
}

void update_energies(const Model& m, SolverState& s) {
  const auto [translational, rotational] = kinetic_energy(s);
  // Under selective mass scaling the deformation modes' added mass moves too (eq. SM-6), as the reference lists it.
  s.energy.kinetic_translational = translational + selective_mass_kinetic_energy(m, s);
  s.energy.kinetic_rotational = rotational;
  const auto [internal, hourglass] = element_energies(s);
  s.energy.internal = internal;
  s.energy.hourglass = hourglass;
}

// A step far below what the elements allow (a contact closing fast on a small gap, a node's mass) slows the run
// by that factor without failing it: the user must see it once (docs/theory/time-step.md, "Step drops").
void warn_step_drop(const SolverState& s, double element_step, double dt, const StepControl& control, RunEvents& events) {
  if (events.step_drop_warned || !(dt < 1e-3 * element_step) || !(element_step < 1e300)) return;
  events.step_drop_warned = true;
  RunEvent event{RunEvent::Kind::StepDropped, s.cycle, s.time};
  event.value = dt, event.second_value = element_step, event.control = control;
  events.pending.push_back(event);
}

namespace {

// No element computed any more: every one deleted (an element in a rigid body is still there).
bool no_element_left(const SolverState& s) {
  for (const auto* status : {&s.shells.deleted, &s.shells3.deleted, &s.bricks.deleted})
    for (std::uint8_t e : *status)
      if (element_condition(e) != kElementDeleted) return false;
  return true;
}

// A run whose elements were all deleted by numerical causes (turned inside out, below their minimum step) has no
// answer to give, unlike one whose elements failed by their material's failure model (which runs on, as the
// reference does): it stops, abnormally. Looked for when such deletions have happened since the last look.
bool every_element_lost(const SolverState& s, RunEvents& events) {
  const long long numerical = events.deleted_inverted + events.deleted_below_minimum_step;
  if (numerical == events.numerical_deletions_checked) return false;
  events.numerical_deletions_checked = numerical;
  return no_element_left(s);
}

}  // namespace

void check_run_limits(const Model& m, const SolverState& s, RunEvents& events) {
  const RunControl& rc = m.run;
  warn_hourglass_share(s, events);
  warn_energy_error(rc, s, events);
  StopReason& stop = events.stop;
  const double total = s.energy.internal + s.energy.kinetic_translational + s.energy.kinetic_rotational;
  if (every_element_lost(s, events)) {
    stop.kind = StopReason::Kind::EveryElementLost, stop.cycle = s.cycle, stop.time = s.time;
    stop.index = static_cast<std::int32_t>(events.deleted_inverted);
    stop.value = static_cast<double>(events.deleted_below_minimum_step);
  } else if (!std::isfinite(total)) {
    stop.kind = StopReason::Kind::EnergyNotFinite, stop.cycle = s.cycle, stop.time = s.time;
  } else if (rc.stop_mass_error > 0.0 && s.mass_added > rc.stop_mass_error * s.mass_initial) {
    stop.kind = StopReason::Kind::AddedMassLimit, stop.cycle = s.cycle, stop.time = s.time;
    stop.value = s.mass_added, stop.minimum = rc.stop_mass_error;
  } else if (const double ratio = std::abs(s.energy.error_percent()) / 100.0;
             rc.stop_energy_error > 0.0 && ratio > rc.stop_energy_error) {
    stop.kind = StopReason::Kind::EnergyErrorLimit, stop.cycle = s.cycle, stop.time = s.time;
    stop.value = ratio;
  }
}

bool stop_requested(const std::atomic<int>* request, SolverState& s, RunEvents& events, Exchange* exchange,
                    bool check_now) {
  int signal = request != nullptr ? request->load(std::memory_order_relaxed) : 0;
  if (s.domain.several()) {
    // Every domain stops at the same cycle: the requests are combined every 64 cycles (the energy checks' rhythm).
    if (!check_now) return false;
    std::vector<std::int32_t>& any = s.group_share.stop_signal;
    any.assign(1, signal);
    exchange->max(any);
    signal = any[0];
  }
  if (signal == 0) return false;
  StopReason& stop = events.stop;
  stop.kind = StopReason::Kind::Requested, stop.cycle = s.cycle, stop.time = s.time, stop.index = signal;
  return true;
}

void advance_schedule(const Model& m, const SolverState& s, const MonitorDue& due, OutputSchedule& schedule) {
  const RunControl& rc = m.run;
  if (due.frame) schedule.next_frame = next_output_time(s.time, rc.anim_start, rc.anim_interval);
  if (due.history && !rc.history_every_cycle())
    schedule.next_history = next_output_time(s.time, 0.0, rc.history_interval);
}

}  // namespace crumple::solver
