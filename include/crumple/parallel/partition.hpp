#pragma once
// The decomposition of a model into domains, one per MPI rank (docs/parallel.md, "Decomposition"): METIS
// (METIS_PartGraphKway) on the element graph, two elements adjacent when they share a node, each element weighted
// by the measured cost of its kind and formulation, so that the partition depends on the model and the domain
// count only (same on every rank, every run).
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"

namespace crumple {

// Relative cost of one element-cycle of each kind and formulation, measured once with the benchmarks and kept in
// the code (docs/parallel.md, "Weights"): the METIS vertex weights.
int element_weight(const Model& model, ElementKind kind, std::size_t element);

struct Partition {
  int domains = 1;
  // Per element kind, per element of the kind's ElementTable: its domain, 0 .. domains - 1.
  std::array<std::vector<std::int32_t>, kElementKinds> domain_of_element;
  // Quality (the listing and `crumple check --ranks N` print it):
  long long edge_cut = 0;            // element-graph edges between domains
  long long shared_nodes = 0;        // nodes used by elements of two or more domains
  std::vector<long long> weight;     // per domain: the sum of its elements' weights
  double imbalance = 1.0;            // largest domain weight over the mean
  std::vector<int> neighbours;       // per domain: how many other domains it shares nodes with
};

// What a running model costs per element beyond its kind and formulation (docs/parallel.md, "Rebalancing"), per
// element kind and element:
// - plastic: how many of its integration points flowed plastically over the last cycles (0 .. 255); a flowing point
//   costs a return to the yield surface, 1 / kPlasticPointDivisor of the element's elastic weight;
// - contact: its share of the contact pairs of its nodes (each secondary node's candidate pairs spread over the
//   elements that use it), kPairWeight each; balanced as its own constraint.
struct RunningCost {
  std::array<std::vector<std::uint8_t>, kElementKinds> plastic;
  std::array<std::vector<std::int32_t>, kElementKinds> contact;
};

// The partition of `model` into `domains` domains (>= 1). One domain: every element in domain 0, no METIS call.
// With `cost`, the weights take the running cost too. Throws std::runtime_error when METIS fails or when domains
// exceeds the element count.
Partition partition_model(const Model& model, int domains, const RunningCost* cost = nullptr);

// Measured on the benchmark tube (Ishell 24, 5 points, Johnson-Cook, 2026-12-02; docs/parallel.md, "Rebalancing"):
// an elastic element-cycle 289 ns (weight 92), a flowing point 95 ns more, a candidate contact pair 80 ns.
inline constexpr int kPlasticPointDivisor = 3;
inline constexpr int kPairWeight = 25;
// The weights METIS gives an element (element_weight) with its running cost: the element cost, and its contact
// cost, which METIS balances as a second constraint (the element phase and the contact pass wait for each other).
int element_weight(const Model& model, ElementKind kind, std::size_t element, const RunningCost& cost);
int element_contact_weight(ElementKind kind, std::size_t element, const RunningCost& cost);

// A partition of the model into `domains` domains, given the running cost (tests of rebalancing).
using Repartition = std::function<Partition(const Model&, int domains, const RunningCost& cost)>;

// The partition's quality as listing lines.
std::vector<std::string> describe(const Partition& partition);

}  // namespace crumple
