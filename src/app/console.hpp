#pragma once
// The process around a run (README, "Watching and stopping a run"): how the progress is shown on stdout, and
// SIGINT and SIGTERM turned into a request to stop at the end of the cycle.
#include <atomic>
#include <csignal>

#include "crumple/output/progress.hpp"

namespace crumple::app {

// Progress on stdout: rewritten in place once a second on a terminal, a plain line every 5 s otherwise (a log
// file, a pipe, a batch job); off with --quiet.
ProgressOptions stdout_progress(bool quiet);

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
