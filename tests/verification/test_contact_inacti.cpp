// Initial penetrations and Inacti (type7.md §7; docs/theory/contact.md, "Initial penetrations").
//
// A block of 2 x 2 shells rests, without load or velocity, with its nodes at 10 % of the gap from a fixed plate
// (penetration p0 = 0.9 g). Each Inacti must show its documented behaviour: 0 pushes the block off with the full
// penalty force of p0; 1 (no stiffness for those nodes) and 2 (no stiffness for those segments) leave it in place
// without force; 3 moves the nodes out to the gap before the run; 5 and 6 reduce their gap to the initial
// distance (6 with 5 % more clearance), so no force acts while they stay.
#include <cmath>

#include "contact_cards.hpp"

namespace crumple::verification::test_contact_inacti {
namespace {

constexpr double kGap = 1e-3, kP0 = 0.9 * kGap;

struct Outcome {
  RunResult run;
  double largest_force = 0.0, first_z = 0.0, last_z = 0.0;
  std::size_t penetrated = 0;
  unsigned first_fixed = 0, last_fixed = 0;  // fixed-dof bits of the block's centre node
};

// `ibc`: the IBC flags; `block_bcs`: a /BCS code for the block's nodes ("" for none).
Outcome start_inside(int inacti, const std::string& ibc = "000", const std::string& block_bcs = "") {
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> plate, block;
  plate = shell_grid(4, 4, 0.025, 0.025, 0.0, 0.0, 0.0, 1, 1, nodes);
  long long id = 17;  // the block's shells follow the plate's 16
  std::vector<long long> block_nodes, plate_nodes;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) {
      nodes.push_back({101 + i + 3 * j, 0.03 + 0.02 * i, 0.03 + 0.02 * j, kGap - kP0});
      block_nodes.push_back(101 + i + 3 * j);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) block.push_back({id++, 101 + i + 3 * j, 102 + i + 3 * j, 105 + i + 3 * j, 104 + i + 3 * j});
  for (long long k = 1; k <= 25; ++k) plate_nodes.push_back(k);
  Type7Options o;
  o.gapmin = kGap, o.inacti = inacti, o.ibc = ibc;
  const std::string bcs = block_bcs.empty() ? "" : boundary_condition(2, block_bcs, 1);
  const std::string starter = bcs + node_cards(nodes) + shell_cards(1, block) + shell_cards(2, plate) + part_card(1) +
                              part_card(2) + shell_property(0.002, 3, 0.0, 24) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, block_nodes) + node_group(2, plate_nodes) + boundary_condition(1, "111 111", 2) +
                              surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  Outcome out;
  test::TempDir dir;
  bool first = true;
  out.run = run_deck(dir, starter, 2e-5, 1e-12, [&](const Model& m, const SolverState& s) {
    const std::size_t k = node_index(m, 105);  // the block's centre node
    if (first) {
      out.first_z = s.nodes.z[k] - s.dt * s.nodes.vz[k], out.penetrated = s.contact.results.at(0).initial_penetrations.size();
      out.first_fixed = s.fixed[k];
    }
    first = false;
    out.last_z = s.nodes.z[k];
    out.last_fixed = s.fixed[k];
    for (long long n : block_nodes) out.largest_force = std::max(out.largest_force, std::abs(s.contact.fz[node_index(m, n)]));
  });
  return out;
}

class InitialPenetration : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Inacti, InitialPenetration, ::testing::Values(0, 1, 2, 3, 5, 6));

TEST_P(InitialPenetration, DocumentedBehaviour) {
  const int inacti = GetParam();
  const Outcome o = start_inside(inacti);
  ASSERT_EQ(o.run.summary.status, RunStatus::Normal) << o.run.summary.message;
  EXPECT_EQ(o.penetrated, 9u) << "every block node starts inside the gap and is listed";
  const double full = 0.5 * 2.1e11 * 0.002 * kGap * kP0 / (kGap - kP0);  // K0 g p0 / (g - p0) on one node
  switch (inacti) {
    case 0:  // full force at the start, the block is pushed off
      EXPECT_GT(o.largest_force, 0.9 * full);
      EXPECT_GT(o.last_z, o.first_z);
      break;
    case 3:  // moved out to the gap before the run, then no force
      EXPECT_NEAR(o.first_z, kGap, 1e-12);
      EXPECT_EQ(o.largest_force, 0.0);
      break;
    case 5:  // the node sits exactly on its corrected gap: at most a round-off force
      EXPECT_LT(o.largest_force, 1e-12 * full);
      EXPECT_NEAR(o.last_z, kGap - kP0, 1e-12);
      break;
    default:  // 1, 2, 6: no force, the block stays where it was
      EXPECT_EQ(o.largest_force, 0.0);
      EXPECT_NEAR(o.last_z, kGap - kP0, 1e-12);
  }
  std::printf("[Inacti %d] listed %zu  largest force %.4g N (full %.4g)  z %.6e -> %.6e\n", inacti, o.penetrated,
              o.largest_force, full, o.first_z, o.last_z);
}

// IBC (type7.md §8): the block's nodes are fixed in x and y (and free in z); IBC = 110 releases x and y at their
// first impact, which is the first cycle here (they start inside the gap with Inacti 0). Without IBC the
// boundary conditions stay.
TEST(ContactIbc, ReleasesTheFlaggedBoundaryConditionsAtFirstImpact) {
  const Outcome released = start_inside(0, "110", "110 000");
  ASSERT_EQ(released.run.summary.status, RunStatus::Normal) << released.run.summary.message;
  EXPECT_EQ(released.last_fixed & 7u, 0u) << "x and y released, z was free";
  const Outcome kept = start_inside(0, "000", "110 000");
  EXPECT_EQ(kept.last_fixed & 7u, 3u) << "without IBC the block stays fixed in x and y";
}

}  // namespace
}  // namespace crumple::verification::test_contact_inacti
