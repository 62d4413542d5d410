#pragma once
// What rigid bodies and rigid walls advance (docs/theory/rigid-bodies.md, docs/theory/rigid-walls.md).
#include <array>
#include <cstdint>
#include <vector>

#include "crumple/core/vec3.hpp"

namespace crumple {

struct RigidBodyState {
  std::int32_t main_node = -1;
  std::vector<std::int32_t> secondary;  // secondary nodes (without the main node)
  std::vector<double> rx, ry, rz;       // secondary node positions relative to the centre of mass, body frame
  double mass = 0.0;                     // total mass [M]
  std::array<double, 9> inertia_body{};  // inertia tensor about the centre of mass in the body frame [M L^2]
  std::array<double, 9> inertia_added{}; // the part of it no nodal mass carries: the card's Jxx..Jxz, the main
                                         // node's mass where it was (ICoG 1)
  Vec3 first_moment{};  // sum of m r over the secondary nodes, body frame [M L]: 0 when the centre is theirs (RB-7)
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // body frame -> global
  Vec3 velocity{};          // velocity of the centre of mass at t^(n-1/2)
  Vec3 momentum_angular{};  // angular momentum about the centre of mass (global) at t^(n-1/2)
  Vec3 omega{};             // angular velocity (global) at t^(n-1/2)
  bool active = true;                        // /RBODY/OFF sets it off: the secondary nodes move on their own
  // /IMPVEL and /IMPDISP cards (indices into Model::imposed) acting on the main node: they drive the body.
  std::vector<std::int32_t> main_node_conditions;
  // /BCS cards in a skew (indices into Model::boundary_conditions) holding the main node (SK-5).
  std::vector<std::int32_t> main_node_skewed_fixes;
};

// /RBE2 (docs/theory/rigid-bodies.md, RE-2): the main node's mass and inertia as the group carries them, from the
// last gather, and the conditions on the main node that drive the group.
struct RigidElementState {
  double mass = 0.0;  // M = m_main + sum m_s [M]
  // About the main node, per axis of its rotation that turns the secondary nodes: I_main + sum 2 m_s |r_s|^2, plus
  // the secondary nodes' own inertia on their coupled axes (RE-2); 0 on the other axes [M L^2].
  Vec3 inertia{};
  std::vector<std::int32_t> main_node_conditions;    // /IMPVEL, /IMPDISP on the main node (indices into Model::imposed)
  std::vector<std::int32_t> main_node_skewed_fixes;  // /BCS in a skew on the main node
};

// /RBE3 (docs/theory/rigid-bodies.md, RI-1 to RI-4): each independent node's dof weights as the solver uses them
// (rotations dropped where the node has no rotational inertia), and the last load solve's inverse, which the
// dependent node's motion of the same cycle reuses.
struct InterpolationState {
  std::vector<std::array<double, 6>> weight;  // per independent node of the model's list [-]
  double length_squared = 0.0;                 // Lc^2 of the last solve [L^2]
  std::array<double, 36> inverse{};            // A^-1 of the last solve, row-major
};

struct RigidWallState {
  std::vector<std::int32_t> nodes;   // candidate secondary nodes
  std::vector<std::uint8_t> tied;    // tied walls: 1 once the node touched
  std::vector<std::uint8_t> active;  // scratch of the cycle: 1 when the node is held by the wall
  // Selective mass scaling's prediction of the step (docs/theory/time-step.md, SM-4), from the velocities before
  // it: per candidate node, the wall's normal there (3 each), whether it holds every direction (tied), and the
  // normal velocity it leaves the node [L/T]; `active` says which it holds.
  std::vector<double> held_normal;
  std::vector<std::uint8_t> held_tied;
  std::vector<double> held_speed;
  Vec3 force{};     // force of the wall on the nodes during the last cycle [F]
  Vec3 normal_force{};  // its part along the wall's normal at each node it held [F]
  Vec3 velocity{};  // wall velocity v^(n+1/2) [L/T]
  Vec3 origin{};    // current point M [L]
  // Moving walls: translation dofs (bit 0 x, 1 y, 2 z) in which the wall node is free, i.e. neither fixed nor
  // imposed; in those the wall takes the nodes' reaction (eq. RW-2), in the others it is driven.
  std::uint8_t free_dofs = 0;
};

}  // namespace crumple
