#pragma once
// Domains as MPI ranks (parallel/exchange.hpp): one domain per rank of MPI_COMM_WORLD. Element values travel with
// MPI_Allgatherv, each rank sending the slots of its own elements; the groups' reductions with MPI_Allreduce
// (MPI_MINLOC on value and index pairs, MPI_MAX, MPI_SUM). Buffers are sized at the first call of each kind of
// share and reused, so that the cycle allocates nothing once warm.
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "crumple/parallel/exchange.hpp"

namespace crumple {

// MPI for the length of a run: MPI_Init at construction, MPI_Finalize at destruction.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank at once with `code` (MPI_Abort): for an error one rank meets alone, so that no rank waits
  // for it forever.
  [[noreturn]] static void abort(int code);
  // Every rank's `flag`, combined: true when any rank's is.
  static bool any(bool flag);

 private:
  int rank_ = 0, size_ = 1;
};

class MpiExchange final : public Exchange {
 public:
  MpiExchange();  // MPI must be initialised
  ~MpiExchange() override;
  int domain() const override { return rank_; }
  int domains() const override { return size_; }
  void share(std::vector<double>& values, int width, const std::vector<std::int32_t>& owner) override;
  void share(std::vector<std::uint8_t>& values, int width, const std::vector<std::int32_t>& owner) override;
  void share(std::vector<float>& values, int width, const std::vector<std::int32_t>& owner) override;
  void halo_start(std::vector<double>& values, int width, const HaloPlan& plan) override;
  void halo_finish() override;
  void renew(const std::vector<std::int32_t>& owner) override;
  void renew_all() override { layouts_.clear(); }
  void gather(const std::vector<double>& mine, std::vector<double>& all) override;
  void min_with_index(std::vector<double>& value, std::vector<std::int32_t>& index) override;
  void max(std::vector<std::int32_t>& values) override;
  void max(std::vector<double>& values) override;
  void sum(std::vector<std::int32_t>& values) override;
  void sum(std::vector<ExactSum>& sums) override;

 private:
  // Per owner array and width: the slots of each rank's elements in rank order, and the counts and displacements
  // of the gathered buffer.
  struct Layout {
    std::vector<std::uint32_t> slots;   // element indices, rank by rank, ascending within a rank
    std::vector<int> counts, displacements;  // per rank, in values
  };
  const Layout& layout(const std::vector<std::int32_t>& owner, int width);
  template <class T>
  void share_slots(std::vector<T>& values, int width, const std::vector<std::int32_t>& owner, std::vector<T>& send,
                   std::vector<T>& gathered);

  int rank_ = 0, size_ = 1;
  std::map<std::pair<const void*, int>, Layout> layouts_;
  std::vector<double> send_double_, gathered_double_;
  std::vector<std::uint8_t> send_byte_, gathered_byte_;
  std::vector<float> send_float_, gathered_float_;
  struct DoubleInt {  // MPI_DOUBLE_INT
    double value;
    int index;
  };
  std::vector<DoubleInt> pairs_;
  std::vector<std::int64_t> digits_;  // exact sums' digits, packed
  std::vector<int> gather_counts_, gather_displacements_;
  // The started halos: where their received slots go, and per neighbour the packed send and receive buffers.
  struct Halo {
    std::vector<double>* values = nullptr;
    std::size_t width = 0;
    const HaloPlan* plan = nullptr;
    std::vector<std::vector<double>> send, receive;  // per neighbour
  };
  std::vector<Halo> halos_;
  std::size_t started_ = 0;  // halos_[0 .. started_) are in flight
  struct Requests;  // MPI_Request storage (mpi.h stays out of this header)
  std::unique_ptr<Requests> requests_;
  std::vector<double> non_finite_;
};

}  // namespace crumple
