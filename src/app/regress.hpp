#pragma once
// `crumple regress DIR...`: runs every deck folder holding a ref.extract and compares each run with its reference
// at the reference's time (docs/regression.md).
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "crumple/output/reference_check.hpp"

namespace crumple::app {

struct RegressOptions {
  std::vector<std::filesystem::path> folders;
  unsigned jobs = 0;  // runs at once; 0: the core count
  double timeout_seconds = 600.0;
  std::filesystem::path junit;  // the JUnit XML report; empty: none
  std::filesystem::path work;   // the runs' output directories go under it; empty: a temporary folder
  bool skip_unknown = false;    // passed on to each `crumple run`
  std::filesystem::path program = "/proc/self/exe";  // the crumple executable the runs use
};

// A deck folder: ref.extract, the starter NAME_0000.rad beside it, and the optional tolerance file.
struct RegressCase {
  std::string name;  // the folder relative to the folder given (its own name when it is the folder given)
  std::filesystem::path folder, starter;
  ReferencePoint reference;
  Tolerances tolerances;
};

// The deck folders under `folders` in path order, each once. Throws ReferenceFileError on a ref.extract or
// tolerance file in error, or on a folder with no starter deck or several.
std::vector<RegressCase> find_regress_cases(const std::vector<std::filesystem::path>& folders);

// Runs and compares every case; prints a table to `out`. Returns the exit code: 0 when every case passes, 1 when
// any fails, 2 on bad input (no deck folder, a file in error) before anything runs.
int regress(const RegressOptions& options, std::ostream& out, std::ostream& err);

}  // namespace crumple::app
