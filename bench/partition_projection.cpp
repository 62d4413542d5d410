// Projection of a parallel run's communication (docs/parallel.md, "Projection"): a square tube of about 2 million
// 4-node shells built in memory, partitioned by partition_model for each rank count, and per rank count the halo a
// rank exchanges each cycle, its messages, the imbalance and the share of a cycle spent communicating under a
// simple network model.
//
//   build/release/bench/partition_projection [--around N] [--along N] [--ns NS] [--ranks P,P,...]
//
// What is counted, per rank and cycle (the slowest rank sets the pace):
//   halo bytes  = sum over its neighbours of the nodes it shares with that neighbour x 6 doubles x 8 bytes (the
//                 forces and moments of the shared nodes, one message per neighbour);
//   messages    = neighbours x 2 exchanges (the force assembly and one more of the same size, e.g. the contact
//                 forces of shared nodes);
//   comm time   = messages x 2 us + 2 x halo bytes / 10 GB/s;
//   compute     = elements x NS ns (the single-core cost of one shell element-cycle);
//   comm share  = max comm / (max compute + max comm).
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "crumple/parallel/partition.hpp"

namespace {

using namespace crumple;

constexpr double kLatencySeconds = 2e-6;        // per message
constexpr double kBandwidthBytesPerSecond = 1e10;  // per rank
constexpr double kBytesPerSharedNode = 6 * 8;   // forces and moments, doubles
constexpr int kExchangesPerCycle = 2;

struct Options {
  int around = 1000;  // elements around the section (4 sides)
  int along = 2000;   // elements along the tube
  // decks/tube_impact (Ishell 24, 5 layers): 7.22 s wall for 8796 cycles of 1600 shells (TUBE.summary.json,
  // Release, 2026-12-02), the whole cycle counted; lower than the 1000 ns of a first guess, so a larger comm share.
  double ns_per_element_cycle = 513.0;
  std::vector<int> ranks{16, 32, 64, 100, 128, 256, 512, 1024};
};

std::vector<int> parse_list(const std::string& text) {
  std::vector<int> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    values.push_back(std::stoi(text.substr(at, comma - at)));
    at = comma + 1;
  }
  return values;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--around") o.around = std::stoi(value);
    else if (key == "--along") o.along = std::stoi(value);
    else if (key == "--ns") o.ns_per_element_cycle = std::stod(value);
    else if (key == "--ranks") o.ranks = parse_list(value);
    else throw std::runtime_error("unknown option " + key);
  }
  return o;
}

// The square tube of decks/tube_impact meshed finely: `around` shells around the section (a multiple of 4), `along`
// along the axis; one part, Ishell 24 with 5 layers (the tube's formulation).
Model square_tube(int around, int along) {
  Model m;
  const double side = 50.0, length = 200.0, size = 4 * side / around;
  for (int j = 0; j <= along; ++j)
    for (int k = 0; k < around; ++k) {
      const int face = k / (around / 4);
      const double s = (k % (around / 4)) * size - side / 2, h = side / 2;
      const double y[4] = {s, h, -s, -h}, z[4] = {-h, s, h, -s};
      m.nodes.user_id.push_back(static_cast<std::int64_t>(m.nodes.size()) + 1);
      m.nodes.x.push_back(length * j / along), m.nodes.y.push_back(y[face]), m.nodes.z.push_back(z[face]);
    }
  ElementTable& shells = m.elements[static_cast<std::size_t>(ElementKind::Shell4)];
  for (int j = 0; j < along; ++j)
    for (int k = 0; k < around; ++k) {
      const int k1 = (k + 1) % around;
      shells.user_id.push_back(static_cast<std::int64_t>(shells.size()) + 1);
      shells.part.push_back(0);
      for (const int node : {j * around + k, (j + 1) * around + k, (j + 1) * around + k1, j * around + k1})
        shells.connectivity.push_back(node);
    }
  m.parts.push_back(Part{});
  m.parts[0].property = 0, m.parts[0].material = 0;
  m.formulations.push_back(ResolvedFormulation{});
  m.formulations[0].ishell = 24, m.formulations[0].n_points = 5;
  return m;
}

struct RankLoad {
  std::vector<long long> elements, halo_nodes;  // per rank; halo: shared nodes counted once per neighbour
};

// Per rank, its elements and its halo: a node used by k >= 2 ranks is sent by each of them to the k - 1 others.
RankLoad rank_load(const Model& m, const Partition& p) {
  RankLoad load;
  load.elements.assign(static_cast<std::size_t>(p.domains), 0);
  load.halo_nodes.assign(static_cast<std::size_t>(p.domains), 0);
  std::vector<std::pair<std::int32_t, std::int32_t>> node_rank;  // (node, rank) of every element corner
  for (std::size_t k = 0; k < static_cast<std::size_t>(kElementKinds); ++k) {
    const ElementTable& t = m.elements[k];
    const auto n = static_cast<std::size_t>(nodes_per_element(t.kind));
    for (std::size_t e = 0; e < t.size(); ++e) {
      const std::int32_t d = p.domain_of_element[k][e];
      ++load.elements[static_cast<std::size_t>(d)];
      for (std::size_t a = 0; a < n; ++a) node_rank.emplace_back(t.connectivity[e * n + a], d);
    }
  }
  std::sort(node_rank.begin(), node_rank.end());
  node_rank.erase(std::unique(node_rank.begin(), node_rank.end()), node_rank.end());
  for (std::size_t i = 0; i < node_rank.size();) {
    std::size_t j = i;
    while (j < node_rank.size() && node_rank[j].first == node_rank[i].first) ++j;
    for (std::size_t r = i; r < j && j - i >= 2; ++r)
      load.halo_nodes[static_cast<std::size_t>(node_rank[r].second)] += static_cast<long long>(j - i - 1);
    i = j;
  }
  return load;
}

double mean(const std::vector<long long>& v) {
  double sum = 0.0;
  for (const long long x : v) sum += static_cast<double>(x);
  return sum / static_cast<double>(v.size());
}

void project(const Model& m, int ranks, double ns) {
  const auto start = std::chrono::steady_clock::now();
  const Partition p = partition_model(m, ranks);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const RankLoad load = rank_load(m, p);
  const long long max_elements = *std::max_element(load.elements.begin(), load.elements.end());
  const long long max_halo = *std::max_element(load.halo_nodes.begin(), load.halo_nodes.end());
  const int max_neighbours = *std::max_element(p.neighbours.begin(), p.neighbours.end());
  double neighbour_sum = 0.0;
  for (const int n : p.neighbours) neighbour_sum += n;
  const double compute = static_cast<double>(max_elements) * ns * 1e-9;
  double comm = 0.0;  // the slowest rank's exchanges
  for (std::size_t d = 0; d < load.halo_nodes.size(); ++d)
    comm = std::max(comm, kExchangesPerCycle * p.neighbours[d] * kLatencySeconds +
                              kExchangesPerCycle * static_cast<double>(load.halo_nodes[d]) * kBytesPerSharedNode /
                                  kBandwidthBytesPerSecond);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  fmt::print("| {} | {} | {:.3f} | {} / {:.1f} | {:.0f} / {:.0f} | {} | {:.0f} | {:.1f} | {:.2f} % | {:.1f} s, {:.2f} GiB |\n",
             ranks, max_elements, p.imbalance, max_neighbours, neighbour_sum / ranks,
             static_cast<double>(max_halo) * kBytesPerSharedNode, mean(load.halo_nodes) * kBytesPerSharedNode,
             kExchangesPerCycle * max_neighbours, compute * 1e6, comm * 1e6, 100.0 * comm / (compute + comm), seconds,
             static_cast<double>(usage.ru_maxrss) / (1024.0 * 1024.0));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    const Model m = square_tube(o.around, o.along);
    fmt::print("Square tube, {} x {} = {} shells, {} nodes; {:.0f} ns per element-cycle\n\n", o.around, o.along,
               m.elements[0].size(), m.nodes.size(), o.ns_per_element_cycle);
    fmt::print("| ranks | elements per rank (max) | imbalance | neighbours (max / mean) | halo bytes per cycle "
               "(max / mean) | messages per cycle (max) | compute [us] | comm [us] | comm share | METIS (time, "
               "peak memory) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (const int ranks : o.ranks) project(m, ranks, o.ns_per_element_cycle);
  } catch (const std::exception& e) {
    fmt::print(stderr, "partition_projection: {}\n", e.what());
    return 1;
  }
  return 0;
}
