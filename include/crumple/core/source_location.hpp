#pragma once
// Where a record came from in the deck: every model record keeps it, so that an error found after reading (while
// resolving, setting up or running) still names the file and the line.
#include <string>

namespace crumple {

struct SourceLocation {
  std::string file;  // path as the user gave it (or as resolved relative to the including file)
  int line = 0;      // 1-based; 0 when the problem concerns the whole file
};

}  // namespace crumple
