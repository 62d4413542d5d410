#pragma once
// The process around a run (README, "Watching and stopping a run"): how the progress is shown on stdout, and
// SIGINT and SIGTERM turned into a request to stop at the end of the cycle.
#include <atomic>
#include <csignal>

#include <filesystem>
#include <iosfwd>
#include <vector>

#include "crumple/core/deck_error.hpp"
#include "crumple/output/progress.hpp"

namespace crumple::app {

// Progress on stdout: rewritten in place once a second on a terminal, a plain line every 5 s otherwise (a log
// file, a pipe, a batch job); off with --quiet.
ProgressOptions stdout_progress(bool quiet);

// The deck's warnings on the console, each once: the same message on several cards of one keyword (the same
// option on /PROP/SHELL/1, 2 and 3) is one line naming the others and their count; files under the starter deck's
// folder (`deck`) are named relative to it. The listing and the summary keep every warning as read.
void print_warnings(const std::vector<DeckWarning>& warnings, const std::filesystem::path& deck, std::ostream& out);

// While it lives, SIGINT and SIGTERM set request() to the signal's number instead of ending the process. The
// handlers are installed once (SA_RESETHAND): a second signal of the same kind ends the process at once, the
// default action. A signal the process started with ignored stays ignored. The destructor puts the previous
// handlers back. One at a time.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
  const std::atomic<int>& request() const;

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

}  // namespace crumple::app
