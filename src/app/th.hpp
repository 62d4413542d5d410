#pragma once
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace crumple::app {

struct ThOptions {
  std::filesystem::path file;          // NAME.h5
  bool csv = false;                    // write the columns as CSV instead of listing them
  std::vector<std::string> select;     // glob patterns on the column labels (empty: every column)
  std::filesystem::path output;        // CSV file (empty: standard output)
};

// `crumple th` (README, "Time histories"): lists the histories of a results file - dataset, kind, id, title and
// columns - or writes the selected columns as CSV, time first, one column per channel, the header their labels
// with units. Returns the process exit code (exit_codes.hpp).
int run_th(const ThOptions& options, std::ostream& out, std::ostream& err);

}  // namespace crumple::app
