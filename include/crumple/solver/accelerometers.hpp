#pragma once
// /ACCEL (docs/output-format.md, "ACCEL"): the 4-pole Butterworth low-pass that filters an accelerometer's
// acceleration, and the update of every accelerometer after the velocity update of a cycle.
#include <array>
#include <vector>

#include "crumple/model/output_requests.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// One second-order section y_n = b0 x_n + b1 x_(n-1) + b2 x_(n-2) - a1 y_(n-1) - a2 y_(n-2) (eq. ACC-2).
struct FilterSection {
  double b0, b1, b2, a1, a2;
};

// The two sections of the 4-pole Butterworth low-pass of corner frequency `cutoff` [1/T] for samples `h` [T]
// apart: the analog filter through the bilinear transform with its corner frequency prewarped (eqs. ACC-1, ACC-2).
// The corner frequency is capped at 0.4 / h, below the Nyquist frequency 0.5 / h where the transform ends.
std::array<FilterSection, 2> butterworth4(double cutoff, double h);

// One sample through the two sections; `memory` holds x1 x2 y1 y2 z1 z2 (the last two inputs, the first section's
// last two outputs, the second's) and moves on by one sample. Returns the filtered value.
double filter_sample(const std::array<FilterSection, 2>& filter, double input, double* memory);

// After the velocity update of a cycle: each accelerometer's raw acceleration a^n = (v^(n+1/2) - before) / dt
// (`dt` = dt^n, the step of the update) into its integral W and, with Fcut > 0, through its filter; with Fcut = 0
// the filtered value is the raw one. An accelerometer in a skew measures along the skew's axes (`skews`, at the
// current positions): its velocity change is written in them before it is integrated and filtered (SK-4). Does
// nothing for a model without accelerometers.
void update_accelerometers(const std::vector<Accelerometer>& accelerometers, const NodalState& nodes,
                           const std::array<const std::vector<double>*, 3>& before, double dt,
                           const std::vector<SkewAxes>& skews, HistoryIntegrals& histories);

// Sizes the accelerometers' values (zero) for `count` accelerometers.
void setup_accelerometers(std::size_t count, HistoryIntegrals& histories);

}  // namespace crumple
