#include "crumple/deck/units.hpp"

#include <array>
#include <cmath>
#include <string_view>
#include <utility>

#include "crumple/deck/fields.hpp"

namespace crumple {
namespace {

struct Prefix {
  std::string_view symbol;
  double factor;
};

constexpr std::array<Prefix, 21> kPrefixes{{{"y", 1e-24}, {"z", 1e-21}, {"a", 1e-18}, {"f", 1e-15}, {"p", 1e-12},
                                           {"n", 1e-9},  {"mu", 1e-6}, {"u", 1e-6},  {"m", 1e-3},  {"c", 1e-2},
                                           {"d", 1e-1},  {"da", 1e1},  {"h", 1e2},   {"k", 1e3},   {"M", 1e6},
                                           {"G", 1e9},   {"T", 1e12},  {"P", 1e15},  {"E", 1e18},  {"Z", 1e21},
                                           {"Y", 1e24}}};

// Non-SI names found in crash decks, with their size in SI base units.
constexpr std::array<std::pair<std::string_view, double>, 4> kMassNames{
    {{"lb", 0.45359237}, {"t", 1000.0}, {"ton", 1000.0}, {"slug", 14.5939029}}};
constexpr std::array<std::pair<std::string_view, double>, 4> kLengthNames{
    {{"in", 0.0254}, {"ft", 0.3048}, {"yd", 0.9144}, {"mi", 1609.344}}};
constexpr std::array<std::pair<std::string_view, double>, 3> kTimeNames{{{"min", 60.0}, {"h", 3600.0}, {"day", 86400.0}}};

}  // namespace

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
    for (const auto& [name, size] : names)
      if (text == name) return size;
    return std::nullopt;
  };
  if (auto v = base == 0 ? match_names(kMassNames) : base == 1 ? match_names(kLengthNames) : match_names(kTimeNames))
    return v;
  if (text == base_symbol) return base_size;
  if (text.size() > base_symbol.size() && text.ends_with(base_symbol)) {
    const std::string_view prefix(text.data(), text.size() - base_symbol.size());
    for (const auto& p : kPrefixes)
      if (prefix == p.symbol) return p.factor * base_size;
    if (prefix == "\xce\xbc" || prefix == "\xc2\xb5") return 1e-6 * base_size;  // Greek mu, micro sign
  }
  return std::nullopt;
}

}  // namespace crumple
