#include "app/child_runs.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

extern char** environ;

namespace crumple::app {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  std::size_t index;
  pid_t pid;
  Clock::time_point start;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Starts one child with stdin from /dev/null and stdout and stderr into its console file; returns its pid, or -1
// with `error` set.
pid_t spawn(const std::filesystem::path& program, const ChildCommand& command, int& error) {
  std::vector<std::string> words{program.string()};
  words.insert(words.end(), command.arguments.begin(), command.arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, command.console.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

ChildResult ended(int status, Clock::time_point start) {
  ChildResult r;
  r.seconds = seconds_since(start);
  if (WIFEXITED(status)) r.end = ChildResult::End::Exited, r.code = WEXITSTATUS(status);
  else r.end = ChildResult::End::Signalled, r.code = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return r;
}

// Whether `child` has ended (reaped into `result`), killing it first when it is past the time limit.
bool poll(const Running& child, double timeout_seconds, ChildResult& result) {
  int status = 0;
  if (waitpid(child.pid, &status, WNOHANG) == child.pid) {
    result = ended(status, child.start);
    return true;
  }
  if (seconds_since(child.start) <= timeout_seconds) return false;
  kill(child.pid, SIGKILL);
  waitpid(child.pid, &status, 0);
  result.end = ChildResult::End::TimedOut;
  result.seconds = seconds_since(child.start);
  return true;
}

}  // namespace

std::vector<ChildResult> run_children(const std::filesystem::path& program, const std::vector<ChildCommand>& commands,
                                      unsigned jobs, double timeout_seconds,
                                      const std::function<void(std::size_t, const ChildResult&)>& done) {
  std::vector<ChildResult> results(commands.size());
  std::vector<Running> running;
  std::size_t next = 0;
  while (next < commands.size() || !running.empty()) {
    while (running.size() < std::max(jobs, 1u) && next < commands.size()) {
      const std::size_t i = next++;
      int error = 0;
      const pid_t pid = spawn(program, commands[i], error);
      if (pid < 0) {
        results[i] = {ChildResult::End::NotStarted, error, 0.0};
        done(i, results[i]);
      } else {
        running.push_back({i, pid, Clock::now()});
      }
    }
    for (auto it = running.begin(); it != running.end();) {
      if (!poll(*it, timeout_seconds, results[it->index])) {
        ++it;
        continue;
      }
      done(it->index, results[it->index]);
      it = running.erase(it);
    }
    if (!running.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return results;
}

std::string describe(const ChildResult& result, double timeout_seconds) {
  switch (result.end) {
    case ChildResult::End::Exited: return fmt::format("exit code {}", result.code);
    case ChildResult::End::Signalled:
      return fmt::format("killed by signal {} ({})", result.code, strsignal(result.code));
    case ChildResult::End::TimedOut: return fmt::format("timed out after {:g} s", timeout_seconds);
    case ChildResult::End::NotStarted: return fmt::format("could not start: {}", std::strerror(result.code));
  }
  return "";
}

}  // namespace crumple::app
