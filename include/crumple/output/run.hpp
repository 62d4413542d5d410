#pragma once
// A whole run of one engine deck with its files written (docs/theory/time-loop.md): the solver's time loop with a
// RunRecorder as its observer. The app runs continued decks and restarts the same way (app/run.cpp).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/progress.hpp"
#include "crumple/solver/solver.hpp"

namespace crumple {

// The solver's options and what the run's files need.
struct SimulationOptions : SolverOptions {
  std::string name;                          // run name: output files are NAME.out, NAME.h5, NAME.summary.json
  std::filesystem::path output_directory = ".";
  bool write_results = true;                 // NAME.h5 (field frames and histories)
  // A resumed run replaces the folder's NAME.h5 and NAME.out instead of continuing them (--overwrite).
  bool overwrite_results = false;
  // Every option of the deck that was skipped or approximated (DeckReport::skipped_options, one line each:
  // "[skipped] file:line: keyword: field F: what"), for the listing header and the summary. Filled by the app.
  std::vector<std::string> approximations;
  std::string accuracy = "standard";  // the --accuracy preset (its changes are among the approximations)
  std::filesystem::path deck;  // the starter deck, named in the listing header (empty: not named)
  ProgressOptions progress;    // the console progress line (off unless the app turns it on)
  std::vector<std::string> notes;  // the caller's start-up notes for the listing (a partition's quality)
};

// Runs the model from its initial state to its end time and writes the listing and results into
// options.output_directory (notes, warnings and progress to `console`). Returns the summary (solver.hpp,
// run_engine_deck, for the statuses).
RunSummary run_simulation(const Model& model, const SimulationOptions& options, std::ostream& console);

}  // namespace crumple
