#pragma once
// The explicit time loop (docs/theory/time-loop.md): central difference with velocities at half steps.
#include <atomic>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/progress.hpp"
#include "crumple/output/run_summary.hpp"

namespace crumple {

struct SolverState;  // crumple/solver/solver_state.hpp
struct ResumeMarks;  // crumple/solver/snapshot.hpp
class RunRecorder;   // crumple/output/run_recorder.hpp

struct SolverOptions {
  std::string name;                          // run name: output files are NAME.out, NAME.h5, NAME.summary.json
  std::filesystem::path output_directory = ".";
  bool write_results = true;                 // NAME.h5 (field frames and histories)
  long long max_cycles = -1;                 // stop after this many cycles (tests); -1: no limit
  // Optional: called with the whole state at every time-history output time (/TFILE interval), after the
  // energies are updated; for tests and tools that read the state. It must not keep references past the call.
  std::function<void(const SolverState&)> observer;
  // Every option of the deck that was skipped or approximated (DeckReport::skipped_options, one line each:
  // "[skipped] file:line: keyword: field F: what"), for the listing header. Filled by the app (app/run.cpp).
  std::vector<std::string> approximations;
  // Restart (docs/theory/time-loop.md, "Restart"): the engine deck being run (1 for NAME_0001.rad), and for a run
  // that resumes a restart file the marks read with its state, so that the cycle goes on exactly where it stopped.
  int engine_deck = 1;
  const ResumeMarks* resume = nullptr;
  std::filesystem::path deck;  // the starter deck, named in the listing header (empty: not named)
  ProgressOptions progress;    // the console progress line (off unless the app turns it on)
  // Optional: the run stops at the end of the first cycle that finds it nonzero (status stopped, the last state
  // written); the value is kept as the reason, a signal number. The app points it at its SIGINT and SIGTERM flag.
  const std::atomic<int>* stop_request = nullptr;
};

// Runs the model to its end time and writes the listing and results. Returns the summary; a run that ends
// abnormally (NaN, inverted element, time step below the minimum, /STOP limit, a stop request) returns status
// error or stopped with the reason in `message`, after writing the last good state.
RunSummary run_simulation(const Model& model, const SolverOptions& options, std::ostream& console);

// The state of a model before its first cycle; `notes` receives the start-up remarks for the listing.
SolverState initial_state(const Model& model, std::vector<std::string>& notes);

// One engine deck from `state` (a fresh state, or the state a previous engine deck left: the snapshot a
// continued run carries on) to the end time of `model.run`, written through `recorder`. `state` is left at the
// end of the run. `notes` are the start-up remarks for the listing.
RunSummary run_engine_deck(const Model& model, const SolverOptions& options, RunRecorder& recorder,
                           SolverState& state, const std::vector<std::string>& notes, std::ostream& console);

// Before the next engine deck of a continued run: its cycle count and energy error start again from 0
// (docs/theory/time-loop.md, "Continued runs").
void continue_from(SolverState& state);

}  // namespace crumple
