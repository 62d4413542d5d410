// The phases of one cycle (docs/theory/time-loop.md, "One cycle"); time_loop.cpp calls them in this order.
#include "solver/cycle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "crumple/contact/contact.hpp"
#include "solver/domain_sharing.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

std::array<std::vector<double>*, 6> velocities(NodalState& n) { return {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz}; }

// /DT/SHELL, /DT/SH_3N, /DT/BRICK: the step control of an element kind.
const TimeStepControl& type_control(const RunControl& rc, ElementKind kind) { return rc.*describe(kind).step_control; }

GroupStepResult group_forces(const Model& m, SolverState& s, std::size_t g) {
  const ElementGroup& group = m.element_groups[g];
  const ElementTable& table = m.elements[static_cast<int>(group.kind)];
  switch (group.kind) {
    case ElementKind::Shell4: return shell4_forces(table, group, s.shell_groups[g], s.nodes, s.shells, s.dt);
    case ElementKind::Shell3: return shell3_forces(table, group, s.shell_groups[g], s.nodes, s.shells3, s.dt);
    case ElementKind::Brick8: return brick8_forces(table, group, s.brick_groups[g], s.nodes, s.bricks, s.dt);
    case ElementKind::Spring: return spring_forces(table, group, s.spring_groups[g], s.nodes, s.springs, s.dt, s.time, s.skew_axes);
    case ElementKind::Truss: return truss_forces(table, group, s.truss_groups[g], s.nodes, s.trusses, s.dt);
    case ElementKind::Beam: return beam_forces(table, group, s.beam_groups[g], s.nodes, s.beams, s.dt);
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
  ElementKindState& state = element_state(s, group.kind);
  auto& deleted = state.deleted;
  const auto& critical_dt = state.critical_dt;
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
    return shell_switch_to_small_strain(table, s.shell_groups[g], s.nodes, shell_state(s, group.kind), e);
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
  const ElementKindState& state = element_state(s, group.kind);
  const auto& status = state.deleted;
  const auto& critical_dt = state.critical_dt;
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


// The elements' forces on the nodes, before contact and loads add theirs (field frames, /ANIM/VECT/FINT).
void record_internal_forces(SolverState& s) {
  std::vector<double>& out = s.recorded.internal_force;
  if (out.empty()) return;
  const NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(),
                      [&](std::size_t k) { out[3 * k] = n.fx[k], out[3 * k + 1] = n.fy[k], out[3 * k + 2] = n.fz[k]; });
}

}  // namespace

double step_scale(const RunControl& run) { return run.dt.scale > 0.0 ? run.dt.scale : 0.9; }


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
      ElementRecords& records = element_state(s, static_cast<ElementKind>(k)).records;
      exchange->halo_start(records.load, records.nodes_per_element * records.values_per_node,
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
  spread_interpolation_loads(m, s);  // first: an independent node may be tied, or carried by a body
  transfer_tied_forces(s);  // before the bodies gather: a segment's node may be a body's
  gather_rigid_element_forces(m, s);
  gather_rigid_body_forces(s);
}

// The step grows by at most a tenth a cycle, as the reference's does (docs/theory/time-step.md, T-5): after a
// contact releases its node, and once nothing bounds it (every element deleted, "No stable step").
constexpr double kStepGrowthPerCycle = 1.1;

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
  // /DAMP: the mass damping lowers the stable step (eq. D-3).
  if (!m.dampings.empty()) bound.dt *= damping_step_factor(m, s, bound.dt);
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
    bound.dt = kStepGrowthPerCycle * s.dt;
    bound.control.source = StepControl::Source::LastStep;
  } else if (s.dt > 0.0 && bound.dt > kStepGrowthPerCycle * s.dt) {
    bound.dt = kStepGrowthPerCycle * s.dt;  // eq. T-5; the listing still names what bounds the step
  }
  // A step of zero (a contact node through its gap, contact.md C-11): the run cannot advance; it stops with an
  // error rather than end short of its end time as if it had reached it.
  if (rc.dt.minimum > 0.0 ? bound.dt < rc.dt.minimum : !(bound.dt > 0.0)) {
    events.stop.kind = StopReason::Kind::StepBelowMinimum, events.stop.cycle = s.cycle, events.stop.time = s.time;
    events.stop.dt = bound.dt, events.stop.minimum = rc.dt.minimum, events.stop.control = bound.control;
    return bound.dt;
  }
  // T-0: no step is cut to land on the end time; a run that starts at or past it takes none.
  return s.time >= rc.end_time ? 0.0 : bound.dt;
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
  const double body_work = update_rigid_bodies(m, s, dt_average, dt_next) +
                           update_rigid_elements(m, s, scratch.before, dt_average, dt_next);
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
  auto keep_as_free = [&](std::int32_t node) {
    for (std::size_t d = 0; d < 6; ++d) scratch.free[d][static_cast<std::size_t>(node)] = (*v[d])[static_cast<std::size_t>(node)];
  };
  for (const RigidElement& e : m.rigid_elements) {  // as a body's: the group's motion is its own (RE-4)
    keep_as_free(e.main_node);
    for (std::int32_t node : e.secondary_nodes) keep_as_free(node);
  }
  impose_kinematics(m, s, s.time, dt_next);
  apply_rigid_walls(m, s, dt_average, dt_next);
  tie_velocities(s);  // on the segments' final velocities; a tied node has no mass, so no work
  interpolate_dependent_motion(m, s);  // last: from the independent nodes' final velocities; no mass, so no work
  // The works of the step as exact sums over the owned nodes, combined over the domains (docs/parallel.md): the
  // loads' and conditions' work, then each interface's contact work.
  std::vector<ExactSum>& work = s.reducer.sums;
  work.assign(1 + s.contact.interfaces.size(), ExactSum{});
  add_load_work(m, s, scratch.before, s.time, dt_average, work[0]);
  add_damping_work(m, s, scratch, dt_average, work[0]);
  add_constraint_work(s, scratch, work[0]);
  if (!s.contact.interfaces.empty())
    contact::add_contact_work(s.contact, n, scratch.before.data(), s.domain.node_owner, s.domain.index, work.data() + 1);
  // Under selective mass scaling, the held dofs' reactions (SM-4b): every domain has them all, the first adds them.
  if (s.selective_mass.solved_cycle == s.cycle && s.domain.index == 0) work[0].add(s.selective_mass.reaction_work);
  s.reducer.sum(work);
  s.energy.external_work += work[0].value() + body_work;
  if (!s.contact.interfaces.empty()) s.energy.contact = contact::absorb_contact_work(s.contact, work.data() + 1, dt_average);
}

void advance_positions(SolverState& s, double dt_next) {
  NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(), [&n, dt_next](std::size_t k) {
    n.x[k] += dt_next * n.vx[k];
    n.y[k] += dt_next * n.vy[k];
    n.z[k] += dt_next * n.vz[k];
  });
  s.time += dt_next;
  s.dt = dt_next;
  ++s.cycle;
}

}  // namespace crumple::solver
