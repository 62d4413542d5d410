#pragma once
// What a run writes while it goes (docs/output-format.md): the listing NAME.out with its energy table and the
// run's events as text, the field frames and histories of NAME.h5, and the run summary at the end.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/history_channels.hpp"
#include "crumple/output/listing.hpp"
#include "crumple/output/progress.hpp"
#include "crumple/output/results_file.hpp"
#include "crumple/output/run_summary.hpp"
#include "crumple/solver/run_observer.hpp"

namespace crumple {

// Listing text of what bounds the step: "SHELL 61", "INTER 2 NODE 17", "NODE 5", "LAST STEP", "-".
std::string describe(const StepControl& control, const Model& model);
// The message of a stopped run, naming the element, node or limit.
std::string describe(const StopReason& stop, const Model& model);
// The listing line of an event.
std::string describe(const RunEvent& event, const Model& model);

// What the caller says about the run: the listing header and the console progress.
struct RunStart {
  std::filesystem::path deck;  // the starter deck (empty: not named)
  // Options of the deck that were skipped or approximated (--skip-unknown, output-only and performance-hint
  // cards), one line each.
  std::vector<std::string> approximations;
  ProgressOptions progress;
  std::string accuracy = "standard";  // the --accuracy preset, for the listing header and the summary
  // A run resumed from a restart at this time [T]: NAME.out and NAME.h5 of the folder, when there, are continued
  // (appended to), not replaced (docs/output-format.md, "Restart").
  std::optional<double> continue_from;
};

// What the energy warning adds under an --accuracy preset: the knobs it moved (its lines among the
// approximations), to loosen; empty for the deck as written.
std::string preset_knobs_to_loosen(const RunStart& run);

// The run's observer that writes it: NAME.out, NAME.h5, NAME.rst and the console's notes, warnings and progress.
class RunRecorder final : public RunObserver {
 public:
  // Opens NAME.out and, when `write_results`, NAME.h5 in `directory`; notes, warnings and progress go to `console`
  // (none: nullptr). Throws std::runtime_error.
  RunRecorder(const Model& model, const std::filesystem::path& directory, const std::string& name,
              bool write_results, RunStart run = {}, std::ostream* console = nullptr);

  // The start of an engine deck from `state`, its kinetic energy up to date. The first time, the listing's run
  // header: the Crumple version, the date, the deck, the working units, the model's counts and the options the
  // deck reader skipped or approximated. Then for every engine deck its number and end time, its start-up notes
  // (also on the console), the table header and the row of cycle 0.
  void start(const SolverState& state, const std::vector<std::string>& notes) override;
  // One row of the energy table with the step dt^(n+1/2) of the cycle and what bounds it; nothing when the row of
  // this cycle is printed already (the last cycle of a run is often a /PRINT cycle too).
  void row(const SolverState& state, double dt, const StepControl& control) override;
  // The events of the last cycles as listing lines (warnings also on the console); empties `events.pending`.
  void events(RunEvents& events) override;
  // True when a console progress update is due: one clock read, none while progress is off. The caller brings
  // the kinetic energy up to date, then calls progress().
  bool progress_due() override { return progress_clock_.due(); }
  void progress(const SolverState& state, double dt, const StepControl& control) override;
  // A field frame of the state, unless the frame of that cycle is written already.
  void frame(const SolverState& state) override;
  // A history row: the energies, walls, bodies and interfaces, and every /TH dataset; `change` is the cycle's
  // velocity update (accelerations and reactions).
  void history(const SolverState& state, double dt, const VelocityChange& change) override;
  // The end of an engine deck: the listing's closing lines (termination, deletions, added mass, interfaces,
  // cycles, time profile); the progress line is cleared. Returns the engine deck's summary.
  RunSummary finish(const SolverState& state, const RunEvents& events, const PhaseTimes& phases, double dt,
                    double wall_seconds) override;
  // The snapshot to NAME.rst beside the listing (restart_file.hpp), with a listing line.
  void restart(SolverState& state, ResumeMarks& marks) override;
  std::filesystem::path restart_file() const { return directory_ / (name_ + ".rst"); }
  // The end of the whole run: the last good state as a frame when it stopped early (unless that cycle's frame is
  // written already), the results file closed.
  void close(const SolverState& state, bool stopped_early);
  const std::string& name() const { return name_; }

 private:
  void header(const RunStart& run);
  void part_table(const std::vector<PartResult>& parts);
  void console_line(const std::string& text);  // on the console, below the progress line
  void clear_progress();

  const Model& model_;
  std::filesystem::path directory_;
  std::string name_;
  std::ostream* console_ = nullptr;
  RunStart run_;
  Listing listing_;
  HistoryChannels channels_;
  std::optional<ResultsFile> results_;
  int engine_decks_ = 0;              // started so far
  long long last_row_cycle_ = -1;     // the cycle of the engine deck's last row
  long long last_frame_cycle_ = -1;   // the last frame's cycle counted over the whole run (cycles_done + cycle)
  ProgressClock progress_clock_;
  double deck_start_time_ = 0.0;      // simulation time [T] and progress clock [s] when the engine deck started
  double deck_start_wall_ = 0.0;
  bool progress_shown_ = false;       // a Terminal line is on the console
};

// The run summary of a finished run (README, "Run summary").
RunSummary summarize_run(const Model& model, const std::string& name, const SolverState& state,
                         const RunEvents& events, const PhaseTimes& phases, double dt, double wall_seconds);

}  // namespace crumple
