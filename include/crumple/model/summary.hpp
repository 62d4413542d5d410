#pragma once
// What `crumple check` reports about a model's geometry: its bounding box (the elements' step estimates are
// elements/critical_step.hpp's).
#include "crumple/core/vec3.hpp"
#include "crumple/model/model.hpp"

namespace crumple {

struct BoundingBox {
  Vec3 min{0, 0, 0};
  Vec3 max{0, 0, 0};
};
BoundingBox bounding_box(const Nodes& nodes);

}  // namespace crumple
