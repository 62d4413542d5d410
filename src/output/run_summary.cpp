#include "crumple/output/run_summary.hpp"

#include "crumple/core/utf8.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <chrono>
#include <ctime>
#include <stdexcept>

namespace crumple {
namespace {

// JSON has no NaN or Inf: a non-finite value (an unstable run) is written as null.
std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : "null"; }

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : valid_utf8(s)) {  // a title cut inside a character by its card's columns
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
        else out += c;
    }
  }
  return out;
}

// ["a", "b"] on one line each, indented under its key; [] when empty.
std::string string_array(const std::vector<std::string>& items) {
  if (items.empty()) return "[]";
  std::string out = "[";
  for (std::size_t k = 0; k < items.size(); ++k)
    out += fmt::format("{}\n    \"{}\"", k == 0 ? "" : ",", escaped(items[k]));
  return out + "\n  ]";
}

// [{"path": ..., "bytes": ..., "crc32": "89abcdef"}, ...]
std::string file_array(const std::vector<DeckFile>& files) {
  if (files.empty()) return "[]";
  std::string out = "[";
  for (std::size_t k = 0; k < files.size(); ++k)
    out += fmt::format("{}\n    {{\"path\": \"{}\", \"bytes\": {}, \"crc32\": \"{:08x}\"}}", k == 0 ? "" : ",",
                       escaped(files[k].path), files[k].bytes, files[k].crc32);
  return out + "\n  ]";
}

// [{"id": 1, "title": ..., "mass": ..., "internal": ..., "kinetic": ..., "hourglass": ...}, ...]
std::string part_array(const std::vector<PartResult>& parts) {
  if (parts.empty()) return "[]";
  std::string out = "[";
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const PartResult& p = parts[k];
    out += fmt::format("{}\n    {{\"id\": {}, \"title\": \"{}\", \"mass\": {}, \"internal\": {}, \"kinetic\": {}, "
                       "\"hourglass\": {}}}",
                       k == 0 ? "" : ",", p.id, escaped(p.title), number(p.mass), number(p.internal), number(p.kinetic),
                       number(p.hourglass));
  }
  return out + "\n  ]";
}

}  // namespace

std::vector<DeckFile> describe_deck_files(const std::vector<std::string>& paths) {
  std::vector<DeckFile> files;
  for (const std::string& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path + " again to take its checksum");
    DeckFile f{path, 0, static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0))};
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      const auto n = static_cast<uInt>(in.gcount());
      f.crc32 = static_cast<std::uint32_t>(crc32(f.crc32, reinterpret_cast<const Bytef*>(buffer), n));
      f.bytes += n;
    }
    files.push_back(f);
  }
  return files;
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", utc);
}

const char* status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Normal: return "normal";
    case RunStatus::Error: return "error";
    case RunStatus::Stopped: return "stopped";
  }
  return "error";
}

std::string to_json(const RunSummary& s) {
  const EnergyBalance& e = s.energy;
  return fmt::format(
      "{{\n  \"name\": \"{}\",\n  \"crumple_version\": \"{}\",\n  \"commit\": \"{}\",\n  \"date\": \"{}\",\n"
      "  \"deck_files\": {},\n  \"cycles\": {},\n  \"cycles_total\": {},\n  \"engine_decks\": {},\n  \"time\": {},\n  \"dt\": {},\n  \"energy\": {{\n"
      "    \"internal\": {},\n    \"kinetic_translational\": {},\n    \"kinetic_rotational\": {},\n"
      "    \"contact\": {},\n    \"hourglass\": {},\n    \"external_work\": {},\n    \"total\": {},\n"
      "    \"error_percent\": {}\n  }},\n  \"mass\": {{\n    \"total\": {},\n    \"added\": {}\n  }},\n"
      "  \"selective_mass\": {{\n    \"solves\": {},\n    \"iterations\": {},\n    \"iterations_max\": {}\n  }},\n"
      "  \"wall_seconds\": {},\n  \"element_cycles_per_second\": {},\n"
      "  \"profile\": {{\n    \"elements\": {},\n    \"contact\": {},\n    \"contact_passes\": {},\n"
      "    \"contact_sort\": {},\n    \"contact_sorts\": {},\n"
      "    \"loads\": {},\n    \"update\": {},\n    \"output\": {}\n  }},\n  \"ranks\": {},\n  \"precision\": \"{}\",\n"
      "  \"deleted_elements\": {},\n  \"parts\": {},\n  \"status\": \"{}\",\n  \"message\": \"{}\",\n  \"accuracy\": \"{}\",\n  \"approximations\": {}\n}}\n",
      escaped(s.name), escaped(s.crumple_version), escaped(s.commit), escaped(s.date), file_array(s.deck_files), s.cycles, s.cycles_total, s.engine_decks, number(s.time), number(s.dt), number(e.internal), number(e.kinetic_translational),
      number(e.kinetic_rotational), number(e.contact), number(e.hourglass), number(e.external_work), number(e.total),
      number(e.error_percent), number(s.mass_total), number(s.mass_added), s.selective_solves, s.selective_iterations,
      s.selective_iterations_max, number(s.wall_seconds),
      number(s.element_cycles_per_second), number(s.phases.elements), number(s.phases.contact),
      s.phases.contact_passes, number(s.phases.contact_sort), s.phases.contact_sorts, number(s.phases.loads), number(s.phases.update), number(s.phases.output), s.ranks, escaped(s.precision), s.deleted_elements, part_array(s.parts), status_name(s.status), escaped(s.message),
      escaped(s.accuracy), string_array(s.approximations));
}

void write_summary(const RunSummary& summary, const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << to_json(summary);
}

}  // namespace crumple
