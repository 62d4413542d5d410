#include "app/console.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cctype>
#include <map>
#include <string>
#include <utility>

namespace crumple::app {
namespace {

// A signal handler may only touch lock-free atomics (or volatile sig_atomic_t): this one and nothing else.
std::atomic<int> stop_request{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) { stop_request.store(signal, std::memory_order_relaxed); }

// "/PROP/SHELL" of "/PROP/SHELL/1": a keyword without its ids, the family whose cards repeat a warning.
std::string keyword_family(const std::string& keyword) {
  std::string family;
  std::size_t at = 0;
  while (at < keyword.size()) {
    const std::size_t next = std::min(keyword.find('/', at + 1), keyword.size());
    const std::string part = keyword.substr(at, next - at);
    const bool number = part.size() > 1 && std::all_of(part.begin() + 1, part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == ' ';
    });
    if (!number) family += part;
    at = next;
  }
  return family;
}

std::string shown_file(const std::string& file, const std::filesystem::path& folder) {
  if (folder.empty()) return file;
  const std::filesystem::path relative = std::filesystem::path(file).lexically_relative(folder);
  return relative.empty() || *relative.begin() == ".." ? file : relative.string();
}

}  // namespace

void print_warnings(const std::vector<DeckWarning>& warnings, const std::filesystem::path& deck, std::ostream& out) {
  const std::filesystem::path folder = deck.parent_path();
  std::map<std::pair<std::string, std::string>, std::vector<std::size_t>> same;  // (family, message): warnings
  std::vector<std::vector<std::size_t>*> order;
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    auto& group = same[{keyword_family(warnings[i].keyword), warnings[i].message}];
    if (group.empty()) order.push_back(&group);
    group.push_back(i);
  }
  for (const std::vector<std::size_t>* group : order) {
    const DeckWarning& first = warnings[group->front()];
    std::string others;
    for (std::size_t k = 1; k < group->size() && k <= 4; ++k) {
      const DeckWarning& w = warnings[(*group)[k]];
      others += fmt::format("{}{} at line {}", k == 1 ? "" : ", ", w.keyword, w.where.line);
    }
    if (group->size() > 5) others += fmt::format(" and {} more", group->size() - 5);
    DeckWarning shown = first;
    shown.where.file = shown_file(first.where.file, folder);
    fmt::print(out, "warning: {}{}\n", shown.text(),
               others.empty() ? "" : fmt::format(" ({} cards; also {})", group->size(), others));
  }
}

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
