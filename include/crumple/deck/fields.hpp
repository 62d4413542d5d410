#pragma once
// Cards and their fields. A card is one keyword line and the data lines that follow it up to the next keyword.
// Starter data lines are fixed width (integers in 10 columns, reals in 20, on a 100-column line); engine data
// lines are free format (fields separated by blanks). A blank field takes the card's default.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "crumple/core/deck_error.hpp"
#include "crumple/deck/source.hpp"
#include "crumple/deck/units.hpp"

namespace crumple {

// Fortran-style real: 1.5, .3, -8, 205, 1E-6, 1.D-3, 1.00000002E20. nullopt for anything else.
std::optional<double> parse_fortran_real(std::string_view text);
// Optional sign and digits only. nullopt for anything else (a real in an integer field is an error).
std::optional<std::int64_t> parse_integer(std::string_view text);
std::string_view trim(std::string_view text);

struct Card {
  std::string keyword;                  // keyword line as written, trimmed, e.g. "/MAT/PLAS_JOHNS/1"
  std::vector<std::string> path;        // its parts: {"MAT", "PLAS_JOHNS", "1"}
  SourceLocation where;                 // the keyword line
  std::vector<const SourceLine*> lines; // data lines, comments removed, blank lines kept
  bool engine = false;                  // true for the engine (run control) part
};

// Splits a source text into cards. Comment lines (# or $) are dropped. The starter part runs from /BEGIN to
// /END. Engine cards are those of the engine file (from `first_engine_file` on), those after the starter's /END
// (single-file deck, deck.md) and those before /BEGIN closed by /END/ENGINE (Radioss single-file form).
// Lines before the first keyword must be blank or comments.
std::vector<Card> split_cards(const SourceText& text, std::int32_t first_engine_file);

class CardReader;

// //SUBMODEL id offsets (docs/deck-format.md, "Submodels"): every id read inside a submodel, whether it defines an
// object or refers to one, is shifted by the offset of its kind; offsets of nested submodels add up. A blank or 0
// id stays "none", and a negative one keeps its meaning.
enum class IdKind : std::uint8_t { Node, Element, Part, Material, Property, Submodel, Other };
inline constexpr std::size_t kIdKinds = 7;
struct IdOffsets {
  std::array<std::int64_t, kIdKinds> by_kind{};
  std::int64_t shifted(std::int64_t id, IdKind kind) const {
    return id > 0 ? id + by_kind[static_cast<std::size_t>(kind)] : id;
  }
};

// One data line of a card, with typed field access that reports errors with file, line, keyword and field.
class Line {
 public:
  Line(const CardReader& reader, const SourceLine& source, std::size_t index)
      : reader_(&reader), source_(&source), index_(index) {}

  // Fixed-width fields; `column` is 1-based.
  std::int64_t integer(int column, int width, std::string_view name, std::int64_t fallback = 0) const;
  // An id of an object of `kind`, shifted by the enclosing //SUBMODEL's offset. Inside a submodel, integer() refuses
  // a field whose name says it is an id, so that no id escapes its offset unread.
  std::int64_t id(int column, int width, std::string_view name, IdKind kind) const;
  // An id that may be blank or 0 (= none); a negative one is an error.
  std::int64_t optional_id(int column, int width, std::string_view name, IdKind kind = IdKind::Other) const;
  double real(int column, int width, std::string_view name, Dimension d, double fallback = 0.0) const;
  std::string text(int column, int width) const;  // trimmed
  std::string raw(int column, int width) const;   // as written, padded with blanks to `width`

  // Free-format fields (engine cards); `index` is 0-based.
  std::size_t token_count() const;
  double token_real(std::size_t index, std::string_view name, Dimension d, std::optional<double> fallback) const;
  std::int64_t token_integer(std::size_t index, std::string_view name, std::optional<std::int64_t> fallback) const;

  bool blank() const;
  SourceLocation where() const;
  const std::string& content() const { return source_->text; }
  // The same line read at the columns as written, whatever the card's layout (a field the narrow layout of input
  // versions 41 to 44 does not place at 4/5 of its 2017 column, CardReader::use_narrow_layout).
  Line as_written() const {
    Line copy = *this;
    copy.as_written_ = true;
    return copy;
  }

  // An error about the field at `column`..`column+width-1` (or the whole line when width is 0).
  [[noreturn]] void fail(int column, int width, std::string_view name, std::string_view expected) const;
  [[noreturn]] void fail_value(std::string_view name, std::string_view expected, std::string_view found) const;
  // The error fail() throws, for callers that may record it instead (DeckContext::unsupported).
  DeckError error(int column, int width, std::string_view name, std::string_view expected) const;

 private:
  std::string field_label(int column, int width, std::string_view name) const;
  // The columns a field given in the 2017 layout is read at: the same, or 4/5 of them in the narrow layout.
  std::pair<int, int> placed(int column, int width) const;
  std::int64_t parsed_integer(int column, int width, std::string_view name, std::int64_t fallback) const;
  double real_value(int column, int width, std::string_view name, Dimension d, double v) const;
  const CardReader* reader_;
  const SourceLine* source_;
  std::size_t index_;  // data line of the card (for the columns read)
  bool as_written_ = false;
};

// Walks the data lines of one card.
class CardReader {
 public:
  CardReader(const Card& card, const SourceText& text, const UnitSystem& units)
      : card_(&card), text_(&text), units_(&units) {}

  const Card& card() const { return *card_; }
  const UnitSystem& units() const { return *units_; }
  // The deck's /UNIT systems by id (set by the reader before the handler runs; they outlive the card).
  void set_local_units(const std::map<std::int64_t, UnitSystem>* local) { local_units_ = local; }
  // The card's values are read in /UNIT system `id`; an undefined one is an error naming the field.
  void use_local_units(std::int64_t id, std::string_view field);
  const SourceText& text() const { return *text_; }
  // Inside a //SUBMODEL: the id offsets of its kinds (set by the reader before the handler runs), else null.
  void set_id_offsets(const IdOffsets* offsets) { id_offsets_ = offsets; }
  const IdOffsets* id_offsets() const { return id_offsets_; }
  std::int64_t shifted_id(std::int64_t id, IdKind kind) const {
    return id_offsets_ != nullptr ? id_offsets_->shifted(id, kind) : id;
  }

  bool at_end() const { return next_ >= card_->lines.size(); }
  // True when at least one non-blank line remains.
  bool has_data() const;
  // The next data line; a missing line is a "truncated card" error naming what the line should hold.
  Line next(std::string_view what);
  // The next non-blank line, for list cards (node lists, id lists) that tolerate blank lines.
  std::optional<Line> next_nonblank();
  // Error when non-blank lines remain after the last line the card layout defines.
  void finish() const;

  // Integer path part (id, unit id...) of the keyword line; `index` counts from 0 over card().path.
  std::int64_t path_id(std::size_t index, std::string_view name, bool required) const;

  [[noreturn]] void fail(std::string_view field, std::string_view expected, std::string_view found) const;
  // The error fail() throws (about the keyword line), for callers that may record it instead.
  DeckError error(std::string_view field, std::string_view expected, std::string_view found) const;

  // Fixed-format cards: text in columns of the lines read that no field of the card covers. Blank or zero text
  // there is the default of a field Crumple does not read; anything else would be a value silently dropped, so it
  // is returned as an error naming its columns (the first one found).
  std::optional<DeckError> unread_columns_error() const;
  void mark_read(std::size_t line, int column, int width) const;  // called by the field readers of Line

  // Input versions 41 to 44 (docs/deck-format.md, "Input versions"): integer and text fields 8 columns wide, reals
  // 16, the title on the keyword line. A field the readers ask at 2017 column c and width w is read at column
  // 1 + 4 (c - 1) / 5, width 4 w / 5; the few cards whose old fields lie elsewhere read them as_written().
  void use_narrow_layout() { narrow_ = true; }
  bool narrow() const { return narrow_; }
  // Narrow layout: the keyword line as written after path part `index` - 1, the card's title (read_title).
  void title_after(std::size_t index) { title_part_ = index; }
  std::string keyword_title() const;

 private:
  bool narrow_ = false;
  std::size_t title_part_ = 0;  // 0: none
  const Card* card_;
  const SourceText* text_;
  const UnitSystem* units_;
  const std::map<std::int64_t, UnitSystem>* local_units_ = nullptr;
  const IdOffsets* id_offsets_ = nullptr;
  std::size_t next_ = 0;
  mutable std::vector<std::vector<bool>> read_columns_;  // per data line: the columns a field read
};

}  // namespace crumple
