#pragma once
// The explicit time loop (docs/theory/time-loop.md): central difference with velocities at half steps.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/run_summary.hpp"

namespace crumple {

struct SolverState;  // crumple/solver/solver_state.hpp

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
};

// Runs the model to its end time and writes the listing and results. Returns the summary; a run that ends
// abnormally (NaN, inverted element, time step below the minimum, /STOP limit) returns status error or stopped
// with the reason in `message`, after writing the last good state.
RunSummary run_simulation(const Model& model, const SolverOptions& options, std::ostream& console);

}  // namespace crumple
