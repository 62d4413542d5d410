#pragma once
// /TH/SECTIO in the solver (docs/output-format.md, "SECTIO"): what the cycle keeps for the cut sections (/SECT) a
// request writes, and only for them. The section's values are sums over the loads its elements hand the nodes of
// its cut, which the kernels record (state/element_records.hpp): in a run of one domain the groups of the written
// sections' elements record, every cycle (a group's kernel writes its elements' loads beside adding them to the
// nodes; nothing of its arithmetic changes); in a run of several domains every element is recorded already, by
// the domain that computes it, and the records of the sections' elements travel to every domain at a history row.
// A request for WORK adds a loop over the sections' elements after the velocity update. A model without
// /TH/SECTIO sets nothing up, and the cycle runs no code of this.
#include <array>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/parallel/exchange.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// At the start (after the domain is taken): the records of the written sections' element groups (one domain) or
// the owners of their records (several), and the work integrals of the sections a request asks WORK of.
void setup_sections(const Model& model, SolverState& state);
// The same for a state that has taken a new domain during the run (docs/parallel.md, "Rebalancing"); with
// `keep_work`, the work integrals (gathered from their old domains) stay as they are.
void bind_sections(const Model& model, SolverState& state, bool keep_work);

// After the velocity update of a cycle (`before`: v^(n-1/2) x y z rx ry rz, `dt` = dt^n): the work of each WORK
// element's recorded load at each of its nodes over the step, dt^n f . (v^(n-1/2) + v^(n+1/2)) / 2 (and the
// moment's with the angular velocities), as the loads' work (docs/theory/energy.md). A domain integrates its own
// elements only. Nothing to do without a request for WORK.
void add_section_work(const Model& model, SolverState& state, const std::array<std::vector<double>, 6>& before,
                      double dt);

// At a history row of a run of several domains: the records of the written sections' elements from the domains
// that compute them, into every domain. Nothing to do for one domain (`exchange` null) or without sections.
void share_section_records(SolverState& state, Exchange* exchange);

}  // namespace crumple
