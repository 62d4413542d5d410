#pragma once
// How domains talk (docs/parallel.md, "Exchange"): the time loop calls it at one point of the cycle, after the
// element kernels, to share what each domain computed of its own elements, and to reduce the element groups'
// results. Two transports: threads in one process (ThreadExchange, the tests of the seams) and MPI ranks
// (MpiExchange). A run of one domain has none.
#include <cstdint>
#include <vector>

#include "crumple/core/exact_sum.hpp"
#include "crumple/parallel/domain.hpp"

namespace crumple {

class Exchange {
 public:
  virtual ~Exchange() = default;
  virtual int domain() const = 0;
  virtual int domains() const = 0;

  // Values of elements (or nodes, or groups): `values` holds `width` values per slot; `owner` the domain of each
  // slot, -1 for a slot that does not travel. Each domain fills its own slots; after the call every domain holds
  // every owner's slots.
  virtual void share(std::vector<double>& values, int width, const std::vector<std::int32_t>& owner) = 0;
  virtual void share(std::vector<std::uint8_t>& values, int width, const std::vector<std::int32_t>& owner) = 0;
  virtual void share(std::vector<float>& values, int width, const std::vector<std::int32_t>& owner) = 0;  // mixed build

  // Point to point with the neighbours of `plan`: this domain's send slots to each neighbour, the neighbours' into
  // its receive slots (`width` values per slot). `halo_start` posts the receives and sends the send slots as they
  // are now (non-blocking); `halo_finish` completes every started halo and fills the receive slots. In between the
  // caller may compute anything that writes neither the send nor the receive slots: the element phase overlaps the
  // exchange with its remaining groups (docs/parallel.md, "Exchange"). Several halos may be started at once.
  virtual void halo_start(std::vector<double>& values, int width, const HaloPlan& plan) = 0;
  virtual void halo_finish() = 0;
  void halo(std::vector<double>& values, int width, const HaloPlan& plan) {
    halo_start(values, width, plan);
    halo_finish();
  }
  // `owner` has changed since its last share (its slots travel differently): forget what was made of it.
  virtual void renew(const std::vector<std::int32_t>& owner) = 0;
  // Every owner array may have changed (a new partition): forget everything made of them.
  virtual void renew_all() = 0;
  // Every domain's `mine`, concatenated in domain order into `all` (lengths may differ between domains).
  virtual void gather(const std::vector<double>& mine, std::vector<double>& all) = 0;

  // Slot-wise reductions over the domains, in place (the same length in every domain): the smallest value with
  // the smallest index among equal values (index -1: no value, +infinity); the largest; the sum.
  virtual void min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) = 0;
  virtual void max(std::vector<std::int32_t>& values) = 0;
  virtual void max(std::vector<double>& values) = 0;
  virtual void sum(std::vector<std::int32_t>& values) = 0;
  // Exact sums (core/exact_sum.hpp) over the domains, slot-wise, in place: every domain ends with the sums of all
  // domains' terms, the same whatever the partition.
  virtual void sum(std::vector<ExactSum>& sums) = 0;
};

}  // namespace crumple
