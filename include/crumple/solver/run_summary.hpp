#pragma once
// What a run ends with (README, "Run summary"; written as NAME.summary.json by output/run_summary.hpp). Energies
// [M L^2 T^-2], masses [M], times [T], all in the deck's working units.
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/solver/run_events.hpp"

namespace crumple {

enum class RunStatus { Normal, Error, Stopped };

struct EnergyBalance {
  double internal = 0.0;
  double kinetic_translational = 0.0;
  double kinetic_rotational = 0.0;
  double contact = 0.0;
  double hourglass = 0.0;
  double external_work = 0.0;
  double total = 0.0;
  double error_percent = 0.0;  // (E_int + E_kin + E_hg + E_contact - E_kin0 - W_ext) / (E_kin0 + W_ext) * 100
};

// Wall time of the stages of the cycle, summed over the run [s] (the listing's TIME PROFILE).
struct PhaseTimes {
  double elements = 0.0;  // element forces and critical steps
  double contact = 0.0;   // TYPE7 passes (search, forces, interface step); exactly 0 without interfaces
  double loads = 0.0;     // external forces, rigid bodies' force gathering, time-step choice
  double update = 0.0;    // velocities, kinematic conditions, energy terms, positions
  double output = 0.0;    // energy records, listing, histories, frames
  long long contact_passes = 0;
  double contact_sort = 0.0;  // of `contact`: the searches (nodes' positions gathered, bucket sort)
  long long contact_sorts = 0;  // searches, over all interfaces
};

// One file of the deck as read (includes too), to tell later which deck a result came from.
struct DeckFile {
  std::string path;
  std::uintmax_t bytes = 0;
  std::uint32_t crc32 = 0;  // zlib's CRC-32 of the file's bytes
};

// One part at the end of a run, as /TH/PART gives it (docs/output-format.md, "Parts": a node shared by parts is
// split among them): its mass [M] and its internal, kinetic (translational and rotational) and hourglass energies.
struct PartResult {
  std::int64_t id = 0;
  std::string title;
  double mass = 0.0, internal = 0.0, kinetic = 0.0, hourglass = 0.0;
};

struct RunSummary {
  std::string name;
  std::string crumple_version;  // build::version()
  std::string commit;           // build::commit(): the git commit Crumple was built from
  std::string date;             // when the run started, UTC, ISO 8601 (2026-12-02T01:23:45Z)
  std::vector<DeckFile> deck_files;
  long long cycles = 0;        // cycles of the last engine deck (a continued run counts each deck from 0)
  long long cycles_total = 0;  // cycles of every engine deck of the run
  int engine_decks = 1;        // NAME_0001.rad, NAME_0002.rad, ... run in order
  double time = 0.0;
  double dt = 0.0;
  EnergyBalance energy;
  double mass_total = 0.0;
  double mass_added = 0.0;  // mass added by time-step control (mass scaling)
  // Selective mass scaling (/DT/AMS): the cycles solved and their conjugate-gradient iterations (0 without it).
  long long selective_solves = 0, selective_iterations = 0, selective_iterations_max = 0;
  double wall_seconds = 0.0;
  double element_cycles_per_second = 0.0;
  PhaseTimes phases;
  int ranks = 1;
  std::string precision = "double";
  long long deleted_elements = 0;  // elements deleted over the run (failure, /DT/<type>/DEL), in every kind
  std::vector<PartResult> parts;   // every part at the end, in deck order
  RunStatus status = RunStatus::Normal;
  std::string message;  // why the run ended when status is not normal
  bool stopped_on_request = false;  // status stopped because SIGINT or SIGTERM asked for it, not a /STOP limit
  // Options of the deck that were skipped or approximated (output-only requests not written, performance hints,
  // options skipped on --skip-unknown), one line each; "approximations" in the JSON. Filled by the app.
  std::vector<std::string> approximations;
  std::string accuracy = "standard";  // the --accuracy preset; its changes are among the approximations
};

// The status a stop reason gives the run: a /STOP limit or a stop on request ends it "stopped", anything else
// that stops it (NaN, an inverted element, a step below its minimum) is an error.
inline RunStatus status_of(const StopReason& stop) {
  if (!stop.stopped()) return RunStatus::Normal;
  return stop.is_limit() || stop.requested() ? RunStatus::Stopped : RunStatus::Error;
}

}  // namespace crumple
