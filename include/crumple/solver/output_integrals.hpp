#pragma once
// What the outputs need of every cycle and no phase of the cycle reads: nodal results of the field frames and
// the integrals of the /TH outputs. The monitor and the output read them.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/model/elements.hpp"

namespace crumple {

// Nodal results a field frame asks for that the cycle would otherwise not keep (/ANIM/VECT/ACC, FINT, FEXT): 3 per
// node (x y z), sized by the solver only when the engine deck asks for them, else empty. Output only: no phase of
// the cycle reads them.
struct RecordedNodalResults {
  std::vector<double> acceleration;    // a^n = (v^(n+1/2) - v^(n-1/2)) / dt^n, after the kinematic conditions
  std::vector<double> internal_force;  // the elements' forces on the node at x^n [M L T^-2]
  std::vector<double> external_force;  // /CLOAD and /GRAV forces at t^n [M L T^-2]
};

// What the /TH outputs need integrated over every cycle and the cycle would otherwise not keep (docs/output-format.md,
// "ACCEL", and "NODE" for DRX DRY DRZ): sized by the solver at the start only when the deck asks for it, else empty,
// so that a deck without them pays nothing. Output only: no phase of the cycle reads it.
struct HistoryIntegrals {
  // /ACCEL, in the order of Model::accelerometers; 3 values (x y z, global) per accelerometer.
  std::vector<double> accel_filtered;  // the filtered acceleration AX AY AZ [L/T^2]
  std::vector<double> accel_velocity;  // WX WY WZ: the sum of the raw accelerations a^n dt^n since the start [L/T]
  // 18 per accelerometer, 6 per component: the filter's last two inputs and the last two outputs of each of its
  // two sections (x1 x2 y1 y2 z1 z2), zero at the start.
  std::vector<double> accel_memory;
  // /TH/NODE DRX DRY DRZ: the nodes a request asks them of (dense indices, sorted) and, 3 per node, the integral of
  // their angular velocity, sum w^(n+1/2) dt^(n+1/2) since the start (global axes) [-].
  std::vector<std::int32_t> rotation_nodes;
  std::vector<double> rotation;
  // /TH/SECTIO (solver/sections.hpp): per element kind, the elements of the sections a request asks WORK of (the
  // cycle integrates their work, ShellState::section_work), and in a run of several domains each element's domain
  // when a written section reads it, else -1 (their records travel at a history row).
  std::array<std::vector<std::int32_t>, kElementKinds> section_work_elements, section_record_owner;
};

}  // namespace crumple
