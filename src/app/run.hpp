#pragma once
#include <filesystem>
#include <iosfwd>

#include "app/accuracy.hpp"
#include "crumple/deck/reader.hpp"
#include "crumple/output/run.hpp"
#include "crumple/output/run_summary.hpp"

namespace crumple::app {

struct RunOptions {
  std::filesystem::path deck;
  std::filesystem::path output_directory = ".";
  bool skip_unknown = false;
  std::filesystem::path restart;  // --restart FILE: resume the snapshot of a NAME.rst (empty: start at t = 0)
  bool overwrite = false;         // --overwrite: a resumed run replaces the folder's results, not continues them
  ProgressOptions progress;  // console progress (console.hpp: stdout_progress)
  AccuracyPreset accuracy = AccuracyPreset::Standard;  // --accuracy (accuracy.hpp)
};

// Runs every engine deck of `deck` in order (NAME_0001.rad, then the continued runs NAME_0002.rad...), each from
// the state the one before left, into one listing and one results file; stops at the first that does not end
// normally. `deck.model.run` is the run control of the deck being run while it runs. Returns the last deck's
// summary with the total cycle count. With `restart`, the state and the engine deck to resume come from that
// restart file (docs/theory/time-loop.md, "Restart"); throws RestartError when it does not fit the deck.
// In a run of several domains, `domain` is this one (options.exchange talks to the others): domain 0 writes the
// listing and the results, the others nothing.
RunSummary run_engine_decks(Deck& deck, const SimulationOptions& options, std::ostream& console,
                            const std::filesystem::path& restart = {}, const Domain* domain = nullptr);

// `crumple run`: reads the deck and runs it, writing NAME.h5, NAME.out and NAME.summary.json into the output
// directory; SIGINT and SIGTERM stop the run at the end of the cycle, with its files written to there. Returns
// the process exit code (exit_codes.hpp). Deck errors propagate as exceptions.
int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err);

// How many MPI ranks the launcher started (1 without mpirun), from the environment Open MPI and MPICH set.
int launched_ranks();

// Why a run could not write its results into `dir` (empty when it can), with the system's reason.
std::string output_directory_problem(const std::filesystem::path& dir);

}  // namespace crumple::app
