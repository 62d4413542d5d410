#pragma once
// Boxes (/BOX/RECTA, /BOX/CYLIN, /BOX/SPHER, /BOX/BOX): volumes that select the nodes and elements of the box groups
// (/GRNOD/BOX, /GRSHEL/BOX, /GRSHEL/BOX2...). A point on a box's surface is inside. The rules, and what the
// reference measured for each, are in docs/deck-format.md, "Boxes".
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/core/vec3.hpp"
#include "crumple/model/skews.hpp"

namespace crumple {

enum class BoxShape : std::uint8_t { Rectangle, Cylinder, Sphere, Combination };

struct Box {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  BoxShape shape = BoxShape::Rectangle;
  // RECTA: two opposite corners; CYLIN: the two ends of the axis; SPHER: the centre (points[0]). Given by node ids
  // (node_ids non-zero) or by coordinates [L]; the model build puts the nodes' initial positions in `points`.
  std::array<std::int64_t, 2> node_ids{};
  std::array<Vec3, 2> points{};
  double diameter = 0.0;          // CYLIN, SPHER [L]
  std::int64_t skew_id = 0;       // RECTA: a skew whose axes the edges follow (0: the global axes)
  SkewAxes axes;                  // RECTA: the skew's axes, a moving one's at the start (model build)
  std::vector<std::int64_t> box_ids;        // /BOX/BOX: signed box ids (negative: taken away)
  std::vector<std::int32_t> added, removed; // /BOX/BOX: dense indices of the boxes (model build)
};

// Whether point p lies in box `box` (a dense index into `boxes`) or on its surface. /BOX/BOX: in one of its positive
// boxes and in none of its negative ones, whatever their order.
bool box_contains(const std::vector<Box>& boxes, std::size_t box, Vec3 p);

}  // namespace crumple
