#pragma once
// NAME.h5: field results at /ANIM/DT times and time histories at /TFILE times (docs/output-format.md).
// Opened once before the first cycle; frames and history rows are appended outside the hot loops.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/output/history_channels.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// One row of global histories: time, energies and per-object values the /TH cards ask for.
struct HistoryRow {
  double time = 0.0;
  double dt = 0.0;
  double internal = 0.0, kinetic_translational = 0.0, kinetic_rotational = 0.0, hourglass = 0.0, contact = 0.0,
         external_work = 0.0, total = 0.0;
  std::vector<double> rigid_wall_force;  // 3 per rigid wall (force of the wall on its nodes)
  std::vector<double> node_values;       // per /TH/NODE node: x y z vx vy vz (6 values)
  std::vector<double> rigid_body_values; // per rigid body: x y z vx vy vz wx wy wz (9 values)
  // per TYPE7 interface: normal force (3), tangential force (3) on the secondary nodes, elastic energy, friction
  // work, absorbed energy, active nodes (10 values)
  std::vector<double> interface_values;
  std::vector<std::vector<double>> th;  // per /TH dataset of the file, its columns' values (HistoryChannels)
};

class ResultsFile {
 public:
  // Creates the file and writes the mesh (coordinates, connectivity, user ids) and the empty history datasets, the
  // /TH ones as `histories` lays them out. Throws std::runtime_error.
  // With `continue_from` (a run resumed from a restart at that time [T]) an existing file is continued instead: its
  // frames and history rows stay, the new ones are appended after them (docs/output-format.md, "Restart"). Throws
  // RestartError, naming what differs, when the file holds another mesh or other /TH datasets, or results past
  // `continue_from`, which continuing would leave out of order.
  ResultsFile(const std::filesystem::path& path, const Model& model, std::vector<HistoryDataset> histories = {},
              std::optional<double> continue_from = std::nullopt);
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  // Appends a field frame at time `time` of cycle `cycle`: the fields every frame has (displacement, velocity,
  // element stress, plastic strain, shell thickness, deleted and VTK ghost flags) and those model.run.anim asks
  // for (docs/output-format.md). Throws when the state does not fit the mesh, before anything is written.
  void write_frame(double time, long long cycle, const Model& model, const SolverState& state);
  // Appends a history row.
  void write_history(const HistoryRow& row);
  std::size_t frames() const;
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace crumple
