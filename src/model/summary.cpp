#include "crumple/model/summary.hpp"

#include <algorithm>

namespace crumple {

BoundingBox bounding_box(const Nodes& nodes) {
  BoundingBox box;
  if (nodes.size() == 0) return box;
  const std::vector<double>* axes[3] = {&nodes.x, &nodes.y, &nodes.z};
  for (int k = 0; k < 3; ++k) {
    const auto [lo, hi] = std::minmax_element(axes[k]->begin(), axes[k]->end());
    box.min[static_cast<std::size_t>(k)] = *lo;
    box.max[static_cast<std::size_t>(k)] = *hi;
  }
  return box;
}

}  // namespace crumple
