#pragma once
// Rigid walls (/RWALL) and rigid bodies (/RBODY).
#include <cstdint>
#include <string>

#include "crumple/deck/error.hpp"
#include "crumple/model/loads.hpp"

namespace crumple {

enum class RigidWallShape : std::uint8_t { Plane, Cylinder, Sphere, Parallelogram };
enum class WallSliding : std::uint8_t { Sliding = 0, Tied = 1, Friction = 2 };

struct RigidWall {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  RigidWallShape shape = RigidWallShape::Plane;
  std::int64_t node_id = 0;  // node that moves the wall (0: fixed wall)
  std::int32_t node = -1;
  WallSliding slide = WallSliding::Sliding;
  std::int64_t node_group1_id = 0;  // secondary nodes
  std::int64_t node_group2_id = 0;  // nodes removed from the secondary set
  std::int32_t node_group1 = -1;
  std::int32_t node_group2 = -1;
  double search_distance = 0.0;  // D_search [L]; 0: every node of the group
  double friction = 0.0;
  double diameter = 0.0;         // cylinder or sphere diameter [L]
  double filter_factor = 0.0;    // friction filtering
  int filter_flag = 0;
  double mass = 0.0;             // moving wall mass [M]
  Vec3 velocity0{};              // moving wall initial velocity [L T^-1]
  Vec3 point{};                  // M: a point of the wall [L]
  Vec3 point1{};                 // M1: with M, the normal or axis direction [L]
  Vec3 point2{};                 // M2: second edge point of a parallelogram [L]
};

struct RigidBody {  // /RBODY
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t main_node_id = 0;  // RBID
  std::int32_t main_node = -1;
  std::int64_t sensor_id = 0;
  std::int64_t skew_id = 0;
  int ispher = 0;
  double mass = 0.0;              // mass added at the main node [M]
  std::int64_t node_group_id = 0; // secondary nodes
  std::int32_t node_group = -1;
  int ikrem = 0;
  int icog = 0;
  std::int64_t surface_id = 0;
  double inertia[6] = {0, 0, 0, 0, 0, 0};  // Jxx Jyy Jzz Jxy Jyz Jxz [M L^2]
  int ioptoff = 0;
  int iexpams = 0;
};

}  // namespace crumple
