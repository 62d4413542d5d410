// /VEL/TRA (docs/theory/loads.md, L-8): linked nodes move with their mass-weighted mean velocity along the link's
// axes, from the start of the engine deck. Two equal free plates, A moving at (1, 0, 2) m/s and B at rest, linked
// along X: every node then moves at 0.5 along X, A keeps its 2 along Z, and the energy balance starts from the
// linked state (error 0). The reference solver gives the same on the same scene in kg mm ms (run-or.sh: kinetic
// energy 1.766e-3 J from cycle 0 with X linked, 9.812e-4 J with X and Z, against 1.962e-3 J unlinked; error 0.0 %).
#include <gtest/gtest.h>

#include <cmath>

#include "contact_cards.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_velocity_links {
namespace {

struct LinkedPlates {
  std::vector<double> vx, vy, vz;
  double error_percent = 0.0;
};

LinkedPlates run_linked(const std::string& link_card, const std::string& extra_starter = "") {
  std::vector<NodeRow> nodes;
  const auto a = shell_grid(2, 2, 0.005, 0.005, 0.0, 0.0, 0.0, 1, 1, nodes);
  const auto b = shell_grid(2, 2, 0.005, 0.005, 0.02, 0.0, 0.0, 101, 101, nodes);
  std::vector<long long> in_a, all;
  for (const NodeRow& n : nodes) {
    if (n.id < 100) in_a.push_back(n.id);
    all.push_back(n.id);
  }
  std::string ids;
  for (long long id : all) ids += std::to_string(id) + " ";
  const std::string starter = node_cards(nodes) + shell_cards(1, a) + shell_cards(2, b) + part_card(1) + part_card(2) +
                              shell_property(0.001, 3) + elastic_material(7850.0, 2.1e11, 0.3) + node_group(1, in_a) +
                              initial_velocity(1, 1.0, 0.0, 2.0, 1) + extra_starter;
  test::TempDir dir;
  LinkedPlates out;
  const RunResult r = run_deck(dir, starter, 2e-4, 1e-4,
                               [&](const Model&, const SolverState& s) {
                                 out.vx = s.nodes.vx, out.vy = s.nodes.vy, out.vz = s.nodes.vz;
                               },
                               link_card + "\n" + ids + "\n");
  EXPECT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  out.error_percent = r.summary.energy.error_percent;
  EXPECT_EQ(out.vx.size(), 18u);
  return out;
}

TEST(VelocityLinks, NodesShareTheirMomentumAlongTheLinkedAxes) {
  const LinkedPlates p = run_linked("/VEL/TRA/X");
  for (std::size_t k = 0; k < p.vx.size(); ++k) {
    EXPECT_NEAR(p.vx[k], 0.5, 1e-12) << "node " << k;
    EXPECT_NEAR(p.vz[k], k < 9 ? 2.0 : 0.0, 1e-12) << "Z is not linked: A keeps its own";
  }
  EXPECT_NEAR(p.error_percent, 0.0, 1e-9) << "the balance starts from the linked state";
}

TEST(VelocityLinks, AlongTheAxesOfASkew) {
  // X' = (1, 1, 0) / sqrt 2: A's component 1 / sqrt 2 and B's 0 average to 1 / (2 sqrt 2); the rest of A's
  // velocity, (1/2, -1/2, 2), is its own.
  const std::string skew = "/SKEW/FIX/5\nskew\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(-1.0) + R(1.0) + R(0.0) + "\n" +
                           R(0.0) + R(0.0) + R(1.0) + "\n";
  const LinkedPlates p = run_linked("/VEL/TRA/X/5", skew);
  for (std::size_t k = 0; k < p.vx.size(); ++k) {
    const bool in_a = k < 9;
    EXPECT_NEAR(p.vx[k], 0.25 + (in_a ? 0.5 : 0.0), 1e-12) << "node " << k;
    EXPECT_NEAR(p.vy[k], 0.25 + (in_a ? -0.5 : 0.0), 1e-12) << "node " << k;
    EXPECT_NEAR(p.vz[k], in_a ? 2.0 : 0.0, 1e-12) << "node " << k;
  }
}

}  // namespace
}  // namespace crumple::verification::test_velocity_links
