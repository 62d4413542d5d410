// /TRANSFORM (docs/deck-format.md, "Transformations"): transformed coordinates against the reference's starter
// listing. The decks below are the ones run by the reference (OpenRadioss starter, input version 2019, /IOFLAG
// Ipri 5): `/opt/openradioss/run-or.sh TRF1/TRF1_0000.rad OUT`, then OUT/TRF1_0000.out, "NEW NODE COORDINATES" under
// each "TRANSFORMATION ID" (printed to 13 digits). The MATRIX result, which the listing does not print, was read
// through /TRANSFORM/TRA cards from its nodes to a node at the origin (their printed translation vectors).
#include <gtest/gtest.h>

#include "crumple/core/geometry.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_transforms {

using namespace crumple;
using test::I;
using test::R;

namespace {

const std::string kBlank(10, ' ');

// 13 shells, shell g on nodes 10 g + 1..4, all at the same four points, node group g = those nodes; free nodes
// 901-909; then `transforms`.
std::string transform_deck(const std::string& transforms, const std::string& extra = "") {
  const double base[4][3] = {{0.3, 0.2, 0.1}, {1.3, 0.2, 0.1}, {1.3, 1.2, 0.3}, {0.3, 1.2, 0.3}};
  const double free_nodes[9][3] = {{0.1, 0.2, 0.3}, {0.6, 0.45, -0.7}, {0, 0, 0.5}, {1, 2, 2.5}, {0.5, 0.5, 0.5},
                                   {0.2, 0, 0},     {1.2, 1, 0},       {0, 0, 0},   {0, 0, 2}};
  std::string s = test::begin_card() + "/NODE\n";
  for (int g = 1; g <= 13; ++g)
    for (int k = 0; k < 4; ++k) s += I(10 * g + 1 + k) + R(base[k][0]) + R(base[k][1]) + R(base[k][2]) + "\n";
  for (int k = 0; k < 9; ++k) s += I(901 + k) + R(free_nodes[k][0]) + R(free_nodes[k][1]) + R(free_nodes[k][2]) + "\n";
  s += "/SHELL/1\n";
  for (int g = 1; g <= 13; ++g) s += I(g) + I(10 * g + 1) + I(10 * g + 2) + I(10 * g + 3) + I(10 * g + 4) + "\n";
  s += "/PART/1\nplate\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(3) + I(0) + R(0.001) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  for (int g = 1; g <= 13; ++g)
    s += "/GRNOD/NODE/" + std::to_string(g) + "\ngroup\n" + I(10 * g + 1) + I(10 * g + 2) + I(10 * g + 3) +
         I(10 * g + 4) + "\n";
  return s + extra + transforms + "/END\n";
}

Deck read(const std::string& starter) {
  test::TempDir dir;
  dir.write("TEST_0001.rad", test::engine_cards());
  return read_deck(dir.write("TEST_0000.rad", starter));
}

std::string error_of(const std::string& starter) {
  test::TempDir dir;
  dir.write("TEST_0001.rad", test::engine_cards());
  return test::first_error(dir.write("TEST_0000.rad", starter));
}

Vec3 at(const Deck& deck, std::int64_t id) { return deck.model.nodes.position(deck.model.index.nodes.at(id)); }

void expect_at(const Deck& deck, std::int64_t id, Vec3 expected, double tolerance = 1e-12) {
  const Vec3 p = at(deck, id);
  EXPECT_NEAR(p.x, expected.x, tolerance) << "node " << id;
  EXPECT_NEAR(p.y, expected.y, tolerance) << "node " << id;
  EXPECT_NEAR(p.z, expected.z, tolerance) << "node " << id;
}

std::string points(double x, double y, double z) { return kBlank + R(x) + R(y) + R(z); }
std::string card(const std::string& type, int id, const std::string& lines) {
  return "/TRANSFORM/" + type + "/" + std::to_string(id) + "\ntitle\n" + lines + "\n";
}

}  // namespace

// TRF1: by a vector, and from node 901 (0.1 0.2 0.3) to node 902 (0.6 0.45 -0.7).
TEST(Transforms, TranslationByVectorOrNodes) {
  const Deck deck = read(transform_deck(card("TRA", 1, I(1) + R(1) + R(2) + R(3)) +
                                        card("TRA", 2, I(2) + R(0) + R(0) + R(0) + I(901) + I(902))));
  expect_at(deck, 11, {1.3, 2.2, 3.1});  // reference: 1.3 2.2 3.1
  expect_at(deck, 13, {2.3, 3.2, 3.3});
  expect_at(deck, 21, {0.8, 0.45, -0.9});  // reference: 0.8 0.45 -0.9
  expect_at(deck, 23, {1.8, 1.45, -0.7});
  expect_at(deck, 901, {0.1, 0.2, 0.3});  // not in the group
}

// TRF1: 30 degrees about (1 0 0) -> (1 1 1); -45 degrees about node 903 -> node 904 (the points, 5 5 5 and 7 8 9,
// not used).
TEST(Transforms, RotationAboutPointsOrNodes) {
  const Deck deck = read(
      transform_deck(card("ROT", 3, I(3) + R(1) + R(0) + R(0) + "\n" + points(1, 1, 1) + R(30)) +
                     card("ROT", 4, I(4) + R(5) + R(5) + R(5) + I(903) + I(904) + "\n" + points(7, 8, 9) + R(-45))));
  // The reference's listing, to its 13 digits.
  expect_at(deck, 31, {0.3584268782916, -0.05418610322607, 0.3541861032261}, 1e-12);
  expect_at(deck, 32, {1.224452282076, 0.2993672873672, 0.0006327126327960}, 1e-12);
  expect_at(deck, 33, {0.9416095696014, 1.245777448881, 0.2542225511190}, 1e-12);
  expect_at(deck, 34, {0.07558416581695, 0.8922240582877, 0.6077759417123}, 1e-12);
  expect_at(deck, 41, {0.4917203777327, -0.1007896423541, 0.3049294534877}, 1e-12);
  expect_at(deck, 42, {1.231370849898, -0.5071067811865, 0.8414213562373}, 1e-12);
  expect_at(deck, 43, {1.686599324882, 0.4033501687796, 0.9033501687796}, 1e-12);
  expect_at(deck, 44, {0.9469488527157, 0.8096673076121, 0.3668582660300}, 1e-12);
}

// TRF1: factors 2 3 0.5 about node 905 (0.5 0.5 0.5); 2 2 2 about the origin (no node); TRF2: Fscale_Y blank is 1.
TEST(Transforms, ScalingAboutNodeOrOrigin) {
  const Deck deck = read(transform_deck(card("SCA", 5, I(5) + R(2) + R(3) + R(0.5) + I(905)) +
                                        card("SCA", 6, I(6) + R(2) + R(2) + R(2)) +
                                        card("SCA", 7, I(3) + R(2) + test::blank(20) + R(3))));
  expect_at(deck, 51, {0.1, -0.4, 0.3});  // reference: 0.1 -0.4 0.3
  expect_at(deck, 53, {2.1, 2.6, 0.4});
  expect_at(deck, 61, {0.6, 0.4, 0.2});  // reference: 0.6 0.4 0.2
  expect_at(deck, 63, {2.6, 2.4, 0.6});
  expect_at(deck, 31, {0.6, 0.2, 0.3});  // reference (TRF2): 0.6 0.2 0.3
  expect_at(deck, 33, {2.6, 1.2, 0.9});
}

// TRF1: the plane through (1 2 3) normal to (1 1 2); the plane through node 906 normal to node 906 -> node 907.
TEST(Transforms, SymmetryAboutPointsOrNodes) {
  const Deck deck = read(transform_deck(card("SYM", 7, I(7) + R(1) + R(2) + R(3) + "\n" + points(2, 3, 5)) +
                                        card("SYM", 8, I(8) + R(0) + R(0) + R(0) + I(906) + I(907))));
  expect_at(deck, 71, {3.066666666667, 2.966666666667, 5.633333333333}, 1e-12);  // 9.2/3, 8.9/3, 16.9/3
  expect_at(deck, 71, {9.2 / 3, 8.9 / 3, 16.9 / 3});
  expect_at(deck, 72, {3.733333333333, 2.633333333333, 4.966666666667}, 1e-12);
  expect_at(deck, 74, {2.6, 3.5, 4.9});
  expect_at(deck, 81, {0.0, -0.1, 0.1});  // reference: 5.6e-17 -0.1 0.1
  expect_at(deck, 83, {-1.0, -1.1, 0.3});
}

// TRF2: rows (0 -1 0), (1 0 0), (0 0 1), T (0.1 0.2 0.3): x' = M x + T (node 11 at -0.1 0.5 0.4 in the reference).
TEST(Transforms, MatrixRowsAndTranslation) {
  const Deck deck = read(transform_deck(card("MATRIX", 9,
                                             I(9) + R(0) + R(-1) + R(0) + R(0.1) + "\n" + kBlank + R(1) + R(0) + R(0) +
                                                 R(0.2) + "\n" + kBlank + R(0) + R(0) + R(1) + R(0.3))));
  expect_at(deck, 91, {-0.1, 0.5, 0.4});
  expect_at(deck, 93, {-1.1, 1.5, 0.6});
}

// TRF2 and TRF3: the reference refuses a matrix that is not orthonormal ("HAVE TO BE ORTHONORMAL"): blank (0) entries,
// or a 30-degree rotation rounded to 2 digits; it accepts it rounded to 4.
TEST(Transforms, MatrixMustBeOrthonormal) {
  const auto matrix = [](double c, double s) {
    return card("MATRIX", 2,
                I(2) + R(c) + R(-s) + R(0) + R(0) + "\n" + kBlank + R(s) + R(c) + R(0) + R(0) + "\n" + kBlank + R(0) +
                    R(0) + R(1) + R(0));
  };
  EXPECT_NE(error_of(transform_deck(matrix(0.87, 0.5))).find("orthonormal"), std::string::npos);
  EXPECT_NE(error_of(transform_deck(matrix(0, 0))).find("M11..M33"), std::string::npos);
  const Deck deck = read(transform_deck(matrix(0.866, 0.5)));
  expect_at(deck, 21, {0.866 * 0.3 - 0.5 * 0.2, 0.5 * 0.3 + 0.866 * 0.2, 0.1});
}

// TRF2: the frame of points 1-3 onto that of points 4-6 (not congruent: e1 along 1 -> 2, e3 normal to the plane), and
// the same by nodes 901-906 (the points, 9 9 9, not used).
TEST(Transforms, PositionByPointsOrNodes) {
  std::string by_points = I(4) + "\n";
  for (const Vec3 p : {Vec3{0.1, 0.2, 0.3}, Vec3{1.1, 0.4, 0.2}, Vec3{0.3, 1.5, 0.1}, Vec3{2, 1, 0}, Vec3{2, 2, 0.5},
                       Vec3{1, 1.5, 0.2}})
    by_points += points(p.x, p.y, p.z) + "\n";
  std::string by_nodes = I(5) + I(901) + I(902) + I(903) + I(904) + I(905) + I(906) + "\n";
  for (int k = 0; k < 6; ++k) by_nodes += points(9, 9, 9) + "\n";
  by_points.pop_back(), by_nodes.pop_back();
  const Deck deck = read(transform_deck(card("POSITION", 4, by_points) + card("POSITION", 5, by_nodes)));
  expect_at(deck, 41, {2.024697083237, 1.273634213939, -0.06718906935951}, 1e-12);
  expect_at(deck, 42, {2.227843688005, 2.110867299635, 0.4405236616082}, 1e-12);
  expect_at(deck, 43, {1.267873496171, 2.135620977310, 0.7838085086834}, 1e-12);
  expect_at(deck, 44, {1.064726891403, 1.298387891614, 0.2760957777157}, 1e-12);
  expect_at(deck, 51, {0.9473669903643, 1.760570308740, 2.358921336695}, 1e-12);
  expect_at(deck, 52, {1.252482408297, 0.8115488823836, 2.438059911715}, 1e-12);
  expect_at(deck, 53, {2.130312495827, 1.055574158042, 1.979948569062}, 1e-12);
  expect_at(deck, 54, {1.825197077894, 2.004595584399, 1.900809994042}, 1e-12);
}

// TRF1: in deck order, not id order (SCA 40 then TRA 30: 2 x + (1 0 0)), and a later transformation takes its nodes
// where the earlier ones left them (TRA 20 moves node 908 to (1 0 0); TRA 10 from node 908 to node 909 (0 0 2) is
// then (-1 0 2)).
TEST(Transforms, DeckOrderAndMovedNodes) {
  const std::string extra =
      "/GRNOD/NODE/14\ngroup 10 and node 908\n" + I(101) + I(102) + I(103) + I(104) + I(908) + "\n";
  const Deck deck = read(transform_deck(
      card("TRA", 20, I(14) + R(1) + R(0) + R(0)) + card("TRA", 10, I(10) + R(0) + R(0) + R(0) + I(908) + I(909)) +
          card("SCA", 40, I(11) + R(2) + R(2) + R(2)) + card("TRA", 30, I(11) + R(1) + R(0) + R(0)),
      extra));
  expect_at(deck, 908, {1, 0, 0});
  expect_at(deck, 101, {0.3, 0.2, 2.1});  // reference: 0.3 0.2 2.1
  expect_at(deck, 103, {1.3, 1.2, 2.3});
  expect_at(deck, 111, {1.6, 0.4, 0.2});  // reference: 1.6 0.4 0.2
  expect_at(deck, 113, {3.6, 2.4, 0.6});
}

// TRF1, TRF2: box groups hold the nodes and elements inside the box at the deck's positions, before any
// transformation (the reference's /GRNOD/BOX held all 52 shell nodes and node 907, its /GRSHEL/BOX all 13 shells,
// although transformations moved most of them out of the box).
TEST(Transforms, BoxGroupsUseTheDeckPositions) {
  const std::string box = "/BOX/RECTA/1\nbox\n\n" + R(0.2) + R(0.1) + R(0.0) + "\n" + R(1.4) + R(1.3) + R(0.4) +
                          "\n/GRNOD/BOX/600\nbox\n" + I(1) + "\n/GRSHEL/BOX/700\nbox\n" + I(1) + "\n";
  const Deck deck = read(transform_deck(card("TRA", 1, I(1) + R(1) + R(2) + R(3)), box));
  const Model& m = deck.model;
  EXPECT_EQ(m.node_groups[m.index.node_groups.at(600)].nodes.size(), 53u);
  EXPECT_EQ(m.shell_groups[m.index.shell_groups.at(700)].elements.size(), 13u);
  expect_at(deck, 11, {1.3, 2.2, 3.1});
}

// A transformation of a box group moves the nodes the box held at the deck's positions.
TEST(Transforms, TransformOfABoxGroup) {
  const std::string box = "/BOX/RECTA/1\nbox\n\n" + R(0.2) + R(0.1) + R(0.0) + "\n" + R(1.4) + R(1.3) + R(0.4) +
                          "\n/GRNOD/BOX/600\nbox\n" + I(1) + "\n";
  const Deck deck = read(transform_deck(card("TRA", 1, I(600) + R(0) + R(0) + R(10)), box));
  expect_at(deck, 11, {0.3, 0.2, 10.1});
  expect_at(deck, 907, {1.2, 1, 10});
  expect_at(deck, 905, {0.5, 0.5, 0.5});
}

TEST(Transforms, RefusedForms) {
  const auto error = [](const std::string& transforms) { return error_of(transform_deck(transforms)); };
  EXPECT_NE(error(card("TRA", 1, I(1) + R(1) + R(0) + R(0) + I(0) + I(0) + I(5))).find("sub_ID"), std::string::npos);
  EXPECT_NE(error(card("TRA", 1, I(1) + R(0) + R(0) + R(0) + I(901))).find("node_ID2"), std::string::npos);
  EXPECT_NE(error(card("TRA", 1, I(0) + R(1))).find("grnd_ID"), std::string::npos);
  EXPECT_NE(error(card("TRA", 1, I(99) + R(1))).find("node group 99 not defined"), std::string::npos);
  EXPECT_NE(error(card("SCA", 1, I(1) + R(-2))).find("Fscale_X"), std::string::npos);
  EXPECT_NE(error(card("ROT", 1, I(1) + R(1) + R(1) + R(1) + "\n" + points(1, 1, 1) + R(30))).find("an axis"),
            std::string::npos);
  EXPECT_NE(error(card("SYM", 1, I(1) + R(0) + R(0) + R(0) + I(901) + I(901))).find("node_ID2"), std::string::npos);
  EXPECT_NE(error(card("POSITION", 1, I(1) + I(901) + I(902))).find("node_ID1..node_ID6"), std::string::npos);
  EXPECT_NE(error(card("RIGID", 1, I(1))).find("TRA, ROT, SCA"), std::string::npos);
  const std::string error_text = error(card("TRA", 1, I(1) + R(1) + R(0) + R(0) + I(0) + I(0) + I(5)));
  EXPECT_NE(error_text.find("/TRANSFORM/TRA/1"), std::string::npos) << error_text;
  EXPECT_NE(error_text.find("TEST_0000.rad"), std::string::npos) << error_text;
}

// POSITION is read from input version 2017 on (the reference read it in a 2019 deck), MATRIX from 100, the others
// from 90.
TEST(Transforms, InputVersions) {
  const auto with_version = [](int version, const std::string& transforms) {
    std::string deck = transform_deck(transforms);
    deck.replace(deck.find(I(2019)), 10, I(version));
    return deck;
  };
  EXPECT_NE(error_of(with_version(140, card("POSITION", 1, I(1)))).find("2017 or later"), std::string::npos);
  EXPECT_NE(error_of(with_version(90, card("MATRIX", 1, I(1)))).find("100 or later"), std::string::npos);
  EXPECT_NE(error_of(with_version(51, card("TRA", 1, I(1) + R(1)))).find("90 or later"), std::string::npos);
  const Deck old = read(with_version(90, card("TRA", 1, I(1) + R(1) + R(2) + R(3))));
  expect_at(old, 11, {1.3, 2.2, 3.1});
}

// A mirror turns bricks inside out: refused (the reference accepts it silently).
// A mirrored brick is renumbered, faces 1-4 and 5-8 swapped (the reference reads it as the same brick: a cube
// compressed after /TRANSFORM/SYM gives the listing of the cube as written, to the last digit, MBA and MBB).
TEST(Transforms, MirroredBrickRenumbered) {
  std::string s = test::begin_card() + "/NODE\n";
  const int corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < 8; ++k) s += I(k + 1) + R(corners[k][0]) + R(corners[k][1]) + R(corners[k][2]) + "\n";
  s += "/BRICK/1\n" + I(1) + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + I(7) + I(8) + "\n";
  s += "/PART/1\nblock\n" + I(1) + I(1) + "\n/PROP/SOLID/1\nsolid\n" + I(1) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  s += "/GRNOD/NODE/1\nall\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + I(7) + I(8) + "\n";
  s += card("SYM", 1, I(1) + R(2) + R(0) + R(0) + "\n" + points(3, 0, 0)) + "/END\n";
  EXPECT_EQ(error_of(s), "");
  const Deck deck = read(s);
  const std::int32_t* n = deck.model.elements[static_cast<int>(ElementKind::Brick8)].nodes_of(0);
  EXPECT_EQ(deck.model.nodes.user_id[static_cast<std::size_t>(n[0])], 5);  // 5 6 7 8 1 2 3 4
  EXPECT_EQ(deck.model.nodes.user_id[static_cast<std::size_t>(n[4])], 1);
  EXPECT_NEAR(geometry::brick_volume(deck.model.nodes.x, deck.model.nodes.y, deck.model.nodes.z, n), 1.0, 1e-12);
  bool warned = false;
  for (const auto& w : deck.report.warnings) warned = warned || w.message.find("renumbered") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace test_transforms
