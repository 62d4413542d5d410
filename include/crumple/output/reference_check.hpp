#pragma once
// A run against a reference solver's values at the reference's time (docs/regression.md): the one definition of
// the comparison, used by `crumple regress` and by the QA-deck ctests (tests/regression/test_qa_decks.cpp).
//
// ref.extract is the reference listing's last printed row, which can come before the run's end: the run's values
// are taken at the TIME of ref.extract, interpolating linearly between the rows of the results file's histories
// (energies) and between the rows of the listing's last energy table (cycles).
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace crumple {

// A mistake in ref.extract or in a tolerance file, naming the file, the line (0: the whole file) and the field.
class ReferenceFileError : public std::runtime_error {
 public:
  ReferenceFileError(std::filesystem::path file, int line, std::string field, const std::string& problem);
  const std::filesystem::path& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  std::filesystem::path file_;
  int line_;
  std::string field_;
};

// One line of ref.extract, "<line> KEY value [scale]".
struct ReferenceValue {
  double value = 0.0;
  double scale = 0.0;  // the energy scale for relative errors (the second number of energy lines; 0 without)
};

// Every line of ref.extract by KEY (CYCLE, TIME, IENERGY, KENERGYT, KENERGYR, ...). Throws ReferenceFileError on
// a file that cannot be read or a line that is not "<integer> KEY number [number]".
std::map<std::string, ReferenceValue> read_reference_values(const std::filesystem::path& file);

// The values the comparison needs.
struct ReferencePoint {
  double time = 0.0;      // TIME
  double cycles = 0.0;    // CYCLE
  double internal = 0.0;  // IENERGY
  double kinetic = 0.0;   // KENERGYT + KENERGYR
  double scale = 0.0;     // the second number of the IENERGY line
};

// ref.extract's point; throws ReferenceFileError naming a missing key.
ReferencePoint read_reference(const std::filesystem::path& file);

// y(time) on a table of increasing times t, linear between rows, the first value before the table and the last
// past its end; NaN on an empty table.
double value_at_time(const std::vector<double>& t, const std::vector<double>& y, double time);

// Time and cycle of the rows of the last energy table of a listing NAME.out (a continued run's tables start again
// from cycle 0); rows of equal time keep the first. Each row's step, internal energy and kinetic energy
// (translational + rotational) where the row has them (NaN where not).
struct ListingCycles {
  std::vector<double> time, cycle;
  std::vector<double> dt, internal, kinetic;
};
ListingCycles read_listing_cycles(const std::filesystem::path& listing);

// A run's values at the reference's time, from DIR/NAME.h5 (histories) and DIR/NAME.out (cycles); at the run's end
// (the reference's time within half a step of the listing's last row, or past it) the energies are that row's, the
// end state's (docs/theory/energy.md, E-3; time-loop.md, T-0), where the histories hold the loop's.
struct RunPoint {
  double history_end = 0.0;  // the last history time (NaN without rows)
  double internal = 0.0;
  double kinetic = 0.0;  // translational + rotational
  double cycles = 0.0;
};
// Throws std::runtime_error when the results file cannot be read.
RunPoint read_run_point(const std::filesystem::path& output_directory, const std::string& name, double time);

// The acceptance bands, as fractions (issue 10). A tolerance file may tighten them, never widen them.
struct Tolerances {
  double internal = 0.10;         // of max(|reference|, internal_floor x scale)
  double internal_floor = 1e-3;   // of the scale: an internal energy near zero is judged against this
  double kinetic = 0.05;          // of the scale
  double cycles = 0.15;           // of the reference's cycles
};

// The name of the optional tolerance file in a deck folder.
inline constexpr const char* kToleranceFile = "crumple-tolerances";

// Reads a tolerance file: lines "FIELD PERCENT" (internal, internal_floor, kinetic, cycles), '#' starts a
// comment. A field left out keeps `defaults`. Throws ReferenceFileError (file, line, field) on an unknown field, a
// value that is not a number, a negative value or one larger than the default.
Tolerances read_tolerances(const std::filesystem::path& file, const Tolerances& defaults = {});

// The histories must reach this share of the reference's time: the last /TFILE row may fall just before it.
inline constexpr double kHistoryReach = 0.98;

// One compared quantity: passes when |run - reference| <= tolerance (NaN fails).
struct QuantityCheck {
  double run = 0.0, reference = 0.0, tolerance = 0.0;
  double difference() const { return run - reference; }
  bool passed() const;
};

struct Comparison {
  double time = 0.0, scale = 0.0, history_end = 0.0;
  bool reaches_time = false;  // history_end >= kHistoryReach x time
  QuantityCheck internal, kinetic, cycles;
  bool passed() const { return reaches_time && internal.passed() && kinetic.passed() && cycles.passed(); }
  // Each failed check with its numbers, "; " between them; empty when the comparison passes.
  std::string failures() const;
};

Comparison compare(const ReferencePoint& reference, const RunPoint& run, const Tolerances& tolerances = {});

}  // namespace crumple
