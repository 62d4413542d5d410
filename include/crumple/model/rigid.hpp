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

// /RBE2: secondary nodes that follow a main node rigidly in the coupled degrees of freedom
// (docs/theory/rigid-bodies.md, RE-1 to RE-5). Crumple couples the three translations (Trarot TX TY TZ 111) and
// any of the rotations; Iflag 0 turns the secondary nodes about the main node with its whole angular velocity,
// Iflag 1 with only its coupled components.
struct RigidElement {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t main_node_id = 0;
  std::int32_t main_node = -1;
  std::array<bool, 3> rotation{true, true, true};  // RX RY RZ coupled (Trarot's last three digits)
  std::int64_t skew_id = 0;                         // only with 111 111, where it changes nothing (RE-1)
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  int iflag = 0;  // 0: the secondaries turn with the whole rotation of the main node; 1: with its coupled part
  std::vector<std::int32_t> secondary_nodes;  // model build: the group's nodes without the main node, sorted
  // The components of the main node's rotation the secondary nodes turn with (RE-2): all three with Iflag 0,
  // the coupled ones with Iflag 1.
  bool turns_about(std::size_t axis) const { return iflag == 0 || rotation[axis]; }
};

// /RBE3: a dependent node whose loads are spread over independent node sets, and which moves with their weighted
// least-squares rigid motion (docs/theory/rigid-bodies.md, RI-1 to RI-6).
struct InterpolationSet {
  double weight = 1.0;  // WT_i [-] (0 or blank: 1)
  // Trarot_Mi: blank or six zeros is 111 000 (measured on the reference; its manual says all six).
  std::array<bool, 3> translation{true, true, true}, rotation{};
  std::int64_t skew_id = 0;  // only with codes a rotation leaves unchanged (111 or 000 for each triple)
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
};

// One independent node of one set: its weight on each dof x y z rx ry rz, after I_modif (RI-2) [-].
struct InterpolationNode {
  std::int32_t node = -1;
  std::array<double, 6> weight{};
  double given_weight = 0.0;  // its set's WT_i as given: its share of the dependent node's mass (RI-5)
};

struct InterpolationConstraint {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t dependent_node_id = 0;
  std::int32_t dependent_node = -1;
  std::array<bool, 6> reference_dofs{true, true, true, true, true, true};  // Trarot_ref (blank or zeros: all six)
  int i_modif = 1;  // weights: 1 made to carry every translation alike, 2 as given, 3 all 1 then as 1
  std::vector<InterpolationSet> sets;
  std::vector<InterpolationNode> independent;  // model build, in set order
  double total_weight = 0.0;                   // sum of the sets' weights over their nodes, as given (RI-5) [-]
};
}  // namespace crumple
