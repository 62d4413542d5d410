#include "app/run.hpp"

#include <fmt/ostream.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>

#include "app/accuracy.hpp"
#include "app/console.hpp"
#include "app/exit_codes.hpp"
#include "crumple/output/restart_file.hpp"
#include "crumple/parallel/mpi_exchange.hpp"
#include "crumple/parallel/partition.hpp"
#include "crumple/output/run_recorder.hpp"
#include "crumple/solver/quiet_observer.hpp"
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
                            const std::filesystem::path& restart, const Domain* domain) {
  Model& m = deck.model;
  const RunControl first = m.run;
  std::vector<RunControl> controls{first};
  controls.insert(controls.end(), deck.continued_runs.begin(), deck.continued_runs.end());
  std::vector<std::string> notes;
  SolverState state = domain != nullptr ? initial_state(m, notes, *domain) : initial_state(m, notes);
  notes.insert(notes.end(), options.notes.begin(), options.notes.end());
  std::optional<ResumeMarks> marks;
  if (!restart.empty()) {
    marks = read_restart(restart, m, state);
    mark_domain(state);  // the restart holds the elements' conditions; this domain computes its own
    if (marks->engine_deck < 1 || marks->engine_deck > static_cast<int>(controls.size()))
      throw RestartError(fmt::format("restart file {} was written in engine deck {}; this deck has {}",
                                     restart.string(), marks->engine_deck, controls.size()));
    notes.push_back(fmt::format("resumed from {} at cycle {}, time {:.6g} (engine deck {})", restart.string(),
                                state.cycle, state.time, marks->engine_deck));
  }
  const int start = marks ? marks->engine_deck : 1;
  // Domain 0 writes the run (or the only domain); the others report to no one.
  std::optional<RunRecorder> recorder;
  QuietObserver quiet;
  if (domain == nullptr || domain->index == 0) {
    RunStart run{options.deck, options.approximations, options.progress, options.accuracy, std::nullopt};
    if (marks && !options.overwrite_results) run.continue_from = state.time;
    recorder.emplace(m, options.output_directory, options.name.empty() ? m.run_name : options.name,
                     options.write_results, std::move(run), &console);
  }
  RunObserver& observer = recorder ? static_cast<RunObserver&>(*recorder) : quiet;
  RunSummary summary;
  for (int k = start; k <= static_cast<int>(controls.size()); ++k) {
    m.run = controls[static_cast<std::size_t>(k - 1)];
    SolverOptions engine = options;  // the solver's part
    engine.engine_deck = k;
    engine.resume = k == start && marks ? &*marks : nullptr;
    if (k > start) continue_from(state);
    const int decks_before = k > start ? summary.engine_decks : 0;
    summary = run_engine_deck(m, engine, observer, state, k == start ? notes : std::vector<std::string>{});
    summary.engine_decks = decks_before + 1;
    if (summary.status != RunStatus::Normal) break;
  }
  m.run = first;
  if (recorder) recorder->close(state, summary.status != RunStatus::Normal);
  return summary;
}

int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) > 1) return std::atoi(value);
  }
  return 1;
}

namespace {

// What a run of several domains adds to a run (docs/parallel.md): the MPI session, this rank's domain and its
// exchange. Absent for a run of one process.
struct Ranks {
  MpiSession& mpi;
  const Domain& domain;
  Exchange& exchange;
};

// Reads, runs and writes the deck; with `ranks`, this rank's domain of it (rank 0 writes, the others only compute).
int run_deck_as(const RunOptions& options, Deck& deck, std::ostream& out, std::ostream& err, Ranks* ranks,
                const std::vector<std::string>& notes, const std::vector<std::string>& preset_changes) {
  const bool writer = ranks == nullptr || ranks->mpi.rank() == 0;
  std::string problem = writer ? output_directory_problem(options.output_directory) : std::string();
  if (ranks != nullptr && MpiSession::any(!problem.empty()) && problem.empty()) return kExitBadInput;  // rank 0 says why
  if (!problem.empty()) {
    fmt::print(err, "crumple: {}\n", problem);
    return kExitBadInput;
  }
  const std::string started = utc_now_iso8601();
  SimulationOptions solver;
  solver.name = deck.model.run.run_name.empty() ? deck.model.run_name : deck.model.run.run_name;
  solver.output_directory = options.output_directory;
  for (const SkippedOption& o : deck.report.skipped_options) solver.approximations.push_back(o.text());
  solver.approximations.insert(solver.approximations.end(), preset_changes.begin(), preset_changes.end());
  solver.accuracy = accuracy_preset_name(options.accuracy);
  solver.deck = options.deck;
  solver.progress = options.progress;
  solver.notes = notes;
  solver.overwrite_results = options.overwrite;
  const StopOnSignals signals;
  solver.stop_request = &signals.request();
  solver.exchange = ranks != nullptr ? &ranks->exchange : nullptr;
  RunSummary summary = run_engine_decks(deck, solver, out, options.restart, ranks != nullptr ? &ranks->domain : nullptr);
  summary.date = started;
  summary.deck_files = describe_deck_files(deck.report.files);
  summary.ranks = ranks != nullptr ? ranks->mpi.size() : 1;
  if (writer) write_summary(summary, options.output_directory / (solver.name + ".summary.json"));
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

// Reads the deck and applies the --accuracy preset to it; `preset_changes` gets one line per knob it moved, and
// the build's own approximation (the mixed precision).
Deck read_run_deck(const RunOptions& options, std::ostream& err, std::vector<std::string>& preset_changes) {
  ReadOptions read;
  read.skip_unknown = options.skip_unknown;
  read.require_engine = true;
  Deck deck = read_deck(options.deck, read);
  print_warnings(deck.report.warnings, options.deck, err);
  std::vector<RunControl*> runs{&deck.model.run};
  for (RunControl& r : deck.continued_runs) runs.push_back(&r);
  preset_changes = apply_accuracy_preset(options.accuracy, deck.model, runs);
  for (const std::string& p : precision_approximations()) preset_changes.push_back(p);
  for (const auto& c : preset_changes) fmt::print(err, "note: {}\n", c);
  return deck;
}

// mpirun -np N crumple run DECK: every rank reads the deck and partitions it the same way; rank 0 alone speaks
// and writes. A deck error or a partition that cannot be made is the same on every rank: rank 0 reports it and
// every rank returns. An error one rank meets during the run ends every rank at once with that rank's message.
int run_deck_on_ranks(const RunOptions& options, std::ostream& out, std::ostream& err) {
  MpiSession mpi;
  std::ostringstream silent;
  std::ostream& console = mpi.rank() == 0 ? out : silent;
  std::ostream& errors = mpi.rank() == 0 ? err : silent;
  Deck deck;
  Partition partition;
  std::vector<std::string> preset_changes;
  try {
    deck = read_run_deck(options, errors, preset_changes);
    partition = partition_model(deck.model, mpi.size());
  } catch (const std::runtime_error& e) {
    if (mpi.rank() != 0) return kExitBadInput;
    if (dynamic_cast<const DeckErrors*>(&e) != nullptr || dynamic_cast<const DeckError*>(&e) != nullptr) throw;
    fmt::print(err, "crumple: {}\n", e.what());  // the partition: more ranks than elements...
    return kExitBadInput;
  }
  const Domain domain = make_domain(deck.model, partition, mpi.rank());
  MpiExchange exchange;
  Ranks ranks{mpi, domain, exchange};
  try {
    return run_deck_as(options, deck, console, errors, &ranks, describe(partition), preset_changes);
  } catch (const std::exception& e) {
    fmt::print(err, "crumple: rank {} of {}: {}\n", mpi.rank(), mpi.size(), e.what());
    err.flush();
    // A restart file or results folder that does not fit the run is bad input, as on one process.
    MpiSession::abort(dynamic_cast<const RestartError*>(&e) != nullptr ? kExitBadInput : kExitInternal);
  }
}

}  // namespace

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err) {
  if (launched_ranks() > 1) return run_deck_on_ranks(options, out, err);
  std::vector<std::string> preset_changes;
  Deck deck = read_run_deck(options, err, preset_changes);
  return run_deck_as(options, deck, out, err, nullptr, {}, preset_changes);
}

}  // namespace crumple::app
