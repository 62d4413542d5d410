// The decomposition (parallel/partition.hpp, docs/parallel.md "Decomposition"): every element in a domain of
// range and every domain with elements, the same partition on every call, the quality measures counted by hand on
// small plates, the rigid-body rule, the weights' order and the rank counts a model does not admit.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

#include "crumple/parallel/partition.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_partition {

using namespace crumple;
using test::I;
using test::R;

namespace {

constexpr double kSize = 0.01;  // element edge [m]

long long node_id(int nx, int i, int j) { return static_cast<long long>(j) * (nx + 1) + i + 1; }

// A plate of nx x ny four-node shells (part 1: property 1, Ishell `ishell`, N `points`, elastic steel), nodes
// numbered row by row from 1, shells likewise.
std::string plate_cards(int nx, int ny, int ishell = 24, int points = 3) {
  std::string s = "/NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) s += I(node_id(nx, i, j)) + R(i * kSize) + R(j * kSize) + R(0.0) + "\n";
  s += "/SHELL/1\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s += I(j * nx + i + 1) + I(node_id(nx, i, j)) + I(node_id(nx, i + 1, j)) + I(node_id(nx, i + 1, j + 1)) +
           I(node_id(nx, i, j + 1)) + "\n";
  s += "/PART/1\nplate\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(ishell) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(points) + I(0) + R(0.001) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  return s;
}

// Bricks (part 2, Isolid `isolid`) on the first row of the plate, and a column of triangles (part 1) beyond its
// last column: every element kind in one model.
std::string other_kinds_cards(int nx, int ny, int isolid = 1) {
  std::string s = "/NODE\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= nx; ++i) s += I(1000 + node_id(nx, i, j)) + R(i * kSize) + R(j * kSize) + R(kSize) + "\n";
  for (int j = 0; j <= ny; ++j) s += I(2000 + j) + R((nx + 1) * kSize) + R(j * kSize) + R(0.0) + "\n";
  s += "/BRICK/2\n";
  for (int i = 0; i < nx; ++i) {
    const long long n[4] = {node_id(nx, i, 0), node_id(nx, i + 1, 0), node_id(nx, i + 1, 1), node_id(nx, i, 1)};
    s += I(i + 1) + I(n[0]) + I(n[1]) + I(n[2]) + I(n[3]) + I(1000 + n[0]) + I(1000 + n[1]) + I(1000 + n[2]) +
         I(1000 + n[3]) + "\n";
  }
  s += "/SH3N/1\n";
  for (int j = 0; j < ny; ++j) {
    s += I(2 * j + 1) + I(node_id(nx, nx, j)) + I(2000 + j) + I(node_id(nx, nx, j + 1)) + "\n";
    s += I(2 * j + 2) + I(2000 + j) + I(2000 + j + 1) + I(node_id(nx, nx, j + 1)) + "\n";
  }
  s += "/PART/2\nbricks\n" + I(2) + I(1) + "\n/PROP/SOLID/2\nsolid\n" + I(isolid) + "\n" + R(0.0) + R(0.0) + R(0.0) +
       "\n";
  return s;
}

// /RBODY/id on main node `main` (a node of its own at the origin's corner) with the nodes of group `group`.
std::string rigid_body_card(long long id, long long main, long long group) {
  const std::string zeros = R(0.0) + R(0.0) + R(0.0) + "\n";
  return "/NODE\n" + I(main) + R(-kSize) + R(-kSize) + R(0.0) + "\n/RBODY/" + std::to_string(id) + "\nbody\n" +
         I(main) + I(0) + I(0) + I(0) + R(1.0) + I(group) + I(0) + I(0) + I(0) + "\n" + zeros + zeros + I(0) + I(0) +
         "\n";
}

Model read(const test::TempDir& dir, const std::string& cards) {
  return read_deck(dir.write("PART_0000.rad", test::begin_card("PART") + cards + "/END\n")).model;
}

std::size_t element_count(const Model& m) {
  std::size_t n = 0;
  for (const ElementTable& t : m.elements) n += t.size();
  return n;
}

std::vector<long long> elements_per_domain(const Partition& p) {
  std::vector<long long> count(static_cast<std::size_t>(p.domains), 0);
  for (const auto& kind : p.domain_of_element)
    for (const std::int32_t d : kind) ++count[static_cast<std::size_t>(d)];
  return count;
}

std::string error_of(const Model& m, int domains) {
  try {
    partition_model(m, domains);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(Partition, EveryElementHasADomainInRangeAndEveryDomainHasElements) {
  test::TempDir dir;
  const Model m = read(dir, plate_cards(12, 8) + other_kinds_cards(12, 8));
  ASSERT_EQ(element_count(m), 12u * 8 + 12 + 16);
  for (int domains : {1, 2, 3, 4, 7, 16}) {
    const Partition p = partition_model(m, domains);
    EXPECT_EQ(p.domains, domains);
    for (std::size_t k = 0; k < static_cast<std::size_t>(kElementKinds); ++k) {
      ASSERT_EQ(p.domain_of_element[k].size(), m.elements[k].size());
      for (const std::int32_t d : p.domain_of_element[k]) EXPECT_TRUE(d >= 0 && d < domains) << d;
    }
    for (const long long n : elements_per_domain(p)) EXPECT_GT(n, 0) << domains << " domains";
    EXPECT_EQ(p.weight.size(), static_cast<std::size_t>(domains));
    EXPECT_EQ(p.neighbours.size(), static_cast<std::size_t>(domains));
  }
}

TEST(Partition, SameModelAndDomainCountGiveTheSamePartition) {
  test::TempDir dir;
  const Model m = read(dir, plate_cards(20, 10) + other_kinds_cards(20, 10));
  for (int domains : {2, 5, 8}) {
    const Partition a = partition_model(m, domains), b = partition_model(m, domains);
    EXPECT_EQ(a.domain_of_element, b.domain_of_element) << domains;
    EXPECT_EQ(a.edge_cut, b.edge_cut);
    EXPECT_EQ(a.shared_nodes, b.shared_nodes);
    EXPECT_EQ(a.weight, b.weight);
    EXPECT_EQ(a.neighbours, b.neighbours);
  }
  // And a model read again from the same deck.
  const Model again = read(dir, plate_cards(20, 10) + other_kinds_cards(20, 10));
  EXPECT_EQ(partition_model(m, 8).domain_of_element, partition_model(again, 8).domain_of_element);
}

// A strip of 4 x 1 shells in two domains: two and two, one cut edge (shells 2 and 3), the two nodes between them
// shared, one neighbour each, equal weights.
TEST(Partition, StripInTwoHasOneCutEdgeAndTwoSharedNodes) {
  test::TempDir dir;
  const Model m = read(dir, plate_cards(4, 1));
  const Partition p = partition_model(m, 2);
  const auto& d = p.domain_of_element[0];
  EXPECT_EQ(d[0], d[1]);
  EXPECT_EQ(d[2], d[3]);
  EXPECT_NE(d[1], d[2]);
  EXPECT_EQ(p.edge_cut, 1);
  EXPECT_EQ(p.shared_nodes, 2);
  EXPECT_EQ(p.neighbours, (std::vector<int>{1, 1}));
  EXPECT_EQ(p.weight[0], p.weight[1]);
  EXPECT_EQ(p.weight[0], 2LL * element_weight(m, ElementKind::Shell4, 0));
  EXPECT_DOUBLE_EQ(p.imbalance, 1.0);
}

// A plate of 2 x 2 shells in four domains: each shell its own; every pair of shells shares a node (the centre), so
// all 6 edges are cut; the centre and the 4 mid-side nodes are shared; each domain has 3 neighbours.
TEST(Partition, TwoByTwoPlateInFourCutsEveryEdge) {
  test::TempDir dir;
  const Partition p = partition_model(read(dir, plate_cards(2, 2)), 4);
  const std::set<std::int32_t> distinct(p.domain_of_element[0].begin(), p.domain_of_element[0].end());
  EXPECT_EQ(distinct.size(), 4u);
  EXPECT_EQ(p.edge_cut, 6);
  EXPECT_EQ(p.shared_nodes, 5);
  EXPECT_EQ(p.neighbours, (std::vector<int>{3, 3, 3, 3}));
}

// One domain: no cut, no shared node, the whole weight in domain 0.
TEST(Partition, OneDomainHoldsEverything) {
  test::TempDir dir;
  const Model m = read(dir, plate_cards(3, 2) + other_kinds_cards(3, 2));
  const Partition p = partition_model(m, 1);
  long long total = 0;
  for (int k = 0; k < kElementKinds; ++k)
    for (std::size_t e = 0; e < m.elements[static_cast<std::size_t>(k)].size(); ++e)
      total += element_weight(m, static_cast<ElementKind>(k), e);
  EXPECT_EQ(p.edge_cut, 0);
  EXPECT_EQ(p.shared_nodes, 0);
  EXPECT_EQ(p.weight, std::vector<long long>{total});
  EXPECT_EQ(p.neighbours, std::vector<int>{0});
  EXPECT_DOUBLE_EQ(p.imbalance, 1.0);
}

// Imbalance is the largest domain weight over the mean: 3 equal shells in 2 domains give 2 / 1.5.
TEST(Partition, ImbalanceIsLargestWeightOverMean) {
  test::TempDir dir;
  const Partition p = partition_model(read(dir, plate_cards(3, 1)), 2);
  std::vector<long long> w = p.weight;
  std::sort(w.begin(), w.end());
  EXPECT_EQ(w[1], 2 * w[0]);
  EXPECT_NEAR(p.imbalance, 4.0 / 3.0, 1e-12);
  // On a larger plate METIS balances within its 1 % (UFACTOR 10), give or take one element's weight.
  const Partition q = partition_model(read(dir, plate_cards(24, 16)), 6);
  const long long largest = *std::max_element(q.weight.begin(), q.weight.end());
  const double mean = static_cast<double>(std::accumulate(q.weight.begin(), q.weight.end(), 0LL)) / 6.0;
  EXPECT_DOUBLE_EQ(q.imbalance, static_cast<double>(largest) / mean);
  EXPECT_LT(q.imbalance, 1.02);
}

// The weights follow the measured costs: more layers cost more, QBAT's four points more than one, a 2 x 2 x 2 brick
// more than a one-point brick.
TEST(Partition, WeightsFollowKindAndFormulation) {
  test::TempDir dir;
  const auto shell = [&](int ishell, int points) {
    return element_weight(read(dir, plate_cards(1, 1, ishell, points)), ElementKind::Shell4, 0);
  };
  const auto brick = [&](int isolid) {
    return element_weight(read(dir, plate_cards(1, 1) + other_kinds_cards(1, 1, isolid)), ElementKind::Brick8, 0);
  };
  EXPECT_GT(shell(24, 1), 0);
  EXPECT_LT(shell(24, 1), shell(24, 3));
  EXPECT_LT(shell(24, 3), shell(24, 5));
  EXPECT_LT(shell(24, 5), shell(12, 5));
  EXPECT_LT(brick(1), brick(24));
  EXPECT_LT(brick(24), brick(14));
  EXPECT_GT(element_weight(read(dir, plate_cards(1, 1) + other_kinds_cards(1, 1)), ElementKind::Shell3, 0), 0);
}

// Shells 3 and 4 of a 4 x 1 strip lie in a rigid body (nodes 3-5 and 8-10): carried, they weigh little and stay in
// one domain; the body counts as one vertex, so the strip admits 3 ranks, not 4.
TEST(Partition, RigidBodyElementsAreLightAndStayTogether) {
  test::TempDir dir;
  const std::string group = "/GRNOD/NODE/20\nbody\n" + I(3) + I(4) + I(5) + I(8) + I(9) + I(10) + "\n";
  const Model m = read(dir, plate_cards(4, 1) + group + rigid_body_card(1, 99, 20));
  const int free_weight = element_weight(m, ElementKind::Shell4, 0);
  EXPECT_EQ(element_weight(m, ElementKind::Shell4, 1), free_weight);
  EXPECT_LT(element_weight(m, ElementKind::Shell4, 2), free_weight / 10);
  EXPECT_EQ(element_weight(m, ElementKind::Shell4, 2), element_weight(m, ElementKind::Shell4, 3));
  for (int domains : {2, 3}) {
    const Partition p = partition_model(m, domains);
    EXPECT_EQ(p.domain_of_element[0][2], p.domain_of_element[0][3]) << domains;
    for (const long long n : elements_per_domain(p)) EXPECT_GT(n, 0);
    EXPECT_EQ(std::accumulate(p.weight.begin(), p.weight.end(), 0LL),
              2LL * free_weight + 2LL * element_weight(m, ElementKind::Shell4, 2));
  }
  EXPECT_EQ(error_of(m, 4),
            "4 ranks for a model of 4 elements: at most 3 ranks, since the elements of each rigid body stay in one "
            "domain");
}

TEST(Partition, MoreRanksThanElementsIsAnError) {
  test::TempDir dir;
  const Model m = read(dir, plate_cards(3, 2));
  EXPECT_EQ(error_of(m, 7), "7 ranks for a model of 6 elements: at most 6 ranks");
  EXPECT_EQ(error_of(m, 6), "");
  EXPECT_EQ(error_of(m, 0), "0 ranks: a run needs at least one");
}

TEST(Partition, ModelWithoutElementsRunsOnOneRankOnly) {
  const Model m;
  const Partition p = partition_model(m, 1);
  EXPECT_EQ(p.domains, 1);
  EXPECT_EQ(p.weight, std::vector<long long>{0});
  EXPECT_DOUBLE_EQ(p.imbalance, 1.0);
  EXPECT_EQ(error_of(m, 2), "2 ranks for a model of 0 elements: at most 1 rank (a model without elements runs on one)");
}

TEST(Partition, DescribeGivesTheQualityLines) {
  test::TempDir dir;
  const std::vector<std::string> lines = describe(partition_model(read(dir, plate_cards(4, 1)), 2));
  ASSERT_GE(lines.size(), 1u);
  EXPECT_EQ(lines[0], "DOMAINS 2  EDGE CUT 1  SHARED NODES 2  IMBALANCE 1.000");
}

}  // namespace test_partition
