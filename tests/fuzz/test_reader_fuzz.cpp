// Mutation fuzz test of the deck reader.
//
// The QA decks (starter and engine) are loaded into memory once; every iteration applies 1-4 random mutations
// (bytes, lines, fields, cards, includes), writes the result to a temporary folder and calls read_deck. The
// reader must either accept the deck (and then the model must be sane: finite coordinates, positive densities...)
// or throw DeckErrors / DeckError whose messages are non-empty and name a file. Any other exception, a call slower
// than the per-call limit, a crash or a sanitizer report is a reader bug.
//
// Environment:
//   CRUMPLE_FUZZ_SECONDS    total time budget (default 20); iterations are bounded by time, not by count
//   CRUMPLE_FUZZ_SEED       base seed (default below); iteration i uses a generator seeded from (seed, i)
//   CRUMPLE_FUZZ_ITERATION  replay that single iteration of the seed (ignores the time budget)
//   CRUMPLE_FUZZ_CALL_LIMIT per-call limit in seconds (default 2): a read_deck that uses more CPU time is a hang.
//                           The machine may be shared, so wall-clock time only counts beyond 5 limits (a call
//                           blocked on a pipe uses no CPU); a call still running after 60 s aborts with a dump.
// A failure writes the mutated deck, ready for `crumple check`, under CRUMPLE_FUZZ_DUMP_DIR (build folder).
#include <gtest/gtest.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <utility>
#include <vector>

#include "crumple/deck/reader.hpp"
#include "deck_files.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define CRUMPLE_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CRUMPLE_FUZZ_ASAN 1
#endif
#endif
#ifdef CRUMPLE_FUZZ_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

namespace crumple::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::uint64_t kDefaultSeed = 0x5EED'C0DE'2026ULL;
constexpr double kDefaultSeconds = 20.0;
constexpr double kDefaultCallLimit = 2.0;  // seconds of CPU; a call that needs more is reported as a hang
constexpr double kBlockedFactor = 5.0;     // a call that waits this many limits (wall clock) is reported too
constexpr double kWatchdogSeconds = 60.0;  // a call still running after this aborts the process with a dump
constexpr int kMaxReportedFailures = 10;   // stop fuzzing after this many failures

// ---------------------------------------------------------------------------------------------------------------
// Environment and randomness

std::optional<std::string> env(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::string(value);
}

std::uint64_t env_seed() {
  const auto text = env("CRUMPLE_FUZZ_SEED");
  return text ? std::strtoull(text->c_str(), nullptr, 0) : kDefaultSeed;
}

double env_seconds(const char* name, double fallback) {
  const auto text = env(name);
  if (!text) return fallback;
  const double value = std::strtod(text->c_str(), nullptr);
  return value > 0.0 ? value : fallback;
}

// splitmix64: small, fast, and identical on every platform (std distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
  bool chance(double p) { return static_cast<double>(next() >> 11) * 0x1.0p-53 < p; }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[below(items.size())];
  }

 private:
  std::uint64_t state_;
};

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::uint64_t iteration_seed(std::uint64_t seed, std::uint64_t iteration) {
  Rng mix(seed ^ (iteration * 0xD1B54A32D192ED03ULL));
  mix.next();
  return mix.next();
}

// ---------------------------------------------------------------------------------------------------------------
// Inputs

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

struct QaDeck {
  std::string name;  // NAME of NAME_0000.rad
  std::string starter;
  std::string engine;
};

std::vector<QaDeck> load_qa_decks() {
  std::vector<QaDeck> decks;
  const fs::path qa = CRUMPLE_QA_DIR;
  for (const auto& [folder, name] : {std::pair{"box_crush", "BOX1BL"}, std::pair{"ball_on_wall", "BOULE1V4"}}) {
    const fs::path starter = qa / folder / (std::string(name) + "_0000.rad");
    const fs::path engine = qa / folder / (std::string(name) + "_0001.rad");
    decks.push_back({name, read_text(starter), read_text(engine)});
  }
  return decks;
}

using Lines = std::vector<std::string>;

Lines split_lines(const std::string& text) {
  Lines lines;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      return lines;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
}

std::string join_lines(const Lines& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i == 0 ? "" : "\n") + lines[i];
  return text;
}

bool is_keyword(const std::string& line) { return !line.empty() && line[0] == '/'; }
bool is_comment(const std::string& line) { return !line.empty() && (line[0] == '#' || line[0] == '$'); }
bool is_data(const std::string& line) { return !is_keyword(line) && !is_comment(line) && !line.empty(); }

// Cards (keyword line and its lines up to the next keyword) of a text.
std::vector<std::string> cards_of(const std::string& text) {
  std::vector<std::string> cards;
  for (const std::string& line : split_lines(text)) {
    if (is_keyword(line))
      cards.push_back(line + "\n");
    else if (!cards.empty() && !is_comment(line))
      cards.back() += line + "\n";
  }
  return cards;
}

// Cards of keywords the QA decks do not use, so that mutations reach their handlers too.
std::vector<std::string> synthetic_cards() {
  return {
      "/MAT/LAW36/77\ntabulated\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + R(0.5) + "\n" + I(2) + I(0) + R(0.0) +
          R(0.0) + "\n" + I(0) + R(1.0) + I(0) + "\n" + I(1) + I(2) + "\n" + R(1.0) + R(1.0) + "\n" + R(0.0) + R(1.0) +
          "\n",
      "/MAT/PLAS_TAB/78\ntabulated\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + I(1) + "\n\n" + I(1) + "\n\n",
      "/MAT/PLAS_JOHNS/79\nIflag 1\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + I(1) + "\n" + R(2e8) + R(3e8) + R(0.2) +
          "\n",
      "/MAT/ELAST/80\nelastic\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n",
      "/FUNCT/1\ncurve\n" + R(0.0) + R(1.0) + "\n" + R(1.0) + R(2.0) + "\n",
      "/FUNCT/2\ncurve\n" + R(0.0) + R(2.0) + "\n" + R(0.5) + R(3.0) + "\n" + R(1.0) + R(4.0) + "\n",
      "/BRICK/88\n" + I(1) + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + I(7) + I(8) + "\n",
      "/SH3N/1\n" + I(9001) + I(1) + I(2) + I(3) + "\n",
      "/PROP/TYPE14/88\nsolid\n" + I(14) + I(0) + "\n" + R(1.1) + R(0.05) + R(0.1) + "\n",
      "/PROP/SHELL/89\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(3) + I(0) + R(0.001) + "\n",
      "/PART/88\nbrick part\n" + I(88) + I(80) + "\n",
      "/SURF/SEG/77\nsegments\n" + I(1) + I(1) + I(2) + I(3) + I(4) + "\n" + I(2) + I(2) + I(3) + I(4) + "\n",
      "/GRNOD/PART/78\nby part\n" + I(1) + I(2) + "\n",
      "/GRNOD/GRNOD/79\ncycle\n" + I(79) + "\n",
      "/GRNOD/NODE/90\nnodes\n" + I(1) + I(2) + I(3) + I(-4) + "\n",
      "/GRSHEL/PART/80\nby part\n" + I(1) + "\n",
      "/GRSHEL/SHEL/81\nby id\n" + I(1) + I(2) + I(3) + "\n",
      "/SUBSET/81\nsubset\n" + I(82) + "\n",
      "/SUBSET/82\nsubset\n" + I(81) + "\n",
      "/DEF_SHELL\n" + I(24) + I(0) + I(0) + I(0) + I(0) + I(0) + I(0) + I(2) + I(0) + "\n",
      "/DEF_SOLID\n" + I(14) + I(0) + "\n",
      "/BEGIN\nAGAIN\n      2019         0\n" + R("Mg") + R("mm") + R("ms") + "\n" + R("1e200") + R("in") +
          R("1e-200") + "\n",
      "/TITLE\n" + std::string(200, 'x') + "\n",
      "/END\n",
      "/END/ENGINE\n",
      "/RUN/X/1\n0.1\n",
  };
}

// Keyword lines that do not exist in the QA decks: malformed paths and ids.
std::vector<std::string> synthetic_keywords() {
  return {"/",
          "//",
          "///",
          "/END",
          "/END/ENGINE",
          "/BEGIN",
          "/NODE/abc",
          "/NODE/-1",
          "/SHELL/-1",
          "/SHELL/0",
          "/SHELL/x",
          "/SHELL",
          "/SHELL/99999999999999999999",
          "/PART/9223372036854775807",
          "/MAT/LAW36/1",
          "/PROP/TYPE14/5",
          "/GRNOD/GRNOD/1",
          "/SURF/SEG/1",
          "/SUBSET/1",
          "/FUNCT/1",
          "/BRICK/1",
          "/SH3N/1",
          "/RUN/X/1",
          "/RUN",
          "/TFILE",
          "/end",
          " /NODE",
          "/NODE /",
          "/MAT//1",
          "/ MAT/ELAST/1",
          "/PROP/TYPE1/-7"};
}

const std::vector<std::string>& interesting_numbers() {
  static const std::vector<std::string> numbers = {
      "1E308",
      "-1E308",
      "1E309",
      "1e-400",
      "4.9e-324",
      "1.7976931348623157E308",
      "99999999999999999999",
      "9223372036854775807",
      "-9223372036854775808",
      "9223372036854775808",
      "2147483647",
      "2147483648",
      "4294967296",
      "4294967297",
      "4294967320",
      "-2147483649",
      "NaN",
      "nan",
      "-nan",
      "inf",
      "-Infinity",
      "1.#QNAN",
      "1.#INF",
      "0x1p3",
      "0x10",
      "1D999",
      "-0",
      "0",
      "-1",
      "+",
      "-",
      ".",
      "E",
      "1E",
      "1.2.3",
      "--1",
      "1e+",
      "1,5",
      "1 2",
      "\xEF\xBC\x91",
      "\xD9\xA1",
      "1E-6",
      "1.D-3",
      ".3",
      "205",
      "+.5E+2",
      "1e+0000000000000000000000000000003",
      std::string(80, '9'),
      "0.000000000000000000000000000000000000000000000000000000000000000000001"};
  return numbers;
}

// ---------------------------------------------------------------------------------------------------------------
// Mutations. Each appends a short description to `log` so that a failure says what was done.

struct Pools {
  std::vector<std::string> keyword_lines;  // every keyword line of the QA decks, plus synthetic ones
  std::vector<std::string> cards;          // every card of the QA decks, plus synthetic ones
};

std::optional<std::size_t> pick_line(const Lines& lines, Rng& rng, bool (*accept)(const std::string&)) {
  if (lines.empty()) return std::nullopt;
  for (int attempt = 0; attempt < 64; ++attempt) {
    const std::size_t i = rng.below(lines.size());
    if (accept(lines[i])) return i;
  }
  return std::nullopt;
}

std::string printable(std::string_view text) {
  std::string out;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 32 || u >= 127) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", u);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out.size() > 60 ? out.substr(0, 60) + "..." : out;
}

void mutate_byte(std::string& text, Rng& rng, std::string& log) {
  static const std::string interesting = std::string("0123456789.E-+ /#\t\r\n$,dD") + '\0' + '\xFF';
  const char c = rng.chance(0.5) ? static_cast<char>(rng.below(256)) : interesting[rng.below(interesting.size())];
  const std::size_t pos = rng.below(text.size() + 1);
  const int how = static_cast<int>(rng.below(3));
  if (how == 0 && pos < text.size()) {
    text[pos] = c;
    log += "replace byte " + std::to_string(pos) + " by " + printable(std::string(1, c));
  } else if (how == 1 && pos < text.size()) {
    text[pos] = static_cast<char>(static_cast<unsigned char>(text[pos]) ^ (1u << rng.below(8)));
    log += "flip a bit of byte " + std::to_string(pos);
  } else {
    text.insert(pos, 1, c);
    log += "insert byte " + printable(std::string(1, c)) + " at " + std::to_string(pos);
  }
}

void mutate_lines(std::string& text, Rng& rng, const Pools& pools, const std::string& self_name,
                  const std::string& other_name, std::string& log) {
  Lines lines = split_lines(text);
  const auto n = lines.size();
  switch (rng.below(12)) {
    case 0: {
      const auto i = rng.below(n);
      log += "delete line " + std::to_string(i + 1);
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    }
    case 1: {
      const auto i = rng.below(n);
      log += "duplicate line " + std::to_string(i + 1);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), lines[i]);
      break;
    }
    case 2: {
      const auto i = rng.below(n), j = rng.below(n);
      log += "swap lines " + std::to_string(i + 1) + " and " + std::to_string(j + 1);
      std::swap(lines[i], lines[j]);
      break;
    }
    case 3: {
      const std::string& keyword = rng.pick(pools.keyword_lines);
      const auto i = rng.below(n + 1);
      log += "insert keyword line '" + printable(keyword) + "' before line " + std::to_string(i + 1);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), keyword);
      break;
    }
    case 4: {  // a number field: free token or fixed-width field
      const auto i = pick_line(lines, rng, is_data);
      if (!i) return mutate_byte(text, rng, log);
      std::string& line = lines[*i];
      const std::string& value = rng.pick(interesting_numbers());
      if (rng.chance(0.5)) {
        std::vector<std::pair<std::size_t, std::size_t>> tokens;
        for (std::size_t k = 0; k < line.size();) {
          while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
          const std::size_t start = k;
          while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
          if (k > start) tokens.emplace_back(start, k - start);
        }
        if (tokens.empty()) return mutate_byte(text, rng, log);
        const auto [start, length] = tokens[rng.below(tokens.size())];
        std::string replacement = value;
        if (replacement.size() < length) replacement.insert(0, length - replacement.size(), ' ');
        line.replace(start, length, replacement);
        log += "replace token at line " + std::to_string(*i + 1) + " column " + std::to_string(start + 1) + " by '" +
               printable(value) + "'";
      } else {
        const std::size_t width = rng.chance(0.5) ? 10 : 20;
        const std::size_t start = width * rng.below(100 / width);
        if (line.size() < start + width) line.resize(start + width, ' ');
        std::string replacement = value;
        if (replacement.size() < width) replacement.insert(0, width - replacement.size(), ' ');
        line.replace(start, width, replacement);
        log += "write '" + printable(value) + "' in columns " + std::to_string(start + 1) + "-" +
               std::to_string(start + width) + " of line " + std::to_string(*i + 1);
      }
      break;
    }
    case 5: {  // blank a field
      const auto i = pick_line(lines, rng, is_data);
      if (!i) return mutate_byte(text, rng, log);
      const std::size_t width = rng.chance(0.5) ? 10 : 20;
      const std::size_t start = width * rng.below(100 / width);
      std::string& line = lines[*i];
      if (start < line.size())
        line.replace(start, std::min(width, line.size() - start), std::min(width, line.size() - start), ' ');
      log += "blank columns " + std::to_string(start + 1) + "-" + std::to_string(start + width) + " of line " +
             std::to_string(*i + 1);
      break;
    }
    case 6:
    case 7: {  // duplicate or delete a card
      const auto k = pick_line(lines, rng, is_keyword);
      if (!k) return mutate_byte(text, rng, log);
      std::size_t end = *k + 1;
      while (end < n && !is_keyword(lines[end])) ++end;
      Lines card(lines.begin() + static_cast<std::ptrdiff_t>(*k), lines.begin() + static_cast<std::ptrdiff_t>(end));
      if (rng.chance(0.5)) {
        log += "delete card '" + printable(lines[*k]) + "' (line " + std::to_string(*k + 1) + ")";
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(*k), lines.begin() + static_cast<std::ptrdiff_t>(end));
      } else {
        const std::size_t at = rng.chance(0.5) ? end : rng.below(n + 1);
        log += "duplicate card '" + printable(lines[*k]) + "' before line " + std::to_string(at + 1);
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), card.begin(), card.end());
      }
      break;
    }
    case 8: {  // a card from elsewhere (the other decks, or a synthetic one)
      const std::string& card = rng.pick(pools.cards);
      Lines card_lines = split_lines(card);
      if (!card_lines.empty() && card_lines.back().empty()) card_lines.pop_back();
      const auto at = rng.below(n + 1);
      log += "insert card '" + printable(card_lines.front()) + "' before line " + std::to_string(at + 1);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), card_lines.begin(), card_lines.end());
      break;
    }
    case 9: {  // #include of a missing file, of itself, of the other deck, of a folder...
      const std::vector<std::string> targets = {"missing_file.inc",
                                                self_name,
                                                other_name,
                                                "'" + self_name + "'",
                                                "\"" + self_name + "\"",
                                                ".",
                                                "..",
                                                "",
                                                "   ",
                                                "sub/../missing.inc",
                                                "\"unterminated",
                                                "missing dir/x.rad",
                                                std::string(300, 'a') + ".inc",
                                                "./" + self_name};
      const std::string& target = rng.pick(targets);
      const std::string line = (rng.chance(0.8) ? "#include " : "#include\t") + target;
      const auto at = rng.below(n + 1);
      log += "insert '" + printable(line) + "' before line " + std::to_string(at + 1);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), line);
      break;
    }
    case 10: {  // a /BEGIN unit field
      const std::vector<std::string> units = {"Mg",  "mm",  "ms",    "g",      "lb",    "in",       "t",         "kkg",
                                              "0",   "-1",  "1e200", "1e-200", "1E308", "4.9e-324", "\xCE\xBCs", "km",
                                              "day", "nan", "",      "1.5",    "Ym",    "ys"};
      std::size_t begin = n;
      for (std::size_t k = 0; k < n; ++k)
        if (lines[k].rfind("/BEGIN", 0) == 0) begin = k;
      std::size_t target = begin;
      for (int data = 0; target < n && data < 3 + static_cast<int>(rng.below(2));) {
        ++target;
        if (target < n && is_data(lines[target])) ++data;
      }
      if (target >= n) return mutate_byte(text, rng, log);
      std::string& line = lines[target];
      const std::size_t start = 20 * rng.below(3);
      if (line.size() < start + 20) line.resize(start + 20, ' ');
      std::string value = rng.pick(units);
      value.insert(0, 20 - std::min<std::size_t>(20, value.size()), ' ');
      line.replace(start, 20, value);
      log += "unit field '" + printable(value) + "' at line " + std::to_string(target + 1);
      break;
    }
    case 11: {  // many copies of a line or a card: big decks must stay fast (no quadratic step)
      // Once per file (at most ~16000 lines each), so that a legitimate read stays far below the call limit
      // even under the sanitizers.
      if (n > 5000) return mutate_lines(text, rng, pools, self_name, other_name, log);
      const auto i = rng.below(n);
      std::size_t end = i + 1;
      if (is_keyword(lines[i]))
        while (end < n && !is_keyword(lines[end])) ++end;
      const std::size_t copies = std::max<std::size_t>(1, (1000 + rng.below(15000)) / (end - i));
      Lines block;
      for (std::size_t c = 0; c < copies; ++c)
        block.insert(block.end(), lines.begin() + static_cast<std::ptrdiff_t>(i),
                     lines.begin() + static_cast<std::ptrdiff_t>(end));
      log += std::to_string(copies) + " copies of lines " + std::to_string(i + 1) + "-" + std::to_string(end);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(end), block.begin(), block.end());
      break;
    }
    default:
      break;
  }
  text = join_lines(lines);
}

void mutate(std::string& text, Rng& rng, const Pools& pools, const std::string& self_name,
            const std::string& other_name, std::string& log) {
  log += "  " + self_name + ": ";
  const auto choice = rng.below(10);
  if (choice < 3) {
    mutate_byte(text, rng, log);
  } else if (choice == 3) {
    const std::size_t keep = rng.below(text.size() + 1);
    log += "truncate to " + std::to_string(keep) + " bytes";
    text.resize(keep);
  } else {
    mutate_lines(text, rng, pools, self_name, other_name, log);
  }
  log += "\n";
}

// ---------------------------------------------------------------------------------------------------------------
// One iteration: mutated deck, options, and the outcome check.

enum class Layout { TwoFiles, StarterOnly, SingleFile };

struct Case {
  std::uint64_t iteration = 0;
  std::string name;
  Layout layout = Layout::TwoFiles;
  std::string starter;
  std::string engine;
  ReadOptions options;
  std::string log;
};

Case make_case(std::uint64_t seed, std::uint64_t iteration, const std::vector<QaDeck>& decks, const Pools& pools) {
  Rng rng(iteration_seed(seed, iteration));
  const QaDeck& deck = rng.pick(decks);
  Case c;
  c.iteration = iteration;
  c.name = deck.name;
  c.starter = deck.starter;
  c.engine = deck.engine;
  const auto layout = rng.below(10);
  // Starter only: no engine deck, hence no "/RUN missing" error, so that skip_unknown reads reach the model
  // resolution. Single file: the engine part after the starter's /END.
  c.layout = layout < 6 ? Layout::TwoFiles : layout < 9 ? Layout::StarterOnly : Layout::SingleFile;
  if (c.layout == Layout::SingleFile) c.starter += "\n" + c.engine;
  c.options.skip_unknown = rng.chance(0.5);
  c.options.require_engine = rng.chance(0.1);
  const std::string starter_name = deck.name + "_0000.rad";
  const std::string engine_name = deck.name + "_0001.rad";
  const auto count = 1 + rng.below(4);
  for (std::size_t m = 0; m < count; ++m) {
    if (c.layout == Layout::TwoFiles && rng.chance(0.25))
      mutate(c.engine, rng, pools, engine_name, starter_name, c.log);
    else
      mutate(c.starter, rng, pools, starter_name, engine_name, c.log);
  }
  return c;
}

const char* layout_name(Layout layout) {
  return layout == Layout::TwoFiles      ? "starter and engine files"
         : layout == Layout::StarterOnly ? "starter file only"
                                         : "single file";
}

fs::path write_case(const fs::path& dir, const Case& c) {
  const fs::path starter = dir / (c.name + "_0000.rad");
  const fs::path engine = dir / (c.name + "_0001.rad");
  std::ofstream(starter, std::ios::binary | std::ios::trunc) << c.starter;
  std::error_code ec;
  if (c.layout == Layout::TwoFiles)
    std::ofstream(engine, std::ios::binary | std::ios::trunc) << c.engine;
  else
    fs::remove(engine, ec);
  return starter;
}

std::string describe(std::uint64_t seed, const Case& c) {
  std::ostringstream out;
  out << "seed " << seed << ", iteration " << c.iteration << ", deck " << c.name << " (" << layout_name(c.layout)
      << "), skip_unknown " << c.options.skip_unknown << ", require_engine " << c.options.require_engine
      << "\nmutations:\n"
      << c.log << "replay: CRUMPLE_FUZZ_SEED=" << seed << " CRUMPLE_FUZZ_ITERATION=" << c.iteration
      << " crumple_fuzz_tests --gtest_filter='ReaderFuzz.*'";
  return out.str();
}

// Writes the mutated deck where the developer can run `crumple check` on it; returns the folder.
fs::path dump_case(std::uint64_t seed, const Case& c, const std::string& failure) {
  const fs::path dir = fs::path(CRUMPLE_FUZZ_DUMP_DIR) /
                       (c.name + "-seed" + std::to_string(seed) + "-iter" + std::to_string(c.iteration));
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path starter = write_case(dir, c);
  std::ofstream(dir / "README.txt") << "failure: " << failure << "\n"
                                    << describe(seed, c) << "\ncommand line: crumple check "
                                    << (c.options.skip_unknown ? "--skip-unknown " : "") << starter.string() << "\n";
  return dir;
}

bool finite_all(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

// An accepted deck must give a sane model: the reader may not turn garbage into numbers silently.
std::optional<std::string> check_model(const Model& m) {
  if (!finite_all(m.nodes.x) || !finite_all(m.nodes.y) || !finite_all(m.nodes.z))
    return "accepted a deck with non-finite node coordinates";
  for (const Material& mat : m.materials) {
    if (!(std::isfinite(mat.density) && mat.density > 0.0))
      return "accepted material " + std::to_string(mat.user_id) + " with density " + std::to_string(mat.density);
    if (!(std::isfinite(mat.young) && mat.young > 0.0))
      return "accepted material " + std::to_string(mat.user_id) + " with E " + std::to_string(mat.young);
    if (!(mat.poisson > -1.0 && mat.poisson < 0.5))
      return "accepted material " + std::to_string(mat.user_id) + " with nu " + std::to_string(mat.poisson);
    const JohnsonCookParameters& jc = mat.johnson_cook;
    if (!finite_all({jc.a, jc.b, jc.n, jc.eps_p_max, jc.sig_max0, jc.c, jc.eps_dot_0, jc.f_cut, jc.chard}))
      return "accepted material " + std::to_string(mat.user_id) + " with non-finite Johnson-Cook parameters";
    if (!finite_all(mat.tabulated.scale) || !finite_all(mat.tabulated.strain_rate))
      return "accepted material " + std::to_string(mat.user_id) + " with non-finite curve scales or rates";
  }
  for (std::size_t p = 0; p < m.properties.size(); ++p) {
    const Property& prop = m.properties[p];
    if (prop.kind == PropertyKind::Shell && !(std::isfinite(prop.shell.thickness) && prop.shell.thickness > 0.0))
      return "accepted property " + std::to_string(prop.user_id) + " with thickness " +
             std::to_string(prop.shell.thickness);
    const ShellSection& sh = prop.shell;
    const SolidSection& so = prop.solid;
    if (!finite_all({sh.hm, sh.hf, sh.hr, sh.dm, sh.dn, sh.ashear, so.qa, so.qb, so.dn, so.h}))
      return "accepted property " + std::to_string(prop.user_id) + " with non-finite coefficients";
  }
  for (const ResolvedFormulation& f : m.formulations) {
    if (f.ishell != 1 && f.ishell != 2 && f.ishell != 3 && f.ishell != 12 && f.ishell != 24)
      return "accepted Ishell " + std::to_string(f.ishell);
    // 30 and 31 are refused only for properties that triangles use (resolve_definitions.cpp).
    if (f.ish3n != 1 && f.ish3n != 2 && f.ish3n != 30 && f.ish3n != 31) return "accepted Ish3n " + std::to_string(f.ish3n);
    if (f.isolid != 1 && f.isolid != 14 && f.isolid != 24) return "accepted Isolid " + std::to_string(f.isolid);
    if (f.n_points < 0 || f.n_points > 10) return "accepted N " + std::to_string(f.n_points);
  }
  for (int u = 0; u < 3; ++u)
    if (!(std::isfinite(m.units.input[u]) && m.units.input[u] > 0.0 && std::isfinite(m.units.work[u]) &&
          m.units.work[u] > 0.0))
      return "accepted non-finite or non-positive unit sizes";
  for (const Function& f : m.functions)
    if (!finite_all(f.x) || !finite_all(f.y))
      return "accepted function " + std::to_string(f.user_id) + " with non-finite points";
  if (!finite_all(m.nodal_mass) || !std::isfinite(m.total_mass())) return "accepted a deck with non-finite mass";
  for (const ElementGroup& g : m.element_groups)
    if (g.begin < 0 || g.end <= g.begin ||
        static_cast<std::size_t>(g.end) > m.elements[static_cast<int>(g.kind)].size())
      return "element group with an invalid range";
  return std::nullopt;
}

// what() as the user sees it (a C string: an embedded NUL would cut it): non-empty, naming a file of the deck,
// and whole (it still holds what was expected).
std::optional<std::string> check_message(const char* what_text, const fs::path& dir, const std::string& expected) {
  const std::string what = what_text;
  if (what.empty()) return "an error with an empty message";
  if (what.find(dir.string()) == std::string::npos) return "an error message without the file path: " + printable(what);
  std::string shown;  // control characters are shown as \xNN in messages
  for (char c : expected) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 32 || u == 127) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", u);
      shown += buffer;
    } else {
      shown += c;
    }
  }
  if (!expected.empty() && what.find("expected " + shown) == std::string::npos)
    return "an error message cut short (expected part missing): " + printable(what);
  return std::nullopt;
}

// Kills the process with a dump when one read_deck call never returns (an infinite loop cannot be timed).
class Watchdog {
 public:
  explicit Watchdog(double seconds) : limit_(seconds), thread_([this] { run(); }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  void arm(std::function<void()> on_hang) {
    std::lock_guard lock(mutex_);
    on_hang_ = std::move(on_hang);
    start_ = Clock::now();
    armed_ = true;
  }
  void disarm() {
    std::lock_guard lock(mutex_);
    armed_ = false;
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    while (!stop_) {
      wake_.wait_for(lock, std::chrono::milliseconds(200));
      if (armed_ && std::chrono::duration<double>(Clock::now() - start_).count() > limit_) {
        on_hang_();
        std::fflush(nullptr);
        std::_Exit(1);
      }
    }
  }

  double limit_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool armed_ = false;
  bool stop_ = false;
  Clock::time_point start_;
  std::function<void()> on_hang_;
  std::thread thread_;  // last: started once the members it uses exist
};

// The case being read, so that a process that dies inside read_deck (a sanitizer report, a crash) still leaves
// the deck behind. Best effort: the dump is not async-signal-safe, but the process is lost anyway.
std::uint64_t g_current_seed = 0;
const Case* g_current_case = nullptr;

void dump_current_case() {
  const Case* c = std::exchange(g_current_case, nullptr);
  if (c == nullptr) return;
  const auto where = dump_case(g_current_seed, *c, "the process died in read_deck (crash or sanitizer report)");
  std::fprintf(stderr, "[fuzz] died reading: %s\ndeck dumped to %s\n", describe(g_current_seed, *c).c_str(),
               where.string().c_str());
}

extern "C" void on_fatal_signal(int signal_number) {
  dump_current_case();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void install_death_hooks() {
#ifdef CRUMPLE_FUZZ_ASAN
  __sanitizer_set_death_callback(dump_current_case);  // AddressSanitizer and UBSan reports (no recovery)
#else
  for (int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(signal_number, on_fatal_signal);
#endif
  std::signal(SIGABRT, on_fatal_signal);  // assert(), std::terminate
}

TEST(ReaderFuzz, MutatedQaDecksGiveDeckErrorsOrValidModels) {
  const std::uint64_t seed = env_seed();
  const double budget = env_seconds("CRUMPLE_FUZZ_SECONDS", kDefaultSeconds);
  const double call_limit = env_seconds("CRUMPLE_FUZZ_CALL_LIMIT", kDefaultCallLimit);
  const auto only = env("CRUMPLE_FUZZ_ITERATION");
  std::printf(
      "[fuzz] seed %llu (CRUMPLE_FUZZ_SEED), budget %.1f s (CRUMPLE_FUZZ_SECONDS), per-call limit %.1f s of CPU\n",
      static_cast<unsigned long long>(seed), budget, call_limit);
  std::fflush(stdout);
  RecordProperty("seed", std::to_string(seed));

  const std::vector<QaDeck> decks = load_qa_decks();
  for (const QaDeck& d : decks) {
    ASSERT_FALSE(d.starter.empty()) << d.name << "_0000.rad not found in " << CRUMPLE_QA_DIR;
    ASSERT_FALSE(d.engine.empty()) << d.name << "_0001.rad not found in " << CRUMPLE_QA_DIR;
  }
  Pools pools;
  for (const std::string& keyword : synthetic_keywords()) pools.keyword_lines.push_back(keyword);
  for (const std::string& card : synthetic_cards()) pools.cards.push_back(card);
  for (const QaDeck& d : decks)
    for (const std::string* text : {&d.starter, &d.engine})
      for (const std::string& card : cards_of(*text)) {
        pools.cards.push_back(card);
        pools.keyword_lines.push_back(card.substr(0, card.find('\n')));
      }

  TempDir dir;
  Watchdog watchdog(std::max(kWatchdogSeconds, 10 * call_limit));
  install_death_hooks();
  g_current_seed = seed;
  int failures = 0;
  std::uint64_t accepted = 0, deck_errors = 0, deck_error = 0, iterations = 0;
  double slowest = 0.0;
  std::uint64_t slowest_iteration = 0;
  const auto fuzz_start = Clock::now();
  const std::uint64_t first = only ? std::strtoull(only->c_str(), nullptr, 0) : 0;
  for (std::uint64_t iteration = first;; ++iteration) {
    if (only ? iteration > first : std::chrono::duration<double>(Clock::now() - fuzz_start).count() >= budget) break;
    const Case c = make_case(seed, iteration, decks, pools);
    const fs::path starter = write_case(dir.path(), c);
    ++iterations;

    std::optional<std::string> failure;
    watchdog.arm([&] {
      const auto where = dump_case(seed, c, "read_deck did not return (hang)");
      std::fprintf(stderr, "[fuzz] read_deck hangs: %s\ndeck dumped to %s\n", describe(seed, c).c_str(),
                   where.string().c_str());
    });
    g_current_case = &c;
    const auto call_start = Clock::now();
    const double cpu_start = thread_cpu_seconds();
    try {
      const Deck deck = read_deck(starter, c.options);
      ++accepted;
      failure = check_model(deck.model);
    } catch (const DeckErrors& e) {
      ++deck_errors;
      if (e.errors().empty()) failure = "DeckErrors without any error";
      if (!failure) failure = check_message(e.what(), dir.path(), {});
      for (const DeckError& each : e.errors())
        if (!failure) failure = check_message(each.what(), dir.path(), each.expected());
    } catch (const DeckError& e) {
      ++deck_error;
      failure = check_message(e.what(), dir.path(), e.expected());
    } catch (const std::exception& e) {
      failure = std::string("exception of type ") + typeid(e).name() + " (not DeckError/DeckErrors): " + e.what();
    } catch (...) {
      failure = "an exception that is not a std::exception";
    }
    g_current_case = nullptr;
    const double cpu = thread_cpu_seconds() - cpu_start;
    const double seconds = std::chrono::duration<double>(Clock::now() - call_start).count();
    watchdog.disarm();
    if (cpu > slowest) slowest = cpu, slowest_iteration = iteration;
    if (!failure && cpu > call_limit)
      failure = "read_deck used " + std::to_string(cpu) + " s of CPU (limit " + std::to_string(call_limit) + " s)";
    if (!failure && seconds > kBlockedFactor * call_limit)
      failure = "read_deck took " + std::to_string(seconds) + " s (blocked? limit " +
                std::to_string(kBlockedFactor * call_limit) + " s of wall-clock time)";

    if (failure) {
      const fs::path where = dump_case(seed, c, *failure);
      ADD_FAILURE() << *failure << "\n" << describe(seed, c) << "\nmutated deck: " << where.string();
      if (++failures >= kMaxReportedFailures) break;
    }
  }
  const double total = std::chrono::duration<double>(Clock::now() - fuzz_start).count();
  std::printf(
      "[fuzz] %llu iterations in %.1f s: %llu accepted, %llu DeckErrors, %llu DeckError; slowest call %.3f s of "
      "CPU (iteration %llu)\n",
      static_cast<unsigned long long>(iterations), total, static_cast<unsigned long long>(accepted),
      static_cast<unsigned long long>(deck_errors), static_cast<unsigned long long>(deck_error), slowest,
      static_cast<unsigned long long>(slowest_iteration));
  RecordProperty("iterations", std::to_string(iterations));
  EXPECT_GT(iterations, 0u);
}

// The unmutated decks must read without any exception but DeckErrors (until every keyword is supported) and,
// with skip_unknown and without the engine deck, give a valid model: the fuzzer's baseline.
TEST(ReaderFuzz, UnmutatedQaStartersReadWithSkipUnknown) {
  TempDir dir;
  for (const QaDeck& d : load_qa_decks()) {
    ASSERT_FALSE(d.starter.empty());
    Case c;
    c.name = d.name;
    c.layout = Layout::StarterOnly;
    c.starter = d.starter;
    c.options.skip_unknown = true;
    const fs::path starter = write_case(dir.path(), c);
    try {
      const Deck deck = read_deck(starter, c.options);
      EXPECT_GT(deck.model.nodes.size(), 0u) << d.name;
      EXPECT_EQ(check_model(deck.model), std::nullopt) << d.name;
    } catch (const DeckErrors& e) {
      ADD_FAILURE() << d.name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace crumple::test
