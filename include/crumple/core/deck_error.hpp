#pragma once
// Errors and warnings about a deck, raised by the reader and by any later stage that finds a problem in the
// model (a contact surface without a gap...). Every message names the file, the line, the keyword and the field,
// and says what was expected and what was found, so a crash engineer can fix the deck without a debugger.
#include <stdexcept>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"

namespace crumple {

class DeckError : public std::runtime_error {
 public:
  DeckError(SourceLocation where, std::string keyword, std::string field, std::string expected, std::string found);

  const SourceLocation& where() const { return where_; }
  const std::string& keyword() const { return keyword_; }
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  SourceLocation where_;
  std::string keyword_;
  std::string field_;
  std::string expected_;
  std::string found_;
};

// All errors of one read, in deck order. Thrown once reading is over so that the user sees every problem at once.
class DeckErrors : public std::runtime_error {
 public:
  explicit DeckErrors(std::vector<DeckError> errors);
  const std::vector<DeckError>& errors() const { return errors_; }

 private:
  std::vector<DeckError> errors_;
};

struct DeckWarning {
  SourceLocation where;
  std::string keyword;
  std::string message;
  std::string text() const;
};

}  // namespace crumple
