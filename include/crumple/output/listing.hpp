#pragma once
// NAME.out: the run listing with the Radioss-style energy balance table (docs/output-format.md, "Listing"). Every
// line and row is flushed as it is written, so that the listing can be followed while the run goes.
#include <filesystem>
#include <fstream>
#include <string>

namespace crumple {

struct ListingRow {
  long long cycle = 0;
  double time = 0.0, dt = 0.0;
  std::string controlling;  // what controls the step, e.g. "SHELL 61"
  double error_percent = 0.0, internal = 0.0, kinetic_translational = 0.0, kinetic_rotational = 0.0,
         external_work = 0.0, hourglass = 0.0, contact = 0.0, mass_error = 0.0, total_mass = 0.0, added_mass = 0.0;
};

class Listing {
 public:
  // Throws std::runtime_error when it cannot be written. `append`: after what the file holds (a resumed run).
  explicit Listing(const std::filesystem::path& path, bool append = false);
  void line(const std::string& text);                    // free text (start, notes, end)
  void table_header();
  void row(const ListingRow& row);
  void flush() { out_.flush(); }

 private:
  std::ofstream out_;
};

}  // namespace crumple
