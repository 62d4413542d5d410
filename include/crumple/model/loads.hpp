#pragma once
// Boundary conditions, imposed motion, initial velocities, loads and added mass. Every record keeps the user ids
// it refers to (`*_id`) and the dense indices the model build resolves them to (no suffix, -1 = none).
// Card layouts and defaults: docs/cards/loads-output-engine.md. Values are in working units.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/core/vec3.hpp"
#include "crumple/model/sensors.hpp"

namespace crumple {

// Degree of freedom addressed by a load or imposed motion: X, Y, Z translations, XX, YY, ZZ rotations.
enum class Dof : std::uint8_t { X, Y, Z, XX, YY, ZZ };

inline bool is_rotation(Dof dof) { return dof == Dof::XX || dof == Dof::YY || dof == Dof::ZZ; }
// Axis of a dof: 0, 1, 2 for x, y, z (translation or rotation).
inline int dof_axis(Dof dof) { return static_cast<int>(dof) % 3; }

struct BoundaryCondition {  // /BCS
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::array<bool, 3> fixed_translation{};  // x, y, z
  std::array<bool, 3> fixed_rotation{};     // about x, y, z
  std::int64_t skew_id = 0;
  std::int32_t skew = -1;  // -1: the global axes; else the fixed dofs are those of the skew's axes (SK-5)
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
};

// /IMPVEL, /IMPDISP, /CLOAD share a layout: value(t) = scale_y * f(t / scale_x) on a dof of each node of a
// group, for t_start <= t <= t_stop (the function is not shifted to start at t_start). With a sensor, also only
// while the sensor is on, and f runs on the sensor's clock: f((t - t_on) / scale_x) (eq. L-7).
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
  std::int32_t skew = -1;  // -1: `dof` is a global axis; else the skew's axis (SK-5, SK-6)
  std::int64_t sensor_id = 0;
  SensorWindow sensor;  // resolved from sensor_id (model build); no sensor: always on, clock from 0
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  std::int64_t frame_id = 0;  // /IMPVEL only (the /IMPDISP and /CLOAD layouts have no frame)
  int icoor = 0;              // 0 Cartesian, 1 cylindrical (/IMPVEL, /IMPDISP)
  double scale_x = 1.0;       // abscissa (time) scale [T]
  // Ordinate scale: /IMPVEL [L T^-1] or [T^-1] (XX, YY, ZZ), /IMPDISP [L] or [-] (radians),
  // /CLOAD [M L T^-2] or [M L^2 T^-2] (moment). The load of /CLOAD applies to each node of the group.
  double scale_y = 1.0;
  double t_start = 0.0;   // [T]; /CLOAD: always 0
  double t_stop = 1e30;   // [T]; /CLOAD: always 1e30
};

// /IMPDISP/FGEO: each listed node is driven from its initial position X0_i to the final one X_i given on the card,
// u_i(t) = f(t / scale_x) (X_i - X0_i) for Tstart <= t <= Tstop while its sensor is on; after Tstop the node is free
// (eq. L-9). f should run from 0 to 1.
struct FinalGeometry {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t function_id = 0;
  std::int32_t function = -1;
  std::int64_t sensor_id = 0;
  SensorWindow sensor;
  double scale_x = 1.0;  // abscissa (time) scale [T]
  double t_start = 0.0;  // [T]
  double t_stop = 1e30;  // [T]
  std::vector<std::int64_t> node_ids;
  std::vector<SourceLocation> node_where;
  std::vector<Vec3> final_positions;  // [L]
  std::vector<std::int32_t> nodes;    // dense (model build)
  std::vector<Vec3> displacements;    // X_i - X0_i [L] (model build, on the positions after /TRANSFORM)
};

struct InitialVelocity {  // /INIVEL/TRA, /INIVEL/T+G (the same on Lagrangian nodes), /INIVEL/ROT
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  bool rotation = false;  // /INIVEL/ROT: the nodes' angular velocity
  Vec3 velocity{};  // [L T^-1], or [T^-1] for /INIVEL/ROT; in the skew's axes when there is one
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
  std::int64_t skew_id = 0;
  std::int32_t skew = -1;  // -1: global axes
};

// /GRAV: acceleration scale_y * f(t / scale_x) along `dof` on a node group (the force is mass * acceleration).
struct Gravity {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t function_id = 0;  // 0: constant acceleration scale_y
  std::int32_t function = -1;    // -1: constant
  Dof dof = Dof::Z;              // X, Y or Z only
  std::int64_t skew_id = 0;
  std::int32_t skew = -1;          // -1: `dof` is a global axis; else the skew's axis
  std::int64_t sensor_id = 0;
  SensorWindow sensor;             // resolved from sensor_id (model build), as for ImposedMotion
  std::int64_t node_group_id = 0;  // 0: every node of the model
  std::int32_t node_group = -1;    // -1: every node of the model
  double scale_x = 1.0;  // [T]
  double scale_y = 1.0;  // [L T^-2]
};

struct AddedMass {  // /ADMAS/type/id, types 0 and 1
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  int type = 0;       // 0: `mass` added to each node of the group; 1: `mass` shared equally by the group's nodes
  double mass = 0.0;  // [M], >= 0
  std::int64_t node_group_id = 0;
  std::int32_t node_group = -1;
};

}  // namespace crumple
