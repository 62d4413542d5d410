#pragma once
// The status byte of every element (ShellState::deleted, BrickState::deleted). Kernels compute only active
// elements; the other states say why an element is not computed.
#include <cstdint>

namespace crumple {

inline constexpr std::uint8_t kElementActive = 0;
// Failed (plastic strain, time-step deletion): gone for good, and gone from the contact interfaces with Idel.
inline constexpr std::uint8_t kElementDeleted = 1;
// Every node in one active rigid body (docs/theory/rigid-bodies.md): the element moves rigidly with it, takes no
// strain and sets no step; it comes back when the body is switched off.
inline constexpr std::uint8_t kElementInRigidBody = 2;
// A flag beside those, in a run of several domains (docs/parallel.md): another domain computes the element. This
// domain skips it and takes its loads from that domain; its condition (the status without the flag) is kept the
// same as its owner's.
inline constexpr std::uint8_t kElementElsewhere = 0x80;
// The element's condition: active, deleted or in a rigid body, whichever domain computes it.
inline std::uint8_t element_condition(std::uint8_t status) { return status & 0x7f; }

}  // namespace crumple
