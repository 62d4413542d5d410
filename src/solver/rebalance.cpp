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
#include "solver/domain_sharing.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// The running cost (parallel/partition.hpp): per element this domain computes, how many of its points have flowed
// plastically since the last check (their plastic strain grew; an element of another domain: 0, until the counts
// are shared); per element of the model, its share of the candidate contact pairs of its nodes (the candidate
// lists are the same in every domain, so every domain finds the same shares).
RunningCost running_cost(const Model& m, const SolverState& s) {
  RunningCost cost;
  for (int k = 0; k < kElementKinds; ++k) cost.plastic[static_cast<std::size_t>(k)].assign(m.elements[static_cast<std::size_t>(k)].size(), 0);
  const std::array<std::vector<point_real>, kElementKinds>& before = s.domain_scratch.rebalancing.eps_p_at_check;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    const ElementKindState& state = element_state(s, group.kind);
    const std::vector<point_real>& eps_p = state.eps_p;
    const std::vector<point_real>& then = before[static_cast<std::size_t>(group.kind)];
    const std::size_t first = state.point_offset[g];
    const auto points = static_cast<std::size_t>(state.points[g]);
    std::vector<std::uint8_t>& counts = cost.plastic[static_cast<std::size_t>(group.kind)];
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      if (!s.domain.mine(group.kind, static_cast<std::size_t>(e))) continue;
      const std::size_t at = first + static_cast<std::size_t>(e - group.begin) * points;
      int flowing = 0;
      for (std::size_t p = at; p < at + points; ++p) flowing += eps_p[p] > (then.empty() ? 0.0 : then[p]) ? 1 : 0;
      counts[static_cast<std::size_t>(e)] = static_cast<std::uint8_t>(std::min(flowing, 255));
    }
  }
  if (s.contact.interfaces.empty()) return cost;
  std::vector<std::int32_t> pairs(m.nodes.size(), 0), uses(m.nodes.size(), 0);
  for (const ContactInterface& in : s.contact.interfaces)
    for (std::int32_t i : in.candidate_node) ++pairs[static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(i)])];
  for (const ElementTable& table : m.elements)
    for (std::int32_t k : table.connectivity) ++uses[static_cast<std::size_t>(k)];
  for (int k = 0; k < kElementKinds; ++k) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(k)];
    const int count = nodes_per_element(table.kind);
    std::vector<std::int32_t>& share = cost.contact[static_cast<std::size_t>(k)];
    share.assign(table.size(), 0);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < count; ++a) {
        const auto node = static_cast<std::size_t>(table.nodes_of(e)[a]);
        share[e] += (pairs[node] * kPairWeight + uses[node] / 2) / uses[node];
      }
  }
  return cost;
}

// The next check counts from the plastic strains of now.
void keep_plastic_strains(SolverState& s) {
  std::array<std::vector<point_real>, kElementKinds>& then = s.domain_scratch.rebalancing.eps_p_at_check;
  for (ElementKind kind : kAllElementKinds) then[static_cast<std::size_t>(kind)] = element_state(s, kind).eps_p;
}

// The largest domain's estimated cost over the mean, of the element phase and of the contact pass, whichever is
// worse (the phases wait for each other in turn): from every domain's own elements, exact sums of integer weights,
// so every domain finds the same.
double estimated_imbalance(const Model& m, SolverState& s, const RunningCost& running) {
  const auto domains = static_cast<std::size_t>(s.domain.count);
  std::vector<ExactSum>& cost = s.reducer.sums;
  cost.assign(2 * domains, ExactSum{});
  ExactSum& elements = cost[static_cast<std::size_t>(s.domain.index)];
  ExactSum& contact = cost[domains + static_cast<std::size_t>(s.domain.index)];
  for (int k = 0; k < kElementKinds; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    for (std::size_t e = 0; e < m.elements[static_cast<std::size_t>(k)].size(); ++e)
      if (s.domain.mine(kind, e)) elements.add(element_weight(m, kind, e, running)), contact.add(element_contact_weight(kind, e, running));
  }
  s.reducer.sum(cost);
  double worst = 1.0;
  for (std::size_t phase = 0; phase < 2; ++phase) {
    double largest = 0.0, total = 0.0;
    for (std::size_t d = 0; d < domains; ++d) largest = std::max(largest, cost[phase * domains + d].value()), total += cost[phase * domains + d].value();
    if (total > 0.0) worst = std::max(worst, largest * static_cast<double>(domains) / total);
  }
  return worst;
}

}  // namespace

bool rebalance_due(const SolverState& s) { return s.domain.several() && s.cycle > 0 && s.cycle % kRebalanceEvery == 0; }

void rebalance(const Model& m, SolverState& s, Exchange& exchange, RunEvents& events, const Repartition& repartition) {
  RunningCost cost = running_cost(m, s);
  const double before = estimated_imbalance(m, s, cost);
  if (!(before > 1.0 + kRebalanceTolerance) && !repartition) {
    keep_plastic_strains(s);
    return;
  }
  for (int k = 0; k < kElementKinds; ++k)
    exchange.share(cost.plastic[static_cast<std::size_t>(k)], 1, s.domain.owner[static_cast<std::size_t>(k)]);
  const Partition partition = repartition ? repartition(m, s.domain.count, cost) : partition_model(m, s.domain.count, &cost);
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
  event.second_value = estimated_imbalance(m, s, running_cost(m, s));  // every domain's own, now
  events.pending.push_back(event);
  keep_plastic_strains(s);
}

}  // namespace crumple::solver
