// The seams of the parallel solver (docs/parallel.md): a deck run as one domain and as two and three domains,
// each a thread of this process with its own state, exchanging through ThreadExchange. Every domain must end with
// the one domain's nodes, energies, time and cycles bit for bit, and each element's state must be its owner's.
// The partitions are the hardest there are for the assembly: elements dealt round-robin, so that nearly every node
// is shared, and in blocks.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "crumple/deck/reader.hpp"
#include "crumple/output/history_channels.hpp"
#include "crumple/parallel/thread_exchange.hpp"
#include "crumple/solver/quiet_observer.hpp"
#include "crumple/solver/solver.hpp"
#include "deck_files.hpp"

namespace crumple::test_domains {
namespace {

const std::filesystem::path kQa = CRUMPLE_QA_DIR;

// Element e of each kind to domain e % domains (round-robin) or to e * domains / n (blocks).
Partition test_partition(const Model& m, int domains, bool round_robin) {
  Partition p;
  p.domains = domains;
  for (int k = 0; k < kElementKinds; ++k) {
    const std::size_t n = m.elements[static_cast<std::size_t>(k)].size();
    auto& owner = p.domain_of_element[static_cast<std::size_t>(k)];
    owner.resize(n);
    for (std::size_t e = 0; e < n; ++e)
      owner[e] = static_cast<std::int32_t>(round_robin ? e % static_cast<std::size_t>(domains)
                                                       : e * static_cast<std::size_t>(domains) / n);
  }
  return p;
}

struct DomainRun {
  SolverState state;
  RunSummary summary;
};

DomainRun run_domain(const Model& m, Domain domain, Exchange* exchange, Repartition repartition = {}) {
  std::vector<std::string> notes;
  DomainRun r{initial_state(m, notes, std::move(domain)), {}};
  SolverOptions options;
  options.exchange = exchange;
  options.repartition = std::move(repartition);
  QuietObserver quiet;
  r.summary = run_engine_deck(m, options, quiet, r.state, notes);
  return r;
}

// With `repartition`, the domains take its partition at every rebalancing check (docs/parallel.md, "Rebalancing").
std::vector<DomainRun> run_domains(const Model& m, const Partition& p, const Repartition& repartition = {}) {
  ThreadBoard board(p.domains);
  std::vector<ThreadExchange> exchanges;
  for (int d = 0; d < p.domains; ++d) exchanges.emplace_back(board, d);
  std::vector<DomainRun> runs(static_cast<std::size_t>(p.domains));
  std::vector<std::thread> threads;
  for (int d = 0; d < p.domains; ++d)
    threads.emplace_back([&, d] {
      runs[static_cast<std::size_t>(d)] =
          run_domain(m, make_domain(m, p, d), &exchanges[static_cast<std::size_t>(d)], repartition);
    });
  for (std::thread& t : threads) t.join();
  return runs;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_nodes_and_energies(const DomainRun& one, const DomainRun& domain, int d) {
  const NodalState &a = one.state.nodes, &b = domain.state.nodes;
  const std::pair<const char*, const std::vector<double>*> fields[][2] = {
      {{"x", &a.x}, {"x", &b.x}}, {{"y", &a.y}, {"y", &b.y}}, {{"z", &a.z}, {"z", &b.z}},
      {{"vx", &a.vx}, {"vx", &b.vx}}, {{"vy", &a.vy}, {"vy", &b.vy}}, {{"vz", &a.vz}, {"vz", &b.vz}},
      {{"wx", &a.wx}, {"wx", &b.wx}}, {{"wy", &a.wy}, {"wy", &b.wy}}, {{"wz", &a.wz}, {"wz", &b.wz}},
      {{"fx", &a.fx}, {"fx", &b.fx}}, {{"mx", &a.mx}, {"mx", &b.mx}}, {{"mass", &a.mass}, {"mass", &b.mass}}};
  for (const auto& f : fields) EXPECT_TRUE(same_bits(*f[0].second, *f[1].second)) << "domain " << d << ": nodes " << f[0].first;
  const EnergyBalanceState &ea = one.state.energy, &eb = domain.state.energy;
  EXPECT_TRUE(same_bits(ea.internal, eb.internal)) << "domain " << d << ": " << ea.internal << " " << eb.internal;
  EXPECT_TRUE(same_bits(ea.hourglass, eb.hourglass)) << "domain " << d;
  EXPECT_TRUE(same_bits(ea.kinetic_translational, eb.kinetic_translational)) << "domain " << d;
  EXPECT_TRUE(same_bits(ea.kinetic_rotational, eb.kinetic_rotational)) << "domain " << d;
  EXPECT_TRUE(same_bits(ea.contact, eb.contact)) << "domain " << d;
  EXPECT_TRUE(same_bits(ea.external_work, eb.external_work)) << "domain " << d;
  EXPECT_TRUE(same_bits(one.state.time, domain.state.time)) << "domain " << d;
  EXPECT_EQ(one.state.cycle, domain.state.cycle) << "domain " << d;
  EXPECT_EQ(one.summary.status, domain.summary.status) << "domain " << d;
}

// Each element's energy and condition in the domain that computes it.
void expect_own_elements(const Model& m, const DomainRun& one, const DomainRun& domain, const Domain& d) {
  auto check = [&](ElementKind kind, const std::vector<double>& ie_one, const std::vector<double>& ie_domain,
                   const std::vector<std::uint8_t>& status_one, const std::vector<std::uint8_t>& status_domain) {
    for (std::size_t e = 0; e < m.elements[static_cast<std::size_t>(kind)].size(); ++e) {
      EXPECT_EQ(element_condition(status_one[e]), element_condition(status_domain[e])) << "element " << e;
      if (d.mine(kind, e)) {
        EXPECT_TRUE(same_bits(ie_one[e], ie_domain[e])) << "domain " << d.index << " element " << e;
      }
    }
  };
  check(ElementKind::Shell4, one.state.shells.internal_energy, domain.state.shells.internal_energy,
        one.state.shells.deleted, domain.state.shells.deleted);
  check(ElementKind::Shell3, one.state.shells3.internal_energy, domain.state.shells3.internal_energy,
        one.state.shells3.deleted, domain.state.shells3.deleted);
  check(ElementKind::Brick8, one.state.bricks.internal_energy, domain.state.bricks.internal_energy,
        one.state.bricks.deleted, domain.state.bricks.deleted);
}

struct DomainCase {
  const char* folder;
  const char* deck;
};

class Domains : public ::testing::TestWithParam<DomainCase> {};

TEST_P(Domains, TwoAndThreeDomainsEndBitForBitWhereOneEnds) {
  const DomainCase& c = GetParam();
  const Model m = read_deck(kQa / c.folder / (std::string(c.deck) + "_0000.rad")).model;
  const DomainRun one = run_domain(m, single_domain(m), nullptr);
  ASSERT_GT(one.state.cycle, 10);
  for (const auto& [domains, round_robin] : {std::pair{2, true}, std::pair{3, false}, std::pair{3, true}}) {
    SCOPED_TRACE(testing::Message() << domains << " domains, " << (round_robin ? "round-robin" : "blocks"));
    const Partition p = test_partition(m, domains, round_robin);
    const std::vector<DomainRun> runs = run_domains(m, p);
    for (int d = 0; d < domains; ++d) {
      const DomainRun& r = runs[static_cast<std::size_t>(d)];
      expect_same_nodes_and_energies(one, r, d);
      expect_own_elements(m, one, r, make_domain(m, p, d));
    }
  }
}

// /TH/SECTIO (docs/output-format.md, "SECTIO"): box_crush's eight sections, asked every variable Crumple writes
// (WORK too, integrated by the domain that computes each element), give at every history row the one domain's
// values bit for bit in every domain: the records of the sections' elements travel from their domains at the row
// and every sum runs in model order.
TEST(DomainSections, BoxCrushSectionHistoriesBitForBit) {
  Model m = read_deck(kQa / "box_crush" / "BOX1BL_0000.rad").model;
  for (TimeHistoryRequest& th : m.histories)
    if (th.object == HistoryObject::Section)
      for (const char* name : {"CENTER", "GLOBAL", "LOCAL", "WORK"}) th.variables.push_back(name);
  using Rows = std::vector<std::vector<double>>;  // per row: the SECTIO columns
  auto run = [&m](Domain domain, Exchange* exchange, Rows& rows) {
    std::vector<std::string> notes;
    SolverState state = initial_state(m, notes, std::move(domain));
    HistoryChannels channels(m);
    SolverOptions options;
    options.exchange = exchange;
    options.on_history_row = [&](const SolverState& s) {
      std::vector<std::vector<double>> values;
      channels.evaluate(s, VelocityChange{}, values);
      for (std::size_t d = 0; d < channels.datasets().size(); ++d)
        if (channels.datasets()[d].kind == "SECTIO") rows.push_back(values[d]);
    };
    QuietObserver quiet;
    return run_engine_deck(m, options, quiet, state, notes);
  };
  Rows one;
  ASSERT_EQ(run(single_domain(m), nullptr, one).status, RunStatus::Normal);
  ASSERT_GT(one.size(), 50u);
  // DEF, CENTER, GLOBAL, LOCAL, WORK: FNX .. M3, CX CY CZ, MX MY MZ, F1 F2 F3, WORK per section.
  ASSERT_EQ(one.front().size(), 8u * 19u);
  double work = 0.0;
  for (std::size_t s = 0; s < 8; ++s) work += std::abs(one.back()[19 * s + 18]);
  EXPECT_GT(work, 0.0);
  for (const auto& [domains, round_robin] : {std::pair{2, true}, std::pair{3, false}}) {
    SCOPED_TRACE(testing::Message() << domains << " domains, " << (round_robin ? "round-robin" : "blocks"));
    const Partition p = test_partition(m, domains, round_robin);
    ThreadBoard board(p.domains);
    std::vector<ThreadExchange> exchanges;
    for (int d = 0; d < domains; ++d) exchanges.emplace_back(board, d);
    std::vector<Rows> rows(static_cast<std::size_t>(domains));
    std::vector<std::thread> threads;
    for (int d = 0; d < domains; ++d)
      threads.emplace_back([&, d] {
        run(make_domain(m, p, d), &exchanges[static_cast<std::size_t>(d)], rows[static_cast<std::size_t>(d)]);
      });
    for (std::thread& t : threads) t.join();
    for (int d = 0; d < domains; ++d) {
      const Rows& r = rows[static_cast<std::size_t>(d)];
      ASSERT_EQ(r.size(), one.size()) << "domain " << d;
      for (std::size_t k = 0; k < r.size(); ++k) EXPECT_TRUE(same_bits(r[k], one[k])) << "domain " << d << " row " << k;
    }
  }
}

// Rebalancing moves elements and nodes between domains mid-run (every kRebalanceEvery cycles here, to blocks, then
// round-robin, then METIS with the running cost): the state each domain then computes from must be the
// one domain's, so the ends are still bit for bit equal; the last check compares each domain's own elements under
// the last partition.
class Repartitioned : public ::testing::TestWithParam<DomainCase> {};

TEST_P(Repartitioned, MidRunTheDomainsEndBitForBit) {
  const DomainCase& c = GetParam();
  const Model m = read_deck(kQa / c.folder / (std::string(c.deck) + "_0000.rad")).model;
  const DomainRun one = run_domain(m, single_domain(m), nullptr);
  ASSERT_GT(one.state.cycle, 10);
  const int domains = 3;
  // Each domain keeps its own copy of the lambda and calls it at the same checks: the same sequence everywhere.
  const Repartition cycle_through = [calls = 0](const Model& model, int count, const RunningCost& cost) mutable {
    const int k = calls++ % 3;
    return k == 2 ? partition_model(model, count, &cost) : test_partition(model, count, k == 1);
  };
  const std::vector<DomainRun> runs = run_domains(m, test_partition(m, domains, true), cycle_through);
  for (int d = 0; d < domains; ++d) {
    const DomainRun& r = runs[static_cast<std::size_t>(d)];
    expect_same_nodes_and_energies(one, r, d);
    expect_own_elements(m, one, r, r.state.domain);
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, Domains,
                         ::testing::Values(DomainCase{"box_crush", "BOX1BL"}, DomainCase{"crash_triangles", "TRITUBV4"},
                                           DomainCase{"brick_bending_isolid24", "CONV_ELS"},
                                           DomainCase{"twisted_beam", "TWISBEAM"}, DomainCase{"contact_idel", "IDEL8"},
                                           DomainCase{"ball_on_wall", "BOULE1V4"}),
                         [](const testing::TestParamInfo<DomainCase>& c) { return std::string(c.param.folder); });

// Rigid bodies, walls, cut sections, contact with friction and deletion: what moves with the elements and nodes.
INSTANTIATE_TEST_SUITE_P(Shared, Repartitioned,
                         ::testing::Values(DomainCase{"box_crush", "BOX1BL"}, DomainCase{"contact_idel", "IDEL8"},
                                           DomainCase{"ball_on_wall", "BOULE1V4"}),
                         [](const testing::TestParamInfo<DomainCase>& c) { return std::string(c.param.folder); });

}  // namespace
}  // namespace crumple::test_domains
