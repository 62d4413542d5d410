#include "crumple/model/functions.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {

double Function::operator()(double at) const {
  if (x.empty()) return 0.0;
  if (x.size() == 1) return y.front();
  // The segment that holds `at`; the first or the last one beyond the end points (linear extrapolation).
  const auto upper = std::upper_bound(x.begin() + 1, x.end() - 1, at);
  const auto i = static_cast<std::size_t>(upper - x.begin());
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

double Function::steepest_slope() const {
  double slope = 0.0;
  for (std::size_t k = 1; k < x.size(); ++k) slope = std::max(slope, std::abs(y[k] - y[k - 1]) / (x[k] - x[k - 1]));
  return slope;
}

}  // namespace crumple
