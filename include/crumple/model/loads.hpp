#pragma once
// Boundary conditions, imposed motion, initial velocities, loads and added mass. Every record keeps the user ids
// it refers to (`*_id`) and the dense indices the model build resolves them to (no suffix, -1 = none).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/deck/error.hpp"

namespace crumple {

using Vec3 = std::array<double, 3>;

// Degree of freedom addressed by a load or imposed motion: X, Y, Z translations, XX, YY, ZZ rotations.
enum class Dof : std::uint8_t { X, Y, Z, XX, YY, ZZ };

struct BoundaryCondition {  // /BCS
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::array<bool, 3> fixed_translation{};  // x, y, z
  std::array<bool, 3> fixed_rotation{};     // about x, y, z
  std::int64_t skew_id = 0;
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
};

// /IMPVEL, /IMPDISP, /CLOAD share a layout: value(t) = scale_y * f(t / scale_x) on a dof of a node group.
enum class ImposedKind : std::uint8_t { Velocity, Displacement, Force };

struct ImposedMotion {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  ImposedKind kind = ImposedKind::Velocity;
  std::int64_t function_id = 0;
  std::int32_t function = -1;
  Dof dof = Dof::X;
  std::int64_t skew_id = 0;
  std::int64_t sensor_id = 0;
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  std::int64_t frame_id = 0;
  int icoor = 0;
  double scale_x = 1.0;   // abscissa (time) scale [T]
  double scale_y = 1.0;   // ordinate scale [velocity, length or force]
  double t_start = 0.0;   // [T]
  double t_stop = 1e30;   // [T]
};

struct InitialVelocity {  // /INIVEL/TRA
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  Vec3 velocity{};  // [L T^-1]
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  std::int64_t skew_id = 0;
};

struct Gravity {  // /GRAV
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t function_id = 0;
  std::int32_t function = -1;
  Dof dof = Dof::Z;
  std::int64_t skew_id = 0;
  std::int64_t sensor_id = 0;
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  double scale_x = 1.0;  // [T]
  double scale_y = 1.0;  // [L T^-2]
};

struct AddedMass {  // /ADMAS
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  int type = 0;       // 0: mass added to each node of the group
  double mass = 0.0;  // [M]
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
};

}  // namespace crumple
