#pragma once
// Runs commands as child processes, a few at a time, each with a time limit: a crash or hang of one costs that
// one only (`crumple regress`).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace crumple::app {

struct ChildCommand {
  std::vector<std::string> arguments;  // after the program's name
  std::filesystem::path console;       // the child's standard output and error go here
};

struct ChildResult {
  enum class End { Exited, Signalled, TimedOut, NotStarted };
  End end = End::NotStarted;
  int code = 0;  // the exit code (Exited), the signal (Signalled), errno (NotStarted)
  double seconds = 0.0;
};

// Runs `program` once per command, at most `jobs` at once, in the order given; a child still running after
// `timeout_seconds` is killed (SIGKILL) and reported TimedOut. `done` is called as each one ends, from this
// thread. Returns the results in the commands' order.
std::vector<ChildResult> run_children(const std::filesystem::path& program, const std::vector<ChildCommand>& commands,
                                      unsigned jobs, double timeout_seconds,
                                      const std::function<void(std::size_t, const ChildResult&)>& done);

// "exit code 1", "killed by signal 11 (Segmentation fault)", "timed out after 600 s", "could not start: ...".
std::string describe(const ChildResult& result, double timeout_seconds);

}  // namespace crumple::app
