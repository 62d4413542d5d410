#pragma once
// Reading the time histories of NAME.h5 back (docs/output-format.md, "/history"): what `crumple th` lists and
// exports. Files written before the histories carried units read with empty units and labels made from the names.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crumple/output/history_channels.hpp"

namespace crumple {

// One history dataset of the file: a global one (/history/<name>) or a /TH request (/history/th/<name>).
struct HistorySeries {
  std::string path;     // "/history/internal", "/history/th/NODE_2"
  std::string kind;     // "global", or the request's kind: "NODE", "PART"...
  std::string keyword;  // the request's keyword line ("" for a global dataset)
  std::int64_t id = 0;  // thgroup id (0 for a global dataset)
  std::string title;
  std::vector<HistoryColumn> columns;  // a 1-D dataset has one
};

class HistoryFile {
 public:
  // Opens a results file read-only. Throws std::runtime_error naming the file when it cannot be read or is not a
  // Crumple results file.
  explicit HistoryFile(const std::filesystem::path& path);
  ~HistoryFile();
  HistoryFile(const HistoryFile&) = delete;
  HistoryFile& operator=(const HistoryFile&) = delete;

  std::size_t rows() const;
  // A column's unit by its name in the file's working units ("ms", "kN", "J"; core/units.hpp), or its dimension
  // letters in a file written without them.
  std::string unit_of(const HistoryColumn& column) const;
  // /history/time, then every dataset with at least one column: the global ones in file order, then /history/th.
  const std::vector<HistorySeries>& series() const;
  // The values of series `s`, rows x columns, row-major.
  std::vector<double> values(std::size_t s) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace crumple
