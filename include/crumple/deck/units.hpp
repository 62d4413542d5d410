#pragma once
// Unit codes of /BEGIN (docs/deck-format.md, "Units"); the unit system itself is core/units.hpp.
#include <optional>
#include <string>

#include "crumple/core/units.hpp"

namespace crumple {

// Size of one unit in SI base units (kg, m, s), parsed from a /BEGIN field: a code such as "kg", "mm", "ms",
// "Mg", "lb", "in" (an SI prefix before g, m or s, or an imperial name), or a positive real number.
std::optional<double> parse_unit(const std::string& field, int base /*0 mass, 1 length, 2 time*/);

}  // namespace crumple
