#include "crumple/deck/source.hpp"

#include <fstream>
#include <functional>

namespace crumple {
namespace {

constexpr int kMaxIncludeDepth = 32;

bool starts_with_include(const std::string& text) {
  return text.rfind("#include", 0) == 0 && (text.size() == 8 || text[8] == ' ' || text[8] == '\t');
}

std::string include_target(const std::string& text) {
  std::string name = text.substr(8);
  const auto first = name.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const auto last = name.find_last_not_of(" \t\r");
  name = name.substr(first, last - first + 1);
  if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front())
    name = name.substr(1, name.size() - 2);
  return name;
}

void read_file(SourceText& text, const std::filesystem::path& path, std::vector<std::filesystem::path>& stack,
               const SourceLocation& included_from) {
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  for (const auto& open : stack) {
    if (open == canonical)
      throw DeckError(included_from, "#include", "", "an include graph without cycles",
                      "'" + path.string() + "' including itself through a cycle");
  }
  if (static_cast<int>(stack.size()) >= kMaxIncludeDepth)
    throw DeckError(included_from, "#include", "", "at most 32 nested include levels", "deeper nesting");
  if (std::filesystem::is_directory(path, ec))
    throw DeckError(included_from, included_from.line > 0 ? "#include" : "", "", "a deck file",
                    "directory '" + path.string() + "'");
  // A pipe or a device (/dev/stdin, /dev/zero) would block the read forever or never end: decks are regular files.
  if (const auto status = std::filesystem::status(path, ec);
      std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw DeckError(included_from, included_from.line > 0 ? "#include" : "", "", "a regular deck file",
                    "special file '" + path.string() + "' (device, pipe or socket)");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw DeckError(included_from, included_from.line > 0 ? "#include" : "", included_from.line > 0 ? "file name" : "",
                    "a readable file", "'" + path.string() + "' missing or unreadable");

  stack.push_back(canonical);
  const auto file_index = static_cast<std::int32_t>(text.files.size());
  text.files.push_back(path.string());
  std::string line;
  std::int32_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (starts_with_include(line)) {
      const std::string target = include_target(line);
      const SourceLocation here{path.string(), number};
      if (target.empty()) throw DeckError(here, "#include", "file name", "a file name", "nothing");
      read_file(text, path.parent_path() / target, stack, here);
      continue;
    }
    text.lines.push_back({std::move(line), file_index, number});
    line.clear();
  }
  stack.pop_back();
}

}  // namespace

SourceText read_source(const std::filesystem::path& path) {
  SourceText text;
  append_source(text, path);
  return text;
}

void append_source(SourceText& text, const std::filesystem::path& path) {
  std::vector<std::filesystem::path> stack;
  read_file(text, path, stack, SourceLocation{path.string(), 0});
}

}  // namespace crumple
