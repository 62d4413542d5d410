// The explicit time loop (docs/theory/time-loop.md). One cycle:
//   1. element internal forces at x^n with the stress update over dt^(n-1/2), element critical steps
//   2. external forces at t^n, rigid-body force gathering
//   3. dt^(n+1/2) = scale * min critical step
//   4. v^(n+1/2) = v^(n-1/2) + dt^n a^n with dt^n = (dt^(n-1/2) + dt^(n+1/2)) / 2   (central difference)
//   5. rigid bodies, fixed dofs, imposed velocity and displacement, rigid walls on v^(n+1/2)
//   6. x^(n+1) = x^n + dt^(n+1/2) v^(n+1/2)
#include <fmt/format.h>
#include <fmt/ostream.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "crumple/contact/contact.hpp"
#include "crumple/output/listing.hpp"
#include "crumple/output/results_file.hpp"
#include "crumple/solver/solver.hpp"
#include "solver/internal.hpp"

namespace crumple {
namespace {

struct Scratch {  // velocities before the update and after the free update, for the work of constraints
  std::vector<double> v_old[6], v_free[6];
  explicit Scratch(std::size_t n) {
    for (auto& v : v_old) v.assign(n, 0.0);
    for (auto& v : v_free) v.assign(n, 0.0);
  }
};

std::array<std::vector<double>*, 6> velocities(NodalState& n) { return {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz}; }

// Power of the /CLOAD and /GRAV loads on the mid-step velocities, times the step.
double load_work(const Model& m, const SolverState& s, const Scratch& scratch, double t, double dt_average) {
  double work = 0.0;
  const NodalState& n = s.nodes;
  const std::vector<double>* now[6] = {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  auto mean_velocity = [&](Dof dof, std::size_t k) {
    const auto d = static_cast<std::size_t>(dof);
    return 0.5 * ((*now[d])[k] + scratch.v_old[d][k]);
  };
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind != ImposedKind::Force || t < im.t_start || t > im.t_stop) continue;
    const double value = im.scale_y * m.functions[static_cast<std::size_t>(im.function)](t / im.scale_x);
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes)
      work += value * mean_velocity(im.dof, static_cast<std::size_t>(node)) * dt_average;
  }
  for (const Gravity& g : m.gravity) {
    const double a = g.scale_y * m.functions[static_cast<std::size_t>(g.function)](t / g.scale_x);
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(g.node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      work += n.mass[k] * a * mean_velocity(g.dof, k) * dt_average;
    }
  }
  return work;
}

// Work of the kinematic conditions: the impulse that changed the free velocity, on the mid-step velocity.
double constraint_work(SolverState& s, const Scratch& scratch) {
  double work = 0.0;
  NodalState& n = s.nodes;
  auto v = velocities(n);
  for (std::size_t k = 0; k < n.size(); ++k) {
    for (std::size_t d = 0; d < 3; ++d) {
      const double dv = (*v[d])[k] - scratch.v_free[d][k];
      if (dv != 0.0) work += n.mass[k] * dv * 0.5 * ((*v[d])[k] + scratch.v_old[d][k]);
    }
    if (n.inertia[k] > 0.0)
      for (std::size_t d = 3; d < 6; ++d) {
        const double dv = (*v[d])[k] - scratch.v_free[d][k];
        if (dv != 0.0) work += n.inertia[k] * dv * 0.5 * ((*v[d])[k] + scratch.v_old[d][k]);
      }
  }
  return work;
}

}  // namespace

RunSummary run_simulation(const Model& m, const SolverOptions& options, std::ostream& console) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<std::string> notes;
  SolverState s = solver::make_state(m, notes);
  NodalState& n = s.nodes;
  const RunControl& rc = m.run;
  const std::string name = options.name.empty() ? m.run_name : options.name;
  Listing listing(options.output_directory / (name + ".out"));
  std::optional<ResultsFile> results;
  if (options.write_results) results.emplace(options.output_directory / (name + ".h5"), m);

  listing.line(fmt::format("Crumple explicit run {}  ({})", name, m.title));
  listing.line(fmt::format("nodes {}  4-node shells {}  element groups {}  end time {:g}", m.nodes.size(),
                           m.elements[0].size(), m.element_groups.size(), rc.end_time));
  for (const auto& note : notes) listing.line("NOTE: " + note);
  for (const auto& note : notes) fmt::print(console, "note: {}\n", note);
  listing.table_header();

  const double scale = rc.dt.scale > 0.0 ? rc.dt.scale : 0.9;
  const double dt_minimum = rc.dt.minimum;
  const long long print_every = rc.print_every != 0 ? std::llabs(rc.print_every) : 100;
  double next_frame = rc.anim_interval > 0.0 ? rc.anim_start : std::numeric_limits<double>::infinity();
  double next_history = rc.history_interval > 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  std::size_t element_count = 0;
  for (const auto& table : m.elements) element_count += table.size();

  Scratch scratch(n.size());
  RunSummary summary;
  summary.name = name;
  std::string controlling = "-";
  double dt_next = 0.0;

  auto record = [&](bool to_listing) {
    const auto [kt, kr] = solver::kinetic_energy(s);
    s.energy.kinetic_translational = kt;
    s.energy.kinetic_rotational = kr;
    double total_mass = 0.0;
    for (double mass : n.mass) total_mass += mass;
    if (to_listing) {
      ListingRow row{s.cycle, s.time, dt_next, controlling, s.energy.error_percent(), s.energy.internal, kt, kr,
                     s.energy.external_work, s.energy.hourglass, s.energy.contact,
                     (total_mass - s.mass_initial) / s.mass_initial, total_mass, s.mass_added};
      listing.row(row);
    }
  };
  auto write_history = [&]() {
    if (!results) return;
    HistoryRow row;
    row.time = s.time, row.dt = dt_next;
    row.internal = s.energy.internal, row.kinetic_translational = s.energy.kinetic_translational;
    row.kinetic_rotational = s.energy.kinetic_rotational, row.hourglass = s.energy.hourglass;
    row.contact = s.energy.contact, row.external_work = s.energy.external_work;
    row.total = row.internal + row.kinetic_translational + row.kinetic_rotational + row.hourglass + row.contact;
    for (const auto& w : s.walls) row.rigid_wall_force.insert(row.rigid_wall_force.end(), w.force.begin(), w.force.end());
    for (const auto& b : s.bodies) {
      const auto k = static_cast<std::size_t>(b.main_node);
      for (double v : {n.x[k], n.y[k], n.z[k], n.vx[k], n.vy[k], n.vz[k], b.omega[0], b.omega[1], b.omega[2]})
        row.rigid_body_values.push_back(v);
    }
    for (const InterfaceResult& r : s.contact.results) {
      row.interface_values.insert(row.interface_values.end(), r.normal_force.begin(), r.normal_force.end());
      row.interface_values.insert(row.interface_values.end(), r.tangential_force.begin(), r.tangential_force.end());
      for (double v : {r.elastic_energy, r.friction_work, r.absorbed, static_cast<double>(r.active_nodes)})
        row.interface_values.push_back(v);
    }
    results->write_history(row);
  };

  RunStatus status = RunStatus::Normal;
  std::string message = "normal termination";
  // Time profile: one clock read per stage boundary (five per cycle, far below the cost of any stage).
  PhaseTimes& phases = summary.phases;
  auto last_lap = std::chrono::steady_clock::now();
  auto lap = [&last_lap](double& bucket) {
    const auto now = std::chrono::steady_clock::now();
    bucket += std::chrono::duration<double>(now - last_lap).count();
    last_lap = now;
  };
  for (;;) {
    // 1. Internal forces and critical steps of the elements.
    n.clear_forces();
    double dt_elements = std::numeric_limits<double>::infinity();
    bool elements_deleted = false;
    for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
      const ElementGroup& group = m.element_groups[g];
      const ElementTable& table = m.elements[static_cast<int>(group.kind)];
      GroupStepResult r;  // min_dt is the unscaled critical step
      switch (group.kind) {
        case ElementKind::Shell4: r = shell4_forces(table, group, s.shell_groups[g], n, s.shells, s.dt); break;
        case ElementKind::Shell3: r = shell3_forces(table, group, s.shell_groups[g], n, s.shells3, s.dt); break;
        case ElementKind::Brick8: r = brick8_forces(table, group, s.brick_groups[g], n, s.bricks, s.dt); break;
      }
      s.energy.internal += r.internal_energy;
      elements_deleted = elements_deleted || r.failed > 0;
      s.energy.hourglass += r.hourglass_energy;
      const std::string_view kind = element_kind_name(group.kind);
      if (r.non_finite >= 0 && status == RunStatus::Normal) {
        status = RunStatus::Error;
        message = fmt::format("{} {} of part {}: NaN or infinite forces at cycle {} (time {:.6g})", kind,
                              table.user_id[static_cast<std::size_t>(r.non_finite)],
                              m.parts[static_cast<std::size_t>(group.part)].user_id, s.cycle, s.time);
      }
      if (r.inverted >= 0) {
        status = RunStatus::Error;
        message = fmt::format("{} {} of part {} inverted ({}) at cycle {}", kind,
                              table.user_id[static_cast<std::size_t>(r.inverted)],
                              m.parts[static_cast<std::size_t>(group.part)].user_id,
                              group.kind == ElementKind::Brick8 ? "negative volume" : "zero or negative area or corner Jacobian",
                              s.cycle);
      }
      // Per-type step control (/DT/SHELL, /DT/SH_3N): own scale, and elements below the minimum are deleted
      // (the default for shells) or stop the run.
      const TimeStepControl& type = group.kind == ElementKind::Shell4   ? rc.dt_shell
                                    : group.kind == ElementKind::Shell3 ? rc.dt_sh3n
                                                                        : rc.dt_brick;
      const double type_scale = type.given && type.scale > 0.0 ? type.scale : scale;
      if (r.controlling >= 0 && type.minimum > 0.0 && type_scale * r.min_dt < type.minimum &&
          status == RunStatus::Normal) {
        const bool stop = type.action == TimeStepAction::Stop ||
                          (type.action == TimeStepAction::Default && group.kind == ElementKind::Brick8);
        if (stop) {
          status = RunStatus::Error;
          message = fmt::format("{} {} of part {}: time step {:.4e} below the minimum {:.4e} at cycle {}", kind,
                                table.user_id[static_cast<std::size_t>(r.controlling)],
                                m.parts[static_cast<std::size_t>(group.part)].user_id, type_scale * r.min_dt,
                                type.minimum, s.cycle);
        } else {
          const bool brick = group.kind == ElementKind::Brick8;
          ShellState& st = group.kind == ElementKind::Shell4 ? s.shells : s.shells3;
          auto& deleted = brick ? s.bricks.deleted : st.deleted;
          const auto& critical_dt = brick ? s.bricks.critical_dt : st.critical_dt;
          r.min_dt = std::numeric_limits<double>::infinity();
          for (std::int32_t e = group.begin; e < group.end; ++e) {
            const auto ue = static_cast<std::size_t>(e);
            if (deleted[ue]) continue;
            if (type_scale * critical_dt[ue] < type.minimum) {
              deleted[ue] = 1;
              ++s.deleted_by_time_step;
            } else if (critical_dt[ue] < r.min_dt) {
              r.min_dt = critical_dt[ue], r.controlling = e;
            }
          }
        }
      }
      // A group whose elements are all deleted or inverted has no controlling element (controlling = -1).
      if (r.controlling >= 0 && type_scale * r.min_dt < dt_elements) {
        dt_elements = type_scale * r.min_dt;
        controlling = fmt::format("{} {}", kind, table.user_id[static_cast<std::size_t>(r.controlling)]);
      }
    }
    lap(phases.elements);
    if (status != RunStatus::Normal) break;
    // 1b. Contact (docs/theory/contact.md), only when the deck has interfaces: forces at x^n with v^(n-1/2),
    // the interface step joins the elements'.
    if (!s.contact.interfaces.empty()) {
      if (elements_deleted)
        contact::remove_deleted_elements(s.contact, {&s.shells.deleted, &s.shells3.deleted, &s.bricks.deleted});
      const contact::ContactStep cs = contact::contact_forces(m, s.contact, n, s.time, s.dt, dt_elements, scale,
                                                                s.mass_added);
      // IBC: boundary conditions of secondary nodes released at their first impact.
      for (const auto& [node, dofs] : s.contact.bc_releases)
        s.fixed[static_cast<std::size_t>(node)] &= static_cast<std::uint8_t>(~dofs);
      s.contact.bc_releases.clear();
      if (cs.dt < dt_elements) {
        dt_elements = cs.dt;
        controlling = fmt::format("INTER {} NODE {}", m.type7_interfaces[static_cast<std::size_t>(cs.interface)].user_id,
                                  m.nodes.user_id[static_cast<std::size_t>(cs.node)]);
      }
      ++phases.contact_passes;
      lap(phases.contact);
    }
    // 2. External forces; rigid bodies collect their nodes' forces.
    solver::add_external_forces(m, s, s.time);
    solver::gather_rigid_body_forces(s);
    // 3. Time step: the elements' (already scaled), or the nodal step with mass scaling (/DT/NODA/CST).
    dt_next = dt_elements;
    if (rc.dt_nodal_cst.given) {
      const solver::NodalStep nodal = solver::nodal_time_step(m, s);
      if (nodal.node >= 0) {
        dt_next = nodal.dt;
        controlling = fmt::format("NODE {}", m.nodes.user_id[static_cast<std::size_t>(nodal.node)]);
      }
    }
    // Nothing bounds the step (docs/theory/time-step.md, "No stable step"): at the start that is a model the
    // explicit scheme cannot advance (point masses and rigid bodies alone); once every element has been deleted
    // the run goes on with its last step.
    if (!std::isfinite(dt_next)) {
      if (s.cycle == 0) {
        status = RunStatus::Error;
        message = "no element limits the time step: the model has nothing with stiffness to integrate (add the "
                  "elements the rigid bodies or masses are attached to)";
        break;
      }
      dt_next = s.dt;
      controlling = "LAST STEP";
    }
    if (dt_minimum > 0.0 && dt_next < dt_minimum) {
      status = RunStatus::Error;
      message = fmt::format("time step {:.4e} below the minimum {:.4e} ({}) at cycle {}", dt_next, dt_minimum,
                            controlling, s.cycle);
      break;
    }
    if (s.time + dt_next > rc.end_time) dt_next = std::max(rc.end_time - s.time, 0.0);
    lap(phases.loads);
    const double dt_average = s.cycle == 0 ? 0.5 * dt_next : 0.5 * (s.dt + dt_next);
    // 4. Central-difference velocity update.
    auto v = velocities(n);
    for (std::size_t d = 0; d < 6; ++d) std::copy(v[d]->begin(), v[d]->end(), scratch.v_old[d].begin());
    for (std::size_t k = 0; k < n.size(); ++k) {
      const double inverse_mass = n.mass[k] > 0.0 ? 1.0 / n.mass[k] : 0.0;
      n.vx[k] += dt_average * n.fx[k] * inverse_mass;
      n.vy[k] += dt_average * n.fy[k] * inverse_mass;
      n.vz[k] += dt_average * n.fz[k] * inverse_mass;
      if (n.inertia[k] > 0.0) {
        const double inverse_inertia = 1.0 / n.inertia[k];
        n.wx[k] += dt_average * n.mx[k] * inverse_inertia;
        n.wy[k] += dt_average * n.my[k] * inverse_inertia;
        n.wz[k] += dt_average * n.mz[k] * inverse_inertia;
      }
    }
    for (std::size_t d = 0; d < 6; ++d) std::copy(v[d]->begin(), v[d]->end(), scratch.v_free[d].begin());
    // 5. Kinematic conditions.
    solver::update_rigid_bodies(s, dt_average, dt_next);
    for (std::size_t d = 0; d < 6; ++d)  // rigid-body motion is internal to the body: not a constraint's work
      for (const auto& b : s.bodies) {
        for (std::int32_t node : b.secondary) scratch.v_free[d][static_cast<std::size_t>(node)] = (*v[d])[static_cast<std::size_t>(node)];
        scratch.v_free[d][static_cast<std::size_t>(b.main_node)] = (*v[d])[static_cast<std::size_t>(b.main_node)];
      }
    solver::impose_kinematics(m, s, s.time, dt_next);
    solver::apply_rigid_walls(m, s, dt_average, dt_next);
    s.energy.external_work += load_work(m, s, scratch, s.time, dt_average) + constraint_work(s, scratch);
    if (!s.contact.interfaces.empty()) s.energy.contact = contact::contact_work(s.contact, n, scratch.v_old, dt_average);
    // 6. Positions.
    for (std::size_t k = 0; k < n.size(); ++k) {
      n.x[k] += dt_next * n.vx[k];
      n.y[k] += dt_next * n.vy[k];
      n.z[k] += dt_next * n.vz[k];
    }
    s.time += dt_next;
    s.dt = dt_next;
    ++s.cycle;
    lap(phases.update);

    const bool finished = s.time >= rc.end_time * (1.0 - 1e-12) || dt_next <= 0.0 ||
                          (options.max_cycles >= 0 && s.cycle >= options.max_cycles);
    const bool print = s.cycle % print_every == 0 || finished;
    const bool frame = s.time >= next_frame * (1.0 - 1e-12);
    const bool history = s.time >= next_history * (1.0 - 1e-12);
    if (print || frame || history || s.cycle % 64 == 0) {
      record(print);
      const double total = s.energy.internal + s.energy.kinetic_translational + s.energy.kinetic_rotational;
      if (!std::isfinite(total)) {
        status = RunStatus::Error;
        message = fmt::format("NaN or Inf in the energy balance at cycle {} (time {:.4e})", s.cycle, s.time);
        break;
      }
      if (rc.stop_mass_error > 0.0 && s.mass_added > rc.stop_mass_error * s.mass_initial) {
        status = RunStatus::Stopped;
        message = fmt::format("/STOP: added mass {:.4g} exceeds {:.3g} of the initial mass at cycle {}", s.mass_added,
                              rc.stop_mass_error, s.cycle);
        break;
      }
      const double ratio = std::abs(s.energy.error_percent()) / 100.0;
      if (rc.stop_energy_error > 0.0 && ratio > rc.stop_energy_error) {
        status = RunStatus::Stopped;
        message = fmt::format("/STOP: energy error {:.3g} % exceeds the limit at cycle {}", 100.0 * ratio, s.cycle);
        break;
      }
    }
    if (frame && results) {
      results->write_frame(s.time, s.cycle, m, s);
      next_frame = solver::next_output_time(s.time, rc.anim_start, rc.anim_interval);
    }
    if (history) {
      write_history();
      if (options.observer) options.observer(s);
      next_history = solver::next_output_time(s.time, 0.0, rc.history_interval);
    }
    lap(phases.output);
    if (finished) break;
  }
  record(true);
  if (results) {
    if (status != RunStatus::Normal) results->write_frame(s.time, s.cycle, m, s);  // the last good state
    results->close();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  listing.line(status == RunStatus::Normal ? "NORMAL TERMINATION" : "ERROR TERMINATION: " + message);
  if (s.deleted_by_time_step > 0)
    listing.line(fmt::format("ELEMENTS DELETED BELOW THEIR MINIMUM TIME STEP: {}", s.deleted_by_time_step));
  if (s.mass_added > 0.0) listing.line(fmt::format("MASS ADDED BY /DT/NODA/CST OR /DT/INTER/CST: {:.6g}", s.mass_added));
  for (std::size_t f = 0; f < s.contact.results.size(); ++f) {
    const InterfaceResult& r = s.contact.results[f];
    listing.line(fmt::format("INTER {}: largest p/g {:.4f}, absorbed energy {:.6g} (elastic now {:.6g}, damping {:.6g}, "
                             "friction {:.6g}), contacts released below dtmin {}, mass added {:.6g}",
                             m.type7_interfaces[f].user_id, r.max_penetration_ratio, r.absorbed, r.elastic_energy,
                             r.damping_work, r.friction_work, r.released, r.added_mass));
  }
  listing.line(fmt::format("TOTAL NUMBER OF CYCLES {}   ELAPSED {:.3f} s", s.cycle, wall));
  {
    const double cycle_time = phases.elements + phases.contact + phases.loads + phases.update + phases.output;
    auto share = [&](double t) { return cycle_time > 0.0 ? 100.0 * t / cycle_time : 0.0; };
    listing.line(fmt::format("TIME PROFILE (s, % of the cycles): elements {:.3f} ({:.1f} %)  contact {:.3f} ({:.1f} %, "
                             "{} passes)  loads and step {:.3f} ({:.1f} %)  nodal update {:.3f} ({:.1f} %)  "
                             "output {:.3f} ({:.1f} %)",
                             phases.elements, share(phases.elements), phases.contact, share(phases.contact),
                             phases.contact_passes, phases.loads, share(phases.loads), phases.update,
                             share(phases.update), phases.output, share(phases.output)));
  }

  summary.cycles = s.cycle;
  summary.time = s.time;
  summary.dt = dt_next;
  summary.energy.internal = s.energy.internal;
  summary.energy.kinetic_translational = s.energy.kinetic_translational;
  summary.energy.kinetic_rotational = s.energy.kinetic_rotational;
  summary.energy.contact = s.energy.contact;
  summary.energy.hourglass = s.energy.hourglass;
  summary.energy.external_work = s.energy.external_work;
  summary.energy.total = s.energy.internal + s.energy.kinetic_translational + s.energy.kinetic_rotational +
                         s.energy.hourglass + s.energy.contact;
  summary.energy.error_percent = s.energy.error_percent();
  for (double mass : n.mass) summary.mass_total += mass;
  summary.mass_added = s.mass_added;
  summary.wall_seconds = wall;
  summary.element_cycles_per_second = wall > 0.0 ? static_cast<double>(element_count) * static_cast<double>(s.cycle) / wall : 0.0;
  summary.status = status;
  summary.message = message;
  return summary;
}

}  // namespace crumple
