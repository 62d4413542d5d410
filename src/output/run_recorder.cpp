#include "crumple/output/run_recorder.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <ctime>

#include "crumple/core/precision.hpp"
#include "crumple/output/build_info.hpp"
#include "crumple/output/restart_file.hpp"
#include "crumple/state/element_status.hpp"

namespace crumple {
namespace {

std::string element_name(const Model& m, ElementKind kind, std::int32_t index) {
  return fmt::format("{} {}", element_kind_name(kind),
                     m.elements[static_cast<int>(kind)].user_id[static_cast<std::size_t>(index)]);
}

std::int64_t part_id_of(const Model& m, ElementKind kind, std::int32_t index) {
  const auto part = m.elements[static_cast<int>(kind)].part[static_cast<std::size_t>(index)];
  return m.parts[static_cast<std::size_t>(part)].user_id;
}

long long deleted_count(const std::vector<std::uint8_t>& status) {
  return std::count_if(status.begin(), status.end(),
                       [](std::uint8_t st) { return element_condition(st) == kElementDeleted; });
}

// The model's mass: its initial mass and what mass scaling added (summed over the domains' own nodes), the same at
// any number of domains (a domain scales only the nodes it advances).
double total_mass(const SolverState& s) { return s.mass_initial + s.mass_added; }

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return fmt::format("signal {}", signal);
}

// The listing's closing verdict.
std::string termination(const StopReason& stop, const Model& m) {
  if (!stop.stopped()) return "NORMAL TERMINATION";
  if (stop.requested()) return "RUN STOPPED ON REQUEST: " + describe(stop, m);
  return "ERROR TERMINATION: " + describe(stop, m);
}

}  // namespace

std::string describe(const StepControl& c, const Model& m) {
  switch (c.source) {
    case StepControl::Source::None: return "-";
    case StepControl::Source::Element: return element_name(m, c.kind, c.index);
    case StepControl::Source::Interface:
      return fmt::format("INTER {} NODE {}", m.type7_interfaces[static_cast<std::size_t>(c.interface)].user_id,
                         m.nodes.user_id[static_cast<std::size_t>(c.index)]);
    case StepControl::Source::Node: return fmt::format("NODE {}", m.nodes.user_id[static_cast<std::size_t>(c.index)]);
    case StepControl::Source::LastStep: return "LAST STEP";
    case StepControl::Source::MaximumStep: return "DTIX DTMAX";
    case StepControl::Source::InitialStep: return "DTIX DTINI";
  }
  return "-";
}

std::string describe(const StopReason& r, const Model& m) {
  using K = StopReason::Kind;
  switch (r.kind) {
    case K::None: return "normal termination";
    case K::NonFiniteForces:
      return fmt::format("{} of part {}: NaN or infinite forces at cycle {} (time {:.6g})",
                         element_name(m, r.element_kind, r.index), part_id_of(m, r.element_kind, r.index), r.cycle,
                         r.time);
    case K::InvertedElement:
      return fmt::format("{} of part {} inverted ({}) at cycle {}", element_name(m, r.element_kind, r.index),
                         part_id_of(m, r.element_kind, r.index),
                         r.element_kind == ElementKind::Brick8 ? "negative volume"
                                                               : "zero or negative area or corner Jacobian",
                         r.cycle);
    case K::ElementStepBelowMinimum:
      return fmt::format("{} of part {}: time step {:.4e} below the minimum {:.4e} at cycle {}",
                         element_name(m, r.element_kind, r.index), part_id_of(m, r.element_kind, r.index), r.dt,
                         r.minimum, r.cycle);
    case K::StepBelowMinimum:
      return fmt::format("time step {:.4e} below the minimum {:.4e} ({}) at cycle {}", r.dt, r.minimum,
                         describe(r.control, m), r.cycle);
    case K::NoStableStep:
      return "no element limits the time step: the model has nothing with stiffness to integrate (add the "
             "elements the rigid bodies or masses are attached to)";
    case K::EnergyNotFinite:
      return fmt::format("NaN or Inf in the energy balance at cycle {} (time {:.4e})", r.cycle, r.time);
    case K::Diverged:
      return fmt::format("the run diverged: energy error {:.3g} % at cycle {} (time {:.4e}), the energy balance off by "
                         "more than {:.0f} times the energy put in; an instability grew (read the warnings above: "
                         "hourglass, energy error, step drops), and the results are not physical",
                         r.value, r.cycle, r.time, kDivergedEnergyErrorPercent / 100.0);
    case K::AddedMassLimit:
      return fmt::format("/STOP: added mass {:.4g} exceeds {:.3g} of the initial mass at cycle {}", r.value,
                         r.minimum, r.cycle);
    case K::EnergyErrorLimit:
      return fmt::format("/STOP: energy error {:.3g} % exceeds the limit at cycle {}", 100.0 * r.value, r.cycle);
    case K::MassScalingDiverged:
      return fmt::format("/DT/AMS: the mass-scaled accelerations did not converge in {} iterations at cycle {} "
                         "(residual {:.3g} against Tol_AMS {:.3g}): the scaling is likely diverging; lower DTmin of "
                         "/DT/AMS, or raise Niter (/DT/AMS/2)",
                         r.index, r.cycle, r.value, r.minimum);
    case K::EveryElementLost:
      return fmt::format("no element is left at cycle {} (time {:.4e}): {} shells turned inside out and {} elements "
                         "fell below their minimum step (/DT/<type>/DEL); the load is beyond what the mesh can carry "
                         "(an initial velocity or an imposed motion too large, or the wrong units)",
                         r.cycle, r.time, r.index, static_cast<long long>(r.value));
    case K::Requested:
      return fmt::format("stopped by {} at the end of cycle {} (time {:.6g})", signal_name(r.index), r.cycle, r.time);
  }
  return "unknown stop";
}

std::string describe(const RunEvent& e, const Model& m) {
  using K = RunEvent::Kind;
  const std::string when = fmt::format("CYCLE {} TIME {:.4e}:", e.cycle, e.time);
  switch (e.kind) {
    case K::ElementDeletedBelowMinimumStep:
      return fmt::format("{} {} of part {} DELETED: time step {:.4e} below its minimum (/DT/{}/DEL)", when,
                         element_name(m, e.element_kind, e.index), part_id_of(m, e.element_kind, e.index), e.value,
                         describe(e.element_kind).step_card);
    case K::ElementSwitchedToSmallStrain:
      return fmt::format("{} {} of part {} SWITCHED TO SMALL STRAIN: time step {:.4e} at its minimum (/DT/{}/CST)", when,
                         element_name(m, e.element_kind, e.index), part_id_of(m, e.element_kind, e.index), e.value,
                         describe(e.element_kind).step_card);
    case K::ShellDeletedInverted:
      return fmt::format("{} {} of part {} DELETED: turned inside out (zero area or two folded corners){}", when,
                         element_name(m, e.element_kind, e.index), part_id_of(m, e.element_kind, e.index),
                         e.value > 1.0 ? fmt::format(", with {:.0f} other shells of its group this cycle", e.value - 1.0) : "");
    case K::ContactBoundaryReleased: {
      std::string dofs;
      for (int d = 0; d < 3; ++d)
        if (static_cast<unsigned>(e.value) & (1u << d)) dofs += "xyz"[d];
      return fmt::format("{} NODE {}: boundary conditions {} released at its first contact (IBC)", when,
                         m.nodes.user_id[static_cast<std::size_t>(e.index)], dofs);
    }
    case K::HourglassShare:
      return fmt::format("{} WARNING: hourglass energy is {:.1f} % of the internal energy (above 10 %): the mesh is "
                         "too coarse for the load or the formulation lets zero-energy modes grow",
                         when, 100.0 * e.value);
    case K::EnergyErrorLarge:
      return fmt::format("{} WARNING: energy error {:.3g} % (beyond {:g} %): the energy balance is not kept; the run "
                         "may be going unstable, or mass scaling or contact releases add or take energy",
                         when, e.value, e.second_value);
    case K::StepDropped:
      return fmt::format("{} WARNING: time step {:.4e} set by {}, below 1/1000 of the elements' step {:.4e}: the run "
                         "slows down by that factor (a contact closing fast on a small gap bounds its step by "
                         "(g - p) / (dp/dt); /DT/INTER/CST or /DT/INTER/DEL bound it)",
                         when, e.value, describe(e.control, m), e.second_value);
    case K::Rebalanced:
      return fmt::format("{} DOMAINS REPARTITIONED: estimated imbalance {:.3f} -> {:.3f} (flowing plastic points weigh "
                         "more; the results do not depend on the partition)",
                         when, e.value, e.second_value);
  }
  return when;
}

RunRecorder::RunRecorder(const Model& model, const std::filesystem::path& directory, const std::string& name,
                         bool write_results, RunStart run, std::ostream* console)
    : model_(model), directory_(directory), name_(name), console_(console), run_(std::move(run)),
      listing_(directory / (name + ".out"), run_.continue_from.has_value()), channels_(model),
      progress_clock_(run_.progress) {
  if (write_results) results_.emplace(directory / (name + ".h5"), model, channels_.datasets(), run_.continue_from);
  if (run_.continue_from)
    listing_.line(fmt::format("RESUMED at t = {:.6g}: the results of the run before continue above and in {}.h5",
                              *run_.continue_from, name));
}

void RunRecorder::start(const SolverState& s, const std::vector<std::string>& notes) {
  if (engine_decks_ == 0) header(run_);
  ++engine_decks_;
  listing_.line(fmt::format("ENGINE DECK {}: end time {:g}", engine_decks_, model_.run.end_time));
  for (const auto& note : notes) listing_.line("NOTE: " + note);
  for (const auto& note : notes) console_line("note: " + note);
  listing_.table_header();
  last_row_cycle_ = -1;
  row(s, s.dt, StepControl{});
  deck_start_time_ = s.time;
  deck_start_wall_ = progress_clock_.elapsed_seconds();
}

void RunRecorder::header(const RunStart& run) {
  const Model& m = model_;
  const auto count = [&m](ElementKind k) { return m.elements[static_cast<int>(k)].size(); };
  listing_.line(fmt::format("Crumple {} ({}) explicit run {}  ({})", build::version(), build::commit(), name_, m.title));
  listing_.line(fmt::format("STARTED {:%Y-%m-%d %H:%M:%S}", fmt::localtime(std::time(nullptr))));
  if (!run.deck.empty()) listing_.line("DECK " + run.deck.string());
  listing_.line(fmt::format("WORKING UNITS (SI size of one unit): mass {:g} kg  length {:g} m  time {:g} s",
                            m.units.work[0], m.units.work[1], m.units.work[2]));
  // The names of the units every number of this listing is in (times, energies, masses, forces).
  listing_.line("UNITS " + describe(unit_names(m.units.work)));
  std::string kinds;
  for (const ElementKindDescription& kind : kElementKindTable)
    kinds += fmt::format("  {} {}", kind.counted, count(kind.kind));
  listing_.line(fmt::format("nodes {}{}  element groups {}  parts {}  interfaces {}  rigid bodies {}  rigid walls {}",
                            m.nodes.size(), kinds, m.element_groups.size(), m.parts.size(), m.type7_interfaces.size(),
                            m.rigid_bodies.size(), m.rigid_walls.size()));
  // Two masses apart: the deck's point masses are in TOTAL MASS from the start; MASS ADDED is what step control adds.
  listing_.line(fmt::format("POINT MASSES (/ADMAS, /RBODY MASS) {:.6g}, in TOTAL MASS; MASS ADDED: the mass added by "
                            "mass scaling (/DT/NODA/CST, /DT/INTER/CST) and spot-weld ties during the run",
                            m.added_mass));
  listing_.line("ACCURACY PRESET " + run.accuracy);
  listing_.line(std::string("PRECISION ") + kPrecision);
  if (!run.approximations.empty()) listing_.line("OPTIONS SKIPPED OR APPROXIMATED:");
  for (const auto& option : run.approximations) listing_.line("  " + option);
}

void RunRecorder::row(const SolverState& s, double dt, const StepControl& control) {
  if (s.cycle == last_row_cycle_) return;
  last_row_cycle_ = s.cycle;
  const EnergyBalanceState& e = s.energy;
  const double mass = total_mass(s);
  listing_.row({s.cycle, s.time, dt, describe(control, model_), e.error_percent(), e.internal,
                e.kinetic_translational, e.kinetic_rotational, e.external_work, e.hourglass, e.contact,
                s.mass_initial > 0.0 ? (mass - s.mass_initial) / s.mass_initial : 0.0, mass, s.mass_added});
}

std::string preset_knobs_to_loosen(const RunStart& run) {
  const std::string prefix = "--accuracy " + run.accuracy + ": ";
  std::vector<std::string> knobs;
  for (const std::string& a : run.approximations)
    if (a.starts_with(prefix)) knobs.push_back(a.substr(prefix.size()));
  if (knobs.empty()) return {};
  return fmt::format("; under --accuracy {} loosen the knob{} it moved ({}), or run --accuracy standard", run.accuracy,
                     knobs.size() > 1 ? "s" : "", fmt::join(knobs, "; "));
}

void RunRecorder::events(RunEvents& events) {
  for (const RunEvent& e : events.pending) {
    std::string text = describe(e, model_);
    if (e.kind == RunEvent::Kind::EnergyErrorLarge) text += preset_knobs_to_loosen(run_);
    listing_.line(text);
    if (e.kind == RunEvent::Kind::HourglassShare || e.kind == RunEvent::Kind::EnergyErrorLarge ||
        e.kind == RunEvent::Kind::ShellDeletedInverted || e.kind == RunEvent::Kind::StepDropped)
      console_line("warning: " + text);
  }
  events.pending.clear();
}

void RunRecorder::restart(SolverState& s, ResumeMarks& marks) {
  write_restart(restart_file(), model_, s, marks);
  listing_.line(fmt::format("CYCLE {} TIME {:.4e}: RESTART FILE {} WRITTEN", s.cycle, s.time,
                            restart_file().filename().string()));
}

void RunRecorder::progress(const SolverState& s, double dt, const StepControl& control) {
  if (console_ == nullptr) return;
  ProgressValues v;
  v.cycle = s.cycle, v.time = s.time, v.end_time = model_.run.end_time, v.dt = dt;
  v.control = describe(control, model_);
  v.error_percent = s.energy.error_percent();
  v.elapsed_seconds = progress_clock_.elapsed_seconds();
  v.remaining_seconds = remaining_seconds(deck_start_time_, s.time, v.end_time, v.elapsed_seconds - deck_start_wall_);
  std::string text = progress_line(v);
  if (run_.progress.mode == ProgressOptions::Mode::Lines) {
    fmt::print(*console_, "{}\n", text);
  } else {
    if (const int width = run_.progress.width; width > 1 && text.size() >= static_cast<std::size_t>(width))
      text.resize(static_cast<std::size_t>(width - 1));  // one row: a wrapped line would not be rewritten in place
    fmt::print(*console_, "\r{}\x1b[K", text);
    progress_shown_ = true;
  }
  console_->flush();
}

// A state is written once: a continued run's first frame may be the last one of the run before it.
void RunRecorder::frame(const SolverState& s) {
  const long long cycle = s.cycles_done + s.cycle;
  if (!results_ || cycle == last_frame_cycle_) return;
  const std::size_t before = results_->frames();
  results_->write_frame(s.time, s.cycle, model_, s);
  last_frame_cycle_ = cycle;
  if (results_->frames() > before)  // a continued file does not take a frame it holds already
    listing_.line(fmt::format("CYCLE {} TIME {:.4e}: FRAME {:04} WRITTEN TO {}.h5", s.cycle, s.time, before, name_));
}

// The parts at the end of the run, as /TH/PART gives them, in the deck's units. Each line starts with PART, so
// that no reader of the listing takes it for a row of the energy table.
void RunRecorder::part_table(const std::vector<PartResult>& parts) {
  const UnitNames units = unit_names(model_.units.work);
  listing_.line(fmt::format("PARTS AT THE END (mass {}, energies {}):", units.mass, units.energy));
  for (const PartResult& p : parts)
    listing_.line(fmt::format("PART {:<10} MASS {:.5e}  INTERNAL {:.5e}  KINETIC {:.5e}  HOURGLASS {:.5e}  {}", p.id,
                              p.mass, p.internal, p.kinetic, p.hourglass, p.title));
}

void RunRecorder::console_line(const std::string& text) {
  if (console_ == nullptr) return;
  clear_progress();
  fmt::print(*console_, "{}\n", text);
}

void RunRecorder::clear_progress() {
  if (!progress_shown_) return;
  fmt::print(*console_, "\r\x1b[K");
  console_->flush();
  progress_shown_ = false;
}

void RunRecorder::history(const SolverState& s, double dt, const VelocityChange& change) {
  if (!results_) return;
  const NodalState& n = s.nodes;
  HistoryRow row;
  row.time = s.time, row.dt = dt;
  row.internal = s.energy.internal, row.kinetic_translational = s.energy.kinetic_translational;
  row.kinetic_rotational = s.energy.kinetic_rotational, row.hourglass = s.energy.hourglass;
  row.contact = s.energy.contact, row.external_work = s.energy.external_work;
  row.total = row.internal + row.kinetic_translational + row.kinetic_rotational + row.hourglass + row.contact;
  for (const auto& w : s.walls) row.rigid_wall_force.insert(row.rigid_wall_force.end(), {w.force.x, w.force.y, w.force.z});
  for (const auto& b : s.bodies) {
    const auto k = static_cast<std::size_t>(b.main_node);
    for (double v : {n.x[k], n.y[k], n.z[k], n.vx[k], n.vy[k], n.vz[k], b.omega[0], b.omega[1], b.omega[2]})
      row.rigid_body_values.push_back(v);
  }
  for (const InterfaceResult& r : s.contact.results) {
    const Vec3 &fn = r.normal_force, &ft = r.tangential_force;
    row.interface_values.insert(row.interface_values.end(), {fn.x, fn.y, fn.z, ft.x, ft.y, ft.z});
    for (double v : {r.elastic_energy, r.friction_work, r.absorbed, static_cast<double>(r.active_nodes)})
      row.interface_values.push_back(v);
  }
  channels_.evaluate(s, change, row.th);
  results_->write_history(row);
}

void RunRecorder::close(const SolverState& s, bool stopped_early) {
  if (!results_) return;
  if (stopped_early) frame(s);  // the last good state (once: frame() skips a cycle written already)
  else if (results_->frames() > 0 || (model_.run.anim_interval > 0.0 && s.time >= model_.run.anim_start))
    frame(s);  // the end time, also when it is not on the /ANIM/DT grid (or a resumed run met none of it)
  results_->close();
}

RunSummary RunRecorder::finish(const SolverState& s, const RunEvents& events, const PhaseTimes& phases, double dt,
                               double wall) {
  clear_progress();
  listing_.line(termination(events.stop, model_));
  if (events.deleted_below_minimum_step > 0)
    listing_.line(fmt::format("ELEMENTS DELETED BELOW THEIR MINIMUM TIME STEP: {}", events.deleted_below_minimum_step));
  if (events.deleted_inverted > 0)
    listing_.line(fmt::format("SHELLS DELETED AS TURNED INSIDE OUT: {}", events.deleted_inverted));
  if (events.hourglass_warned)
    listing_.line(fmt::format("HOURGLASS ENERGY AT THE END {:.6g}: {:.1f} % OF THE INTERNAL ENERGY {:.6g}{}", s.energy.hourglass,
                              s.energy.internal != 0.0 ? 100.0 * s.energy.hourglass / std::abs(s.energy.internal) : 0.0,
                              s.energy.internal, s.energy.hourglass > 0.1 * std::abs(s.energy.internal) ? " (WARNING: above 10 %)" : ""));
  if (s.mass_added > 0.0) listing_.line(fmt::format("MASS ADDED BY /DT/NODA/CST, /DT/INTER/CST OR SPOT-WELD TIES (/INTER/TYPE2 SPOTFLAG 1): {:.6g}", s.mass_added));
  if (const SelectiveMassState& sm = s.selective_mass; sm.solves > 0)
    listing_.line(fmt::format("SELECTIVE MASS SCALING (/DT/AMS): {} SOLVES, {:.1f} ITERATIONS EACH ON AVERAGE, AT MOST {}",
                              sm.solves, static_cast<double>(sm.iterations) / static_cast<double>(sm.solves),
                              sm.max_iterations));
  for (std::size_t f = 0; f < s.contact.results.size(); ++f) {
    const InterfaceResult& r = s.contact.results[f];
    listing_.line(fmt::format("INTER {}: largest p/g {:.4f}, absorbed energy {:.6g} (elastic now {:.6g}, damping "
                              "{:.6g}, friction {:.6g}), contacts released below dtmin {}, mass added {:.6g} (its kinetic energy {:.6g})",
                              model_.type7_interfaces[f].user_id, r.max_penetration_ratio, r.absorbed,
                              r.elastic_energy, r.damping_work, r.friction_work, r.released, r.added_mass,
                              r.added_mass_energy));
  }
  const std::vector<PartResult> parts = channels_.part_results(s);
  part_table(parts);
  listing_.line(fmt::format("TOTAL NUMBER OF CYCLES {}   ELAPSED {:.3f} s", s.cycle, wall));
  const double cycle_time = phases.elements + phases.contact + phases.loads + phases.update + phases.output;
  auto share = [&](double t) { return cycle_time > 0.0 ? 100.0 * t / cycle_time : 0.0; };
  listing_.line(fmt::format("TIME PROFILE (s, % of the cycles): elements {:.3f} ({:.1f} %)  contact {:.3f} ({:.1f} %, "
                            "{} passes; searches {:.3f}, {} sorts)  loads and step {:.3f} ({:.1f} %)  nodal update "
                            "{:.3f} ({:.1f} %)  output {:.3f} ({:.1f} %)",
                            phases.elements, share(phases.elements), phases.contact, share(phases.contact),
                            phases.contact_passes, phases.contact_sort, phases.contact_sorts, phases.loads, share(phases.loads), phases.update,
                            share(phases.update), phases.output, share(phases.output)));
  RunSummary summary = summarize_run(model_, name_, s, events, phases, dt, wall);
  summary.approximations = run_.approximations;
  summary.accuracy = run_.accuracy;
  summary.parts = parts;
  return summary;
}

RunSummary summarize_run(const Model& m, const std::string& name, const SolverState& s, const RunEvents& events,
                         const PhaseTimes& phases, double dt, double wall) {
  RunSummary summary;
  summary.name = name;
  summary.crumple_version = build::version();
  summary.commit = build::commit();
  summary.precision = kPrecision;
  summary.deleted_elements = 0;
  for (ElementKind kind : kAllElementKinds) summary.deleted_elements += deleted_count(element_state(s, kind).deleted);
  summary.phases = phases;
  summary.cycles = s.cycle;
  summary.cycles_total = s.cycles_done + s.cycle;
  summary.time = s.time;
  summary.dt = dt;
  const EnergyBalanceState& e = s.energy;
  summary.energy.internal = e.internal;
  summary.energy.kinetic_translational = e.kinetic_translational;
  summary.energy.kinetic_rotational = e.kinetic_rotational;
  summary.energy.contact = e.contact;
  summary.energy.hourglass = e.hourglass;
  summary.energy.external_work = e.external_work;
  summary.energy.total = e.internal + e.kinetic_translational + e.kinetic_rotational + e.hourglass + e.contact;
  summary.energy.error_percent = e.error_percent();
  summary.mass_total = total_mass(s);
  summary.mass_added = s.mass_added;
  summary.selective_solves = s.selective_mass.solves;
  summary.selective_iterations = s.selective_mass.iterations;
  summary.selective_iterations_max = s.selective_mass.max_iterations;
  summary.wall_seconds = wall;
  std::size_t element_count = 0;
  for (const auto& table : m.elements) element_count += table.size();
  summary.element_cycles_per_second =
      wall > 0.0 ? static_cast<double>(element_count) * static_cast<double>(s.cycle) / wall : 0.0;
  summary.status = status_of(events.stop);
  summary.stopped_on_request = events.stop.requested();
  summary.message = describe(events.stop, m);
  return summary;
}

}  // namespace crumple
