#include "crumple/output/reference_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "crumple/output/results_reader.hpp"

namespace crumple {

ReferenceFileError::ReferenceFileError(std::filesystem::path file, int line, std::string field,
                                       const std::string& problem)
    : std::runtime_error(fmt::format("{}{}: {}{}", file.string(), line > 0 ? fmt::format(":{}", line) : "",
                                     field.empty() ? "" : field + ": ", problem)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)) {}

namespace {

// The whole of `text` as a number, or false.
bool parse_number(const std::string& text, double& value) {
  std::istringstream in(text);
  return (in >> value) && (in >> std::ws).eof();
}

}  // namespace

std::map<std::string, ReferenceValue> read_reference_values(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ReferenceFileError(file, 0, "", "cannot read the reference values");
  std::map<std::string, ReferenceValue> values;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;
    ReferenceValue v;
    double line_field = 0.0;
    const bool shaped = (words.size() == 3 || words.size() == 4) && parse_number(words[0], line_field) &&
                        parse_number(words[2], v.value) && (words.size() == 3 || parse_number(words[3], v.scale));
    if (!shaped)
      throw ReferenceFileError(file, number, words.size() > 1 ? words[1] : "",
                               fmt::format("expected '<line> KEY value [scale]', found '{}'", line));
    values[words[1]] = v;
  }
  return values;
}

ReferencePoint read_reference(const std::filesystem::path& file) {
  const auto values = read_reference_values(file);
  const auto get = [&](const char* key) {
    const auto it = values.find(key);
    if (it == values.end()) throw ReferenceFileError(file, 0, key, "missing (needed for the comparison)");
    return it->second;
  };
  ReferencePoint p;
  p.time = get("TIME").value;
  p.cycles = get("CYCLE").value;
  p.internal = get("IENERGY").value;
  p.scale = get("IENERGY").scale;
  p.kinetic = get("KENERGYT").value + get("KENERGYR").value;
  return p;
}

double value_at_time(const std::vector<double>& t, const std::vector<double>& y, double time) {
  if (t.empty()) return std::nan("");
  if (time <= t.front()) return y.front();
  for (std::size_t k = 1; k < t.size(); ++k)
    if (time <= t[k]) {
      const double w = t[k] > t[k - 1] ? (time - t[k - 1]) / (t[k] - t[k - 1]) : 1.0;
      return y[k - 1] + w * (y[k] - y[k - 1]);
    }
  return y.back();
}

ListingCycles read_listing_cycles(const std::filesystem::path& listing) {
  std::ifstream in(listing);
  if (!in) throw std::runtime_error("cannot read the listing " + listing.string());
  const std::regex row(R"(^\s*(\d+)\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)?)");
  const std::regex energies(R"(%\s+([-+0-9.eEnaif]+)\s+([-+0-9.eEnaif]+)\s+([-+0-9.eEnaif]+))");
  const auto number = [](const std::string& text) {
    try {
      return std::stod(text);
    } catch (const std::exception&) {
      return std::nan("");
    }
  };
  ListingCycles rows;
  std::smatch m, e;
  for (std::string line; std::getline(in, line);) {
    if (!std::regex_search(line, m, row)) continue;
    const double cycle = std::stod(m[1]), time = std::stod(m[2]);
    if (!rows.cycle.empty() && cycle < rows.cycle.back()) rows = ListingCycles{};
    if (!rows.time.empty() && time <= rows.time.back()) continue;
    rows.time.push_back(time), rows.cycle.push_back(cycle);
    rows.dt.push_back(m[3].matched ? number(m[3]) : std::nan(""));
    const bool has = std::regex_search(line, e, energies);
    rows.internal.push_back(has ? number(e[1]) : std::nan(""));
    rows.kinetic.push_back(has ? number(e[2]) + number(e[3]) : std::nan(""));
  }
  return rows;
}

RunPoint read_run_point(const std::filesystem::path& output_directory, const std::string& name, double time) {
  const ResultsReader h5(output_directory / (name + ".h5"));
  const std::vector<double> t = h5.doubles("/history/time");
  // Kinetic energy row by row first, then interpolated: the order of the ctests' earlier verdicts.
  std::vector<double> kinetic = h5.doubles("/history/kinetic_translational");
  const std::vector<double> rotational = h5.doubles("/history/kinetic_rotational");
  for (std::size_t k = 0; k < kinetic.size() && k < rotational.size(); ++k) kinetic[k] += rotational[k];
  RunPoint p;
  p.history_end = t.empty() ? std::nan("") : t.back();
  p.internal = value_at_time(t, h5.doubles("/history/internal"), time);
  p.kinetic = value_at_time(t, kinetic, time);
  const ListingCycles listing = read_listing_cycles(output_directory / (name + ".out"));
  p.cycles = value_at_time(listing.time, listing.cycle, time);
  if (!listing.time.empty() && std::isfinite(listing.internal.back()) && std::isfinite(listing.kinetic.back()) &&
      time >= listing.time.back() - 0.5 * (std::isfinite(listing.dt.back()) ? listing.dt.back() : 0.0))
    p.internal = listing.internal.back(), p.kinetic = listing.kinetic.back();
  return p;
}

namespace {

struct ToleranceField {
  const char* name;
  double Tolerances::*member;
};
constexpr ToleranceField kToleranceFields[] = {{"internal", &Tolerances::internal},
                                               {"internal_floor", &Tolerances::internal_floor},
                                               {"kinetic", &Tolerances::kinetic},
                                               {"cycles", &Tolerances::cycles}};

// One "FIELD PERCENT" line into `t`.
void read_tolerance_line(const std::filesystem::path& file, int number, const std::string& line,
                         const Tolerances& defaults, Tolerances& t) {
  std::istringstream in(line);
  std::string name, value_text, extra;
  in >> name >> value_text >> extra;
  const auto field = std::find_if(std::begin(kToleranceFields), std::end(kToleranceFields),
                                  [&](const ToleranceField& f) { return name == f.name; });
  if (field == std::end(kToleranceFields))
    throw ReferenceFileError(file, number, name, "unknown field (internal, internal_floor, kinetic or cycles)");
  double percent = 0.0;
  if (!extra.empty() || !parse_number(value_text, percent))
    throw ReferenceFileError(file, number, name, fmt::format("expected one number (percent), found '{}'", line));
  const double default_percent = 100.0 * (defaults.*field->member);
  if (!(percent >= 0.0))
    throw ReferenceFileError(file, number, name, fmt::format("{} % is negative", value_text));
  if (percent > default_percent * (1.0 + 1e-12))  // the slack: 100 x 0.15 need not be 15 exactly
    throw ReferenceFileError(file, number, name,
                             fmt::format("{} % is larger than the default {:g} %: a tolerance file may only tighten "
                                         "the tolerances",
                                         value_text, default_percent));
  t.*field->member = percent / 100.0;
}

}  // namespace

Tolerances read_tolerances(const std::filesystem::path& file, const Tolerances& defaults) {
  std::ifstream in(file);
  if (!in) throw ReferenceFileError(file, 0, "", "cannot read the tolerance file");
  Tolerances t = defaults;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    read_tolerance_line(file, number, line, defaults, t);
  }
  return t;
}

bool QuantityCheck::passed() const { return std::abs(run - reference) <= tolerance; }

Comparison compare(const ReferencePoint& reference, const RunPoint& run, const Tolerances& tolerances) {
  Comparison c;
  c.time = reference.time;
  c.scale = reference.scale;
  c.history_end = run.history_end;
  c.reaches_time = run.history_end >= kHistoryReach * reference.time;
  const double internal_band = std::max(std::abs(reference.internal), tolerances.internal_floor * reference.scale);
  c.internal = {run.internal, reference.internal, tolerances.internal * internal_band};
  c.kinetic = {run.kinetic, reference.kinetic, tolerances.kinetic * reference.scale};
  c.cycles = {run.cycles, reference.cycles, tolerances.cycles * reference.cycles};
  return c;
}

std::string Comparison::failures() const {
  std::vector<std::string> lines;
  if (!reaches_time)
    lines.push_back(fmt::format("the histories end at {:.5g}, before the reference's time {:.5g}", history_end, time));
  if (!internal.passed())
    lines.push_back(fmt::format("internal energy {:.5g} against {:.5g}: difference {:.4g}, tolerance {:.4g}",
                                internal.run, internal.reference, internal.difference(), internal.tolerance));
  if (!kinetic.passed())
    lines.push_back(fmt::format("kinetic energy {:.5g} against {:.5g}: {:.2f} % of the scale {:.5g}, tolerance {:.4g} %",
                                kinetic.run, kinetic.reference, 100.0 * std::abs(kinetic.difference()) / scale, scale,
                                100.0 * kinetic.tolerance / scale));
  if (!cycles.passed())
    lines.push_back(fmt::format("cycles {:.0f} against {:.0f}: {:+.1f} %, tolerance {:.4g} %", cycles.run,
                                cycles.reference, 100.0 * cycles.difference() / cycles.reference,
                                100.0 * cycles.tolerance / cycles.reference));
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "; ") + l;
  return out;
}

}  // namespace crumple
