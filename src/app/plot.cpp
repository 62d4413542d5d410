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

int plot_results(const PlotOptions& options) {
  if (!std::filesystem::is_regular_file(options.results)) {
    fmt::print(stderr, "crumple plot: {}: no such file\n", options.results.string());
    return kExitBadInput;
  }
  std::vector<std::string> args{plot_python(), "-c", kPlotScript, options.results.string()};
  if (!options.output_directory.empty()) args.insert(args.end(), {"-o", options.output_directory.string()});
  if (!options.select.empty()) {
    args.emplace_back("--select");
    args.insert(args.end(), options.select.begin(), options.select.end());
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  if (const int e = posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ); e != 0) {
    fmt::print(stderr, "crumple plot: cannot start {}: {} (set CRUMPLE_PYTHON to a Python 3 with matplotlib)\n",
               args[0], std::strerror(e));
    return kExitBadInput;
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status) == 0 ? kExitNormal : kExitBadInput;
  fmt::print(stderr, "crumple plot: {} ended by signal {}\n", args[0], WTERMSIG(status));
  return kExitRunFailed;
}

}  // namespace crumple::app
