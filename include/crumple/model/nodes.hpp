#pragma once
// Nodes as structure of arrays: the dense index i of a node is its position in every array.
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"

namespace crumple {

struct Nodes {
  std::vector<std::int64_t> user_id;  // id as written in the deck, for messages and output
  std::vector<double> x, y, z;        // initial coordinates [L]
  std::size_t size() const { return user_id.size(); }
  // The deck position of node i.
  Vec3 position(std::int32_t i) const {
    const auto k = static_cast<std::size_t>(i);
    return {x[k], y[k], z[k]};
  }
};

}  // namespace crumple
