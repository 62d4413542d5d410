#include "crumple/output/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace crumple {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0 || seconds > 1e12) return "?";
  const auto whole = static_cast<long long>(seconds);  // whole seconds: the clock does not run ahead
  if (whole < 3600) return fmt::format("{}:{:02}", whole / 60, whole % 60);
  return fmt::format("{}:{:02}:{:02}", whole / 3600, whole / 60 % 60, whole % 60);
}

double remaining_seconds(double start_time, double time, double end_time, double elapsed) {
  const double done = time - start_time;
  if (!(done > 0.0) || !(elapsed >= 0.0)) return -1.0;
  return std::max(0.0, end_time - time) * elapsed / done;
}

std::string progress_line(const ProgressValues& v) {
  const double share = v.end_time > 0.0 ? 100.0 * v.time / v.end_time : 0.0;
  return fmt::format("cycle {}  t {:.3e} {:.1f}%  dt {:.3e} {}  err {:.2f}%  elapsed {}  left {}", v.cycle, v.time,
                     share, v.dt, v.control, v.error_percent, format_duration(v.elapsed_seconds),
                     format_duration(v.remaining_seconds));
}

namespace {
std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}
}  // namespace

ProgressClock::ProgressClock(ProgressOptions options)
    : options_(options), next_(started_ + seconds(options.interval_seconds)) {}

bool ProgressClock::due() {
  if (options_.mode == ProgressOptions::Mode::Off) return false;
  const auto now = Clock::now();
  if (now < next_) return false;
  next_ = now + seconds(options_.interval_seconds);  // from now: a slow cycle does not queue updates up
  return true;
}

double ProgressClock::elapsed_seconds() const {
  return std::chrono::duration<double>(Clock::now() - started_).count();
}

}  // namespace crumple
