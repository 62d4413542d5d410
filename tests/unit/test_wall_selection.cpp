// Rigid-wall secondary nodes chosen by D_search (docs/theory/rigid-walls.md, RW-0): 90 nodes around a wall of each
// shape, grnod_ID1 = 0, against the counts the reference solver's starter listing gives for the same decks.
#include <gtest/gtest.h>

#include <cstdio>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_wall_selection {

using namespace crumple;
using test::I;
using test::R;

namespace {

// Nodes on x in {-0.5, 0.05, 0.5, 0.95, 1.5}, y in {-0.1, 0.3, 1.2}, z in {-0.2, -0.05, 0, 0.02, 0.08, 0.2}, each
// with 1 kg; node 999 at (0.3, 0.3, 0.5) carries the moving walls.
std::string grid() {
  std::string s = "/NODE\n", group = "/GRNOD/NODE/1\nall\n";
  int id = 1, on_line = 0;
  for (double x : {-0.5, 0.05, 0.5, 0.95, 1.5})
    for (double y : {-0.1, 0.3, 1.2})
      for (double z : {-0.2, -0.05, 0.0, 0.02, 0.08, 0.2}) {
        s += I(id) + R(x) + R(y) + R(z) + "\n";
        group += I(id++) + (++on_line % 10 == 0 ? "\n" : "");
      }
  s += I(999) + R(0.3) + R(0.3) + R(0.5) + "\n";
  return s + group + "\n/ADMAS/0/1\nm\n" + R(1.0) + I(1) + "\n";
}

std::size_t secondary_count(const std::string& wall) {
  test::TempDir dir;
  const auto path = dir.write("T_0000.rad", test::begin_card() + grid() + wall + "/END\n");
  const Model m = read_deck(path).model;
  return m.rigid_walls.at(0).secondary_nodes.size();
}

std::string point(double x, double y, double z) { return R(x) + R(y) + R(z) + "\n"; }

std::string wall(const std::string& type, long long node, const std::string& lines) {
  return "/RWALL/" + type + "/1\nwall\n" + I(node) + I(0) + I(0) + I(0) + "\n" + lines;
}

}  // namespace

TEST(WallSelection, DsearchSelectsAsTheReference) {
  const std::string search = R(0.1) + R(0.0) + R(0.0) + "\n", moving = R(5e5) + R(0.0) + R(0.0) + R(-10.0) + "\n";
  const std::string fixed_m = R(0.0) + R(0.0) + R(0.0) + "\n";
  // A parallelogram selects by its plane, beside its edges too: 45 (not the 9 above it).
  EXPECT_EQ(secondary_count(wall("PARAL", 0, search + fixed_m + point(1, 0, 0) + point(0, 1, 0))), 45u);
  // Moving: M on node 999, M1 and M2 points as given: the tilted plane picks 3 nodes.
  EXPECT_EQ(secondary_count(wall("PARAL", 999, search + moving + point(1, 0, 0) + point(0, 1, 0))), 3u);
  EXPECT_EQ(secondary_count(wall("PLANE", 0, search + fixed_m + point(0, 0, 1))), 45u);
  EXPECT_EQ(secondary_count(wall("PLANE", 999, search + moving + point(0.3, 0.3, 1.5))), 0u);
  const std::string round = R(0.5) + R(0.0) + R(0.6) + "\n" + R(0.5) + R(0.3) + R(0.0) + "\n";
  EXPECT_EQ(secondary_count(wall("CYL", 0, round + point(0.5, 0.3, 1.0))), 30u);
  EXPECT_EQ(secondary_count(wall("SPHER", 0, round)), 31u);
}

}  // namespace test_wall_selection
