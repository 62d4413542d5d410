#include "app/th.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fnmatch.h>

#include <fstream>
#include <ostream>
#include <stdexcept>

#include "app/exit_codes.hpp"
#include "crumple/output/history_reader.hpp"

namespace crumple::app {
namespace {

// One selected column: series and column index.
struct Channel {
  std::size_t series, column;
};

// "NODE_2/6/DX [mm]": the label and the unit's name in the file's working units (none when dimensionless).
std::string with_unit(const HistoryFile& file, const HistoryColumn& c) {
  const std::string unit = file.unit_of(c);
  return unit.empty() ? c.label : fmt::format("{} [{}]", c.label, unit);
}

bool selected(const HistoryColumn& c, const std::vector<std::string>& patterns) {
  if (patterns.empty()) return true;
  for (const std::string& p : patterns)
    if (fnmatch(p.c_str(), c.label.c_str(), 0) == 0) return true;
  return false;
}

// The selected columns other than the time, and the patterns that select none.
std::vector<Channel> channels(const HistoryFile& file, const std::vector<std::string>& patterns,
                              std::vector<std::string>& unmatched) {
  std::vector<Channel> out;
  const auto& series = file.series();
  for (std::size_t s = 1; s < series.size(); ++s)  // series 0 is /history/time
    for (std::size_t c = 0; c < series[s].columns.size(); ++c)
      if (selected(series[s].columns[c], patterns)) out.push_back({s, c});
  for (const std::string& p : patterns) {
    bool any = false;
    for (const Channel& ch : out) any = any || fnmatch(p.c_str(), series[ch.series].columns[ch.column].label.c_str(), 0) == 0;
    if (!any) unmatched.push_back(p);
  }
  return out;
}

void list(const std::filesystem::path& path, const HistoryFile& file, const std::vector<Channel>& chosen,
          std::ostream& out) {
  const auto& series = file.series();
  const std::vector<double> time = file.values(0);
  fmt::print(out, "{}: {} history rows", path.filename().string(), file.rows());
  if (!time.empty())
    fmt::print(out, ", time {:.6g} to {:.6g} {}", time.front(), time.back(), file.unit_of(series[0].columns[0]));
  fmt::print(out, "\n");
  std::size_t shown = series.size();
  for (const Channel& ch : chosen) {
    const HistorySeries& s = series[ch.series];
    if (ch.series != shown) {
      shown = ch.series;
      if (s.kind == "global") fmt::print(out, "{}  global  {} column{}\n", s.path, s.columns.size(), s.columns.size() == 1 ? "" : "s");
      else fmt::print(out, "{}  {} {}  \"{}\"  {}  {} columns\n", s.path, s.kind, s.id, s.title, s.keyword, s.columns.size());
    }
    const HistoryColumn& c = s.columns[ch.column];
    fmt::print(out, "  {}{}\n", with_unit(file, c), c.object_title.empty() ? "" : fmt::format("  ({})", c.object_title));
  }
}

void write_csv(const HistoryFile& file, const std::vector<Channel>& chosen, std::ostream& out) {
  const auto& series = file.series();
  std::vector<std::vector<double>> values(series.size());
  values[0] = file.values(0);
  for (const Channel& ch : chosen)
    if (values[ch.series].empty()) values[ch.series] = file.values(ch.series);
  fmt::print(out, "{}", with_unit(file, series[0].columns[0]));
  for (const Channel& ch : chosen) fmt::print(out, ",{}", with_unit(file, series[ch.series].columns[ch.column]));
  fmt::print(out, "\n");
  for (std::size_t r = 0; r < file.rows(); ++r) {  // shortest decimal forms that read back to the same doubles
    fmt::print(out, "{}", values[0][r]);
    for (const Channel& ch : chosen)
      fmt::print(out, ",{}", values[ch.series][r * series[ch.series].columns.size() + ch.column]);
    fmt::print(out, "\n");
  }
}

}  // namespace

int run_th(const ThOptions& options, std::ostream& out, std::ostream& err) {
  std::unique_ptr<HistoryFile> file;
  try {
    file = std::make_unique<HistoryFile>(options.file);
  } catch (const std::runtime_error& e) {
    fmt::print(err, "crumple: cannot read the histories of {}\n", e.what());
    return kExitBadInput;
  }
  std::vector<std::string> unmatched;
  const std::vector<Channel> chosen = channels(*file, options.select, unmatched);
  for (const std::string& p : unmatched) fmt::print(err, "crumple: --select {}: no history column matches\n", p);
  if (!unmatched.empty()) return kExitBadInput;
  if (!options.csv) {
    list(options.file, *file, chosen, out);
    return kExitNormal;
  }
  if (options.output.empty()) {
    write_csv(*file, chosen, out);
    return kExitNormal;
  }
  std::ofstream csv(options.output, std::ios::binary | std::ios::trunc);
  if (csv) write_csv(*file, chosen, csv);
  csv.close();
  if (!csv) {
    fmt::print(err, "crumple: cannot write {}\n", options.output.string());
    return kExitRunFailed;
  }
  return kExitNormal;
}

}  // namespace crumple::app
