#pragma once
// The console progress of a running job (README, "Watching a run"): on a terminal one line rewritten in place about
// once a second, otherwise a plain line every few seconds. The app chooses the mode; the recorder shows it.
#include <chrono>
#include <cstdint>
#include <string>

namespace crumple {

struct ProgressOptions {
  enum class Mode : std::uint8_t {
    Off,       // --quiet, and every run the app does not start (tests, tools)
    Terminal,  // one line rewritten in place ("\r", clear to the end of the line)
    Lines,     // a log or a pipe: one newline-terminated line each interval
  };
  Mode mode = Mode::Off;
  double interval_seconds = 1.0;  // wall time between two updates
  int width = 0;                  // Terminal: its columns; a longer line is cut to width - 1 (0: never cut)
};

// What one progress line says.
struct ProgressValues {
  long long cycle = 0;
  double time = 0.0, end_time = 0.0;  // simulation time and the engine deck's end time [T]
  double dt = 0.0;                    // dt^(n+1/2) [T]
  std::string control;                // what bounds it: the listing's ELEMENT column ("SHELL 61")
  double error_percent = 0.0;         // the energy error of the balance
  double elapsed_seconds = 0.0;       // wall time since the run started
  double remaining_seconds = -1.0;    // estimated wall time to the end time; negative: not known yet
};

// "cycle 4000  t 1.684e+00 56.1%  dt 2.829e-04 SHELL 10  err -0.02%  elapsed 0:04  left 0:03"
std::string progress_line(const ProgressValues& values);
// A wall-clock duration as m:ss, or h:mm:ss from one hour ("0:04", "12:05", "3:07:02"); "?" when negative or not
// finite (no estimate yet).
std::string format_duration(double seconds);
// Wall time left to `end_time` at the rate the run had since it started: `elapsed` wall seconds took the run from
// `start_time` to `time`. Negative while no simulation time has passed.
double remaining_seconds(double start_time, double time, double end_time, double elapsed);

// When the next update is due: one steady_clock read per call while progress is on, none while it is off.
class ProgressClock {
 public:
  explicit ProgressClock(ProgressOptions options = {});
  bool due();
  double elapsed_seconds() const;

 private:
  using Clock = std::chrono::steady_clock;
  ProgressOptions options_;
  Clock::time_point started_ = Clock::now();
  Clock::time_point next_;
};

}  // namespace crumple
