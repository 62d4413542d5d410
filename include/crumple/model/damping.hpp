#pragma once
// /DAMP: Rayleigh damping of a node group (docs/theory/damping.md).
#include <cstdint>

#include "crumple/core/source_location.hpp"

namespace crumple {

struct RayleighDamping {
  SourceLocation where;
  std::int64_t user_id = 0;
  double alpha = 0.0;  // mass-proportional coefficient, every degree of freedom [1/T] (eq. D-1)
  double beta = 0.0;   // stiffness-proportional coefficient [T] (eq. D-5)
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;  // dense index (model build)
  double start = 0.0, stop = 1e30;  // it acts for start <= t <= stop [T]
  bool active(double t) const { return t >= start && t <= stop; }
};

// Engine /DAMP/damp_ID: new coefficients for a starter /DAMP from the start of this engine deck.
struct DampingChange {
  SourceLocation where;
  std::int64_t damping_id = 0;
  std::int32_t damping = -1;  // dense index into Model::dampings (model build)
  double alpha = 0.0, beta = 0.0;
};

}  // namespace crumple
