// The unit system of a model (core/units.hpp).
#include "crumple/core/units.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>

namespace crumple {

double UnitSystem::factor(Dimension d) const {
  const int exponents[3] = {d.mass, d.length, d.time};
  double f = 1.0;
  for (int i = 0; i < 3; ++i)
    if (exponents[i] != 0) f *= std::pow(input[i] / work[i], exponents[i]);
  return f;
}

namespace {

bool same_size(double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); }

// The name of a base unit of SI size `si`: an SI prefix before `symbol` (whose unit has SI size `symbol_si`: the
// gram 1e-3 kg), else a non-SI name of `names`, else the size in SI ("1.5 kg").
template <std::size_t N>
std::string base_name(double si, std::string_view symbol, double symbol_si, const std::array<NamedUnit, N>& names,
                      std::string_view si_name) {
  if (same_size(si, symbol_si)) return std::string(symbol);
  for (const UnitPrefix& p : kSiPrefixes)
    if (same_size(si, p.factor * symbol_si)) return std::string(p.symbol) + std::string(symbol);
  for (const NamedUnit& u : names)
    if (same_size(si, u.si)) return std::string(u.name);
  return fmt::format("{:g} {}", si, si_name);
}

// `si_name` with the prefix that makes one unit of SI size `si` (kN for 1e3 N), or "" when no prefix of a power of
// 1000 does.
std::string prefixed(double si, const char* si_name) {
  if (same_size(si, 1.0)) return si_name;
  for (const UnitPrefix& p : kSiPrefixes) {
    const double thousands = std::log10(p.factor) / 3.0;
    if (same_size(si, p.factor) && std::abs(thousands - std::round(thousands)) < 1e-9)
      return std::string(p.symbol) + si_name;
  }
  return {};
}

}  // namespace

UnitNames unit_names(const double (&work_si)[3]) {
  const double m = work_si[0], l = work_si[1], t = work_si[2];
  UnitNames n;
  n.mass = base_name(m, "g", 1e-3, kMassNames, "kg");
  n.length = base_name(l, "m", 1.0, kLengthNames, "m");
  n.time = base_name(t, "s", 1.0, kTimeNames, "s");
  const auto or_composed = [&](std::string name, const std::string& composed) {
    return name.empty() ? composed : name;
  };
  n.force = or_composed(prefixed(m * l / (t * t), "N"), fmt::format("{} {}/{}^2", n.mass, n.length, n.time));
  n.energy = or_composed(prefixed(m * l * l / (t * t), "J"), fmt::format("{} {}", n.force, n.length));
  n.stress = or_composed(prefixed(m / (l * t * t), "Pa"), fmt::format("{}/{}^2", n.force, n.length));
  return n;
}

std::string describe(const UnitNames& n) {
  return fmt::format("mass {}, length {}, time {}, force {}, energy {}, stress {}", n.mass, n.length, n.time, n.force,
                     n.energy, n.stress);
}

std::string unit_name(std::string_view letters, const UnitNames& names) {
  if (letters == "-") return {};
  if (letters == "F/L^2") return names.stress;
  std::string out;
  for (const char c : letters) {
    switch (c) {
      case 'M': out += names.mass; break;
      case 'L': out += names.length; break;
      case 'T': out += names.time; break;
      case 'F': out += names.force; break;
      case 'E': out += names.energy; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace crumple
