#include "app/console.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <utility>

namespace crumple::app {
namespace {

// A signal handler may only touch lock-free atomics (or volatile sig_atomic_t): this one and nothing else.
std::atomic<int> stop_request{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) { stop_request.store(signal, std::memory_order_relaxed); }

}  // namespace

ProgressOptions stdout_progress(bool quiet) {
  ProgressOptions progress;
  if (quiet) return progress;
  if (isatty(STDOUT_FILENO) == 1) {
    progress.mode = ProgressOptions::Mode::Terminal;
    progress.interval_seconds = 1.0;
    winsize size{};
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0) progress.width = size.ws_col;
  } else {
    progress.mode = ProgressOptions::Mode::Lines;
    progress.interval_seconds = 5.0;
  }
  return progress;
}

StopOnSignals::StopOnSignals() {
  stop_request.store(0);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;  // the second one is not caught: it ends the process
  // A signal the process was started with ignored stays ignored (a job started in the background of a script,
  // nohup): the terminal's Ctrl-C is not meant for it.
  for (auto [signal, previous] : {std::pair{SIGINT, &previous_int_}, std::pair{SIGTERM, &previous_term_}}) {
    sigaction(signal, nullptr, previous);
    if (previous->sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
  }
}

StopOnSignals::~StopOnSignals() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

const std::atomic<int>& StopOnSignals::request() const { return stop_request; }

}  // namespace crumple::app
