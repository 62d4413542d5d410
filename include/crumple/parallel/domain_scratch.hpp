#pragma once
// What the exchanges of a run of several domains keep from one cycle to the next (solver/domain_sharing.cpp,
// solver/rebalance.cpp): owners of what travels, whose layouts the exchange keeps, and the element phase's scratch.
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/model/elements.hpp"

namespace crumple {

struct DomainScratch {
  // Per element kind, the domain of each integration point (its element's).
  std::array<std::vector<std::int32_t>, kElementKinds> point_owner;
  // Scratch of the element phase's exchange (several domains only): per element group, its smallest step and the
  // element that has it, the last element that inverted and the last with NaN forces, the failed count.
  struct GroupShare {
    std::vector<double> min_dt;
    std::vector<std::int32_t> controlling, last_inverted, last_non_finite, failed, inverted_count;
    std::vector<std::int32_t> stop_signal;  // the combined stop request
    // Owners of what travels at a sort and before an output (kept, so that the exchange's layouts, made once per
    // owner array, stay valid): per accelerometer and per /TH/NODE rotation node, the owner of its node; per
    // interface and node, its owner when it is one of the interface's nodes, else -1.
    std::vector<std::int32_t> accelerometer_owner, rotation_owner;
    std::vector<std::vector<std::int32_t>> interface_node_owner;  // per interface
    // Per interface, per secondary node, and per candidate pair (renewed at each sort): the owner of the
    // secondary node, for a restart snapshot of the contact state.
    std::vector<std::vector<std::int32_t>> secondary_owner, pair_owner;
    std::vector<std::vector<std::int32_t>> wall_node_owner;  // per rigid wall, per candidate node: its owner
  };
  GroupShare group_share;
  // Several domains, rebalancing (solver/rebalance.cpp): per element kind, every point's plastic strain at the last
  // check (its growth since tells which points flow).
  struct Rebalancing {
    std::array<std::vector<point_real>, kElementKinds> eps_p_at_check;
  };
  Rebalancing rebalancing;
};

}  // namespace crumple
