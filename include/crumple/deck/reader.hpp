#pragma once
// Entry point of the deck reader: a starter deck (and the engine deck beside it) -> a validated Model.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crumple/core/deck_error.hpp"
#include "crumple/model/model.hpp"

namespace crumple {

struct ReadOptions {
  // Keywords and options Crumple lacks (unknown keywords, Radioss keywords and field values it does not support)
  // become warnings instead of errors; each is listed in DeckReport::skipped_options.
  bool skip_unknown = false;
  bool require_engine = false;  // a run needs the engine part (/RUN); `check` does not
};

// What kind of option a deck asked for that Crumple does not act on.
enum class SkipKind : std::uint8_t {
  Unsupported,      // a keyword or field value Crumple lacks, skipped on --skip-unknown (otherwise an error)
  OutputOnly,       // an output request Crumple does not write
  PerformanceHint,  // a parallel, memory or speed hint with no effect on Crumple's results
};

// One option skipped or approximated, for the listing and the run summary ("approximations").
struct SkippedOption {
  SourceLocation where;
  std::string keyword;  // the keyword line as written, e.g. "/MAT/LAW44/3"
  std::string field;    // the field with its columns, empty for the whole card
  std::string what;     // what was skipped and why
  SkipKind kind = SkipKind::Unsupported;
  std::string text() const;  // "[output-only] file:line: keyword: field F: what"
};

struct DeckReport {
  std::vector<std::string> files;                    // every file read, includes too
  std::vector<std::string> keywords_read;            // distinct keyword names, in order of first use
  std::vector<std::string> accepted_without_effect;  // distinct keyword names read but ignored by design
  std::vector<DeckWarning> warnings;
  std::vector<SkippedOption> skipped_options;        // every skipped or approximated option, in deck order
};

struct Deck {
  Model model;  // model.run: the run control of the first engine deck, NAME_0001.rad
  // A continued run: the run controls of NAME_0002.rad, NAME_0003.rad, ... in order. Each carries on the time and
  // the whole state of the one before (docs/theory/time-loop.md, "Continued runs").
  std::vector<RunControl> continued_runs;
  DeckReport report;
};

// Engine deck `number` of a starter deck: NAME_0001.rad (the first), NAME_0002.rad... beside NAME_0000.rad (empty
// when there is none).
std::filesystem::path engine_deck_for(const std::filesystem::path& starter, int number = 1);

// Reads and validates. Throws DeckErrors (every error found, in deck order) or DeckError; nothing is computed
// from an invalid deck.
Deck read_deck(const std::filesystem::path& starter, const ReadOptions& options = {});

}  // namespace crumple
