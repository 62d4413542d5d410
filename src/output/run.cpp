// A whole run of one engine deck with its files written (output/run.hpp).
#include "crumple/output/run.hpp"

#include "crumple/output/run_recorder.hpp"

namespace crumple {

RunSummary run_simulation(const Model& m, const SimulationOptions& options, std::ostream& console) {
  std::vector<std::string> notes;
  SolverState s = initial_state(m, notes);
  RunRecorder recorder(m, options.output_directory, options.name.empty() ? m.run_name : options.name,
                       options.write_results, {options.deck, options.approximations, options.progress, options.accuracy, std::nullopt}, &console);
  RunSummary summary = run_engine_deck(m, options, recorder, s, notes);
  recorder.close(s, summary.status != RunStatus::Normal);
  return summary;
}

}  // namespace crumple
