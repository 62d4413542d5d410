#include "crumple/core/deck_error.hpp"

#include <fmt/format.h>

namespace crumple {
namespace {

// Control characters from a corrupted deck (a NUL in a keyword line would cut what() short, an escape sequence
// would drive the terminal) are shown as \xNN.
std::string printable(std::string text) {
  std::string out;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 32 || u == 127) out += fmt::format("\\x{:02x}", u);
    else out += c;
  }
  return out;
}

std::string location_text(const SourceLocation& where) {
  if (where.file.empty()) return "<deck>";
  if (where.line <= 0) return where.file;
  return fmt::format("{}:{}", where.file, where.line);
}

std::string compose(const SourceLocation& where, const std::string& keyword, const std::string& field,
                    const std::string& expected, const std::string& found) {
  std::string text = location_text(where) + ": ";
  if (!keyword.empty()) text += keyword + ": ";
  if (!field.empty()) text += "field " + field + ": ";
  text += "expected " + expected;
  if (!found.empty()) text += ", found " + found;
  return printable(std::move(text));
}

}  // namespace

DeckError::DeckError(SourceLocation where, std::string keyword, std::string field, std::string expected,
                     std::string found)
    : std::runtime_error(compose(where, keyword, field, expected, found)),
      where_(std::move(where)),
      keyword_(std::move(keyword)),
      field_(std::move(field)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

DeckErrors::DeckErrors(std::vector<DeckError> errors)
    : std::runtime_error(errors.empty() ? std::string("deck error") : std::string(errors.front().what())),
      errors_(std::move(errors)) {}

std::string DeckWarning::text() const {
  std::string text = location_text(where) + ": ";
  if (!keyword.empty()) text += keyword + ": ";
  return printable(text + message);
}

}  // namespace crumple
