#pragma once
// What a run writes while it goes (docs/output-format.md): the listing NAME.out with its energy table and the
// run's events as text, the field frames and histories of NAME.h5, and the run summary at the end.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/listing.hpp"
#include "crumple/output/results_file.hpp"
#include "crumple/output/run_summary.hpp"
#include "crumple/solver/run_events.hpp"
#include "crumple/solver/snapshot.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// Listing text of what bounds the step: "SHELL 61", "INTER 2 NODE 17", "NODE 5", "LAST STEP", "-".
std::string describe(const StepControl& control, const Model& model);
// The message of a stopped run, naming the element, node or limit.
std::string describe(const StopReason& stop, const Model& model);
// The listing line of an event.
std::string describe(const RunEvent& event, const Model& model);
// The status a stop reason gives the run.
RunStatus status_of(const StopReason& stop);

class RunRecorder {
 public:
  // Opens NAME.out and, when `write_results`, NAME.h5 in `directory`. Throws std::runtime_error.
  RunRecorder(const Model& model, const std::filesystem::path& directory, const std::string& name,
              bool write_results);

  // Listing header, the start-up notes (also on the console) and the options the deck reader skipped or
  // approximated (--skip-unknown, output-only and performance-hint cards).
  void start(const std::vector<std::string>& notes, const std::vector<std::string>& approximations,
             std::ostream& console);
  // One row of the energy table with the step dt^(n+1/2) of the cycle and what bounds it.
  void row(const SolverState& state, double dt, const StepControl& control);
  // The events of the last cycles as listing lines (warnings also on the console); empties `events.pending`.
  void events(RunEvents& events);
  // A field frame of the state, unless the frame of that cycle is written already.
  void frame(const SolverState& state);
  void history(const SolverState& state, double dt);
  // The end of an engine deck: the listing's closing lines (termination, deletions, added mass, interfaces,
  // cycles, time profile).
  void finish(const SolverState& state, const RunEvents& events, const PhaseTimes& phases, double wall_seconds);
  // The snapshot to NAME.rst.h5 beside the listing (restart_file.hpp), with a listing line.
  void restart(SolverState& state, ResumeMarks& marks);
  std::filesystem::path restart_file() const { return directory_ / (name_ + ".rst.h5"); }
  // The end of the whole run: the last state as a frame (the last good one when it stopped early; at the end time
  // when frames were written and the last was earlier), the results file closed.
  void close(const SolverState& state, bool stopped_early);
  const std::string& name() const { return name_; }

 private:
  const Model& model_;
  std::filesystem::path directory_;
  std::string name_;
  std::ostream* console_ = nullptr;
  Listing listing_;
  std::optional<ResultsFile> results_;
  long long last_frame_cycle_ = -1;  // cycles_done + cycle of the last frame()
};

// The run summary of a finished run (README, "Run summary").
RunSummary summarize_run(const Model& model, const std::string& name, const SolverState& state,
                         const RunEvents& events, const PhaseTimes& phases, double dt, double wall_seconds);

}  // namespace crumple
