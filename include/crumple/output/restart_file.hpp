#pragma once
// NAME.rst: the run's last snapshot (docs/output-format.md, "Restart file"). Written at the /RFILE interval, at
// the end of the run and when it is stopped; `crumple run DECK --restart FILE` goes on from it, with results
// bit-identical to the run it continues.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "crumple/model/model.hpp"
#include "crumple/solver/snapshot.hpp"

namespace crumple {

// A restart file that cannot be read, or that does not belong to the model it is read for: names the file.
class RestartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes the snapshot to `file` through a temporary file beside it, renamed over `file` once complete and closed,
// so that a run killed while writing keeps the previous snapshot. Throws std::runtime_error on an HDF5 failure.
void write_restart(const std::filesystem::path& file, const Model& model, SolverState& state, ResumeMarks& marks);

// Overwrites the snapshot's fields of `state` (a state built from the same deck by initial_state) from `file`.
// Throws RestartError when the file is missing, unreadable or written for another model (node or element counts).
ResumeMarks read_restart(const std::filesystem::path& file, const Model& model, SolverState& state);

}  // namespace crumple
