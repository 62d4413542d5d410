#pragma once
// Unit systems of /BEGIN. Every model quantity is converted once, at read time, from the input units to the
// working units (docs/deck-format.md, "Units"). A quantity's dimension is M^mass L^length T^time.
#include <array>
#include <string>
#include <string_view>

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

// The unit names of the deck's /BEGIN codes and of what Crumple shows, one table for both (deck/units.hpp reads
// them): the SI prefixes, and the non-SI names found in crash decks with their size in SI base units.
struct UnitPrefix {
  std::string_view symbol;
  double factor;
};
inline constexpr std::array<UnitPrefix, 21> kSiPrefixes{
    {{"y", 1e-24}, {"z", 1e-21}, {"a", 1e-18}, {"f", 1e-15}, {"p", 1e-12}, {"n", 1e-9}, {"u", 1e-6},
     {"mu", 1e-6}, {"m", 1e-3},  {"c", 1e-2},  {"d", 1e-1},  {"da", 1e1}, {"h", 1e2},  {"k", 1e3},
     {"M", 1e6},  {"G", 1e9},   {"T", 1e12},  {"P", 1e15},  {"E", 1e18}, {"Z", 1e21}, {"Y", 1e24}}};
struct NamedUnit {
  std::string_view name;
  double si;
};
inline constexpr std::array<NamedUnit, 4> kMassNames{{{"lb", 0.45359237}, {"t", 1000.0}, {"ton", 1000.0},
                                                     {"slug", 14.5939029}}};
inline constexpr std::array<NamedUnit, 4> kLengthNames{{{"in", 0.0254}, {"ft", 0.3048}, {"yd", 0.9144},
                                                       {"mi", 1609.344}}};
inline constexpr std::array<NamedUnit, 3> kTimeNames{{{"min", 60.0}, {"h", 3600.0}, {"day", 86400.0}}};

// The names of the units a quantity is shown in (the listing, `check`, `th`, `plot`, NAME.h5's histories), for the
// working units of a deck: its base units by their SI size (kg, mm, ms; Mg, mm, s; ...) and the derived units by
// their SI name where the size is a power of 1000 of it (kN, J, GPa), else composed of the base units.
struct UnitNames {
  std::string mass, length, time;  // "kg", "mm", "ms" (an SI prefix, else a name of the tables above; "1.5 kg")
  std::string force, energy, stress;  // "kN", "J", "GPa"; composed ("g cm/us^2") where no prefix fits
};
UnitNames unit_names(const double (&work_si)[3]);
// "mass kg, length mm, time ms, force kN, energy J, stress GPa": the line the listing and `check` print.
std::string describe(const UnitNames& names);
// The unit of a quantity whose dimension is written in letters, as NAME.h5's histories write it: M, L, T, F (force),
// E (energy), products by spaces, a quotient by "/", powers by "^" ("L/T^2", "F L", "M L^2", "F/L^2", "1/T"; "-"
// or "" dimensionless). Each letter becomes its unit's name ("mm/ms^2", "kN mm", "kg mm^2"); "F/L^2" is a stress.
std::string unit_name(std::string_view letters, const UnitNames& names);

struct UnitSystem {
  // SI size of one input unit and one working unit of mass, length and time.
  double input[3] = {1.0, 1.0, 1.0};
  double work[3] = {1.0, 1.0, 1.0};

  // Factor that turns a value given in input units into working units.
  double factor(Dimension d) const;
};

}  // namespace crumple
