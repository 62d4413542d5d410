// Rebalancing a run of several domains (docs/parallel.md, "Rebalancing"): the partition made at the start weighs
// each element by its kind; in a crash the plastic zone concentrates where the structure folds, and a point that
// flows plastically costs a return to the yield surface, so the domain that holds the folds falls behind. Every
// kRebalanceEvery cycles the domains estimate their cost from the points that flowed since the last check; when
// the largest is more than kRebalanceTolerance above the mean, every domain makes the same new partition with those
// weights, the state is gathered (every element and node from its owner) and every domain takes its new share. The answer does not depend on the partition (fixed-order assembly, exact sums), so it is unchanged, bit
// for bit; only the time per cycle changes.
#include <algorithm>

#include "crumple/parallel/partition.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// Per element kind, per element this domain computes: how many of its points have flowed plastically since the
// last check (their plastic strain grew; an element of another domain: 0, until the counts are shared).
PlasticPoints plastic_points(const Model& m, const SolverState& s) {
  PlasticPoints plastic;
  for (int k = 0; k < kElementKinds; ++k) plastic[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  const std::array<std::vector<double>, kElementKinds>& before = s.rebalancing.eps_p_at_check;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    const bool brick = group.kind == ElementKind::Brick8;
    const ShellState& shell = group.kind == ElementKind::Shell4 ? s.shells : s.shells3;
    const std::vector<double>& eps_p = brick ? s.bricks.eps_p : shell.eps_p;
    const std::vector<double>& then = before[static_cast<std::size_t>(group.kind)];
    const std::size_t first = brick ? s.bricks.point_offset[g] : shell.point_offset[g];
    const auto points = static_cast<std::size_t>(brick ? s.bricks.points[g] : shell.points[g]);
    std::vector<std::uint8_t>& counts = plastic[static_cast<std::size_t>(group.kind)];
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      if (!s.domain.mine(group.kind, static_cast<std::size_t>(e))) continue;
      const std::size_t at = first + static_cast<std::size_t>(e - group.begin) * points;
      int flowing = 0;
      for (std::size_t p = at; p < at + points; ++p) flowing += eps_p[p] > (then.empty() ? 0.0 : then[p]) ? 1 : 0;
      counts[static_cast<std::size_t>(e)] = static_cast<std::uint8_t>(std::min(flowing, 255));
    }
  }
  return plastic;
}

// The next check counts from the plastic strains of now.
void keep_plastic_strains(SolverState& s) {
  std::array<std::vector<double>, kElementKinds>& then = s.rebalancing.eps_p_at_check;
  then[static_cast<std::size_t>(ElementKind::Shell4)] = s.shells.eps_p;
  then[static_cast<std::size_t>(ElementKind::Shell3)] = s.shells3.eps_p;
  then[static_cast<std::size_t>(ElementKind::Brick8)] = s.bricks.eps_p;
}

// The largest domain's estimated cost over the mean, from every domain's own elements (exact sums of integer
// weights, so every domain finds the same).
double estimated_imbalance(const Model& m, SolverState& s, const PlasticPoints& plastic) {
  std::vector<ExactSum>& cost = s.reducer.sums;
  cost.assign(static_cast<std::size_t>(s.domain.count), ExactSum{});
  ExactSum& mine = cost[static_cast<std::size_t>(s.domain.index)];
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    for (std::size_t e = 0; e < m.elements[static_cast<std::size_t>(k)].size(); ++e)
      if (s.domain.mine(kind, e)) mine.add(element_weight(m, kind, e, plastic[static_cast<std::size_t>(k)][e]));
  }
  s.reducer.sum(cost);
  double largest = 0.0, total = 0.0;
  for (const ExactSum& c : cost) largest = std::max(largest, c.value()), total += c.value();
  return total > 0.0 ? largest * static_cast<double>(cost.size()) / total : 1.0;
}

}  // namespace

bool rebalance_due(const SolverState& s) { return s.domain.several() && s.cycle > 0 && s.cycle % kRebalanceEvery == 0; }

void rebalance(const Model& m, SolverState& s, Exchange& exchange, RunEvents& events, const Repartition& repartition) {
  PlasticPoints plastic = plastic_points(m, s);
  const double before = estimated_imbalance(m, s, plastic);
  if (!(before > 1.0 + kRebalanceTolerance) && !repartition) {
    keep_plastic_strains(s);
    return;
  }
  for (int k = 0; k < kElementKinds; ++k)
    exchange.share(plastic[static_cast<std::size_t>(k)], 1, s.domain.owner[static_cast<std::size_t>(k)]);
  const Partition partition = repartition ? repartition(m, s.domain.count, plastic) : partition_model(m, s.domain.count, &plastic);
  if (partition.domain_of_element == s.domain.owner) {
    keep_plastic_strains(s);
    return;
  }
  // Every element and node, and the contact and section state, from the domains that keep them now.
  share_element_state(s, exchange);
  share_node_state(m, s, exchange, true);
  exchange.renew_all();
  rebind_domain(m, s, make_domain(m, partition, s.domain.index));
  RunEvent event{RunEvent::Kind::Rebalanced, s.cycle, s.time};
  event.value = before;
  event.second_value = estimated_imbalance(m, s, plastic_points(m, s));  // every domain's own, now
  events.pending.push_back(event);
  keep_plastic_strains(s);
}

}  // namespace crumple::solver
