#pragma once
// Tabulated functions y(x) of /FUNCT, piecewise linear, abscissae strictly increasing.
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"

namespace crumple {

struct Function {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::vector<double> x;  // abscissa, strictly increasing (time [T] for loads, strain for hardening...)
  std::vector<double> y;  // ordinate; its unit is given by the card that uses the function

  // Linear interpolation, and linear extrapolation beyond the end points along the first or last segment, as the
  // reference does for load curves and yield curves alike (docs/deck-format.md, "Functions"); a one-point function
  // is a constant.
  double operator()(double at) const;
  // The steepest segment, max |dy / dx| (0 for a one-point function).
  double steepest_slope() const;
};

}  // namespace crumple
