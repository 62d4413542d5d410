// read_deck: source text -> cards -> keyword handlers (records with user ids) -> resolve (dense indices, checks).
#include "crumple/deck/reader.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "context.hpp"
#include "keyword_catalog.hpp"
#include "resolve.hpp"

namespace crumple {
namespace deck {
namespace {

constexpr std::size_t kMaxErrors = 100;

std::vector<std::string_view> name_parts(std::string_view name) {
  std::vector<std::string_view> parts;
  std::size_t start = 1;
  while (start <= name.size()) {
    const auto slash = name.find('/', start);
    const auto end = slash == std::string_view::npos ? name.size() : slash;
    parts.push_back(name.substr(start, end - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return parts;
}

// The spec whose name is the longest prefix of the card's path, in the requested deck part.
const KeywordSpec* find_spec(const Card& card, DeckPart part) {
  const KeywordSpec* best = nullptr;
  std::size_t best_length = 0;
  for (const KeywordSpec& spec : keyword_table()) {
    if (spec.part != part) continue;
    const auto parts = name_parts(spec.name);
    if (parts.size() > card.path.size() || parts.size() <= best_length) continue;
    if (std::equal(parts.begin(), parts.end(), card.path.begin())) {
      best = &spec;
      best_length = parts.size();
    }
  }
  return best;
}

// Keyword name without ids: the leading path parts that are not numbers.
std::string keyword_name(const Card& card) {
  std::string name;
  for (const auto& part : card.path) {
    if (!part.empty() && (std::isdigit(static_cast<unsigned char>(part[0])) || part[0] == '-')) break;
    name += "/" + part;
  }
  return name.empty() ? card.keyword : name;
}

void note_once(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

bool is_card(const Card& card, std::initializer_list<std::string_view> path) {
  return card.path.size() == path.size() && std::equal(path.begin(), path.end(), card.path.begin());
}

// Fixed-format cards whose handlers other work owns (the shell and solid properties and defaults, the rigid
// walls) are left as they read today; every other starter card has each of its columns checked.
bool columns_checked(const KeywordSpec& spec) {
  for (std::string_view owned : {"/PROP", "/DEF_SHELL", "/DEF_SOLID", "/RWALL"})
    if (spec.name.substr(0, owned.size()) == owned) return false;
  return true;
}

const char* part_name(DeckPart part) { return part == DeckPart::Starter ? "starter" : "engine"; }

// A card that Crumple has no handler for, in this order: a Radioss output-only or performance card of this deck
// part (named warning); another Radioss keyword of this part (not supported by Crumple); a keyword of the other
// deck part (error); a word that is no keyword (unknown, with the nearest known keyword). The unsupported and
// unknown errors are those that --skip-unknown turns into warnings and skipped options.
void read_card_without_handler(const Card& card, DeckPart part, const std::string& name, DeckContext& context) {
  const DeckPart other_part = part == DeckPart::Starter ? DeckPart::Engine : DeckPart::Starter;
  const RadiossKeyword* radioss = find_radioss_keyword(card.path, part);
  if (radioss == nullptr && (find_spec(card, other_part) != nullptr || find_radioss_keyword(card.path, other_part)))
    throw DeckError(card.where, card.keyword, "",
                    card.engine ? "an engine keyword (this one belongs to the starter deck, before /END)"
                                : "a starter keyword (this one belongs to the engine deck, after /END)",
                    "'" + card.keyword + "'");
  if (radioss != nullptr) {
    note_once(context.report.keywords_read, name);
    switch (card_class(card.path, part)) {
      case CardClass::OutputOnly:
        note_once(context.report.accepted_without_effect, name);
        context.note(card.where, card.keyword, "",
                     fmt::format("output-only card ({}): not written by Crumple", radioss->name), SkipKind::OutputOnly);
        return;
      case CardClass::PerformanceHint:
        note_once(context.report.accepted_without_effect, name);
        context.note(card.where, card.keyword, "",
                     fmt::format("performance hint ({}): no effect on Crumple's results", radioss->name),
                     SkipKind::PerformanceHint);
        return;
      case CardClass::Model: break;
    }
    context.unsupported(
        DeckError(card.where, card.keyword, "", "a keyword Crumple supports (or --skip-unknown to skip it)",
                  fmt::format("the Radioss {} keyword {}, which is not supported by Crumple", part_name(part),
                              radioss->name)),
        fmt::format("keyword skipped (--skip-unknown): the Radioss {} keyword {} is not supported by Crumple",
                    part_name(part), radioss->name));
    return;
  }
  const std::string nearest = nearest_keyword(name);
  const std::string hint = nearest.empty() ? "" : fmt::format("nearest known keyword: {}", nearest);
  context.unsupported(
      DeckError(card.where, card.keyword, "",
                fmt::format("a Crumple or Radioss keyword{} (or --skip-unknown to skip it)",
                            hint.empty() ? "" : " (" + hint + ")"),
                fmt::format("unknown keyword '{}'", card.keyword)),
      fmt::format("unknown keyword skipped (--skip-unknown{})", hint.empty() ? "" : "; " + hint));
}

// One card to its handler (or to read_card_without_handler); its errors go to `record`.
template <class Record>
void dispatch(const Card& card, const SourceText& text, DeckContext& context, Record& record) {
  const DeckPart part = card.engine ? DeckPart::Engine : DeckPart::Starter;
  const KeywordSpec* spec = find_spec(card, part);
  const std::string name = keyword_name(card);
  if (spec == nullptr) {
    try {
      read_card_without_handler(card, part, name, context);
    } catch (const DeckError& e) {
      record(e);
    }
    return;
  }
  note_once(context.report.keywords_read, name);
  if (!spec->handler) {
    note_once(context.report.accepted_without_effect, name);
    return;
  }
  try {
    CardReader reader(card, text, context.model.units);
    reader.set_local_units(&context.local_units);
    if (!card.engine && !context.open_submodels.empty()) {  // a card of a //SUBMODEL block: its offsets and units
      SubmodelScope& block = context.open_submodels.back();
      reader.set_id_offsets(&block.offsets);
      if (block.unit_id != 0) reader.use_local_units(block.unit_id, "unit_ID");
      block.keywords.push_back(name);
    }
    if (!card.engine && narrow_layout_version(context.model.input_version) && !spec->same_layout_in_every_version)
      reader.use_narrow_layout();
    spec->handler(reader, context);
    if (!card.engine && columns_checked(*spec))
      if (const auto unread = reader.unread_columns_error()) context.unsupported(*unread);
  } catch (const DeckError& e) {
    record(e);
  }
}

// The engine decks of a continued run, NAME_0002.rad, NAME_0003.rad, ... as long as they follow each other: each
// one's cards read into its own run control (the model's is kept for NAME_0001.rad).
template <class Record>
void read_continued_runs(const std::filesystem::path& starter, Deck& deck, DeckContext& context, Record& record) {
  const RunControl first = deck.model.run;
  for (int k = 2;; ++k) {
    const std::filesystem::path engine = engine_deck_for(starter, k);
    if (engine.empty()) break;
    const SourceText text = read_source(engine);
    deck.report.files.insert(deck.report.files.end(), text.files.begin(), text.files.end());
    deck.model.run = RunControl{};
    context.run_seen = false;
    context.engine_deck = k;
    for (const Card& card : split_cards(text, 0)) {
      if (is_card(card, {"END", "ENGINE"}) || is_card(card, {"END"})) continue;  // an engine deck's closing /END
      dispatch(card, text, context, record);
    }
    if (!context.run_seen)
      record(DeckError(SourceLocation{text.files.front(), 0}, "/RUN", "", "a /RUN card in the engine deck",
                       "an engine deck without /RUN"));
    deck.continued_runs.push_back(std::move(deck.model.run));
  }
  deck.model.run = first;
  context.engine_deck = 1;
}

}  // namespace
}  // namespace deck

std::string SkippedOption::text() const {
  const char* label = kind == SkipKind::OutputOnly        ? "[output-only]"
                      : kind == SkipKind::PerformanceHint ? "[performance hint]"
                                                          : "[skipped]";
  const DeckWarning w{where, keyword, field.empty() ? what : "field " + field + ": " + what};
  return std::string(label) + " " + w.text();
}

std::filesystem::path engine_deck_for(const std::filesystem::path& starter, int number) {
  const std::string stem = starter.stem().string();
  if (stem.size() < 5 || stem.substr(stem.size() - 5) != "_0000" || number < 1 || number > 9999) return {};
  auto engine = starter;
  engine.replace_filename(fmt::format("{}_{:04d}{}", stem.substr(0, stem.size() - 5), number,
                                      starter.extension().string()));
  std::error_code ec;
  return std::filesystem::is_regular_file(engine, ec) ? engine : std::filesystem::path{};
}

Deck read_deck(const std::filesystem::path& starter, const ReadOptions& options) {
  using namespace deck;
  SourceText text = read_source(starter);
  std::int32_t first_engine_file = -1;
  if (const auto engine = engine_deck_for(starter); !engine.empty()) {
    first_engine_file = static_cast<std::int32_t>(text.files.size());
    append_source(text, engine);
  }
  const std::vector<Card> cards = split_cards(text, first_engine_file);

  Deck deck;
  deck.report.files = text.files;
  DeckContext context{deck.model, deck.report, options.skip_unknown, {}, {}, {}, {}};
  std::vector<DeckError> errors;
  auto record = [&](const DeckError& e) {
    if (errors.size() < kMaxErrors) errors.push_back(e);
  };

  bool starter_ended = false;
  bool engine_seen = false;
  bool begin_first = false;
  bool starter_started = false;
  bool units_read = false;
  const Card* first_starter_card = nullptr;
  for (std::size_t i = 0; i < cards.size(); ++i) {
    const Card& card = cards[i];
    if (!card.engine && is_card(card, {"END"})) {
      starter_ended = true;
      continue;
    }
    // The engine deck may close with /END (as decks of every version do; the reference reads them).
    if (card.engine && (is_card(card, {"END", "ENGINE"}) || is_card(card, {"END"}))) continue;
    if (card.engine) engine_seen = true;
    const bool unit_card = !card.engine && !card.path.empty() && card.path[0] == "UNIT";
    if (unit_card && units_read) continue;  // read with /BEGIN
    if (!card.engine && !starter_started) {
      starter_started = true;
      // /BEGIN/0 is /BEGIN in old decks (the reference reads it so: the QA deck RESSORT/prop_type25/input_51).
      begin_first = is_card(card, {"BEGIN"}) || is_card(card, {"BEGIN", "0"});
      first_starter_card = &card;
    }

    dispatch(card, text, context, record);
    // The /UNIT systems right after /BEGIN (its units complete them), before any card that names one.
    if (!card.engine && is_card(card, {"BEGIN"}) && !units_read) {
      units_read = true;
      int depth = 0;  // of //SUBMODEL blocks
      for (const Card& unit : cards) {
        if (unit.engine || unit.path.empty()) continue;
        if (unit.path.size() > 1 && unit.path[0].empty())
          depth += unit.path[1] == "SUBMODEL" ? 1 : unit.path[1] == "ENDSUB" ? -1 : 0;
        if (unit.path[0] != "UNIT") continue;
        if (depth > 0)
          record(DeckError(unit.where, unit.keyword, "",
                           "/UNIT outside //SUBMODEL blocks (a /UNIT inside one is not supported by Crumple: define "
                           "it before the block, with the id the block's offset gives it)",
                           "a /UNIT inside a //SUBMODEL block"));
        else
          dispatch(unit, text, context, record);
      }
    }
  }
  for (const SubmodelScope& open : context.open_submodels)
    record(DeckError(open.where, "//SUBMODEL", "", "//ENDSUB closing the block before /END", "no //ENDSUB"));

  const SourceLocation starter_file{text.files.front(), 0};
  if (!begin_first)
    errors.insert(errors.begin(),
                  DeckError(first_starter_card ? first_starter_card->where : starter_file, "/BEGIN", "",
                            "/BEGIN as the first keyword of the starter deck",
                            first_starter_card ? "'" + first_starter_card->keyword + "'" : "no starter keyword"));
  if (!starter_ended) {
    // Point at the last line of the starter part (the place where /END belongs), else at the file.
    SourceLocation end_where = starter_file;
    for (auto it = text.lines.rbegin(); it != text.lines.rend(); ++it)
      if (first_engine_file < 0 || it->file < first_engine_file) {
        end_where = text.where(*it);
        break;
      }
    record(DeckError(end_where, "/END", "", "/END closing the starter deck", "end of file without /END"));
  }
  if (engine_seen && !context.run_seen)
    record(DeckError(SourceLocation{text.files.back(), 0}, "/RUN", "", "a /RUN card in the engine deck",
                     "an engine deck without /RUN"));
  // An engine deck beside the starter that holds no keyword (only comments and blank lines) is an error of its
  // own, not a deck to skip.
  if (first_engine_file >= 0) {
    const std::string& engine_file = text.files[static_cast<std::size_t>(first_engine_file)];
    if (std::none_of(cards.begin(), cards.end(), [&](const Card& c) { return c.where.file == engine_file; }))
      record(DeckError(SourceLocation{engine_file, 0}, "/RUN", "", "the engine deck's keywords (/RUN first)",
                       "no keyword: only comments and blank lines"));
  }
  if (options.require_engine && !engine_seen)
    record(DeckError(starter_file, "/RUN", "",
                     "an engine deck (NAME_0001.rad beside NAME_0000.rad, or engine cards after /END)", "none"));
  if (!errors.empty()) throw DeckErrors(std::move(errors));
  read_continued_runs(starter, deck, context, record);
  if (!errors.empty()) throw DeckErrors(std::move(errors));

  resolve_model(context, deck.continued_runs);
  return deck;
}

}  // namespace crumple
