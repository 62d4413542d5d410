#include "crumple/deck/fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace crumple {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::optional<double> parse_fortran_real(std::string_view raw) {
  const std::string_view text = trim(raw);
  if (text.empty() || text.size() > 64) return std::nullopt;
  // Grammar: [sign] (digits [. digits*] | . digits) [(E|e|D|d) [sign] digits]
  std::string normal;
  std::size_t i = 0;
  auto digit = [&](std::size_t k) { return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])); };
  if (text[i] == '-') normal += '-';
  if (text[i] == '+' || text[i] == '-') ++i;
  if (i < text.size() && text[i] == '.') normal += '0';  // from_chars needs a digit before the point
  std::size_t mantissa_digits = 0;
  while (digit(i)) normal += text[i++], ++mantissa_digits;
  if (i < text.size() && text[i] == '.') {
    normal += text[i++];
    if (!digit(i)) normal += '0';
    while (digit(i)) normal += text[i++], ++mantissa_digits;
  }
  if (mantissa_digits == 0) return std::nullopt;
  if (i < text.size()) {
    const char e = text[i];
    if (e != 'E' && e != 'e' && e != 'D' && e != 'd') return std::nullopt;
    normal += 'e';
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) normal += text[i++];
    if (!digit(i)) return std::nullopt;
    while (digit(i)) normal += text[i++];
    if (i != text.size()) return std::nullopt;
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(normal.data(), normal.data() + normal.size(), value);
  if (ec == std::errc::result_out_of_range) return std::nullopt;
  if (ec != std::errc() || end != normal.data() + normal.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view raw) {
  std::string_view text = trim(raw);
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return std::nullopt;  // "+-5": one sign only
  }
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

std::vector<std::string> split_path(std::string_view keyword) {
  std::vector<std::string> parts;
  std::size_t start = 1;  // skip the leading '/'
  while (start <= keyword.size()) {
    const auto slash = keyword.find('/', start);
    const auto end = slash == std::string_view::npos ? keyword.size() : slash;
    parts.emplace_back(trim(keyword.substr(start, end - start)));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return parts;
}

bool is_comment(const std::string& text) { return !text.empty() && (text[0] == '#' || text[0] == '$'); }

std::string quote_text(std::string_view s) {
  std::string out = "'";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 32 || u >= 127) out += fmt::format("\\x{:02x}", u);
    else out += c;
  }
  return out + "'";
}

}  // namespace

std::vector<Card> split_cards(const SourceText& text, std::int32_t first_engine_file) {
  std::vector<Card> cards;
  bool after_starter_end = false;
  bool engine_keyword_seen = false;  // a keyword of the engine deck's file (first_engine_file) has been read
  for (const SourceLine& line : text.lines) {
    if (is_comment(line.text)) continue;
    const bool engine_file = first_engine_file >= 0 && line.file >= first_engine_file;
    if (!line.text.empty() && line.text[0] == '/') {
      Card card;
      const std::string_view keyword = trim(line.text);
      card.keyword = std::string(keyword);
      card.path = split_path(keyword);
      // A trailing slash ends the keyword line, as in "/BEGIN/" or "/RUN/name/1/" (Radioss reads them so).
      while (card.path.size() > 1 && card.path.back().empty()) card.path.pop_back();
      for (auto& part : card.path) part = upper(part);
      // Radioss reads a material law number as a number: /MAT/LAW01 is /MAT/LAW1 (QA deck contact_idel).
      if (card.path.size() > 1 && card.path[0] == "MAT" && card.path[1].size() > 4 &&
          card.path[1].compare(0, 4, "LAW0") == 0 &&
          std::all_of(card.path[1].begin() + 3, card.path[1].end(), [](unsigned char c) { return std::isdigit(c); })) {
        const auto first = card.path[1].find_first_not_of('0', 3);
        card.path[1] = "LAW" + (first == std::string::npos ? std::string("0") : card.path[1].substr(first));
      }
      card.where = text.where(line);
      card.engine = engine_file || after_starter_end;
      engine_keyword_seen = engine_keyword_seen || engine_file;
      if (!card.engine && card.path.size() == 1 && card.path[0] == "END") after_starter_end = true;
      cards.push_back(std::move(card));
      continue;
    }
    // Data before the first keyword of a file that opens a deck (the starter, or the engine deck read after it) is
    // an error: it would otherwise be taken as the last card's data, or skipped.
    const bool before_any_keyword = cards.empty() || (engine_file && !engine_keyword_seen);
    if (before_any_keyword) {
      if (trim(line.text).empty()) continue;
      throw DeckError(text.where(line), "", "", "a keyword line starting with '/' or a comment",
                      "data " + quote_text(trim(line.text).substr(0, 40)) + " before any keyword");
    }
    cards.back().lines.push_back(&line);
  }
  // Radioss single-file form: engine cards first, closed by /END/ENGINE, then /BEGIN ... /END.
  for (std::size_t k = 0; k < cards.size() && !cards[k].engine; ++k) {
    if (cards[k].path.size() == 1 && cards[k].path[0] == "BEGIN") break;
    if (cards[k].path.size() == 2 && cards[k].path[0] == "END" && cards[k].path[1] == "ENGINE") {
      for (std::size_t j = 0; j <= k; ++j) cards[j].engine = true;
      break;
    }
  }
  return cards;
}

// ---------------------------------------------------------------------------------------------------------------
// Line

SourceLocation Line::where() const { return reader_->text().where(*source_); }

bool Line::blank() const { return trim(source_->text).empty(); }

std::pair<int, int> Line::placed(int column, int width) const {
  if (!reader_->narrow() || as_written_ || width <= 0) return {column, width};
  return {1 + 4 * (column - 1) / 5, std::max(1, 4 * width / 5)};  // a one-column flag stays one column
}

std::string Line::raw(int given_column, int given_width) const {
  const auto [column, width] = placed(given_column, given_width);
  reader_->mark_read(index_, column, width);
  const auto& s = source_->text;
  const auto begin = static_cast<std::size_t>(column - 1);
  std::string out = begin < s.size() ? s.substr(begin, static_cast<std::size_t>(width)) : std::string();
  out.resize(static_cast<std::size_t>(width), ' ');
  return out;
}

std::string Line::text(int column, int width) const { return std::string(trim(raw(column, width))); }

std::string Line::field_label(int given_column, int given_width, std::string_view name) const {
  if (given_width <= 0) return std::string(name);
  const auto [column, width] = placed(given_column, given_width);
  return fmt::format("{} (columns {}-{})", name, column, column + width - 1);
}

DeckError Line::error(int column, int width, std::string_view name, std::string_view expected) const {
  const std::string found = width > 0 ? quote_text(trim(raw(column, width))) : quote_text(trim(source_->text));
  return DeckError(where(), reader_->card().keyword, field_label(column, width, name), std::string(expected), found);
}

void Line::fail(int column, int width, std::string_view name, std::string_view expected) const {
  throw error(column, width, name, expected);
}

void Line::fail_value(std::string_view name, std::string_view expected, std::string_view found) const {
  throw DeckError(where(), reader_->card().keyword, std::string(name), std::string(expected), std::string(found));
}

namespace {
// A field name that says it holds an id: "grnd_ID", "node_ID1", "fct_IDp", "Slav_id", "RBID" (not "Isolid").
bool names_an_id(std::string_view name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower.find("_id") != std::string::npos || name.ends_with("ID");
}
}  // namespace

std::int64_t Line::integer(int column, int width, std::string_view name, std::int64_t fallback) const {
  const std::int64_t value = parsed_integer(column, width, name, fallback);
  if (value > 0 && reader_->id_offsets() != nullptr && names_an_id(name))
    fail(column, width, name,
         "blank or 0 inside //SUBMODEL (Crumple does not shift this id by the block's offset, so it would name "
         "another object)");
  return value;
}

std::int64_t Line::id(int column, int width, std::string_view name, IdKind kind) const {
  return reader_->shifted_id(parsed_integer(column, width, name, 0), kind);
}

std::int64_t Line::optional_id(int column, int width, std::string_view name, IdKind kind) const {
  const std::int64_t value = id(column, width, name, kind);
  if (value < 0) fail(column, width, name, "a non-negative id (0 or blank: none)");
  return value;
}

std::int64_t Line::parsed_integer(int column, int width, std::string_view name, std::int64_t fallback) const {
  const std::string field = raw(column, width);
  if (trim(field).empty()) return fallback;
  if (auto v = parse_integer(field)) {
    // Radioss integers are 32-bit; a larger value would wrap silently where a flag is stored as an int.
    if (*v < INT32_MIN || *v > INT32_MAX) fail(column, width, name, "an integer between -2147483648 and 2147483647");
    return *v;
  }
  fail(column, width, name, "an integer");
}

namespace {
std::vector<std::string> split_words(const std::string& text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}
}  // namespace

// A value read in the input units, converted to the working ones.
double Line::real_value(int column, int width, std::string_view name, Dimension d, double v) const {
  const double converted = v * reader_->units().factor(d);
  // A value that the /BEGIN unit conversion turns into infinity (or a non-zero value into 0) would pass the
  // range checks of the card with a meaning the user never wrote.
  if (!std::isfinite(converted) || (converted == 0.0) != (v == 0.0))
    fail(column, width, name, "a value that stays finite and non-zero after conversion to the working units");
  return converted;
}

double Line::real(int column, int width, std::string_view name, Dimension d, double fallback) const {
  const std::string field = raw(column, width);
  if (trim(field).empty()) return fallback * reader_->units().factor(d);
  if (auto v = parse_fortran_real(field)) return real_value(column, width, name, d, *v);
  // A field that holds several numbers apart (a misaligned deck): the reference reads the first and so does Crumple
  // (measured: delta_max written "0.03      .000000000" breaks the spring at 0.03). Anything else is an error.
  const auto words = split_words(field);
  if (words.size() > 1 && std::all_of(words.begin(), words.end(), [](const std::string& w) { return parse_fortran_real(w).has_value(); }))
    return real_value(column, width, name, d, *parse_fortran_real(words.front()));
  fail(column, width, name, "a real number");
}

namespace {
std::vector<std::string_view> tokens_of(const std::string& text) {
  std::vector<std::string_view> out;
  std::string_view s(text);
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == ',')) ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != ',') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}
}  // namespace

std::size_t Line::token_count() const { return tokens_of(source_->text).size(); }

double Line::token_real(std::size_t index, std::string_view name, Dimension d, std::optional<double> fallback) const {
  const auto tokens = tokens_of(source_->text);
  if (index >= tokens.size()) {
    if (fallback) return *fallback * reader_->units().factor(d);
    fail_value(fmt::format("{} (value {})", name, index + 1), "a real number", "end of line");
  }
  if (auto v = parse_fortran_real(tokens[index])) {
    const double converted = *v * reader_->units().factor(d);
    if (!std::isfinite(converted) || (converted == 0.0) != (*v == 0.0))
      fail_value(fmt::format("{} (value {})", name, index + 1),
                 "a value that stays finite and non-zero after conversion to the working units",
                 quote_text(tokens[index]));
    return converted;
  }
  fail_value(fmt::format("{} (value {})", name, index + 1), "a real number", quote_text(tokens[index]));
}

std::int64_t Line::token_integer(std::size_t index, std::string_view name, std::optional<std::int64_t> fallback) const {
  const auto tokens = tokens_of(source_->text);
  if (index >= tokens.size()) {
    if (fallback) return *fallback;
    fail_value(fmt::format("{} (value {})", name, index + 1), "an integer", "end of line");
  }
  if (auto v = parse_integer(tokens[index])) return *v;
  fail_value(fmt::format("{} (value {})", name, index + 1), "an integer", quote_text(tokens[index]));
}

// ---------------------------------------------------------------------------------------------------------------
// CardReader

bool CardReader::has_data() const {
  for (std::size_t i = next_; i < card_->lines.size(); ++i)
    if (!trim(card_->lines[i]->text).empty()) return true;
  return false;
}

Line CardReader::next(std::string_view what) {
  if (at_end()) {
    const SourceLocation where =
        card_->lines.empty() ? card_->where : text_->where(*card_->lines.back());
    throw DeckError(where, card_->keyword, "", fmt::format("a line with {} (truncated card)", what),
                    "end of card");
  }
  const std::size_t index = next_++;
  return Line(*this, *card_->lines[index], index);
}

std::optional<Line> CardReader::next_nonblank() {
  while (!at_end()) {
    const std::size_t index = next_++;
    Line line(*this, *card_->lines[index], index);
    if (!line.blank()) return line;
  }
  return std::nullopt;
}

void CardReader::finish() const {
  for (std::size_t i = next_; i < card_->lines.size(); ++i) {
    const SourceLine& line = *card_->lines[i];
    if (!trim(line.text).empty())
      throw DeckError(text_->where(line), card_->keyword, "", "no more data lines for this keyword",
                      quote_text(trim(line.text).substr(0, 40)));
  }
}

std::int64_t CardReader::path_id(std::size_t index, std::string_view name, bool required) const {
  if (index >= card_->path.size() || card_->path[index].empty()) {
    if (!required) return 0;
    throw DeckError(card_->where, card_->keyword, std::string(name), "an id in the keyword line", "none");
  }
  if (auto v = parse_integer(card_->path[index]); v && *v >= 0) return *v;
  throw DeckError(card_->where, card_->keyword, std::string(name), "a non-negative integer id in the keyword line",
                  quote_text(card_->path[index]));
}

void CardReader::use_local_units(std::int64_t id, std::string_view field) {
  if (local_units_ != nullptr)
    if (const auto found = local_units_->find(id); found != local_units_->end()) {
      units_ = &found->second;
      return;
    }
  throw DeckError(card_->where, card_->keyword, std::string(field), "the id of a /UNIT card of the deck (or 0)",
                  fmt::format("unit {} not defined", id));
}

std::string CardReader::keyword_title() const {
  if (title_part_ == 0) return {};
  // After the title_part_-th slash that follows the leading one, as written (the path parts are upper-cased).
  const std::string& k = card_->keyword;
  std::size_t at = 0;
  for (std::size_t slashes = 0; slashes <= title_part_; ++slashes) {
    at = k.find('/', at);
    if (at == std::string::npos) return {};
    ++at;
  }
  return std::string(trim(std::string_view(k).substr(at)));
}

void CardReader::mark_read(std::size_t line, int column, int width) const {
  if (column < 1 || width <= 0) return;
  if (read_columns_.size() <= line) read_columns_.resize(line + 1);
  auto& read = read_columns_[line];
  const auto end = static_cast<std::size_t>(column - 1 + width);
  if (read.size() < end) read.resize(end, false);
  for (auto k = static_cast<std::size_t>(column - 1); k < end; ++k) read[k] = true;
}

std::optional<DeckError> CardReader::unread_columns_error() const {
  for (std::size_t i = 0; i < next_ && i < card_->lines.size(); ++i) {
    const std::string& text = card_->lines[i]->text;
    const std::vector<bool> none;
    const std::vector<bool>& read = i < read_columns_.size() ? read_columns_[i] : none;
    std::size_t k = 0;
    while (k < text.size()) {
      const bool unread = k >= read.size() || !read[k];
      if (!unread || text[k] == ' ' || text[k] == '\t' || text[k] == '\r') {
        ++k;
        continue;
      }
      std::size_t end = k;  // the unread word starting at column k + 1
      while (end < text.size() && (end >= read.size() || !read[end]) && text[end] != ' ' && text[end] != '\t' &&
             text[end] != '\r')
        ++end;
      const std::string_view word(text.data() + k, end - k);
      const auto value = parse_fortran_real(word);
      if (!value || *value != 0.0) {
        const int first = static_cast<int>(k) + 1, last = static_cast<int>(end);
        return DeckError(text_->where(*card_->lines[i]), card_->keyword,
                         fmt::format("(none, columns {}-{})", first, last),
                         "blank or 0 in columns that no field of this card layout uses (Crumple reads no option "
                         "there; a shifted field or an option of another layout)",
                         quote_text(word));
      }
      k = end;
    }
  }
  return std::nullopt;
}

DeckError CardReader::error(std::string_view field, std::string_view expected, std::string_view found) const {
  return DeckError(card_->where, card_->keyword, std::string(field), std::string(expected), std::string(found));
}

void CardReader::fail(std::string_view field, std::string_view expected, std::string_view found) const {
  throw error(field, expected, found);
}

}  // namespace crumple
