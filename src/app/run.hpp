#pragma once
#include <filesystem>
#include <iosfwd>

#include "crumple/deck/reader.hpp"
#include "crumple/output/run_summary.hpp"
#include "crumple/solver/solver.hpp"

namespace crumple::app {

struct RunOptions {
  std::filesystem::path deck;
  std::filesystem::path output_directory = ".";
  bool skip_unknown = false;
  ProgressOptions progress;  // console progress (console.hpp: stdout_progress)
};

// Runs every engine deck of `deck` in order (NAME_0001.rad, then the continued runs NAME_0002.rad...), each from
// the state the one before left, into one listing and one results file; stops at the first that does not end
// normally. `deck.model.run` is the run control of the deck being run while it runs. Returns the last deck's
// summary with the total cycle count.
RunSummary run_engine_decks(Deck& deck, const SolverOptions& options, std::ostream& console);

// `crumple run`: reads the deck and runs it, writing NAME.h5, NAME.out and NAME.summary.json into the output
// directory; SIGINT and SIGTERM stop the run at the end of the cycle, with its files written to there. Returns
// the process exit code (exit_codes.hpp). Deck errors propagate as exceptions.
int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace crumple::app
