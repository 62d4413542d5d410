#pragma once
// Nodes as structure of arrays: the dense index i of a node is its position in every array.
#include <cstdint>
#include <vector>

namespace crumple {

struct Nodes {
  std::vector<std::int64_t> user_id;  // id as written in the deck, for messages and output
  std::vector<double> x, y, z;        // initial coordinates [L]
  std::size_t size() const { return user_id.size(); }
};

}  // namespace crumple
