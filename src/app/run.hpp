#pragma once
#include <filesystem>
#include <iosfwd>

#include "crumple/deck/reader.hpp"

namespace crumple::app {

struct RunOptions {
  std::filesystem::path deck;
  std::filesystem::path output_directory = ".";
  bool skip_unknown = false;
};

// `crumple run`: reads the deck and runs it, writing NAME.h5, NAME.out and NAME.summary.json into the output
// directory. Returns the process exit code (exit_codes.hpp). Deck errors propagate as exceptions.
int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace crumple::app
