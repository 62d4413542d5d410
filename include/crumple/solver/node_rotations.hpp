#pragma once
// /TH/NODE DRX DRY DRZ (docs/output-format.md, "NODE"): the integral of the angular velocity of the nodes a request
// asks them of, kept by the cycle for those nodes only.
#include "crumple/model/model.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// The variables that need the integral.
inline constexpr std::string_view kNodeRotationVariables[] = {"DRX", "DRY", "DRZ"};

// The nodes the model's /TH/NODE requests ask DRX, DRY or DRZ of, their integrals zero.
void setup_node_rotations(const Model& model, HistoryIntegrals& histories);

// After the velocity update of a cycle: theta += w^(n+1/2) dt^(n+1/2) at those nodes (eq. TH-1), `dt` the step the
// positions advance by. Does nothing when no request asks for them.
void integrate_node_rotations(const NodalState& nodes, double dt, HistoryIntegrals& histories);

}  // namespace crumple
