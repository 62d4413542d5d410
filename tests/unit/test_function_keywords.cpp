// /FUNCT and /MOVE_FUNCT reading (docs/deck-format.md, "Functions").
#include <gtest/gtest.h>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_function_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

std::string with_function(const std::string& extra) {
  return "/FUNCT/2\nf\n" + R(-4.0) + R(1.0) + "\n" + R(-3.8) + R(2.0) + "\n" + extra;
}

std::string move_card(const std::string& id, const std::string& line) {
  return "/MOVE_FUNCT/" + id + "\nmove\n" + line + "\n";
}

}  // namespace

TEST(FunctionKeywords, MoveFunctScalesFirstThenShifts) {
  test::TempDir dir;
  const Deck deck = read_deck(test::write_deck(dir, with_function(move_card("2", R(2) + R(3) + R(8) + R(-3)))));
  const Function& f = deck.model.functions.front();
  EXPECT_DOUBLE_EQ(f.x[0], 0.0);
  EXPECT_NEAR(f.x[1], 0.4, 1e-15);
  EXPECT_DOUBLE_EQ(f.y[0], 0.0);
  EXPECT_DOUBLE_EQ(f.y[1], 3.0);
  EXPECT_NEAR(f(0.6), 4.5, 1e-12);  // beyond the last point: along the last segment
  EXPECT_NEAR(f(-0.2), -1.5, 1e-12);
  // Two cards act in deck order; blank scales are 1.
  const Deck twice = read_deck(test::write_deck(
      dir, with_function(move_card("2", R(0) + R(0) + R(4)) + move_card("2", R(2) + R(0) + R(0) + R(1)))));
  EXPECT_NEAR(twice.model.functions.front().x[0], 0.0, 1e-15);  // (-4 + 4) * 2
  EXPECT_NEAR(twice.model.functions.front().y[1], 3.0, 1e-15);  // 2 + 1
}

TEST(FunctionKeywords, MoveFunctErrorsNameTheField) {
  test::TempDir dir;
  EXPECT_NE(test::first_error(test::write_deck(dir, with_function(move_card("9", R(2))))).find("fct_ID"),
            std::string::npos);
  EXPECT_NE(test::first_error(test::write_deck(dir, with_function(move_card("2", R(-2))))).find("Ascale_x"),
            std::string::npos);
}

// /IMPDISP/FGEO: the nodes' displacements to their final positions; springs (part_ID) and a node another condition
// drives are errors that name the field.
TEST(FunctionKeywords, FinalGeometryReadsEachNodesTarget) {
  test::TempDir dir;
  const auto card = [](long long part, long long node) {
    return "/FUNCT/1\nramp\n" + R(0.0) + R(0.0) + "\n" + R(1.0) + R(1.0) + "\n/IMPDISP/FGEO/10\nfgeo\n" + I(1) +
           I(part) + I(0) + I(0) + "\n" + R(0.0) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(node) + R(0.03) + R(0.0) +
           R(0.0) + "\n";
  };
  const Deck deck = read_deck(test::write_deck(dir, card(0, 3)));
  ASSERT_EQ(deck.model.final_geometries.size(), 1u);
  const FinalGeometry& g = deck.model.final_geometries.front();
  EXPECT_NEAR(g.displacements.front().x, 0.01, 1e-15);  // node 3 at x = 0.02
  EXPECT_EQ(g.t_stop, 1e30);
  EXPECT_NE(test::first_error(test::write_deck(dir, card(7, 3))).find("part_ID"), std::string::npos);
  EXPECT_NE(test::first_error(test::write_deck(dir, card(0, 99))).find("node_ID"), std::string::npos);
  const std::string body = "/RBODY/1\nbody\n" + I(1) + I(0) + I(0) + I(0) + R(0.0) + I(2) + I(0) + I(0) + I(0) +
                           "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + I(0) + I(0) +
                           "\n/GRNOD/NODE/2\nb\n" + I(2) + I(3) + "\n";
  EXPECT_NE(test::first_error(test::write_deck(dir, card(0, 3) + body)).find("rigid body"), std::string::npos)
      << test::first_error(test::write_deck(dir, card(0, 3) + body));
}

}  // namespace test_function_keywords
