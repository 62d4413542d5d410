// Boxes and box groups (docs/deck-format.md, "Boxes"): the members of every box group of
// tests/regression/decks/box_groups/BOXG_0000.rad against the reference's starter listing for that deck (Ipri 5:
// `/opt/openradioss/run-or.sh .../BOXG_0000.rad OUT`, OUT/BOXG_0000.out, "NODE GROUP:", "SHEL. GROUP:"...), and the
// cards Crumple refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_box_groups {

using namespace crumple;
using test::I;
using test::R;

namespace {

using Ids = std::vector<std::int64_t>;

const Deck& box_deck() {
  static const Deck deck = read_deck(std::filesystem::path(CRUMPLE_TEST_DECKS) / "box_groups" / "BOXG_0000.rad");
  return deck;
}

template <class Members>
Ids user_ids(const Members& members, const std::vector<std::int64_t>& ids) {
  Ids out;
  for (auto k : members) out.push_back(ids[static_cast<std::size_t>(k)]);
  std::sort(out.begin(), out.end());
  return out;
}

Ids node_group(std::int64_t id) {
  const Model& m = box_deck().model;
  for (const NodeGroup& g : m.node_groups)
    if (g.user_id == id) return user_ids(g.nodes, m.nodes.user_id);
  ADD_FAILURE() << "no node group " << id;
  return {};
}

Ids element_group(const std::vector<ElementSet>& groups, std::int64_t id) {
  const Model& m = box_deck().model;
  for (const ElementSet& g : groups)
    if (g.user_id == id) return user_ids(g.elements, m.elements[static_cast<int>(g.kind)].user_id);
  ADD_FAILURE() << "no element group " << id;
  return {};
}

// A deck of the 2 x 1 plate (nodes 1-6 at x 0, 0.01, 0.02 and y 0, 0.01) with `extra` cards; its first error.
std::string error_of(const std::string& extra) {
  test::TempDir dir;
  return test::first_error(test::write_deck(dir, extra));
}

std::string warnings_of(const std::string& extra) {
  test::TempDir dir;
  std::string all;
  for (const auto& w : read_deck(test::write_deck(dir, extra)).report.warnings) all += w.text() + "\n";
  return all;
}

std::string point(double x, double y, double z) { return R(x) + R(y) + R(z) + "\n"; }
std::string recta(const std::string& ids, const std::string& p1, const std::string& p2) {
  return "/BOX/RECTA/1\nbox\n" + ids + "\n" + p1 + p2;
}

}  // namespace

// Plate nodes 1-25 (x = 0.01 i, y = 0.01 j, node 1 + i + 5 j), box groups 101-122 of boxes 1-22.
TEST(BoxGroups, NodeGroupsHoldWhatTheReferenceListed) {
  const std::map<std::int64_t, Ids> reference = {
      {101, {2, 3, 7, 8}},                               // RECTA cutting shells: 4 nodes
      {102, {7, 8, 9, 12, 13, 14}},                      // faces through nodes, flat in z: surface nodes inside
      {103, {2, 3, 7, 8}},                               // corners swapped: the same box
      {104, {7, 8, 9, 12, 13, 14, 17, 18, 19}},          // corners at nodes 7 and 19, coordinates not used
      {105, {1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13,
             14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25}},  // corners at nodes 1 and 25
      {106, {3, 7, 8, 9, 11, 12, 13, 14, 15, 17, 18, 19, 23}},  // skew 1 (45 degrees): a diamond of 13
      {107, {8, 12, 13, 14, 18}},                        // cylinder along z, radius 0.0125 about node 13
      {108, {7, 8, 12, 13, 17, 18}},                     // cylinder along x: cut by the planes at its ends
      {109, {11, 12, 13, 14, 15}},                       // axis from node 11 to node 15: ends inside
      {110, {7, 8, 9, 12, 13, 14, 17, 18, 19}},          // sphere of diameter 0.03 about node 13
      {111, {1, 2, 3, 7}},                               // sphere about node 2 (its coordinates not used)
      {112, {7, 9, 17, 19}},                             // /BOX/BOX 4 -7
      {113, {7, 9, 17, 19}},                             // /BOX/BOX -7 4: order does not matter
      {114, {1, 2, 3, 7, 8}},                            // /BOX/BOX 1 11: union
      {115, {1, 2, 3, 7, 8, 9, 17, 19}},                 // /BOX/BOX 12 14: nested
      {116, {102, 103, 107, 108}},                       // RECTA on the 3-node shell strip
      {117, {201, 202, 203, 205, 206, 207, 209, 210, 217, 218, 219, 221, 222, 225, 233, 234, 237}},  // sphere
      {118, {202, 203, 206, 207, 210, 211, 214, 215, 218, 219, 222, 223, 226, 227, 230, 231}},       // slab
      {119, {3, 7, 8, 9, 11, 12, 13, 14, 15, 17, 18, 19, 23}},  // skew 2: skew 1 about another origin, the same
      {120, {2, 3, 7, 9, 17, 19}},                       // /BOX/BOX 1 -7 4: (1 or 4) and not 7
      {121, {3, 7, 8, 9, 11, 12, 13, 14, 15, 17, 18, 19, 23}},  // moving skew 3, at 45 degrees at the start
      {122, {1, 2, 4, 5, 6, 10, 16, 20, 21, 22, 24, 25}},       // /BOX/BOX 5 -6: the plate outside the diamond
  };
  for (const auto& [id, nodes] : reference) EXPECT_EQ(node_group(id), nodes) << "node group " << id;
}

TEST(BoxGroups, ElementGroupsTakeAllNodesForBoxAndOneForBox2) {
  const Model& m = box_deck().model;
  EXPECT_EQ(element_group(m.shell_groups, 301), (Ids{2}));                  // BOX, box 1
  EXPECT_EQ(element_group(m.shell_groups, 302), (Ids{1, 2, 3, 5, 6, 7}));   // BOX2, box 1
  EXPECT_EQ(element_group(m.shell_groups, 303), Ids{});                     // BOX, cylinder 7: empty
  EXPECT_EQ(element_group(m.shell_groups, 304), (Ids{2, 3, 5, 6, 7, 8, 9, 10, 11, 12, 14, 15}));
  EXPECT_EQ(element_group(m.shell_groups, 305), (Ids{6, 7, 10, 11}));       // BOX, box 4
  EXPECT_EQ(element_group(m.shell_groups, 306).size(), 16u);                // BOX2, box 4: every shell
  EXPECT_EQ(element_group(m.sh3n_groups, 401), (Ids{103, 104}));
  EXPECT_EQ(element_group(m.sh3n_groups, 402), (Ids{101, 102, 103, 104, 105, 106}));
  EXPECT_EQ(element_group(m.brick_groups, 501), (Ids{201}));
  EXPECT_EQ(element_group(m.brick_groups, 502),
            (Ids{201, 202, 203, 204, 205, 206, 207, 208, 210, 211, 212, 213, 214, 216, 219, 220, 222}));
  EXPECT_EQ(element_group(m.brick_groups, 503), (Ids{202, 205, 208}));
  EXPECT_EQ(element_group(m.brick_groups, 504),
            (Ids{201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218}));
}

TEST(BoxGroups, CornersAndCentresMayBeNodes) {
  const std::string p = point(0, 0, 0);
  const std::string box = recta(I(1) + I(6), p, p) + "/GRNOD/BOX/9\ng\n" + I(1) + "\n";
  test::TempDir dir;
  const Model m = read_deck(test::write_deck(dir, box)).model;
  EXPECT_EQ(m.node_groups.at(0).nodes.size(), 6u);
  // The coordinates beside a node have no effect: said so.
  EXPECT_NE(warnings_of(recta(I(1) + I(6), point(1, 1, 1), p)).find("Xp1, Yp1, Zp1 have no effect"),
            std::string::npos);
  // A sphere centred at the origin: the reference refuses it (error 752, measured), Crumple reads it and says so.
  EXPECT_NE(warnings_of("/BOX/SPHER/2\ns\n" + I(1) + test::blank(20) + R(0.025) + "\n" + p).find("origin"),
            std::string::npos);
}

TEST(BoxGroups, AmbiguousOrMeaninglessBoxesAreRefused) {
  const std::string p0 = point(0, 0, 0), p1 = point(0.01, 0.01, 0);
  // One corner by node, the other not: the reference reads both coordinate lines, the manual the node.
  EXPECT_NE(error_of(recta(I(1), p0, p1)).find("field N2 (columns 11-20)"), std::string::npos);
  EXPECT_NE(error_of(recta(I(0) + I(3), p0, p1)).find("field N1"), std::string::npos);
  EXPECT_NE(error_of(recta("", p0, p0)).find("no node and every coordinate 0"), std::string::npos);
  EXPECT_NE(error_of(recta(I(0) + I(0) + I(4), p0, p1)).find("skew 4 not defined"), std::string::npos);
  EXPECT_NE(error_of(recta(I(1) + I(99), p0, p1)).find("node 99 not defined"), std::string::npos);
  EXPECT_NE(error_of("/BOX/RECTA/1/3\nbox\n\n" + p0 + p1).find("unit_ID"), std::string::npos);
  EXPECT_NE(error_of("/BOX/ELLIPS/1\nbox\n").find("field type"), std::string::npos);
  const std::string cyl = "/BOX/CYLIN/1\nc\n" + test::blank(30);
  EXPECT_NE(error_of(cyl + R(0.0) + "\n" + p0 + p1).find("a positive diameter"), std::string::npos);
  EXPECT_NE(error_of(cyl + R(0.01) + "\n" + p1 + p1).find("both ends at one point"), std::string::npos);
  EXPECT_NE(error_of("/BOX/SPHER/1\ns\n" + test::blank(30) + R(-1.0) + "\n" + p1).find("Diameter"),
            std::string::npos);
}

TEST(BoxGroups, BoxListsAndGroupListsAreChecked) {
  const std::string box = recta("", point(0, 0, 0), point(0.01, 0.01, 0));
  EXPECT_NE(error_of(box + "/BOX/BOX/2\nb\n" + I(-1) + "\n").find("only negative box ids"), std::string::npos);
  EXPECT_NE(error_of(box + "/BOX/BOX/2\nb\n" + I(3) + "\n/BOX/BOX/3\nb\n" + I(2) + "\n").find("a cycle of /BOX/BOX"),
            std::string::npos);
  EXPECT_NE(error_of(box + "/BOX/BOX/2\nb\n" + I(1) + I(-7) + "\n").find("box 7 not defined"), std::string::npos);
  // The group cards take one box: the reference reads the first positive id of a list and skips the rest.
  EXPECT_NE(error_of(box + "/GRNOD/BOX/5\ng\n" + I(1) + I(1) + "\n").find("2 box ids"), std::string::npos);
  EXPECT_NE(error_of(box + "/GRSHEL/BOX2/5\ng\n" + I(-1) + "\n").find("a positive box id"), std::string::npos);
  EXPECT_NE(error_of(box + "/GRBRIC/BOX/5\ng\n\n").find("field box_ID"), std::string::npos);
  EXPECT_NE(error_of(box + "/GRSH3N/BOX/5\ng\n" + I(8) + "\n").find("/GRSH3N/BOX/5: field box_ID"),
            std::string::npos);
  EXPECT_NE(error_of(box + "/GRNOD/BOX/5\ng\n" + I(8) + "\n").find("box 8 not defined"), std::string::npos);
}

// /LINE/SURF and /LINE/EDGE (docs/deck-format.md, "Lines"): on the 2 x 2 plate of 4-node shells the reference's
// starter listing (LINES, input version 2019, /IOFLAG Ipri 5) prints 12 segments for /LINE/SURF (every edge once) and
// 8 for /LINE/EDGE (the free edges): 1-2, 2-3, 1-4, 3-6, 4-7, 7-8, 6-9, 8-9.
TEST(Lines, SurfaceEdgesAndFreeEdges) {
  using test::I;
  using test::R;
  test::TempDir dir;
  std::string plate = "/NODE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) plate += I(1 + i + 3 * j) + R(0.005 * i) + R(0.005 * j) + R(0.0) + "\n";
  plate += "/SHELL/1\n";
  for (int j = 0, e = 1; j < 2; ++j)
    for (int i = 0; i < 2; ++i, ++e) {
      const int n1 = 1 + i + 3 * j;
      plate += I(e) + I(n1) + I(n1 + 1) + I(n1 + 4) + I(n1 + 3) + "\n";
    }
  plate += "/PART/1\nplate\n" + I(1) + I(1) + "\n/PROP/SHELL/1\nshell\n" + I(24) + "\n" + R(0.0) + "\n" + I(5) + I(0) +
           R(0.001) + "\n/MAT/ELAST/1\nsteel\n" + R(7850.0) + "\n" + R(2.1e11) + R(0.3) + "\n/SURF/PART/5\nsurf\n" + I(1) +
           "\n";
  const std::string lines = "/LINE/SURF/7\nall edges\n" + I(5) + "\n/LINE/EDGE/8\nfree edges\n" + I(5) + "\n";
  dir.write("TEST_0001.rad", test::engine_cards());
  const Deck deck = read_deck(dir.write("TEST_0000.rad", test::begin_card() + plate + lines + "/END\n"));
  ASSERT_EQ(deck.model.lines.size(), 2u);
  EXPECT_EQ(deck.model.lines[0].segments.size(), 12u);
  std::set<std::pair<std::int64_t, std::int64_t>> free;
  for (const auto& seg : deck.model.lines[1].segments)
    free.insert(std::minmax(deck.model.nodes.user_id[static_cast<std::size_t>(seg[0])],
                            deck.model.nodes.user_id[static_cast<std::size_t>(seg[1])]));
  const std::set<std::pair<std::int64_t, std::int64_t>> expected{{1, 2}, {2, 3}, {1, 4}, {3, 6},
                                                                 {4, 7}, {7, 8}, {6, 9}, {8, 9}};
  EXPECT_EQ(free, expected);
  const std::string undefined = "/LINE/EDGE/8\nfree edges\n" + I(6) + "\n";
  const auto path = dir.write("TEST_0000.rad", test::begin_card() + plate + undefined + "/END\n");
  EXPECT_NE(test::first_error(path).find("surf_ID"), std::string::npos);
}

}  // namespace test_box_groups
