#include "crumple/model/functions.hpp"

#include <algorithm>

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

}  // namespace crumple
