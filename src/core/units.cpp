// The unit system of a model (core/units.hpp).
#include "crumple/core/units.hpp"

#include <cmath>

namespace crumple {

double UnitSystem::factor(Dimension d) const {
  const int exponents[3] = {d.mass, d.length, d.time};
  double f = 1.0;
  for (int i = 0; i < 3; ++i)
    if (exponents[i] != 0) f *= std::pow(input[i] / work[i], exponents[i]);
  return f;
}

}  // namespace crumple
