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

// Per element kind, per element: how many of its integration points flowed plastically over the last cycles (0 ..
// 255). A point that flows costs a return to the yield surface on top of the element's elastic update: the weights
// of a repartition during a run take it (docs/parallel.md, "Rebalancing").
using PlasticPoints = std::array<std::vector<std::uint8_t>, kElementKinds>;

// The partition of `model` into `domains` domains (>= 1). One domain: every element in domain 0, no METIS call.
// With `plastic`, each element's weight grows by kPlasticPointShare of its elastic weight per flowing point.
// Throws std::runtime_error when METIS fails or when domains exceeds the element count.
Partition partition_model(const Model& model, int domains, const PlasticPoints* plastic = nullptr);

// The cost of a point's plastic return against its element's elastic weight: 1 / kPlasticPointDivisor per point
// (docs/parallel.md, "Rebalancing").
inline constexpr int kPlasticPointDivisor = 3;
// The weight METIS gives an element (element_weight) with `plastic_points` points flowing.
int element_weight(const Model& model, ElementKind kind, std::size_t element, int plastic_points);

// A partition of the model into `domains` domains, given the elements' flowing points (tests of rebalancing).
using Repartition = std::function<Partition(const Model&, int domains, const PlasticPoints& plastic)>;

// The partition's quality as listing lines.
std::vector<std::string> describe(const Partition& partition);

}  // namespace crumple
