#pragma once
// The deck as a flat sequence of text lines, with every `#include` expanded in place and every line remembering
// the file and line number it came from (for error messages).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crumple/core/deck_error.hpp"

namespace crumple {

struct SourceLine {
  std::string text;    // without the line terminator (LF or CRLF)
  std::int32_t file;   // index into SourceText::files
  std::int32_t line;   // 1-based line number in that file
};

struct SourceText {
  std::vector<std::string> files;  // every file read, in order of first reading
  std::vector<SourceLine> lines;

  SourceLocation where(const SourceLine& l) const { return {files[static_cast<std::size_t>(l.file)], l.line}; }
};

// Reads `path` and, recursively, the files it includes (`#include name`, relative to the including file).
// Throws DeckError for a missing or unreadable file, an include cycle or includes nested deeper than 32 levels.
SourceText read_source(const std::filesystem::path& path);

// Appends `path` (and its includes) to an existing text, e.g. the engine deck after the starter deck.
void append_source(SourceText& text, const std::filesystem::path& path);

}  // namespace crumple
