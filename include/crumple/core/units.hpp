#pragma once
// Unit systems of /BEGIN. Every model quantity is converted once, at read time, from the input units to the
// working units (docs/deck-format.md, "Units"). A quantity's dimension is M^mass L^length T^time.

namespace crumple {

struct Dimension {
  int mass = 0;
  int length = 0;
  int time = 0;
};

namespace dim {
inline constexpr Dimension none{0, 0, 0};
inline constexpr Dimension mass{1, 0, 0};
inline constexpr Dimension length{0, 1, 0};
inline constexpr Dimension time{0, 0, 1};
inline constexpr Dimension area{0, 2, 0};
inline constexpr Dimension area_moment{0, 4, 0};  // second moment of area
inline constexpr Dimension velocity{0, 1, -1};
inline constexpr Dimension acceleration{0, 1, -2};
inline constexpr Dimension rate{0, 0, -1};            // strain rate, frequency
inline constexpr Dimension force{1, 1, -2};
inline constexpr Dimension moment{1, 2, -2};           // also energy
inline constexpr Dimension pressure{1, -1, -2};        // stress, modulus
inline constexpr Dimension density{1, -3, 0};
inline constexpr Dimension inertia{1, 2, 0};           // mass moment of inertia
inline constexpr Dimension stiffness{1, 0, -2};        // force per length
inline constexpr Dimension viscous_damping{1, 0, -1};  // force per velocity
inline constexpr Dimension angular_velocity{0, 0, -1};
inline constexpr Dimension energy_per_volume{1, -1, -2};
}  // namespace dim

struct UnitSystem {
  // SI size of one input unit and one working unit of mass, length and time.
  double input[3] = {1.0, 1.0, 1.0};
  double work[3] = {1.0, 1.0, 1.0};

  // Factor that turns a value given in input units into working units.
  double factor(Dimension d) const;
};

}  // namespace crumple
