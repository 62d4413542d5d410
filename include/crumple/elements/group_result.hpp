#pragma once
// What an element kernel returns for one group, and how every kernel closes an element's cycle.
#include <cstdint>

#include "crumple/state/element_status.hpp"

namespace crumple {

struct GroupStepResult {
  double min_dt = 1e300;           // smallest critical step of the group's active elements [T]
  std::int32_t controlling = -1;   // element (ElementTable index) with that step
  double internal_energy = 0.0;    // increment of the cycle [M L^2 T^-2]
  double hourglass_energy = 0.0;   // increment of the cycle
  std::int32_t failed = 0;         // elements deleted during the cycle
  std::int32_t inverted = -1;      // an element whose area or volume became zero or negative (-1: none)
  std::int32_t inverted_count = 0; // shells deleted as inverted during the cycle (of them `inverted` is the last)
  std::int32_t non_finite = -1;    // an element whose forces became NaN or infinite (-1: none)
};

// A failed truss or beam lets go over a few cycles: its factor `off` falls by the first number a cycle from the
// cycle it fails in, and it is deleted after the cycle the factor falls below the second (docs/theory/truss.md,
// TR-7; beam.md, BM-9; measured on both).
inline constexpr double kLettingGoDecay = 0.8, kLettingGoDeleted = 0.1;

// The end of one element's cycle in a kernel: its critical step into the state and the group's result (the
// smallest and its element), and its deletion when it failed (every kernel closes its elements this way).
template <class State>
inline void close_element(State& state, GroupStepResult& result, std::int32_t e, double step, bool failed) {
  const auto ue = static_cast<std::size_t>(e);
  state.critical_dt[ue] = step;
  if (step < result.min_dt) result.min_dt = step, result.controlling = e;
  if (failed) {
    state.deleted[ue] = kElementDeleted;
    ++result.failed;
  }
}

// A shell turned inside out (no frame, zero area, or a quadrilateral folded into a bow tie) leaves the run: it is
// deleted and named in the listing, as crash solvers delete distorted shells instead of stopping
// (docs/theory/shell4.md, "Inverted elements"). A brick of negative volume still ends the run.
template <class State>
inline void delete_inverted_shell(State& state, GroupStepResult& result, std::int32_t e) {
  state.deleted[static_cast<std::size_t>(e)] = kElementDeleted;
  ++result.failed;
  ++result.inverted_count;
  result.inverted = e;
}

}  // namespace crumple
