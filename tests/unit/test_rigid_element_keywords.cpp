// /RBE2 (docs/theory/rigid-bodies.md, RE-1 to RE-6): its codes and defaults as the reference reads them, and the
// errors for what Crumple does not do or for a node that another kinematic condition already drives.
#include <gtest/gtest.h>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_rigid_element_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

// Nodes 1-4 on a line (1 kg each), node 9 the main node; group 5 holds nodes 1-4, group 6 node 1.
const std::string kNodes = "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) + R(0.0) + "\n" +
                           I(3) + R(2.0) + R(0.0) + R(0.0) + "\n" + I(4) + R(3.0) + R(0.0) + R(0.0) + "\n" + I(9) +
                           R(1.5) + R(1.0) + R(0.0) + "\n/GRNOD/NODE/5\nsecondary\n" + I(1) + I(2) + I(3) + I(4) +
                           "\n/GRNOD/NODE/6\none\n" + I(1) + "\n/ADMAS/0/1\nmass\n" + R(1.0) + I(5) + "\n";

std::string rbe2(int id, int main, const std::string& trarot, int skew, int group, const std::string& iflag = "") {
  return "/RBE2/" + std::to_string(id) + "\nlink\n" + I(main) + "   " + trarot + I(skew) + I(group) + iflag + "\n";
}
std::filesystem::path starter(const test::TempDir& dir, const std::string& cards) {
  return dir.write("T_0000.rad", test::begin_card("T") + kNodes + cards + "/END\n");
}
std::string error_of(const std::string& cards) {
  test::TempDir dir;
  return test::first_error(starter(dir, cards));
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(RigidElementKeywords, ReadsTheCodesTheGroupAndIflag) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, rbe2(3, 9, "111 001", 0, 5, I(1)))).model;
  ASSERT_EQ(m.rigid_elements.size(), 1u);
  const RigidElement& e = m.rigid_elements[0];
  EXPECT_EQ(e.user_id, 3);
  EXPECT_EQ(m.nodes.user_id[static_cast<std::size_t>(e.main_node)], 9);
  EXPECT_EQ(e.rotation, (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(e.iflag, 1);
  EXPECT_EQ(e.secondary_nodes.size(), 4u);
  // Iflag 1 turns the secondary nodes with the coupled rotations only; Iflag 0 with all three (RE-1).
  EXPECT_FALSE(e.turns_about(0));
  EXPECT_TRUE(e.turns_about(2));
}

// A blank Trarot and six zeros are the same to the reference (it reads digits as integers): every dof coupled; a blank
// Iflag is 0 (its starter listing prints 111 111 and 0, measured).
TEST(RigidElementKeywords, BlankOrZeroCodesCoupleEverything) {
  for (const std::string& codes : {std::string("       "), std::string("000 000")}) {
    test::TempDir dir;
    const Model m = read_deck(starter(dir, rbe2(1, 9, codes, 0, 5))).model;
    EXPECT_EQ(m.rigid_elements[0].rotation, (std::array<bool, 3>{true, true, true})) << codes;
    EXPECT_EQ(m.rigid_elements[0].iflag, 0);
  }
}

TEST(RigidElementKeywords, MainNodeInItsOwnGroupIsLeftOut) {
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, "/GRNOD/NODE/7\nall\n" + I(1) + I(2) + I(9) + "\n" + rbe2(1, 9, "111 111", 0, 7)));
  EXPECT_EQ(d.model.rigid_elements[0].secondary_nodes.size(), 2u);
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text();
  EXPECT_TRUE(contains(all, "main node 9 is in its secondary node group 7")) << all;
}

// What Crumple does not do is an error naming the field: secondary nodes that follow some translations only, a
// skew with partial codes, an Iflag other than 0 or 1.
TEST(RigidElementKeywords, RefusesWhatCrumpleDoesNotDo) {
  const std::string partial = error_of(rbe2(1, 9, "100 000", 0, 5));
  EXPECT_TRUE(contains(partial, "/RBE2/1")) << partial;
  EXPECT_TRUE(contains(partial, "Trarot TX TY TZ")) << partial;
  const std::string skew = error_of(rbe2(1, 9, "111 001", 4, 5));
  EXPECT_TRUE(contains(skew, "skew_ID")) << skew;
  const std::string iflag = error_of(rbe2(1, 9, "111 111", 0, 5, I(2)));
  EXPECT_TRUE(contains(iflag, "Iflag")) << iflag;
}

// A secondary node that /BCS holds, or that another /RBE2 carries, would be moved by two conditions.
TEST(RigidElementKeywords, RefusesANodeThatAnotherConditionDrives) {
  const std::string bcs = error_of("/BCS/8\nheld\n   111 000" + I(0) + I(6) + "\n" + rbe2(1, 9, "111 111", 0, 5));
  EXPECT_TRUE(contains(bcs, "/RBE2/1")) << bcs;
  EXPECT_TRUE(contains(bcs, "node 1 is held by /BCS/8")) << bcs;
  const std::string two = error_of(rbe2(1, 9, "111 111", 0, 5) + "/NODE\n" + I(10) + R(0.0) + R(2.0) + R(0.0) + "\n" +
                                   rbe2(2, 10, "111 111", 0, 6));
  EXPECT_TRUE(contains(two, "/RBE2/2")) << two;
  EXPECT_TRUE(contains(two, "a secondary node of /RBE2/1")) << two;
}

// A group of nodes without mass (no element, no added mass) has nothing to carry its force: the reference's 804.
TEST(RigidElementKeywords, RefusesAGroupWithoutMass) {
  const std::string e = error_of("/NODE\n" + I(11) + R(0.0) + R(5.0) + R(0.0) + "\n" + I(12) + R(1.0) + R(5.0) + R(0.0) +
                                 "\n/GRNOD/NODE/13\nmassless\n" + I(12) + "\n" + rbe2(1, 11, "111 111", 0, 13));
  EXPECT_TRUE(contains(e, "/RBE2/1")) << e;
  EXPECT_TRUE(contains(e, "no mass")) << e;
}

// /RBE3 (RI-1 to RI-6): blank Trarot_Mi is 111 000 as the reference reads it (its manual says all six); I_modif 1
// scales each translation's weights by W / W_k, and the rotation of the same axis alike.
std::string rbe3(const std::string& ref, const std::string& sets, int count, int imodif = 0) {
  return "/RBE3/4\nspread\n" + I(9) + "   " + ref + I(count) + I(imodif) + "\n" + sets;
}
std::string rbe3_set(double weight, const std::string& codes, int group) {
  return R(weight) + "   " + codes + I(0) + I(group) + "\n";
}

TEST(InterpolationKeywords, ReadsTheSetsAndTheirDefaults) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, rbe3("       ", rbe3_set(0.0, "       ", 5), 1))).model;
  ASSERT_EQ(m.interpolation_constraints.size(), 1u);
  const InterpolationConstraint& c = m.interpolation_constraints[0];
  EXPECT_EQ(c.reference_dofs, (std::array<bool, 6>{true, true, true, true, true, true}));
  ASSERT_EQ(c.independent.size(), 4u);
  // WT 0 is 1; blank codes are 111 000; the default I_modif 1 changes nothing when every node has every translation.
  EXPECT_EQ(c.independent[0].weight, (std::array<double, 6>{1.0, 1.0, 1.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(c.i_modif, 1);
}

TEST(InterpolationKeywords, ModifiedWeightsCarryEveryTranslationAlike) {
  test::TempDir dir;
  const std::string cards = "/GRNOD/NODE/7\nrest\n" + I(2) + I(3) + I(4) + "\n" +
                            rbe3("111 111", rbe3_set(1.0, "111 111", 6) + rbe3_set(3.0, "110 000", 7), 2);
  const Model m = read_deck(starter(dir, cards)).model;
  const InterpolationConstraint& c = m.interpolation_constraints[0];
  // W = 1 + 3 x 3 = 10, W_z = 1: node 1's z weight and its rotation about z are scaled by 10.
  EXPECT_EQ(c.independent[0].weight, (std::array<double, 6>{1.0, 1.0, 10.0, 1.0, 1.0, 10.0}));
  EXPECT_EQ(c.independent[1].weight, (std::array<double, 6>{3.0, 3.0, 0.0, 0.0, 0.0, 0.0}));
  test::TempDir as_given;
  const Model g = read_deck(starter(as_given, "/GRNOD/NODE/7\nrest\n" + I(2) + I(3) + I(4) + "\n" +
                                                  rbe3("111 111", rbe3_set(1.0, "111 111", 6) + rbe3_set(3.0, "110 000", 7), 2, 2)))
                      .model;
  EXPECT_EQ(g.interpolation_constraints[0].independent[0].weight, (std::array<double, 6>{1.0, 1.0, 1.0, 1.0, 1.0, 1.0}));
}

TEST(InterpolationKeywords, RefusesWhatCrumpleDoesNotDo) {
  // A dependent node with an element: the reference's penalty formulation.
  const std::string spring = error_of(rbe3("       ", rbe3_set(1.0, "111 000", 5), 1) + "/NODE\n" + I(11) + R(5.0) +
                                      R(0.0) + R(0.0) + "\n/TRUSS/2\n" + I(1) + I(9) + I(11) + "\n/PART/2\nbar\n" +
                                      I(3) + I(4) + "\n/PROP/TRUSS/3\nbar\n" + R(1e-4) + "\n/MAT/LAW1/4\nsteel\n" +
                                      R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n");
  EXPECT_TRUE(contains(spring, "/RBE3/4")) << spring;
  EXPECT_TRUE(contains(spring, "Node_IDr")) << spring;
  // A node in two sets (the reference's error 705 where the weights differ).
  const std::string twice = error_of(rbe3("       ", rbe3_set(1.0, "111 000", 5) + rbe3_set(2.0, "111 000", 6), 2));
  EXPECT_TRUE(contains(twice, "node 1 is in two sets")) << twice;
  // Partial codes in a skew.
  const std::string skew = error_of(rbe3("       ", R(1.0) + "   110 000" + I(3) + I(5) + "\n", 1));
  EXPECT_TRUE(contains(skew, "skew_IDi")) << skew;
}

}  // namespace test_rigid_element_keywords
