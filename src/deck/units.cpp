#include "crumple/deck/units.hpp"

#include <array>
#include <cmath>
#include <string_view>
#include <utility>

#include "crumple/deck/fields.hpp"

namespace crumple {

std::optional<double> parse_unit(const std::string& field, int base) {
  std::string text;
  for (char c : field)
    if (c != ' ' && c != '\t') text += c;
  if (text.empty()) return 1.0;  // blank: the SI base unit
  if (auto number = parse_fortran_real(text)) {
    if (*number > 0.0 && std::isfinite(*number)) return number;
    return std::nullopt;
  }
  const std::string_view base_symbol = base == 0 ? "g" : base == 1 ? "m" : "s";
  const double base_size = base == 0 ? 1e-3 : 1.0;  // the gram is 1e-3 kg
  auto match_names = [&](const auto& names) -> std::optional<double> {
    for (const NamedUnit& u : names)
      if (text == u.name) return u.si;
    return std::nullopt;
  };
  if (auto v = base == 0 ? match_names(kMassNames) : base == 1 ? match_names(kLengthNames) : match_names(kTimeNames))
    return v;
  if (text == base_symbol) return base_size;
  if (text.size() > base_symbol.size() && text.ends_with(base_symbol)) {
    const std::string_view prefix(text.data(), text.size() - base_symbol.size());
    for (const UnitPrefix& p : kSiPrefixes)
      if (prefix == p.symbol) return p.factor * base_size;
    if (prefix == "\xce\xbc" || prefix == "\xc2\xb5") return 1e-6 * base_size;  // Greek mu, micro sign
  }
  return std::nullopt;
}

}  // namespace crumple
