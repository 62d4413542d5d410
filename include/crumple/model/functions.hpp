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

  // Linear interpolation, constant extrapolation beyond the end points.
  double operator()(double at) const;
};

}  // namespace crumple
