#pragma once
// Sums and extremes over the domains of a run (docs/parallel.md, "Sums over many domains"): each domain adds the
// terms of its own nodes into exact sums (core/exact_sum.hpp) and the reducer combines them, so that the result is
// the same for any partition. In a run of one domain (no exchange) every call leaves its values as they are.
#include <cstdint>
#include <vector>

#include "crumple/core/exact_sum.hpp"
#include "crumple/parallel/exchange.hpp"

namespace crumple {

class Reducer {
 public:
  Reducer() = default;
  explicit Reducer(Exchange* exchange) : exchange_(exchange != nullptr && exchange->domains() > 1 ? exchange : nullptr) {}
  bool several() const { return exchange_ != nullptr; }
  Exchange* exchange() const { return exchange_; }

  void sum(std::vector<ExactSum>& in_place) {
    if (exchange_ != nullptr) exchange_->sum(in_place);
  }
  void max(std::vector<double>& in_place) {
    if (exchange_ != nullptr) exchange_->max(in_place);
  }
  void max(std::vector<std::int32_t>& in_place) {
    if (exchange_ != nullptr) exchange_->max(in_place);
  }
  void min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) {
    if (exchange_ != nullptr) exchange_->min_with_index(value, index);
  }

  // Scratch the callers reuse, so that the cycle allocates nothing once warm.
  std::vector<ExactSum> sums;
  std::vector<std::int32_t> flags;
  std::vector<double> values;
  std::vector<std::int32_t> indices;

 private:
  Exchange* exchange_ = nullptr;
};

}  // namespace crumple
