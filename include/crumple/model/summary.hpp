#pragma once
// What `crumple check` reports about a model: counts, mass, bounding box and the smallest element time step.
#include <array>
#include <cstdint>

#include "crumple/core/vec3.hpp"
#include "crumple/model/model.hpp"

namespace crumple {

// Critical (unscaled) time step of one element on the initial geometry (docs/theory/time-step.md):
// dt = L / c with L the characteristic length and c the plate (shells) or dilatational (bricks) wave speed.
double initial_element_time_step(const Model& model, ElementKind kind, std::size_t element);

struct ControllingElement {
  double time_step = 0.0;  // unscaled critical step [T]; 0 when the model has no element
  ElementKind kind = ElementKind::Shell4;
  std::int64_t element_user_id = 0;
  std::int64_t part_user_id = 0;
};

ControllingElement smallest_element_time_step(const Model& model);

struct BoundingBox {
  Vec3 min{0, 0, 0};
  Vec3 max{0, 0, 0};
};
BoundingBox bounding_box(const Nodes& nodes);

}  // namespace crumple
