// /RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER, /RWALL/PARAL and /RBODY: values, defaults, units, secondary node sets
// and errors. The decks have no engine file, so these tests do not depend on the engine keywords.
#include <gtest/gtest.h>

#include <cmath>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_rigid_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

std::string gram_mm_ms_begin() {
  return "/BEGIN\nTEST\n      2019         0\n" + R("g") + R("mm") + R("ms") + "\n" + R("kg") + R("m") + R("s") + "\n";
}

// The plate (nodes 1-6 at z = 0, x in {0, 0.01, 0.02}, y in {0, 0.01}), a free node 7 at (0.05, 0, 0.1),
// groups: 10 = all plate nodes, 11 = {1, 2}, 12 = {2}, 13 = {7}, 14 = {3, 6}.
std::string references() {
  return "/NODE\n" + I(7) + R(0.05) + R(0.0) + R(0.1) + "\n" + "/GRNOD/NODE/10\nall\n" + I(1) + I(2) + I(3) + I(4) +
         I(5) + I(6) + "\n" + "/GRNOD/NODE/11\ntwo\n" + I(1) + I(2) + "\n" + "/GRNOD/NODE/12\none\n" + I(2) + "\n" +
         "/GRNOD/NODE/13\nfree\n" + I(7) + "\n" + "/GRNOD/NODE/14\nedge\n" + I(3) + I(6) + "\n";
}

std::filesystem::path starter(const test::TempDir& dir, const std::string& extra,
                              const std::string& begin = test::begin_card()) {
  return dir.write("T_0000.rad", begin + test::plate_cards() + references() + extra + "/END\n");
}

Model read(const test::TempDir& dir, const std::string& extra, const std::string& begin = test::begin_card()) {
  return read_deck(starter(dir, extra, begin)).model;
}

std::string error_of(const test::TempDir& dir, const std::string& extra) {
  return test::first_error(starter(dir, extra));
}

std::string warnings_of(const test::TempDir& dir, const std::string& extra) {
  std::string all;
  for (const auto& w : read_deck(starter(dir, extra)).report.warnings) all += w.text() + "\n";
  return all;
}

std::string vec(double x, double y, double z) { return R(x) + R(y) + R(z) + "\n"; }

struct Wall {
  std::string type = "PLANE";
  long long id = 1;
  long long node = 0, slide = 0, group1 = 10, group2 = 0;
  std::string contact = vec(0, 0, 0);  // D_search, fric, Diameter (ffac, ifq appended by the test when needed)
  std::string origin = vec(0, 0, 0);   // XM YM ZM, or Mass VX0 VY0 VZ0 for a moving wall
  std::string m1 = vec(0, 0, 1);
  std::string m2 = vec(0, 1, 0);

  std::string card() const {
    std::string s = "/RWALL/" + type + "/" + std::to_string(id) + "\nwall\n" + I(node) + I(slide) + I(group1) +
                    I(group2) + "\n" + contact + origin;
    if (type != "SPHER") s += m1;
    if (type == "PARAL") s += m2;
    return s;
  }
};

std::vector<std::int64_t> user_ids(const Model& m, const std::vector<std::int32_t>& nodes) {
  std::vector<std::int64_t> ids;
  for (std::int32_t n : nodes) ids.push_back(m.nodes.user_id[static_cast<std::size_t>(n)]);
  return ids;
}

struct Body {
  long long id = 7, main = 7, ispher = 0, group = 14, ikrem = 0, icog = 0, sensor = 0;
  std::string mass = R(3.0);
  std::string diagonal = vec(0, 0, 0);
  std::string products = vec(0, 0, 0);
  std::string options = I(0) + I(0) + "\n";

  std::string card() const {
    return "/RBODY/" + std::to_string(id) + "\nbody\n" + I(main) + I(sensor) + I(0) + I(ispher) + mass + I(group) +
           I(ikrem) + I(icog) + I(0) + "\n" + diagonal + products + options;
  }
};

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// /RWALL

TEST(RigidKeywords, FixedPlaneWall) {
  test::TempDir dir;
  Wall w;
  w.group2 = 12;
  w.origin = vec(0, 0, -1);
  w.m1 = vec(0, 0, 1);
  const Model m = read(dir, w.card());
  ASSERT_EQ(m.rigid_walls.size(), 1u);
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(wall.user_id, 1);
  EXPECT_EQ(wall.title, "wall");
  EXPECT_EQ(wall.shape, RigidWallShape::Plane);
  EXPECT_EQ(wall.slide, WallSliding::Sliding);
  EXPECT_EQ(wall.node, -1);
  EXPECT_EQ(wall.point, (Vec3{0, 0, -1}));
  EXPECT_EQ(wall.point1, (Vec3{0, 0, 1}));  // a point, not a vector
  EXPECT_EQ(wall.direction, (Vec3{0, 0, 1}));
  EXPECT_EQ(wall.filter_flag, 0);
  // Group 10 minus group 12.
  EXPECT_EQ(user_ids(m, wall.secondary_nodes), (std::vector<std::int64_t>{1, 3, 4, 5, 6}));
  EXPECT_EQ(m.index.rigid_walls.at(1), 0);
}

TEST(RigidKeywords, SearchDistanceFindsNodesOnTheOuterSide) {
  test::TempDir dir;
  Wall w;
  w.group1 = 0;
  w.contact = R(0.006) + R(0.0) + R(0.0) + "\n";
  w.origin = vec(0.015, 0, 0);  // plane x = 0.015, normal -x: nodes at x = 0 and 0.01 are in front
  w.m1 = vec(0.0, 0, 0);
  const Model m = read(dir, w.card());
  EXPECT_EQ(m.rigid_walls[0].direction, (Vec3{-1, 0, 0}));
  EXPECT_EQ(user_ids(m, m.rigid_walls[0].secondary_nodes), (std::vector<std::int64_t>{2, 5}));
}

TEST(RigidKeywords, WallUnitsAndFriction) {
  test::TempDir dir;
  Wall w;
  w.slide = 2;
  w.contact = R(2.0) + R(0.1) + R(0.0) + R(0.5) + I(3) + "\n";  // ffac a frequency (ifq 3)
  w.origin = vec(1, 2, 3);
  w.m1 = vec(1, 2, 4);
  const Model m = read(dir, w.card(), gram_mm_ms_begin());
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(wall.slide, WallSliding::Friction);
  EXPECT_DOUBLE_EQ(wall.search_distance, 2e-3);
  EXPECT_DOUBLE_EQ(wall.friction, 0.1);
  EXPECT_EQ(wall.filter_flag, 3);
  EXPECT_DOUBLE_EQ(wall.filter_factor, 500.0);  // 0.5 / ms
  EXPECT_DOUBLE_EQ(wall.point[2], 3e-3);
  EXPECT_DOUBLE_EQ(wall.point1[2], 4e-3);
}

TEST(RigidKeywords, FilterOffWhenFactorIsZero) {
  test::TempDir dir;
  Wall w;
  w.slide = 2;
  w.contact = R(0.0) + R(0.1) + R(0.0) + R(0.0) + I(2) + "\n";
  EXPECT_EQ(read(dir, w.card()).rigid_walls[0].filter_flag, 0);
}

TEST(RigidKeywords, ZeroNormalIsAnError) {
  test::TempDir dir;
  Wall w;
  w.origin = vec(1, 1, 0);
  w.m1 = vec(1, 1, 0);
  const std::string e = error_of(dir, w.card());
  EXPECT_NE(e.find("X_M1"), std::string::npos) << e;
  EXPECT_NE(e.find("distinct from M"), std::string::npos) << e;
}

TEST(RigidKeywords, WallFieldErrors) {
  test::TempDir dir;
  Wall slide;
  slide.slide = 3;
  EXPECT_NE(error_of(dir, slide.card()).find("Slide"), std::string::npos);
  Wall ifq;
  ifq.contact = R(0.0) + R(0.0) + R(0.0) + R(0.5) + I(4) + "\n";
  EXPECT_NE(error_of(dir, ifq.card()).find("ifq"), std::string::npos);
  Wall alpha;
  alpha.contact = R(0.0) + R(0.0) + R(0.0) + R(1.5) + I(1) + "\n";
  EXPECT_NE(error_of(dir, alpha.card()).find("ffac"), std::string::npos);
  Wall search;
  search.contact = R(-1.0) + "\n";
  EXPECT_NE(error_of(dir, search.card()).find("D_search"), std::string::npos);
  Wall group;
  group.group1 = 99;
  EXPECT_NE(error_of(dir, group.card()).find("node group 99 not defined"), std::string::npos);
  Wall type;
  type.type = "LAGMUL";
  const std::string e = error_of(dir, type.card());
  EXPECT_NE(e.find("PLANE, CYL, SPHER or PARAL"), std::string::npos) << e;
  Wall truncated;
  truncated.m1 = "";
  EXPECT_NE(error_of(dir, truncated.card()).find("truncated"), std::string::npos);
}

TEST(RigidKeywords, CylinderWall) {
  test::TempDir dir;
  Wall w;
  w.type = "CYL";
  w.group1 = 0;
  // Axis along y through (0, 0, 0.01), diameter 0.01: plate nodes at x = 0 are 0.005 outside, x = 0.01 at 0.0091.
  w.contact = R(0.006) + R(0.0) + R(0.01) + "\n";
  w.origin = vec(0, 0, 0.01);
  w.m1 = vec(0, 1, 0.01);
  const Model m = read(dir, w.card());
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(wall.shape, RigidWallShape::Cylinder);
  EXPECT_DOUBLE_EQ(wall.diameter, 0.01);
  EXPECT_EQ(wall.direction, (Vec3{0, 1, 0}));
  EXPECT_EQ(user_ids(m, wall.secondary_nodes), (std::vector<std::int64_t>{1, 4}));
}

TEST(RigidKeywords, CylinderAndSphereNeedADiameter) {
  test::TempDir dir;
  for (const char* type : {"CYL", "SPHER"}) {
    Wall w;
    w.type = type;
    const std::string e = error_of(dir, w.card());
    EXPECT_NE(e.find("Diameter"), std::string::npos) << e;
    EXPECT_NE(e.find("a positive diameter"), std::string::npos) << e;
  }
}

TEST(RigidKeywords, SphereWallHasNoM1Line) {
  test::TempDir dir;
  Wall w;
  w.type = "SPHER";
  w.group1 = 11;
  w.contact = R(0.0) + R(0.0) + R(4.0) + "\n";
  w.origin = vec(0, 0, 5);
  const Model m = read(dir, w.card(), gram_mm_ms_begin());
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(wall.shape, RigidWallShape::Sphere);
  EXPECT_DOUBLE_EQ(wall.diameter, 4e-3);
  EXPECT_DOUBLE_EQ(wall.point[2], 5e-3);
  EXPECT_EQ(wall.secondary_nodes.size(), 2u);
  // An M1 line would be one line too many.
  EXPECT_NE(error_of(dir, w.card() + vec(0, 0, 1)).find("no more data lines"), std::string::npos);
}

TEST(RigidKeywords, ParallelogramWall) {
  test::TempDir dir;
  Wall w;
  w.type = "PARAL";
  w.group1 = 0;
  // Corner (0.005, -1, -0.001), edges along x (0.01) and y (2): covers x in [0.005, 0.015], plate nodes 2 and 5.
  // D_search selects by the plane, beside the edges too, as the reference (RW-0): every plate node is 1 mm above.
  w.contact = R(0.002) + "\n";
  w.origin = vec(0.005, -1, -0.001);
  w.m1 = vec(0.015, -1, -0.001);
  w.m2 = vec(0.005, 1, -0.001);
  const Model m = read(dir, w.card());
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(wall.shape, RigidWallShape::Parallelogram);
  EXPECT_EQ(wall.direction, (Vec3{0, 0, 1}));
  EXPECT_EQ(user_ids(m, wall.secondary_nodes), (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6}));
  Wall flat = w;
  flat.m2 = vec(0.025, -1, -0.001);  // on the line M M1
  const std::string e = error_of(dir, flat.card());
  EXPECT_NE(e.find("X_M2"), std::string::npos) << e;
}

TEST(RigidKeywords, MovingWallSitsOnItsNode) {
  test::TempDir dir;
  Wall w;
  w.node = 7;
  w.origin = R(2.0) + R(1.0) + R(0.0) + R(-3.0) + "\n";  // Mass, VX0, VY0, VZ0
  w.m1 = vec(0.05, 0, 0);                                 // below node 7 at (0.05, 0, 0.1): normal -z
  const Model base = read(dir, "");
  const Model m = read(dir, w.card());
  const RigidWall& wall = m.rigid_walls[0];
  EXPECT_EQ(m.nodes.user_id[static_cast<std::size_t>(wall.node)], 7);
  EXPECT_EQ(wall.point, (Vec3{0.05, 0, 0.1}));
  EXPECT_EQ(wall.direction, (Vec3{0, 0, -1}));
  EXPECT_DOUBLE_EQ(wall.mass, 2.0);
  EXPECT_EQ(wall.velocity0, (Vec3{1, 0, -3}));
  EXPECT_NEAR(m.total_mass() - base.total_mass(), 2.0, 1e-12);  // the wall mass goes to node 7
  EXPECT_NEAR(m.nodal_mass[6], 2.0, 1e-12);
}

TEST(RigidKeywords, MovingWallErrors) {
  test::TempDir dir;
  Wall on_node;
  on_node.node = 7;
  on_node.m1 = vec(0.05, 0, 0.1);  // the node's position
  const std::string e = error_of(dir, on_node.card());
  EXPECT_NE(e.find("X_M1"), std::string::npos) << e;
  EXPECT_NE(e.find("node 7"), std::string::npos) << e;
  Wall in_group;
  in_group.node = 7;
  in_group.group1 = 13;
  EXPECT_NE(error_of(dir, in_group.card()).find("wall node 7 is in node group 13"), std::string::npos);
  Wall missing;
  missing.node = 77;
  EXPECT_NE(error_of(dir, missing.card()).find("node 77 not defined"), std::string::npos);
  Wall heavy;
  heavy.node = 7;
  heavy.origin = R(-1.0) + "\n";
  EXPECT_NE(error_of(dir, heavy.card()).find("Mass"), std::string::npos);
}

TEST(RigidKeywords, WallWarnings) {
  test::TempDir dir;
  Wall w;
  w.contact = R(0.0) + R(0.3) + R(1.0) + "\n";
  const std::string text = warnings_of(dir, w.card());
  EXPECT_NE(text.find("fric ignored"), std::string::npos) << text;
  EXPECT_NE(text.find("Diameter ignored"), std::string::npos) << text;
  Wall none;
  none.group1 = 0;
  EXPECT_NE(warnings_of(dir, none.card()).find("no secondary nodes"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------------------------
// /RBODY

TEST(RigidKeywords, RigidBodyDefaults) {
  test::TempDir dir;
  Body b;
  const Model base = read(dir, "");
  const Model m = read(dir, b.card());
  ASSERT_EQ(m.rigid_bodies.size(), 1u);
  const RigidBody& body = m.rigid_bodies[0];
  EXPECT_EQ(body.user_id, 7);
  EXPECT_EQ(body.title, "body");
  EXPECT_EQ(m.nodes.user_id[static_cast<std::size_t>(body.main_node)], 7);
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(body.node_group)].user_id, 14);
  EXPECT_EQ(body.ispher, 2);  // 0 means 2
  EXPECT_EQ(body.icog, 1);    // 0 means 1
  EXPECT_EQ(body.ikrem, 0);
  EXPECT_DOUBLE_EQ(body.mass, 3.0);
  EXPECT_NEAR(m.total_mass() - base.total_mass(), 3.0, 1e-12);
  EXPECT_NEAR(m.nodal_mass[6], 3.0, 1e-12);  // added at the main node
  EXPECT_EQ(m.index.rigid_bodies.at(7), 0);
}

// The solver computes the inertia from the nodes (Ispher 2, made spherical for Ispher 1) about the centre ICoG
// chooses (1 to 4, RB-0e); inertia from the card alone (Ispher 3) is an error naming the field.
TEST(RigidKeywords, InertiaFromTheCardAloneIsAnErrorAndEveryCentreChoiceIsRead) {
  {
    test::TempDir dir;
    Body b;
    b.ispher = 3;
    const std::string e = error_of(dir, b.card());
    EXPECT_NE(e.find("field Ispher"), std::string::npos) << e;
    EXPECT_NE(e.find("not supported by Crumple"), std::string::npos) << e;
  }
  for (int icog : {2, 3, 4}) {
    test::TempDir dir;
    Body b;
    b.icog = icog;
    EXPECT_EQ(read(dir, b.card()).rigid_bodies.at(0).icog, icog);
  }
}

TEST(RigidKeywords, RigidBodyUnits) {
  test::TempDir dir;
  Body b;
  b.ikrem = 1;
  b.mass = R(140.0);
  b.diagonal = vec(1, 2, 3);
  b.products = vec(-4, 5, 6);
  const Model m = read(dir, b.card(), gram_mm_ms_begin());
  const RigidBody& body = m.rigid_bodies[0];
  EXPECT_EQ(body.ispher, 2);
  EXPECT_EQ(body.icog, 1);
  EXPECT_EQ(body.ikrem, 1);
  EXPECT_DOUBLE_EQ(body.mass, 0.14);
  // g mm^2 = 1e-9 kg m^2; the order on the card is Jxy, Jyz, Jxz.
  const std::array<double, 6> expected{1e-9, 2e-9, 3e-9, -4e-9, 5e-9, 6e-9};
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(body.inertia[k], expected[k], 1e-22) << k;
}

TEST(RigidKeywords, RigidBodyFieldErrors) {
  test::TempDir dir;
  Body mass;
  mass.mass = R(-1.0);
  const std::string e = error_of(dir, mass.card());
  EXPECT_NE(e.find("Mass"), std::string::npos) << e;
  EXPECT_NE(e.find("non-negative"), std::string::npos) << e;
  Body ispher;
  ispher.ispher = 5;
  EXPECT_NE(error_of(dir, ispher.card()).find("Ispher"), std::string::npos);
  Body icog;
  icog.icog = 9;
  EXPECT_NE(error_of(dir, icog.card()).find("ICoG"), std::string::npos);
  Body ikrem;
  ikrem.ikrem = 2;
  EXPECT_NE(error_of(dir, ikrem.card()).find("Ikrem"), std::string::npos);
  Body inertia;
  inertia.diagonal = vec(0, -1, 0);
  EXPECT_NE(error_of(dir, inertia.card()).find("Jyy"), std::string::npos);
  Body fail;
  fail.options = I(0) + I(0) + I(1) + "\n";
  EXPECT_NE(error_of(dir, fail.card()).find("Ifail"), std::string::npos);
  Body main;
  main.main = 0;
  EXPECT_NE(error_of(dir, main.card()).find("RBID"), std::string::npos);
  Body group;
  group.group = 0;
  EXPECT_NE(error_of(dir, group.card()).find("grnod_ID"), std::string::npos);
  Body sensor;
  sensor.sensor = 2;  // no /SENSOR 2 in the deck
  EXPECT_NE(error_of(dir, sensor.card()).find("sensor 2 not defined"), std::string::npos);
  Body truncated;
  truncated.products = "";
  truncated.options = "";
  EXPECT_NE(error_of(dir, truncated.card()).find("truncated"), std::string::npos);
}

TEST(RigidKeywords, TwoBodiesOnOneMainNode) {
  test::TempDir dir;
  Body first;
  Body second;
  second.id = 8;
  second.group = 11;
  const std::string e = error_of(dir, first.card() + second.card());
  EXPECT_NE(e.find("RBID"), std::string::npos) << e;
  EXPECT_NE(e.find("main node of /RBODY/7"), std::string::npos) << e;
}

TEST(RigidKeywords, RigidBodyWarnings) {
  test::TempDir dir;
  Body old;
  old.options = "";  // pre-2019 layout
  EXPECT_NE(warnings_of(dir, old.card()).find("Ioptoff"), std::string::npos);
  Body on_element;
  on_element.main = 1;
  on_element.group = 14;
  EXPECT_NE(warnings_of(dir, on_element.card()).find("main node 1 belongs to an element"), std::string::npos);
}

TEST(RigidKeywords, BodyNodesLeaveWallsUnlessIkrem) {
  test::TempDir dir;
  Wall w;  // group 10: every plate node
  Body b;  // secondary nodes 3 and 6
  const Model removed = read(dir, w.card() + b.card());
  EXPECT_EQ(user_ids(removed, removed.rigid_walls[0].secondary_nodes), (std::vector<std::int64_t>{1, 2, 4, 5}));
  // Ikrem 1 would keep them, and a wall would push the body off its centre: refused (rigid-walls.md, RW-3).
  b.ikrem = 1;
  const std::string kept = error_of(dir, w.card() + b.card());
  EXPECT_NE(kept.find("field Ikrem"), std::string::npos) << kept;
  EXPECT_NE(kept.find("a wall holds a rigid body through its main node only"), std::string::npos) << kept;
}

TEST(RigidKeywords, OtherBodyFormsAndUnitsAreErrors) {
  test::TempDir dir;
  const std::string card = Body{}.card();
  const std::string lagmul = error_of(dir, "/RBODY/LAGMUL/7" + card.substr(card.find('\n')));
  EXPECT_NE(lagmul.find("/RBODY/LAGMUL form is not supported"), std::string::npos) << lagmul;
  const std::string unit = error_of(dir, "/RBODY/7/3" + card.substr(card.find('\n')));
  EXPECT_NE(unit.find("unit_ID"), std::string::npos) << unit;
}

// A body with a sensor (docs/theory/rigid-bodies.md, RB-6): off while the sensor is on; the manual's ignored fields
// (added mass and inertia, skew, ICoG) must be blank, and Ikrem is 1.
TEST(RigidKeywords, SensorBodyTakesTheWindowAndRefusesWhatItIgnores) {
  test::TempDir dir;
  const std::string sensor = "/SENSOR/TIME/2\ntimer\n" + R(0.25) + "\n";
  Body body;
  body.sensor = 2;
  body.mass = R(0.0);
  const Model m = read(dir, sensor + body.card());
  ASSERT_EQ(m.rigid_bodies.size(), 1u);
  EXPECT_DOUBLE_EQ(m.rigid_bodies[0].sensor.on, 0.25);
  EXPECT_EQ(m.rigid_bodies[0].ikrem, 1);
  Body heavy = body;
  heavy.mass = R(3.0);
  EXPECT_NE(error_of(dir, sensor + heavy.card()).find("Mass"), std::string::npos);
  Body spinning = body;
  spinning.diagonal = vec(1, 1, 1);
  EXPECT_NE(error_of(dir, sensor + spinning.card()).find("Jxx"), std::string::npos);
  Body centred = body;
  centred.icog = 3;
  EXPECT_NE(error_of(dir, sensor + centred.card()).find("ICoG"), std::string::npos);
}

}  // namespace test_rigid_keywords
