#pragma once
// Rigid walls (/RWALL) and rigid bodies (/RBODY). Card layouts and defaults: docs/cards/loads-output-engine.md.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/model/loads.hpp"

namespace crumple {

enum class RigidWallShape : std::uint8_t { Plane, Cylinder, Sphere, Parallelogram };

// The shape's word in the keyword, /RWALL/<name>/id.
inline const char* rigid_wall_shape_name(RigidWallShape shape) {
  switch (shape) {
    case RigidWallShape::Plane: return "PLANE";
    case RigidWallShape::Cylinder: return "CYL";
    case RigidWallShape::Sphere: return "SPHER";
    case RigidWallShape::Parallelogram: return "PARAL";
  }
  return "";
}
enum class WallSliding : std::uint8_t { Sliding = 0, Tied = 1, Friction = 2 };

struct RigidWall {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  RigidWallShape shape = RigidWallShape::Plane;
  std::int64_t node_id = 0;  // node that carries the wall (0: fixed wall)
  std::int32_t node = -1;
  WallSliding slide = WallSliding::Sliding;
  std::int64_t node_group1_id = 0;  // nodes added to the secondary set (0: none)
  std::int64_t node_group2_id = 0;  // nodes removed from the secondary set (0: none)
  std::int32_t node_group1 = -1;
  std::int32_t node_group2 = -1;
  double search_distance = 0.0;  // D_search [L]; 0: no search, only the nodes of group 1
  double friction = 0.0;         // Coulomb coefficient, used with WallSliding::Friction [-]
  double diameter = 0.0;         // cylinder or sphere diameter [L], > 0 for those shapes
  // Friction filter: filter_flag 0 none; 1 alpha = filter_factor [-]; 2 filter_factor is a period [T];
  // 3 filter_factor is a frequency [T^-1]. A zero factor turns the filter off (flag 0).
  double filter_factor = 0.0;
  int filter_flag = 0;
  double mass = 0.0;             // moving wall: mass added to the wall node [M]
  Vec3 velocity0{};              // moving wall: initial velocity of the wall node [L T^-1]
  // M: a point of the wall [L]: the plane point, a point of the cylinder axis, the sphere centre, the
  // parallelogram corner. For a moving wall it is the wall node's initial position (model build).
  Vec3 point{};
  Vec3 point1{};                 // M1, a point [L]: M -> M1 is the plane normal or the cylinder axis
  Vec3 point2{};                 // M2, a point [L]: parallelogram corner; M -> M1 and M -> M2 are its edges
  // Model build: unit normal (plane, parallelogram: along (M1 - M) x (M2 - M)) or unit axis (cylinder); zero
  // for a sphere.
  Vec3 direction{};
  // Model build: dense indices of the secondary nodes, sorted: nodes within D_search on the outer side, plus
  // group 1, minus group 2, minus the wall node, minus rigid-body secondary nodes of bodies with Ikrem = 0.
  std::vector<std::int32_t> secondary_nodes;
};

// Unit normal (plane: along M1 - M; parallelogram: along (M1 - M) x (M2 - M)) or unit axis (cylinder: along
// M1 - M) of a wall; zero for a sphere. nullopt when the points define none: M1 on M, or for a parallelogram M2
// on M or on the line M M1. "On" means closer than 1e-10 times the size of the coordinates, so that the result
// does not depend on the length unit.
inline std::optional<Vec3> wall_direction(RigidWallShape shape, const Vec3& m, const Vec3& m1, const Vec3& m2) {
  if (shape == RigidWallShape::Sphere) return Vec3{};
  const double size = std::max({norm(m), norm(m1), norm(m2)});
  const Vec3 edge1 = m1 - m;
  const double length1 = norm(edge1);
  if (!(length1 > 1e-10 * size)) return std::nullopt;
  Vec3 direction = edge1;
  double length = length1;
  if (shape == RigidWallShape::Parallelogram) {
    const Vec3 edge2 = m2 - m;
    direction = cross(edge1, edge2);
    length = norm(direction);
    // |e1 x e2| = |e1| |e2| sin(angle): a zero or tiny angle (or edge) leaves no plane.
    if (!(length > 1e-10 * length1 * std::max(norm(edge2), 1e-10 * size))) return std::nullopt;
  }
  return Vec3{direction[0] / length, direction[1] / length, direction[2] / length};
}

struct RigidBody {  // /RBODY
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t main_node_id = 0;  // node_ID (RBID in HyperCrash decks)
  std::int32_t main_node = -1;
  std::int64_t sensor_id = 0;
  // With a sensor the body is off while the sensor is on, and formed again from its nodes when the sensor turns off
  // (measured on the reference: "RIGID BODY SET OFF" at its activation; docs/theory/rigid-bodies.md, RB-6).
  SensorWindow sensor;            // resolved from sensor_id (model build)
  std::int64_t skew_id = 0;
  std::int32_t skew = -1;         // the added inertia's axes (-1: global)
  int ispher = 2;                 // 1 spherical inertia; 2 from the nodes + added inertia; 3 from data
  double mass = 0.0;              // mass added at the main node [M], >= 0
  std::int64_t node_group_id = 0; // secondary nodes
  std::int32_t node_group = -1;
  int ikrem = 0;                  // 0: secondary nodes removed from rigid walls; 1: kept
  int icog = 1;                   // centre of the body (RB-0e): 1 of all masses; 2 of the secondary nodes; 3, 4 main node
  std::int64_t surface_id = 0;
  std::array<double, 6> inertia{};  // added inertia Jxx Jyy Jzz Jxy Jyz Jxz [M L^2]
  int ioptoff = 0;                // load-balancing hint, no effect
  int iexpams = 0;                // AMS expansion flag, no effect
};

}  // namespace crumple
