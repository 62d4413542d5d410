#include "app/plot.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "app/exit_codes.hpp"

extern char** environ;

namespace crumple::app {

extern const char* const kPlotScript;

std::string plot_python() {
  if (const char* chosen = std::getenv("CRUMPLE_PYTHON"); chosen != nullptr && *chosen != '\0') return chosen;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

namespace {

// Runs the embedded script with `script_args`; `command` names it in messages ("crumple plot").
int run_script(std::vector<std::string> script_args, const char* command) {
  std::vector<std::string> args{plot_python(), "-c", kPlotScript};
  args.insert(args.end(), script_args.begin(), script_args.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  if (const int e = posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ); e != 0) {
    fmt::print(stderr, "{}: cannot start {}: {} (set CRUMPLE_PYTHON to a Python 3 with matplotlib)\n", command,
               args[0], std::strerror(e));
    return kExitBadInput;
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status) == 0 ? kExitNormal : kExitBadInput;
  fmt::print(stderr, "{}: {} ended by signal {}\n", command, args[0], WTERMSIG(status));
  return kExitRunFailed;
}

bool exists(const std::filesystem::path& results, const char* command) {
  if (std::filesystem::is_regular_file(results)) return true;
  fmt::print(stderr, "{}: {}: no such file\n", command, results.string());
  return false;
}

}  // namespace

int plot_results(const PlotOptions& options) {
  if (!exists(options.results, "crumple plot")) return kExitBadInput;
  std::vector<std::string> args{options.results.string()};
  if (!options.output_directory.empty()) args.insert(args.end(), {"-o", options.output_directory.string()});
  if (!options.select.empty()) {
    args.emplace_back("--select");
    args.insert(args.end(), options.select.begin(), options.select.end());
  }
  return run_script(std::move(args), "crumple plot");
}

int compare_results(const CompareOptions& options) {
  std::vector<std::string> args{"compare"};
  for (const std::filesystem::path& f : options.results) {
    if (!exists(f, "crumple compare")) return kExitBadInput;
    args.push_back(f.string());
  }
  if (!options.output_directory.empty()) args.insert(args.end(), {"-o", options.output_directory.string()});
  if (!options.nodes.empty()) {
    args.emplace_back("--nodes");
    for (long long n : options.nodes) args.push_back(std::to_string(n));
  }
  return run_script(std::move(args), "crumple compare");
}

}  // namespace crumple::app
