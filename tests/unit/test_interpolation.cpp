// The /RBE3 system (docs/theory/rigid-bodies.md, RI-1 to RI-4) against its conservation laws: the independent nodes'
// loads sum to the dependent node's force and, about it, to its moment; the motion fit is the loads' transpose, so
// the load does the same work on the dependent node as the nodes' loads on theirs; a rigid motion is fitted exactly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "crumple/model/interpolation.hpp"

namespace test_interpolation {

using namespace crumple;

namespace {

struct Node {
  Vec3 r;       // from the dependent node
  Vector6 w;    // dof weights, rotations already scaled by Lc^2
};

// Five nodes off a plane, unequal weights, partial codes (the second without z, the fourth without rotations).
std::vector<Node> nodes() {
  return {{{50.0, -50.0, -10.0}, {1.0, 1.0, 1.0, 900.0, 900.0, 900.0}},
          {{150.0, -50.0, -10.0}, {2.0, 2.0, 0.0, 1800.0, 1800.0, 0.0}},
          {{150.0, 50.0, -10.0}, {3.0, 3.0, 3.0, 2700.0, 2700.0, 2700.0}},
          {{50.0, 50.0, -10.0}, {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}},
          {{100.0, 0.0, 30.0}, {2.0, 2.0, 2.0, 1800.0, 1800.0, 1800.0}}};
}

InterpolationInverse system(const std::vector<Node>& ns) {
  Matrix6 a{};
  for (const Node& n : ns) add_interpolation_node(n.r, n.w, a);
  return invert_interpolation(a);
}

}  // namespace

TEST(Interpolation, NodesLoadsAreTheDependentNodesForceAndMoment) {
  const std::vector<Node> ns = nodes();
  const InterpolationInverse inv = system(ns);
  ASSERT_TRUE(inv.constrained);
  const Vector6 load{3.0, -2.0, 5.0, 40.0, -70.0, 25.0};
  const Vector6 q = multiply(inv.inverse, load);
  Vec3 force{}, moment{};
  for (const Node& n : ns) {
    const Vector6 f = interpolation_node_load(n.r, n.w, q);
    force = force + Vec3{f[0], f[1], f[2]};
    moment = moment + cross(n.r, Vec3{f[0], f[1], f[2]}) + Vec3{f[3], f[4], f[5]};
  }
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(force[d], load[static_cast<std::size_t>(d)], 1e-12 * 100.0);
    EXPECT_NEAR(moment[d], load[static_cast<std::size_t>(3 + d)], 1e-12 * 1e4);
  }
}

TEST(Interpolation, RigidMotionIsFittedAndTheLoadsWorkIsTheSame) {
  const std::vector<Node> ns = nodes();
  const InterpolationInverse inv = system(ns);
  // The nodes in the rigid motion (u, theta) of the dependent node: the fit gives it back.
  const Vec3 u{0.3, -1.2, 0.7}, theta{0.01, 0.02, -0.03};
  Vector6 b{};
  std::vector<Vector6> motion;
  for (const Node& n : ns) {
    const Vec3 v = u + cross(theta, n.r);
    motion.push_back({v.x, v.y, v.z, theta.x, theta.y, theta.z});
    const Vector6 share = interpolation_node_motion(n.r, n.w, motion.back());
    for (std::size_t e = 0; e < 6; ++e) b[e] += share[e];
  }
  const Vector6 q = multiply(inv.inverse, b);
  const Vector6 expected{u.x, u.y, u.z, theta.x, theta.y, theta.z};
  // Round-off only: A's condition number is about 1e7 here (weights of 1 beside Lc^2 w r^2 of 1e7).
  for (std::size_t e = 0; e < 6; ++e) EXPECT_NEAR(q[e], expected[e], 1e-9);
  // Any node motion: the dependent node's load on its fitted motion does the work of the nodes' loads on theirs.
  std::vector<Vector6> any = {{1, 2, 3, 0.1, 0.2, 0.3}, {-1, 0, 2, 0, 0.1, 0}, {0, 0, 0, 0.2, 0, 0},
                              {3, -1, 1, 0, 0, 0}, {0.5, 0.5, -0.5, 0.01, -0.02, 0.03}};
  Vector6 fit_rhs{};
  for (std::size_t i = 0; i < ns.size(); ++i) {
    const Vector6 share = interpolation_node_motion(ns[i].r, ns[i].w, any[i]);
    for (std::size_t e = 0; e < 6; ++e) fit_rhs[e] += share[e];
  }
  const Vector6 fitted = multiply(inv.inverse, fit_rhs);
  const Vector6 load{3.0, -2.0, 5.0, 40.0, -70.0, 25.0};
  const Vector6 q_load = multiply(inv.inverse, load);
  double on_dependent = 0.0, on_nodes = 0.0;
  for (std::size_t e = 0; e < 6; ++e) on_dependent += load[e] * fitted[e];
  for (std::size_t i = 0; i < ns.size(); ++i) {
    const Vector6 f = interpolation_node_load(ns[i].r, ns[i].w, q_load);
    for (std::size_t e = 0; e < 6; ++e) on_nodes += f[e] * any[i][e];
  }
  EXPECT_NEAR(on_dependent, on_nodes, 1e-12 * std::abs(on_nodes));
}

// Nodes on one line with translations only hold no rotation about it: the reference's error 706.
TEST(Interpolation, CollinearTranslationsLeaveAMotionUnheld) {
  std::vector<Node> line;
  for (int k = 0; k < 4; ++k) line.push_back({{-50.0, 25.0 * k, 0.0}, {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}});
  EXPECT_FALSE(system(line).constrained);
  line[1].w = {1.0, 1.0, 1.0, 900.0, 900.0, 900.0};  // one node's rotations hold it
  EXPECT_TRUE(system(line).constrained);
}

}  // namespace test_interpolation
