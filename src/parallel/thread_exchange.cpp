// Domains as threads of one process (parallel/thread_exchange.hpp). Every call is two barriers: after the first
// every domain's buffer is offered, after the second every domain has read what it needs, so a buffer is never
// changed while another domain reads it.
#include "crumple/parallel/thread_exchange.hpp"

#include <algorithm>
#include <limits>

namespace crumple {

template <class T>
void ThreadExchange::share_slots(std::vector<T>& values, int width, const std::vector<std::int32_t>& owner) {
  board_.offered_[static_cast<std::size_t>(domain_)] = &values;
  board_.barrier_.arrive_and_wait();
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t e = 0; e < owner.size(); ++e) {
    if (owner[e] < 0 || owner[e] == domain_) continue;
    const auto& from = *static_cast<const std::vector<T>*>(board_.offered_[static_cast<std::size_t>(owner[e])]);
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(e * w), w, values.begin() + static_cast<std::ptrdiff_t>(e * w));
  }
  board_.barrier_.arrive_and_wait();
}

void ThreadExchange::share(std::vector<double>& values, int width, const std::vector<std::int32_t>& owner) {
  share_slots(values, width, owner);
}
void ThreadExchange::share(std::vector<std::uint8_t>& values, int width, const std::vector<std::int32_t>& owner) {
  share_slots(values, width, owner);
}
void ThreadExchange::share(std::vector<float>& values, int width, const std::vector<std::int32_t>& owner) {
  share_slots(values, width, owner);
}

// Every domain combines the offered buffers in domain order into a copy, then takes it: all domains end equal.
template <class T, class Combine>
void ThreadExchange::reduce(std::vector<T>& values, Combine combine) {
  board_.offered_[static_cast<std::size_t>(domain_)] = &values;
  board_.barrier_.arrive_and_wait();
  std::vector<T> result = *static_cast<const std::vector<T>*>(board_.offered_[0]);
  for (int d = 1; d < domains(); ++d) {
    const auto& other = *static_cast<const std::vector<T>*>(board_.offered_[static_cast<std::size_t>(d)]);
    for (std::size_t i = 0; i < result.size(); ++i) combine(i, result[i], other[i], d);
  }
  board_.barrier_.arrive_and_wait();
  values = std::move(result);
}

void ThreadExchange::min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) {
  // Pairs (value, index) travel together: reduce the indices with the values read from the same domains.
  board_.offered_[static_cast<std::size_t>(domain_)] = &value;
  board_.barrier_.arrive_and_wait();
  std::vector<const std::vector<double>*> values(static_cast<std::size_t>(domains()));
  for (int d = 0; d < domains(); ++d) values[static_cast<std::size_t>(d)] = static_cast<const std::vector<double>*>(board_.offered_[static_cast<std::size_t>(d)]);
  board_.barrier_.arrive_and_wait();
  board_.offered_[static_cast<std::size_t>(domain_)] = &index;
  board_.barrier_.arrive_and_wait();
  std::vector<double> best_value(value.size(), std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> best_index(index.size(), -1);
  for (int d = 0; d < domains(); ++d) {
    const auto& v = *values[static_cast<std::size_t>(d)];
    const auto& i = *static_cast<const std::vector<std::int32_t>*>(board_.offered_[static_cast<std::size_t>(d)]);
    for (std::size_t s = 0; s < v.size(); ++s) {
      if (i[s] < 0) continue;
      if (best_index[s] < 0 || v[s] < best_value[s] || (v[s] == best_value[s] && i[s] < best_index[s]))
        best_value[s] = v[s], best_index[s] = i[s];
    }
  }
  board_.barrier_.arrive_and_wait();
  value = std::move(best_value), index = std::move(best_index);
}

// The threads meet at halo_finish: every domain then offers each started halo in turn (the same order everywhere).
// A receive slot is another domain's element, which this domain's kernels never write, so copying at the finish
// gives what a copy at the start would have.
void ThreadExchange::halo_start(std::vector<double>& values, int width, const HaloPlan& plan) {
  started_.push_back({&values, width, &plan});
}

void ThreadExchange::halo_finish() {
  for (const Halo& h : started_) exchange_halo(*h.values, h.width, *h.plan);
  started_.clear();
}

void ThreadExchange::exchange_halo(std::vector<double>& values, int width, const HaloPlan& plan) {
  board_.offered_[static_cast<std::size_t>(domain_)] = &values;
  board_.barrier_.arrive_and_wait();
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t i = 0; i < plan.neighbours.size(); ++i) {
    const auto& from = *static_cast<const std::vector<double>*>(board_.offered_[static_cast<std::size_t>(plan.neighbours[i])]);
    for (std::uint32_t slot : plan.receive[i])
      std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(slot * w), w, values.begin() + static_cast<std::ptrdiff_t>(slot * w));
  }
  board_.barrier_.arrive_and_wait();
}

void ThreadExchange::renew(const std::vector<std::int32_t>&) {}

void ThreadExchange::gather(const std::vector<double>& mine, std::vector<double>& all) {
  board_.offered_[static_cast<std::size_t>(domain_)] = &mine;
  board_.barrier_.arrive_and_wait();
  std::vector<double> result;
  for (int d = 0; d < domains(); ++d) {
    const auto& from = *static_cast<const std::vector<double>*>(board_.offered_[static_cast<std::size_t>(d)]);
    result.insert(result.end(), from.begin(), from.end());
  }
  board_.barrier_.arrive_and_wait();
  all = std::move(result);
}

void ThreadExchange::max(std::vector<std::int32_t>& values) {
  reduce(values, [](std::size_t, std::int32_t& a, std::int32_t b, int) { a = std::max(a, b); });
}
void ThreadExchange::max(std::vector<double>& values) {
  reduce(values, [](std::size_t, double& a, double b, int) { a = std::max(a, b); });
}
void ThreadExchange::sum(std::vector<ExactSum>& sums) {
  reduce(sums, [](std::size_t, ExactSum& a, const ExactSum& b, int) { a.add(b); });
}
void ThreadExchange::sum(std::vector<std::int32_t>& values) {
  reduce(values, [](std::size_t, std::int32_t& a, std::int32_t b, int) { a += b; });
}

}  // namespace crumple
