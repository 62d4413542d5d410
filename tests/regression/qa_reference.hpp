#pragma once
// Reads ../shared/qa/<case>/ref.extract: end-of-run values of the reference solver. Each line is
// "<line number> <KEY> <value> [<scale>]".
#include <filesystem>
#include <sstream>

#include "crumple/deck/reader.hpp"
#include "crumple/solver/solver.hpp"
#include "deck_files.hpp"
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace crumple::test {

struct ReferenceValue {
  double value = 0.0;
  double scale = 0.0;  // the energy scale for relative errors (second number on energy lines)
};

inline std::map<std::string, ReferenceValue> read_reference(const std::filesystem::path& file) {
  std::map<std::string, ReferenceValue> values;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string number, key;
    ReferenceValue v;
    if (!(fields >> number >> key >> v.value)) continue;
    if (!(fields >> v.scale)) v.scale = 0.0;
    values[key] = v;
  }
  return values;
}

// Runs a QA deck to its end time with its results in a temporary folder; returns the run summary.
inline RunSummary run_qa_deck(const std::filesystem::path& starter) {
  const Deck deck = read_deck(starter);
  TempDir dir;
  SolverOptions options;
  options.output_directory = dir.path();
  std::ostringstream console;
  return run_simulation(deck.model, options, console);
}

}  // namespace crumple::test
