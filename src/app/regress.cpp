#include "app/regress.hpp"

#include <fmt/ostream.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <thread>

#include "app/child_runs.hpp"
#include "app/exit_codes.hpp"
#include "crumple/output/junit_report.hpp"

namespace crumple::app {
namespace {

namespace fs = std::filesystem;

// The one NAME_0000.rad of a deck folder.
fs::path starter_deck(const fs::path& folder) {
  std::vector<fs::path> starters;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string file = entry.path().filename().string();
    if (entry.is_regular_file() && file.size() > 9 && file.ends_with("_0000.rad")) starters.push_back(entry.path());
  }
  if (starters.size() != 1)
    throw ReferenceFileError(folder / "ref.extract", 0, "",
                             starters.empty() ? "no starter deck NAME_0000.rad beside it"
                                              : "several starter decks *_0000.rad beside it: keep one per folder");
  return starters.front();
}

RegressCase read_case(const fs::path& root, const fs::path& folder) {
  RegressCase c;
  c.folder = folder;
  const fs::path relative = folder.lexically_relative(root);
  c.name = relative.empty() || relative == "." ? fs::weakly_canonical(folder).filename().string()
                                               : relative.generic_string();
  c.starter = starter_deck(folder);
  c.reference = read_reference(folder / "ref.extract");
  if (fs::exists(folder / kToleranceFile)) c.tolerances = read_tolerances(folder / kToleranceFile);
  return c;
}

}  // namespace

std::vector<RegressCase> find_regress_cases(const std::vector<fs::path>& folders) {
  std::vector<RegressCase> cases;
  std::set<fs::path> seen;
  for (const fs::path& root : folders) {
    std::vector<fs::path> found;
    if (fs::is_regular_file(root / "ref.extract")) found.push_back(root);
    for (const auto& entry : fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied))
      if (entry.is_directory() && fs::is_regular_file(entry.path() / "ref.extract")) found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    for (const fs::path& folder : found)
      if (seen.insert(fs::weakly_canonical(folder)).second) cases.push_back(read_case(root, folder));
  }
  return cases;
}

namespace {

// What became of one case.
struct Outcome {
  bool passed = false;
  std::string kind = "not run";  // pass, mismatch, unsupported, bad input, timeout, crash, run failed, no results
  std::string message;           // the numbers, or what went wrong
  std::string console;           // the run's last console lines
  std::optional<Comparison> comparison;
  double seconds = 0.0;
};

std::string console_tail(const fs::path& console, std::size_t lines) {
  std::ifstream in(console);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);) all.push_back(line);
  std::string tail;
  for (std::size_t k = all.size() > lines ? all.size() - lines : 0; k < all.size(); ++k) tail += all[k] + "\n";
  return tail;
}

// The run's NAME: the one NAME.summary.json `crumple run` wrote.
std::string run_name(const fs::path& output) {
  for (const auto& entry : fs::directory_iterator(output)) {
    const std::string file = entry.path().filename().string();
    if (file.ends_with(".summary.json")) return file.substr(0, file.size() - std::string(".summary.json").size());
  }
  throw std::runtime_error("no NAME.summary.json in " + output.string());
}

// The run's first error line on its console (a deck error names the file, line, keyword and field), or "".
std::string first_error(const fs::path& console) {
  std::ifstream in(console);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("error: ", 0) == 0 || line.rfind("crumple: ", 0) == 0) return line;
  return {};
}

// What kind of failure a run that did not end normally is: a deck Crumple refuses for a keyword or option it
// lacks ("unsupported", counted apart from wrong answers), other bad input, a timeout, a crash, a failed run.
std::string failure_kind(const ChildResult& r, const std::string& error) {
  switch (r.end) {
    case ChildResult::End::TimedOut: return "timeout";
    case ChildResult::End::Signalled: return "crash";
    default: break;
  }
  if (r.end == ChildResult::End::Exited && r.code == kExitBadInput)
    return error.find("not supported by Crumple") != std::string::npos ||
                   error.find("unknown keyword") != std::string::npos
               ? "unsupported"
               : "bad input";
  return "run failed";
}

Outcome evaluate(const RegressCase& c, const ChildResult& r, const fs::path& output, double timeout) {
  Outcome o;
  o.seconds = r.seconds;
  o.console = console_tail(output / "console.txt", 12);
  if (r.end != ChildResult::End::Exited || r.code != 0) {
    const std::string error = first_error(output / "console.txt");
    o.kind = failure_kind(r, error);
    o.message = "crumple run: " + describe(r, timeout) + (error.empty() ? "" : ": " + error);
    return o;
  }
  try {
    o.comparison = compare(c.reference, read_run_point(output, run_name(output), c.reference.time), c.tolerances);
  } catch (const std::exception& e) {
    o.kind = "no results";
    o.message = e.what();
    return o;
  }
  o.passed = o.comparison->passed();
  o.kind = o.passed ? "pass" : "mismatch";
  o.message = o.comparison->failures();
  return o;
}

std::string verdict(const Outcome& o) {
  if (o.passed) return "pass";
  if (!o.comparison) return fmt::format("FAIL ({})", o.kind);
  const Comparison& c = *o.comparison;
  std::string what;
  const auto add = [&](bool failed, const char* name) {
    if (failed) what += (what.empty() ? "" : ", ") + std::string(name);
  };
  add(!c.reaches_time, "time");
  add(!c.internal.passed(), "IE");
  add(!c.kinetic.passed(), "KE");
  add(!c.cycles.passed(), "cycles");
  return "FAIL (" + what + ")";
}

void print_table(const std::vector<RegressCase>& cases, const std::vector<Outcome>& outcomes, std::ostream& out) {
  std::size_t width = 4;
  for (const RegressCase& c : cases) width = std::max(width, c.name.size());
  // IE diff: % of the reference's internal energy (or of its floor share of the scale); KE diff: % of the scale;
  // cycles: Crumple's against the reference's at its time.
  fmt::print(out, "\n{:<{}}  {:>11} {:>11} {:>8} {:>8} {:>13} {:>11}  {:>7}  {}\n", "deck", width, "IE crumple",
             "IE ref", "IE diff", "KE diff", "cycles cr/ref", "cycles diff", "seconds", "verdict");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Outcome& o = outcomes[i];
    if (!o.comparison) {
      fmt::print(out, "{:<{}}  {:>11} {:>11} {:>8} {:>8} {:>13} {:>11}  {:>7.1f}  {}\n", cases[i].name, width, "-",
                 "-", "-", "-", "-", "-", o.seconds, verdict(o));
      continue;
    }
    const Comparison& c = *o.comparison;
    // IE diff in % of the quantity its tolerance is a share of: max(|ref|, floor x scale).
    const double internal_base =
        std::max(std::abs(c.internal.reference), cases[i].tolerances.internal_floor * c.scale);
    fmt::print(out, "{:<{}}  {:>11.5g} {:>11.5g} {:>+6.1f} % {:>+6.1f} % {:>13} {:>+9.1f} %  {:>7.1f}  {}\n",
               cases[i].name, width, c.internal.run, c.internal.reference,
               100.0 * c.internal.difference() / internal_base, 100.0 * c.kinetic.difference() / c.scale,
               fmt::format("{:.0f}/{:.0f}", c.cycles.run, c.cycles.reference),
               100.0 * c.cycles.difference() / c.cycles.reference, o.seconds, verdict(o));
  }
}

JunitSuite junit_suite(const std::vector<RegressCase>& cases, const std::vector<Outcome>& outcomes, double seconds) {
  JunitSuite suite{"crumple regress", seconds, {}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Outcome& o = outcomes[i];
    JunitCase jc{cases[i].name, o.seconds, !o.passed, o.passed ? "" : o.kind, o.passed ? "" : o.message, ""};
    if (!o.passed) jc.failure_text = o.message + "\n\nlast console lines of crumple run:\n" + o.console;
    suite.cases.push_back(std::move(jc));
  }
  return suite;
}

// The folder the runs go in: the one given, or a new temporary folder.
fs::path work_folder(const RegressOptions& options) {
  if (!options.work.empty()) {
    fs::create_directories(options.work);
    return options.work;
  }
  std::string pattern = (fs::temp_directory_path() / "crumple-regress-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder " + pattern);
  return pattern;
}

// The output directory of case i: its number and name, so that equal names under different folders stay apart.
fs::path case_output(const fs::path& work, std::size_t i, const std::string& name) {
  std::string safe = name;
  std::replace(safe.begin(), safe.end(), '/', '_');
  return work / fmt::format("{:03d}-{}", i + 1, safe);
}

std::vector<ChildCommand> run_commands(const RegressOptions& options, const std::vector<RegressCase>& cases,
                                       const fs::path& work) {
  std::vector<ChildCommand> commands;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path output = case_output(work, i, cases[i].name);
    fs::remove_all(output);  // a given work folder may hold an earlier run's files: never judge those
    fs::create_directories(output);
    ChildCommand command{{"run", cases[i].starter.string(), "-o", output.string()}, output / "console.txt"};
    if (options.skip_unknown) command.arguments.push_back("--skip-unknown");
    commands.push_back(std::move(command));
  }
  return commands;
}

// Runs every case as a child process and judges each as it ends.
std::vector<Outcome> run_cases(const RegressOptions& options, const std::vector<RegressCase>& cases,
                               const fs::path& work, unsigned jobs, std::ostream& out) {
  std::vector<Outcome> outcomes(cases.size());
  std::size_t finished = 0;
  run_children(options.program, run_commands(options, cases, work), jobs, options.timeout_seconds,
               [&](std::size_t i, const ChildResult& r) {
                 outcomes[i] = evaluate(cases[i], r, case_output(work, i, cases[i].name), options.timeout_seconds);
                 fmt::print(out, "[{}/{}] {}: {} ({:.1f} s)\n", ++finished, cases.size(), cases[i].name,
                            verdict(outcomes[i]), r.seconds);
                 out.flush();
               });
  return outcomes;
}

// The failures' numbers, the JUnit report, the work folder kept or removed; the exit code.
int report(const std::vector<RegressCase>& cases, const std::vector<Outcome>& outcomes, double seconds,
           const fs::path& work, const RegressOptions& options, std::ostream& out, std::ostream& err) {
  const auto failed = std::count_if(outcomes.begin(), outcomes.end(), [](const Outcome& o) { return !o.passed; });
  const auto unsupported =
      std::count_if(outcomes.begin(), outcomes.end(), [](const Outcome& o) { return o.kind == "unsupported"; });
  fmt::print(out, "\n{} passed, {} failed{} ({:.1f} s)\n", cases.size() - static_cast<std::size_t>(failed), failed,
             unsupported > 0 ? fmt::format(" ({} wrong or failed, {} refused as unsupported)", failed - unsupported,
                                           unsupported)
                             : std::string(),
             seconds);
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (!outcomes[i].passed) fmt::print(out, "  {}: {}\n", cases[i].name, outcomes[i].message);
  int code = failed > 0 ? kExitRunFailed : kExitNormal;
  if (!options.junit.empty()) {
    try {
      write_junit(options.junit, junit_suite(cases, outcomes, seconds));
    } catch (const std::exception& e) {
      fmt::print(err, "crumple regress: {}\n", e.what());
      code = kExitRunFailed;
    }
  }
  if (options.work.empty() && failed == 0) {
    std::error_code ec;
    fs::remove_all(work, ec);
  } else {
    fmt::print(out, "runs kept in {}\n", work.string());
  }
  return code;
}

}  // namespace

int regress(const RegressOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<RegressCase> cases;
  try {
    cases = find_regress_cases(options.folders);
  } catch (const ReferenceFileError& e) {
    fmt::print(err, "error: {}\ncrumple regress: nothing was run\n", e.what());
    return kExitBadInput;
  }
  if (cases.empty()) {
    fmt::print(err, "crumple regress: no deck folder (a folder holding ref.extract) under the folders given\n");
    return kExitBadInput;
  }
  const unsigned jobs = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  const fs::path work = work_folder(options);
  fmt::print(out, "crumple regress: {} deck{}, {} at a time, runs in {}\n", cases.size(), cases.size() == 1 ? "" : "s",
             jobs, work.string());
  out.flush();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Outcome> outcomes = run_cases(options, cases, work, jobs, out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_table(cases, outcomes, out);
  return report(cases, outcomes, seconds, work, options, out, err);
}

}  // namespace crumple::app
