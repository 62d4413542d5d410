#pragma once
// Internal to the deck reader: the Radioss keyword list (data/radioss_keywords.txt, embedded at build time) and
// what Crumple makes of a Radioss keyword it has no handler for. Output-only and performance cards become named
// warnings; every other Radioss keyword is "not supported by Crumple"; a word in neither Crumple's table nor the
// Radioss list is "unknown", with the nearest known keyword suggested.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "context.hpp"

namespace crumple::deck {

extern const char* const kRadiossKeywordsText;  // generated from data/radioss_keywords.txt

struct RadiossKeyword {
  std::string name;                // as listed, e.g. "/MAT/LAW36" or "/ANIM/*/TENS"
  std::vector<std::string> parts;  // {"MAT", "LAW36"}; "*" matches any one path part
  DeckPart part;
};

// The parsed list, in file order.
const std::vector<RadiossKeyword>& radioss_keywords();

// The Radioss keyword of deck part `part` that matches the most leading parts of `path`, or nullptr.
const RadiossKeyword* find_radioss_keyword(const std::vector<std::string>& path, DeckPart part);

// What a card does in Radioss, for the rule on options Crumple lacks (docs/deck-format.md, "Options Crumple does
// not have"): output-only and performance cards are warnings, model (physics) cards are errors.
enum class CardClass : std::uint8_t { Model, OutputOnly, PerformanceHint };
CardClass card_class(const std::vector<std::string>& path, DeckPart part);

// Levenshtein distance (insertions, deletions, substitutions of one character each).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The keyword of Crumple's table or of the Radioss list (either deck part) nearest to `name` ("/MAT/LAW99") by
// edit distance; empty when none is within a third of the name's length.
std::string nearest_keyword(std::string_view name);

}  // namespace crumple::deck
