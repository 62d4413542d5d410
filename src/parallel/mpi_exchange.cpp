// Domains as MPI ranks (parallel/mpi_exchange.hpp).
#include "crumple/parallel/mpi_exchange.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <iterator>
#include <cstdlib>
#include <limits>
#include <type_traits>

namespace crumple {

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}
MpiSession::~MpiSession() { MPI_Finalize(); }
void MpiSession::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return
}
bool MpiSession::any(bool flag) {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return global != 0;
}

struct MpiExchange::Requests {
  std::vector<MPI_Request> pending;
};

MpiExchange::MpiExchange() : requests_(std::make_unique<Requests>()) {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}
MpiExchange::~MpiExchange() = default;

// Receives posted first, then each neighbour's slots packed and sent; one message per neighbour and direction. The
// buffers of a halo are kept for the next cycle's (the same plans come back every cycle).
void MpiExchange::halo_start(std::vector<double>& values, int width, const HaloPlan& plan) {
  if (started_ == halos_.size()) halos_.emplace_back();
  Halo& h = halos_[started_++];
  const std::size_t neighbours = plan.neighbours.size(), w = static_cast<std::size_t>(width);
  h.values = &values, h.width = w, h.plan = &plan;
  h.send.resize(neighbours), h.receive.resize(neighbours);
  std::vector<MPI_Request>& pending = requests_->pending;
  constexpr int kTag = 7;
  for (std::size_t i = 0; i < neighbours; ++i) {
    h.receive[i].resize(plan.receive[i].size() * w);
    if (h.receive[i].empty()) continue;
    pending.emplace_back();
    MPI_Irecv(h.receive[i].data(), static_cast<int>(h.receive[i].size()), MPI_DOUBLE, plan.neighbours[i], kTag,
              MPI_COMM_WORLD, &pending.back());
  }
  for (std::size_t i = 0; i < neighbours; ++i) {
    std::vector<double>& buffer = h.send[i];
    buffer.resize(plan.send[i].size() * w);
    if (buffer.empty()) continue;
    for (std::size_t j = 0; j < plan.send[i].size(); ++j)
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(plan.send[i][j] * w), w, buffer.begin() + static_cast<std::ptrdiff_t>(j * w));
    pending.emplace_back();
    MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, plan.neighbours[i], kTag, MPI_COMM_WORLD,
              &pending.back());
  }
}

// Messages between two ranks arrive in the order they were sent (same tag), so the halos started in the same order
// on every rank match up.
void MpiExchange::halo_finish() {
  std::vector<MPI_Request>& pending = requests_->pending;
  MPI_Waitall(static_cast<int>(pending.size()), pending.data(), MPI_STATUSES_IGNORE);
  pending.clear();
  for (std::size_t k = 0; k < started_; ++k) {
    Halo& h = halos_[k];
    for (std::size_t i = 0; i < h.plan->neighbours.size(); ++i)
      for (std::size_t j = 0; j < h.plan->receive[i].size(); ++j)
        std::copy_n(h.receive[i].begin() + static_cast<std::ptrdiff_t>(j * h.width), h.width,
                    h.values->begin() + static_cast<std::ptrdiff_t>(h.plan->receive[i][j] * h.width));
  }
  started_ = 0;
}

const MpiExchange::Layout& MpiExchange::layout(const std::vector<std::int32_t>& owner, int width) {
  auto [it, added] = layouts_.try_emplace({owner.data(), width});
  Layout& l = it->second;
  if (!added) return l;
  l.counts.assign(static_cast<std::size_t>(size_), 0);
  for (std::int32_t d : owner)
    if (d >= 0) l.counts[static_cast<std::size_t>(d)] += width;
  l.displacements.assign(static_cast<std::size_t>(size_), 0);
  for (int d = 1; d < size_; ++d)
    l.displacements[static_cast<std::size_t>(d)] = l.displacements[static_cast<std::size_t>(d - 1)] + l.counts[static_cast<std::size_t>(d - 1)];
  l.slots.reserve(owner.size());
  for (int d = 0; d < size_; ++d)
    for (std::size_t e = 0; e < owner.size(); ++e)
      if (owner[e] == d) l.slots.push_back(static_cast<std::uint32_t>(e));
  return l;
}

template <class T>
void MpiExchange::share_slots(std::vector<T>& values, int width, const std::vector<std::int32_t>& owner,
                              std::vector<T>& send, std::vector<T>& gathered) {
  const Layout& l = layout(owner, width);
  const auto w = static_cast<std::size_t>(width);
  const auto first = static_cast<std::size_t>(l.displacements[static_cast<std::size_t>(rank_)]) / w;
  const auto mine = static_cast<std::size_t>(l.counts[static_cast<std::size_t>(rank_)]) / w;
  send.resize(mine * w);
  for (std::size_t i = 0; i < mine; ++i)
    for (std::size_t c = 0; c < w; ++c) send[i * w + c] = values[l.slots[first + i] * w + c];
  gathered.resize(l.slots.size() * w);
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, float> || std::is_same_v<T, std::uint8_t>);
  const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : std::is_same_v<T, float> ? MPI_FLOAT : MPI_UINT8_T;
  MPI_Allgatherv(send.data(), static_cast<int>(send.size()), type, gathered.data(), l.counts.data(),
                 l.displacements.data(), type, MPI_COMM_WORLD);
  for (std::size_t i = 0; i < l.slots.size(); ++i)
    for (std::size_t c = 0; c < w; ++c) values[l.slots[i] * w + c] = gathered[i * w + c];
}

void MpiExchange::share(std::vector<double>& values, int width, const std::vector<std::int32_t>& owner) {
  if (values.empty()) return;
  share_slots(values, width, owner, send_double_, gathered_double_);
}
void MpiExchange::share(std::vector<std::uint8_t>& values, int width, const std::vector<std::int32_t>& owner) {
  if (values.empty()) return;
  share_slots(values, width, owner, send_byte_, gathered_byte_);
}
void MpiExchange::share(std::vector<float>& values, int width, const std::vector<std::int32_t>& owner) {
  if (values.empty()) return;
  share_slots(values, width, owner, send_float_, gathered_float_);
}

void MpiExchange::renew(const std::vector<std::int32_t>& owner) {
  for (auto it = layouts_.begin(); it != layouts_.end();)
    it = it->first.first == owner.data() ? layouts_.erase(it) : std::next(it);
}

void MpiExchange::gather(const std::vector<double>& mine, std::vector<double>& all) {
  gather_counts_.assign(static_cast<std::size_t>(size_), 0);
  int count = static_cast<int>(mine.size());
  MPI_Allgather(&count, 1, MPI_INT, gather_counts_.data(), 1, MPI_INT, MPI_COMM_WORLD);
  gather_displacements_.assign(static_cast<std::size_t>(size_), 0);
  for (int d = 1; d < size_; ++d)
    gather_displacements_[static_cast<std::size_t>(d)] =
        gather_displacements_[static_cast<std::size_t>(d - 1)] + gather_counts_[static_cast<std::size_t>(d - 1)];
  all.resize(static_cast<std::size_t>(gather_displacements_.back() + gather_counts_.back()));
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), gather_counts_.data(), gather_displacements_.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
}

// MPI_MINLOC keeps the smallest value and, among equal values, the smallest index: the first element in model
// order. A slot without a value (index -1) goes in as (+infinity, INT_MAX) so that it never wins.
void MpiExchange::min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) {
  pairs_.resize(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    pairs_[i] = index[i] < 0 ? DoubleInt{std::numeric_limits<double>::infinity(), INT_MAX} : DoubleInt{value[i], index[i]};
  MPI_Allreduce(MPI_IN_PLACE, pairs_.data(), static_cast<int>(pairs_.size()), MPI_DOUBLE_INT, MPI_MINLOC, MPI_COMM_WORLD);
  for (std::size_t i = 0; i < value.size(); ++i) {
    const bool none = pairs_[i].index == INT_MAX;
    value[i] = none ? std::numeric_limits<double>::infinity() : pairs_[i].value;
    index[i] = none ? -1 : pairs_[i].index;
  }
}

void MpiExchange::max(std::vector<std::int32_t>& values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT32_T, MPI_MAX, MPI_COMM_WORLD);
}
void MpiExchange::max(std::vector<double>& values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

// The normalised digits of every sum, summed as integers (exact, in any order); the non-finite parts as doubles
// (inf, -inf and NaN combine to the same result in any order).
void MpiExchange::sum(std::vector<ExactSum>& sums) {
  constexpr auto n = static_cast<std::size_t>(ExactSum::kDigits);
  digits_.resize(n * sums.size()), non_finite_.resize(sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) {
    sums[i].normalise();
    std::copy(sums[i].digits().begin(), sums[i].digits().end(), digits_.begin() + static_cast<std::ptrdiff_t>(i * n));
    non_finite_[i] = sums[i].non_finite();
  }
  MPI_Allreduce(MPI_IN_PLACE, digits_.data(), static_cast<int>(digits_.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, non_finite_.data(), static_cast<int>(non_finite_.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  for (std::size_t i = 0; i < sums.size(); ++i) {
    std::copy_n(digits_.begin() + static_cast<std::ptrdiff_t>(i * n), n, sums[i].digits().begin());
    sums[i].non_finite() = non_finite_[i];
  }
}

void MpiExchange::sum(std::vector<std::int32_t>& values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT32_T, MPI_SUM, MPI_COMM_WORLD);
}

}  // namespace crumple
