#include "app/run.hpp"

#include <fmt/ostream.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "app/console.hpp"
#include "app/exit_codes.hpp"
#include "crumple/output/restart_file.hpp"
#include "crumple/output/run_recorder.hpp"
#include "crumple/solver/solver.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple::app {

// Why the run could not write its files into `dir` (empty when it can): the directory is created if needed and a
// file is created and removed in it, so that a read-only or full directory is refused before any cycle, with the
// system's reason, rather than failing at the first listing line.
std::string output_directory_problem(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fmt::format("cannot create the output directory {}: {}", dir.string(), ec.message());
  const std::filesystem::path probe = dir / fmt::format(".crumple-write-test-{}", ::getpid());
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (f == nullptr) return fmt::format("cannot write into the output directory {}: {}", dir.string(), std::strerror(errno));
  std::fclose(f);
  std::filesystem::remove(probe, ec);
  return {};
}

RunSummary run_engine_decks(Deck& deck, const SimulationOptions& options, std::ostream& console,
                            const std::filesystem::path& restart) {
  Model& m = deck.model;
  const RunControl first = m.run;
  std::vector<RunControl> controls{first};
  controls.insert(controls.end(), deck.continued_runs.begin(), deck.continued_runs.end());
  std::vector<std::string> notes;
  SolverState state = initial_state(m, notes);
  std::optional<ResumeMarks> marks;
  if (!restart.empty()) {
    marks = read_restart(restart, m, state);
    if (marks->engine_deck < 1 || marks->engine_deck > static_cast<int>(controls.size()))
      throw RestartError(fmt::format("restart file {} was written in engine deck {}; this deck has {}",
                                     restart.string(), marks->engine_deck, controls.size()));
    notes.push_back(fmt::format("resumed from {} at cycle {}, time {:.6g} (engine deck {})", restart.string(),
                                state.cycle, state.time, marks->engine_deck));
  }
  const int start = marks ? marks->engine_deck : 1;
  RunRecorder recorder(m, options.output_directory, options.name.empty() ? m.run_name : options.name,
                       options.write_results, {options.deck, options.approximations, options.progress}, &console);
  RunSummary summary;
  for (int k = start; k <= static_cast<int>(controls.size()); ++k) {
    m.run = controls[static_cast<std::size_t>(k - 1)];
    SolverOptions engine = options;  // the solver's part
    engine.engine_deck = k;
    engine.resume = k == start && marks ? &*marks : nullptr;
    if (k > start) continue_from(state);
    const int decks_before = k > start ? summary.engine_decks : 0;
    summary = run_engine_deck(m, engine, recorder, state, k == start ? notes : std::vector<std::string>{});
    summary.engine_decks = decks_before + 1;
    if (summary.status != RunStatus::Normal) break;
  }
  m.run = first;
  recorder.close(state, summary.status != RunStatus::Normal);
  return summary;
}

int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) > 1) return std::atoi(value);
  }
  return 1;
}

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err) {
  if (const int ranks = launched_ranks(); ranks > 1) {
    // Each rank would run the whole model and they would race on the same files.
    fmt::print(err, "crumple: started as {} MPI ranks (mpirun -np {}): parallel runs are not supported by Crumple "
                    "yet; run it as one process (the result does not depend on it)\n", ranks, ranks);
    return kExitBadInput;
  }
  ReadOptions read;
  read.skip_unknown = options.skip_unknown;
  read.require_engine = true;
  Deck deck = read_deck(options.deck, read);
  for (const auto& w : deck.report.warnings) fmt::print(err, "warning: {}\n", w.text());

  if (const std::string problem = output_directory_problem(options.output_directory); !problem.empty()) {
    fmt::print(err, "crumple: {}\n", problem);
    return kExitBadInput;
  }
  const std::string started = utc_now_iso8601();
  SimulationOptions solver;
  solver.name = deck.model.run.run_name.empty() ? deck.model.run_name : deck.model.run.run_name;
  solver.output_directory = options.output_directory;
  for (const SkippedOption& o : deck.report.skipped_options) solver.approximations.push_back(o.text());
  solver.deck = options.deck;
  solver.progress = options.progress;
  const StopOnSignals signals;
  solver.stop_request = &signals.request();
  RunSummary summary = run_engine_decks(deck, solver, out, options.restart);
  summary.date = started;
  summary.deck_files = describe_deck_files(deck.report.files);
  write_summary(summary, options.output_directory / (solver.name + ".summary.json"));
  fmt::print(out, "crumple run {}: {} after {} cycles, time {:.6g}, energy error {:.3g} %, {:.2f} s\n", solver.name,
             status_name(summary.status), summary.cycles, summary.time, summary.energy.error_percent,
             summary.wall_seconds);
  if (summary.stopped_on_request) {
    fmt::print(err, "crumple: {}; the listing, the results and the summary end there\n", summary.message);
    return kExitStopped;
  }
  if (summary.status != RunStatus::Normal) {
    fmt::print(err, "crumple: run ended abnormally: {}\n", summary.message);
    return kExitRunFailed;
  }
  return kExitNormal;
}

}  // namespace crumple::app
