#include "keyword_catalog.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace crumple::deck {
namespace {

std::vector<std::string> split_name(std::string_view name) {
  std::vector<std::string> parts;
  std::size_t start = 1;
  while (start <= name.size()) {
    const auto slash = name.find('/', start);
    const auto end = slash == std::string_view::npos ? name.size() : slash;
    if (end > start) parts.emplace_back(name.substr(start, end - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return parts;
}

std::vector<RadiossKeyword> parse_list(std::string_view text) {
  std::vector<RadiossKeyword> list;
  bool section_seen = false;
  DeckPart part = DeckPart::Starter;
  while (!text.empty()) {
    const auto newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    if (line == "[starter]" || line == "[engine]") {
      part = line == "[starter]" ? DeckPart::Starter : DeckPart::Engine;
      section_seen = true;
      continue;
    }
    // The list is build input: a malformed line is a bug of the repository, found by the first unit test.
    if (!section_seen || line.front() != '/')
      throw std::logic_error("radioss_keywords.txt: malformed line '" + std::string(line) + "'");
    list.push_back({std::string(line), split_name(line), part});
  }
  return list;
}

bool matches(const RadiossKeyword& k, const std::vector<std::string>& path) {
  if (k.parts.size() > path.size()) return false;
  for (std::size_t i = 0; i < k.parts.size(); ++i)
    if (k.parts[i] != "*" && k.parts[i] != path[i]) return false;
  return true;
}

bool starts_with(const std::vector<std::string>& path, std::initializer_list<std::string_view> prefix) {
  return path.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

}  // namespace

const std::vector<RadiossKeyword>& radioss_keywords() {
  static const std::vector<RadiossKeyword> list = parse_list(kRadiossKeywordsText);
  return list;
}

const RadiossKeyword* find_radioss_keyword(const std::vector<std::string>& path, DeckPart part) {
  const RadiossKeyword* best = nullptr;
  for (const RadiossKeyword& k : radioss_keywords())
    if (k.part == part && matches(k, path) && (best == nullptr || k.parts.size() > best->parts.size())) best = &k;
  return best;
}

CardClass card_class(const std::vector<std::string>& path, DeckPart part) {
  if (path.empty()) return CardClass::Model;
  const std::string& first = path[0];
  // Output requests: animations, time histories (and the extra time-history files /ATH../ITH), accelerometers,
  // listing and file controls. They change what is written, never what is computed.
  constexpr std::array<std::string_view, 12> kStarterOutput{"ANIM", "TH",  "ATH", "BTH", "CTH",    "DTH",
                                                            "ETH",  "FTH", "GTH", "HTH", "ITH",    "ACCEL"};
  constexpr std::array<std::string_view, 16> kEngineOutput{"ANIM", "TH",    "@TFILE", "ABF",  "ATFILE", "H3D",
                                                           "OUTP", "STATE", "PRINT",  "TFILE", "MON",   "RFILE",
                                                           "CHKPT", "INTTH", "TITLE", "VERS"};
  // Parallel decomposition, memory and vector-length hints: the same results on any machine.
  constexpr std::array<std::string_view, 4> kStarterPerformance{"SPMD", "PROC", "MEMORY", "ARCH"};
  constexpr std::array<std::string_view, 2> kEnginePerformance{"PARITH", "PROC"};
  const auto in = [&first](auto const& list) { return std::find(list.begin(), list.end(), first) != list.end(); };
  if (part == DeckPart::Starter) {
    if (in(kStarterOutput) || starts_with(path, {"IOFLAG"}) || starts_with(path, {"CHECK", "RFILE"}))
      return CardClass::OutputOnly;
    if (in(kStarterPerformance)) return CardClass::PerformanceHint;
    return CardClass::Model;
  }
  if (in(kEngineOutput)) return CardClass::OutputOnly;
  if (in(kEnginePerformance)) return CardClass::PerformanceHint;
  return CardClass::Model;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string nearest_keyword(std::string_view name) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
  auto consider = [&](std::string_view candidate) {
    if (candidate.find('*') != std::string_view::npos) return;
    const std::size_t d = edit_distance(name, candidate);
    if (d < best_distance) best_distance = d, best = std::string(candidate);
  };
  for (const KeywordSpec& spec : keyword_table()) consider(spec.name);  // Crumple's own names first on ties
  for (const RadiossKeyword& k : radioss_keywords()) consider(k.name);
  return best;
}

}  // namespace crumple::deck
