#include "app/run.hpp"

#include <fmt/ostream.h>

#include "app/console.hpp"
#include "app/exit_codes.hpp"
#include "crumple/output/run_recorder.hpp"
#include "crumple/solver/solver.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple::app {

RunSummary run_engine_decks(Deck& deck, const SolverOptions& options, std::ostream& console) {
  Model& m = deck.model;
  const RunControl first = m.run;
  std::vector<std::string> notes;
  SolverState state = initial_state(m, notes);
  RunRecorder recorder(m, options.output_directory, options.name.empty() ? m.run_name : options.name,
                       options.write_results);
  RunSummary summary = run_engine_deck(m, options, recorder, state, notes, console);
  for (const RunControl& next : deck.continued_runs) {
    if (summary.status != RunStatus::Normal) break;
    m.run = next;
    continue_from(state);
    summary = run_engine_deck(m, options, recorder, state, {}, console);
    ++summary.engine_decks;
  }
  m.run = first;
  recorder.close(state, summary.status != RunStatus::Normal);
  return summary;
}

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err) {
  ReadOptions read;
  read.skip_unknown = options.skip_unknown;
  read.require_engine = true;
  Deck deck = read_deck(options.deck, read);
  for (const auto& w : deck.report.warnings) fmt::print(err, "warning: {}\n", w.text());

  std::error_code ec;
  std::filesystem::create_directories(options.output_directory, ec);
  if (ec) {
    fmt::print(err, "crumple: cannot create the output directory {}: {}\n", options.output_directory.string(),
               ec.message());
    return kExitBadInput;
  }
  SolverOptions solver;
  solver.name = deck.model.run.run_name.empty() ? deck.model.run_name : deck.model.run.run_name;
  solver.output_directory = options.output_directory;
  for (const SkippedOption& o : deck.report.skipped_options) solver.approximations.push_back(o.text());
  solver.deck = options.deck;
  solver.progress = options.progress;
  const StopOnSignals signals;
  solver.stop_request = &signals.request();
  const RunSummary summary = run_engine_decks(deck, solver, out);
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
