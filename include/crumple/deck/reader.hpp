#pragma once
// Entry point of the deck reader: a starter deck (and the engine deck beside it) -> a validated Model.
#include <filesystem>
#include <string>
#include <vector>

#include "crumple/deck/error.hpp"
#include "crumple/model/model.hpp"

namespace crumple {

struct ReadOptions {
  bool skip_unknown = false;  // unknown keywords become warnings (each listed once) instead of errors
  bool require_engine = false;  // a run needs the engine part (/RUN); `check` does not
};

struct DeckReport {
  std::vector<std::string> files;                    // every file read, includes too
  std::vector<std::string> keywords_read;            // distinct keyword names, in order of first use
  std::vector<std::string> accepted_without_effect;  // distinct keyword names read but ignored by design
  std::vector<DeckWarning> warnings;
};

struct Deck {
  Model model;
  DeckReport report;
};

// The engine deck that belongs to a starter deck: NAME_0001.rad beside NAME_0000.rad (empty when none).
std::filesystem::path engine_deck_for(const std::filesystem::path& starter);

// Reads and validates. Throws DeckErrors (every error found, in deck order) or DeckError; nothing is computed
// from an invalid deck.
Deck read_deck(const std::filesystem::path& starter, const ReadOptions& options = {});

}  // namespace crumple
