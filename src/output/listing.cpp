#include "crumple/output/listing.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace crumple {

Listing::Listing(const std::filesystem::path& path, bool append)
    : out_(path, append ? std::ios::out | std::ios::app : std::ios::out) {
  if (!out_) throw std::runtime_error("cannot write the listing " + path.string());
}

// Every line and row is flushed as it is written, so that the listing can be followed while the run goes
// (`tail -f NAME.out`): a row is printed every /PRINT cycles, and a write of one line costs little next to them.
void Listing::line(const std::string& text) { out_ << text << '\n' << std::flush; }

void Listing::table_header() {
  out_ << fmt::format("{:>9} {:>11} {:>11} {:<16} {:>7} {:>11} {:>11} {:>11} {:>11} {:>11} {:>11} {:>9} {:>11} {:>11}\n",
                      "CYCLE", "TIME", "TIME-STEP", "ELEMENT", "ERROR", "I-ENERGY", "K-ENERGY T", "K-ENERGY R",
                      "EXT-WORK", "HG-ENERGY", "CONTACT", "MAS.ERR", "TOTAL MASS", "MASS ADDED");
}

void Listing::row(const ListingRow& r) {
  out_ << fmt::format(
      "{:>9} {:>11.4e} {:>11.4e} {:<16} {:>6.1f}% {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e} {:>11.4e} "
      "{:>9.2e} {:>11.4e} {:>11.4e}\n",
      r.cycle, r.time, r.dt, r.controlling, r.error_percent, r.internal, r.kinetic_translational,
      r.kinetic_rotational, r.external_work, r.hourglass, r.contact, r.mass_error, r.total_mass, r.added_mass);
  out_.flush();
}

}  // namespace crumple
