#pragma once
// Domains as threads of one process (parallel/exchange.hpp): what MPI ranks do, through shared memory, so that the
// seams of the parallel solver are tested without mpirun. Each domain's thread holds its own ThreadExchange, all
// made from one ThreadBoard.
#include <barrier>
#include <memory>
#include <vector>

#include "crumple/parallel/exchange.hpp"

namespace crumple {

// What the domains' threads share: a barrier and, per domain, the buffer it offers in the current call.
class ThreadBoard {
 public:
  explicit ThreadBoard(int domains) : barrier_(domains), offered_(static_cast<std::size_t>(domains), nullptr) {}
  int domains() const { return static_cast<int>(offered_.size()); }

 private:
  friend class ThreadExchange;
  std::barrier<> barrier_;
  std::vector<const void*> offered_;
};

class ThreadExchange final : public Exchange {
 public:
  ThreadExchange(ThreadBoard& board, int domain) : board_(board), domain_(domain) {}
  int domain() const override { return domain_; }
  int domains() const override { return board_.domains(); }
  void share(std::vector<double>& values, int width, const std::vector<std::int32_t>& owner) override;
  void share(std::vector<std::uint8_t>& values, int width, const std::vector<std::int32_t>& owner) override;
  void share(std::vector<float>& values, int width, const std::vector<std::int32_t>& owner) override;
  void halo_start(std::vector<double>& values, int width, const HaloPlan& plan) override;
  void halo_finish() override;
  void renew(const std::vector<std::int32_t>& owner) override;
  void renew_all() override {}
  void gather(const std::vector<double>& mine, std::vector<double>& all) override;
  void min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) override;
  void max(std::vector<std::int32_t>& values) override;
  void max(std::vector<double>& values) override;
  void sum(std::vector<std::int32_t>& values) override;
  void sum(std::vector<ExactSum>& sums) override;

 private:
  void exchange_halo(std::vector<double>& values, int width, const HaloPlan& plan);
  template <class T>
  void share_slots(std::vector<T>& values, int width, const std::vector<std::int32_t>& owner);
  template <class T, class Combine>
  void reduce(std::vector<T>& values, Combine combine);

  ThreadBoard& board_;
  int domain_;
  // The started halos, exchanged one after the other at halo_finish (the board holds one offer per domain).
  struct Halo {
    std::vector<double>* values;
    int width;
    const HaloPlan* plan;
  };
  std::vector<Halo> started_;
};

}  // namespace crumple
