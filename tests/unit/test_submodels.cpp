// //SUBMODEL ... //ENDSUB (docs/deck-format.md, "Submodels"): id offsets by kind, nested blocks, the block's units and
// the transformation of a block. Each figure was read from the reference's starter listing on the same deck (the
// OpenRadioss starter, input version 2019: `/opt/openradioss/run-or.sh SUBA/SUBA_0000.rad OUT`, OUT/SUBA_0000.out):
// the property, material and part numbers under "PROPERTY SETS" and "PARTS", the nodes of each group, its error
// numbers, and the transformed coordinates printed as "NEW NODE COORDINATES" of a probing /TRANSFORM/TRA.
#include <gtest/gtest.h>

#include "crumple/deck/fields.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_submodels {

using namespace crumple;
using test::I;
using test::R;

namespace {

// A 2 x 2 plate of 5 mm shells at height z, its part, property (thickness t), material and node group 1, all with
// ids 1 (nodes 1 to 9, shells 1 to 4).
std::string plate(double z, double t) {
  std::string s = "/NODE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) s += I(1 + i + 3 * j) + R(0.005 * i) + R(0.005 * j) + R(z) + "\n";
  s += "/SHELL/1\n";
  for (int j = 0, e = 1; j < 2; ++j)
    for (int i = 0; i < 2; ++i, ++e) {
      const int n1 = 1 + i + 3 * j;
      s += I(e) + I(n1) + I(n1 + 1) + I(n1 + 4) + I(n1 + 3) + "\n";
    }
  s += "/PART/1\nplate\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(5) + I(0) + R(t) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7850.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  s += "/GRNOD/NODE/1\nall\n";
  for (int n = 1; n <= 9; ++n) s += I(n);
  return s + "\n";
}

std::string inivel(int id, double vz) {
  return "/INIVEL/TRA/" + std::to_string(id) + "\nv\n" + R(0) + R(0) + R(vz) + I(1) + "\n";
}

std::string offsets(std::initializer_list<long long> values) {
  std::string s;
  for (long long v : values) s += I(v);
  return s + "\n";
}

// The reference's deck SUBA: a plate, then the same plate 10 mm higher in a block with off_def 1000, off_nod 100,
// off_ele 200, off_part 10, off_mat 20, off_type 30; an /INIVEL of group 1 inside the block and one outside.
std::string block_deck(const std::string& header = "//SUBMODEL/1", const std::string& inside = "",
                       const std::string& after = "") {
  return test::begin_card() + plate(0.0, 0.001) + header + "\nsub\n" + offsets({1000, 100, 200, 10, 20, 30, 0}) +
         plate(0.01, 0.002) + inivel(1, 1.0) + inside + "//ENDSUB\n" + inivel(2, -1.0) + after + "/END\n";
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

const Part& part(const Model& m, std::int64_t id) {
  for (const Part& p : m.parts)
    if (p.user_id == id) return p;
  throw std::runtime_error("no part " + std::to_string(id));
}

const InitialVelocity& velocity(const Model& m, std::int64_t id) {
  for (const InitialVelocity& v : m.initial_velocities)
    if (v.user_id == id) return v;
  throw std::runtime_error("no /INIVEL " + std::to_string(id));
}

}  // namespace

// Reference (SUBA): parts 1 and 11; part 11 has property 31 and material 21; nodes 101 to 109; the /INIVEL in the
// block moves group 1001 (nodes 101-109), the one outside group 1 (nodes 1-9).
TEST(Submodels, OffsetsShiftEveryIdOfTheBlockByItsKind) {
  const Deck deck = read(block_deck());
  const Model& m = deck.model;
  EXPECT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(part(m, 11).property_id, 31);
  EXPECT_EQ(part(m, 11).material_id, 21);
  EXPECT_EQ(part(m, 1).property_id, 1);
  for (std::int64_t n = 101; n <= 109; ++n) EXPECT_EQ(m.index.nodes.count(n), 1u) << n;
  EXPECT_EQ(m.index.nodes.count(10), 0u);
  EXPECT_EQ(velocity(m, 1001).node_group_id, 1001);  // the block's /INIVEL/1 and its group 1
  EXPECT_EQ(velocity(m, 2).node_group_id, 1);
  const auto& block_group = m.node_groups[static_cast<std::size_t>(m.index.node_groups.at(1001))];
  EXPECT_EQ(block_group.nodes.size(), 9u);
  EXPECT_EQ(m.nodes.user_id[static_cast<std::size_t>(block_group.nodes.front())], 101);
}

// Reference (SUBN): a block with off_def 5000 inside SUBA's block: its property is 5031 (5000 + 30 + 1), its part
// 5011, its material 5021. Offsets of nested blocks add up, kind by kind.
TEST(Submodels, NestedBlocksAddTheirOffsets) {
  const std::string inner = "//SUBMODEL/2\ninner\n" + offsets({5000, 0, 0, 0, 0, 0, 0}) + plate(0.02, 0.003) +
                            "//ENDSUB\n";
  const Deck deck = read(block_deck("//SUBMODEL/1", inner));
  const Model& m = deck.model;
  EXPECT_EQ(part(m, 5011).property_id, 5031);
  EXPECT_EQ(part(m, 5011).material_id, 5021);
  EXPECT_EQ(m.index.nodes.count(5109), 1u);  // 9 + 100 + 5000
  EXPECT_EQ(m.index.node_groups.count(6001), 1u);
}

// Reference (SUBU): a /MAT/ELAST/1/2 inside the block names unit 1002 (ERROR 659 "unknown reference to local unit
// system identifier ID=1002"): a unit id is shifted by off_def like any other.
TEST(Submodels, UnitIdsInsideTheBlockAreShifted) {
  std::string deck = block_deck();
  const auto block = deck.find("//SUBMODEL/1");
  const auto material = deck.find("/MAT/ELAST/1\n", block);
  deck.replace(material, 13, "/MAT/ELAST/1/2\n");
  const std::string units = "/UNIT/2\ngram\n" + R("g") + R("mm") + R("ms") + "\n";
  deck.insert(deck.find("/NODE"), units);
  EXPECT_NE(error_of(deck).find("unit 1002 not defined"), std::string::npos) << error_of(deck);
  deck.replace(deck.find("/UNIT/2\n"), 8, "/UNIT/1002\n");
  const Deck read_back = read(deck);
  // 7850 g/mm^3 read as 7.85e9 kg/m^3: the block's material is in unit 1002.
  const Model& m = read_back.model;
  for (const Material& mat : m.materials)
    if (mat.user_id == 21) {
      EXPECT_NEAR(mat.density, 7850.0 * 1e-3 / 1e-9, 1.0);
    }
}

// The header's unit_ID: every card of the block reads its values in it.
TEST(Submodels, TheBlockReadsItsValuesInItsUnitSystem) {
  std::string deck = block_deck("//SUBMODEL/1/2");
  deck.insert(deck.find("/NODE"), "/UNIT/2\nmm\n" + R("") + R("mm") + R("") + "\n");
  const Model m = read(deck).model;
  EXPECT_NEAR(m.nodes.position(m.index.nodes.at(109)).z, 0.01e-3, 1e-15);  // 0.01 read in mm
  EXPECT_NEAR(m.nodes.position(m.index.nodes.at(9)).z, 0.0, 1e-15);
}

// Reference (SUBX): /TRANSFORM/ROT of block 1, 30 degrees about the X axis through the origin: node 109 (0.01 0.01
// 0.01) goes to (10, 3.660254037844, 13.66025403784) mm; the nodes outside the block stay.
TEST(Submodels, ATransformationMovesTheNodesOfItsBlock) {
  const std::string rotation = "/TRANSFORM/ROT/1\nturn\n" + I(0) + R(0) + R(0) + R(0) + I(0) + I(0) + I(1) + "\n" +
                               test::blank(10) + R(1) + R(0) + R(0) + R(30) + "\n";
  std::string deck = block_deck("//SUBMODEL/1", "", rotation);
  deck.erase(deck.find("/INIVEL/TRA/1\n"), inivel(1, 1.0).size());  // a velocity would have to turn too
  const Model m = read(deck).model;
  const Vec3 p = m.nodes.position(m.index.nodes.at(109));
  EXPECT_NEAR(p.x, 0.01, 1e-15);
  EXPECT_NEAR(p.y, 3.660254037844e-3, 1e-15);
  EXPECT_NEAR(p.z, 13.66025403784e-3, 1e-14);
  EXPECT_NEAR(m.nodes.position(m.index.nodes.at(9)).z, 0.0, 1e-15);
}

// Reference (SUBV): the same rotation, 90 degrees, turns the block's /INIVEL (+Z became -Y). Crumple moves only the
// nodes, so it refuses the card rather than leave the velocity unturned.
TEST(Submodels, ATransformedBlockWithADirectionIsRefused) {
  const std::string rotation = "/TRANSFORM/ROT/1\nturn\n" + I(0) + R(0) + R(0) + R(0) + I(0) + I(0) + I(1) + "\n" +
                               test::blank(10) + R(1) + R(0) + R(0) + R(90) + "\n";
  const std::string e = error_of(block_deck("//SUBMODEL/1", "", rotation));
  EXPECT_NE(e.find("sub_ID"), std::string::npos) << e;
  EXPECT_NE(e.find("/INIVEL/TRA in block 1"), std::string::npos) << e;
  // A translation keeps directions: accepted.
  const std::string translation = "/TRANSFORM/TRA/1\nmove\n" + I(0) + R(1) + R(2) + R(3) + I(0) + I(0) + I(1) + "\n";
  const Model m = read(block_deck("//SUBMODEL/1", "", translation)).model;
  EXPECT_NEAR(m.nodes.position(m.index.nodes.at(101)).x, 1.0, 1e-15);
  EXPECT_NEAR(m.nodes.position(m.index.nodes.at(1)).x, 0.0, 1e-15);
}

// Reference (SUBB): ERROR 914 "not possible to use node group transformation & submodel transformation in the same
// /TRANSFORM option".
TEST(Submodels, AGroupAndABlockInOneTransformationAreAnError) {
  const std::string both = "/TRANSFORM/TRA/1\nmove\n" + I(1) + R(1) + R(2) + R(3) + I(0) + I(0) + I(1) + "\n";
  EXPECT_NE(error_of(block_deck("//SUBMODEL/1", "", both)).find("one of them"), std::string::npos);
  const std::string missing = "/TRANSFORM/TRA/1\nmove\n" + I(0) + R(1) + R(2) + R(3) + I(0) + I(0) + I(7) + "\n";
  EXPECT_NE(error_of(block_deck("//SUBMODEL/1", "", missing)).find("//SUBMODEL block"), std::string::npos);
}

TEST(Submodels, BrokenBlocksAreErrors) {
  const std::string open = test::begin_card() + "//SUBMODEL/1\nsub\n" + offsets({0}) + plate(0.0, 0.001) + "/END\n";
  EXPECT_NE(error_of(open).find("no //ENDSUB"), std::string::npos) << error_of(open);
  const std::string close = test::begin_card() + plate(0.0, 0.001) + "//ENDSUB\n/END\n";
  EXPECT_NE(error_of(close).find("no open //SUBMODEL"), std::string::npos) << error_of(close);
  EXPECT_NE(error_of(block_deck("//SUBMODEL/1/0/V100")).find("Vers_number"), std::string::npos);
  EXPECT_EQ(error_of(block_deck("//SUBMODEL/1/0/V2019")), "");
  std::string negative = block_deck();
  negative.replace(negative.find(I(1000) + I(100)), 20, I(-5) + I(100));
  EXPECT_NE(error_of(negative).find("off_def"), std::string::npos);
  std::string unit_inside = block_deck("//SUBMODEL/1", "/UNIT/9\nu\n" + R("g") + "\n");
  EXPECT_NE(error_of(unit_inside).find("a /UNIT inside a //SUBMODEL block"), std::string::npos);
}

// The safety net: inside a block, a field whose name says it holds an id and that a reader takes with integer() (not
// id(), which shifts it) is an error when given, so that no id is read unshifted; blank stays none.
TEST(Submodels, AnIdReadWithoutItsOffsetIsRefused) {
  SourceText text;
  text.files = {"TEST_0000.rad"};
  text.lines = {{"/CARD/1", 0, 1}, {"         7         7         0", 0, 2}};
  const std::vector<Card> cards = split_cards(text, -1);
  const UnitSystem units{};
  CardReader reader(cards.front(), text, units);
  IdOffsets block;
  block.by_kind[static_cast<std::size_t>(IdKind::Other)] = 1000;
  block.by_kind[static_cast<std::size_t>(IdKind::Node)] = 100;
  reader.set_id_offsets(&block);
  const Line line = reader.next("fields");
  EXPECT_EQ(line.id(1, 10, "grnod_ID", IdKind::Other), 1007);
  EXPECT_EQ(line.id(11, 10, "node_ID", IdKind::Node), 107);
  EXPECT_EQ(line.id(21, 10, "node_ID", IdKind::Node), 0);  // none stays none
  EXPECT_EQ(line.integer(11, 10, "Isolid"), 7);           // a flag, not an id
  EXPECT_THROW(line.integer(11, 10, "sens_ID"), DeckError);
  EXPECT_THROW(line.integer(11, 10, "RBID"), DeckError);
  EXPECT_EQ(line.integer(21, 10, "sens_ID"), 0);
  reader.set_id_offsets(nullptr);
  EXPECT_EQ(line.integer(11, 10, "sens_ID"), 7);  // outside a block
}

}  // namespace test_submodels
