// /BCS, /IMPVEL, /IMPDISP, /CLOAD, /INIVEL/TRA, /GRAV, /ADMAS: values, defaults, units and errors.
// The decks have no engine file, so these tests do not depend on the engine keywords.
#include <gtest/gtest.h>

#include <cmath>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_load_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

// /BEGIN with input units g, mm, ms and working units kg, m, s.
std::string gram_mm_ms_begin() {
  return "/BEGIN\nTEST\n      2019         0\n" + R("g") + R("mm") + R("ms") + "\n" + R("kg") + R("m") + R("s") + "\n";
}

// The plate's six nodes in group 10, nodes 1 and 2 in group 11, an empty group 12, a ramp function 1.
std::string references() {
  return "/GRNOD/NODE/10\nall\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + "\n" + "/GRNOD/NODE/11\ntwo\n" + I(1) +
         I(2) + "\n" + "/GRNOD/NODE/12\nempty\n" + "/FUNCT/1\nramp\n" + R(0.0) + R(0.0) + "\n" + R(1.0) + R(1.0) + "\n";
}

// A starter deck alone (no engine file): the plate, the references above and `extra`.
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

std::string bcs(const std::string& codes, long long group = 10, long long skew = 0) {
  return "/BCS/1\nclamp\n" + codes + std::string(10 - codes.size(), ' ') + I(skew) + I(group) + "\n";
}

// /IMPVEL-style card: funct_IDT, Dir, skew, sensor, group, frame, Icoor, then the scales line.
std::string imposed(const std::string& keyword, const std::string& dir, const std::string& scales,
                    long long function = 1, long long frame = 0, long long icoor = 0, long long sensor = 0) {
  return keyword + "\nimposed\n" + I(function) + std::string(10 - dir.size(), ' ') + dir + I(0) + I(sensor) +
         I(10) + I(frame) + I(icoor) + "\n" + scales + "\n";
}

std::string cload(const std::string& dir, const std::string& scales, long long function = 1, long long id = 3) {
  return "/CLOAD/" + std::to_string(id) + "\nload\n" + I(function) + std::string(10 - dir.size(), ' ') + dir +
         I(0) + I(0) + I(11) + test::blank(10) + scales + "\n";
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// /BCS

TEST(LoadKeywords, BcsCodesInColumnsFourToTen) {
  test::TempDir dir;
  const Model m = read(dir, bcs("   101 011"));
  ASSERT_EQ(m.boundary_conditions.size(), 1u);
  const BoundaryCondition& bc = m.boundary_conditions[0];
  EXPECT_EQ(bc.user_id, 1);
  EXPECT_EQ(bc.title, "clamp");
  EXPECT_EQ(bc.fixed_translation, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(bc.fixed_rotation, (std::array<bool, 3>{false, true, true}));
  EXPECT_EQ(bc.node_group_id, 10);
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(bc.node_group)].user_id, 10);
}

TEST(LoadKeywords, BcsBlankCodesAreFree) {
  test::TempDir dir;
  const Model m = read(dir, bcs("   1"));
  EXPECT_EQ(m.boundary_conditions[0].fixed_translation, (std::array<bool, 3>{true, false, false}));
  EXPECT_EQ(m.boundary_conditions[0].fixed_rotation, (std::array<bool, 3>{false, false, false}));
}

TEST(LoadKeywords, BcsMisalignedCodesAreErrors) {
  test::TempDir dir;
  EXPECT_NE(error_of(dir, bcs("    111111")).find("columns 7-7"), std::string::npos);  // shifted by one
  EXPECT_NE(error_of(dir, bcs("111 111")).find("columns 1-3"), std::string::npos);
  const std::string bad_digit = error_of(dir, bcs("   121 111"));
  EXPECT_NE(bad_digit.find("TY"), std::string::npos) << bad_digit;
  EXPECT_NE(bad_digit.find("0, 1 or blank"), std::string::npos) << bad_digit;
}

TEST(LoadKeywords, BcsNeedsAGroupAndRejectsSkews) {
  test::TempDir dir;
  EXPECT_NE(error_of(dir, bcs("   111", 0)).find("grnod_ID"), std::string::npos);
  EXPECT_NE(error_of(dir, bcs("   111", 99)).find("node group 99 not defined"), std::string::npos);
  EXPECT_NE(error_of(dir, bcs("   111", 10, 3)).find("skew_ID"), std::string::npos);
}

TEST(LoadKeywords, BcsWithoutFixedDofWarns) {
  test::TempDir dir;
  EXPECT_NE(warnings_of(dir, bcs("   000 000")).find("no degree of freedom fixed"), std::string::npos);
}

// /ALE/BCS fixes the ALE grid of ALE parts, which a Crumple model never has: a named warning, no constraint.
TEST(LoadKeywords, AleBcsActsOnNothingWithAWarning) {
  test::TempDir dir;
  const std::string card = "/ALE/BCS/1\ngrid\n" + std::string("   111 111") + I(0) + I(10) + "\n";
  const std::string w = warnings_of(dir, card);
  EXPECT_NE(w.find("/ALE/BCS"), std::string::npos) << w;
  EXPECT_NE(w.find("ALE grid"), std::string::npos) << w;
  EXPECT_TRUE(read(dir, card).boundary_conditions.empty());
}

// An imposed velocity on a dof that a /BCS fixes: the imposed motion wins, and the warning says what the reference's
// listing makes of it (a quarter of the kinetic energy, measured; resolve_loads.cpp). A free dof says nothing.
TEST(LoadKeywords, ImposedMotionOnAFixedDofIsNamed) {
  test::TempDir dir;
  const std::string velocity = imposed("/IMPVEL/2", "Z", R(0.0) + R(1.0));
  const std::string w = warnings_of(dir, bcs("   001") + velocity);
  EXPECT_NE(w.find("/IMPVEL/2: 6 of its nodes have this dof fixed by /BCS/1 too"), std::string::npos) << w;
  EXPECT_EQ(warnings_of(dir, bcs("   110") + velocity).find("fixed by /BCS"), std::string::npos);
}

TEST(LoadKeywords, DuplicateIdsAreErrors) {
  test::TempDir dir;
  const std::string e = error_of(dir, bcs("   111") + bcs("   111"));
  EXPECT_NE(e.find("/BCS/1"), std::string::npos) << e;
  EXPECT_NE(e.find("duplicate"), std::string::npos) << e;
}

// ---------------------------------------------------------------------------------------------------------------
// /IMPVEL, /IMPDISP

TEST(LoadKeywords, ImpvelDefaults) {
  test::TempDir dir;
  // The QA form: Ascale_x 0 and Tstop 0 take their defaults.
  const Model m = read(dir, imposed("/IMPVEL/4", "Y", R(0.0) + R(2.5) + R(0.0) + R(0.0)));
  ASSERT_EQ(m.imposed.size(), 1u);
  const ImposedMotion& im = m.imposed[0];
  EXPECT_EQ(im.kind, ImposedKind::Velocity);
  EXPECT_EQ(im.user_id, 4);
  EXPECT_EQ(im.dof, Dof::Y);
  EXPECT_EQ(im.function_id, 1);
  EXPECT_EQ(m.functions[static_cast<std::size_t>(im.function)].user_id, 1);
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(im.node_group)].user_id, 10);
  EXPECT_DOUBLE_EQ(im.scale_x, 1.0);
  EXPECT_DOUBLE_EQ(im.scale_y, 2.5);
  EXPECT_DOUBLE_EQ(im.t_start, 0.0);
  EXPECT_DOUBLE_EQ(im.t_stop, 1e30);
}

TEST(LoadKeywords, ImpvelBlankScaleIsOne) {
  test::TempDir dir;
  const Model m = read(dir, imposed("/IMPVEL/4", "ZZ", ""));
  EXPECT_EQ(m.imposed[0].dof, Dof::ZZ);
  EXPECT_DOUBLE_EQ(m.imposed[0].scale_x, 1.0);
  EXPECT_DOUBLE_EQ(m.imposed[0].scale_y, 1.0);
}

TEST(LoadKeywords, ImpdispConvertsUnits) {
  test::TempDir dir;
  const Model m =
      read(dir, imposed("/IMPDISP/5", "X", R(2.0) + R(3.0) + R(1.0) + R(4.0)) +
                    imposed("/IMPVEL/6", "XX", R(0.0) + R(0.0)),
           gram_mm_ms_begin());
  ASSERT_EQ(m.imposed.size(), 2u);
  const ImposedMotion& d = m.imposed[0];
  EXPECT_EQ(d.kind, ImposedKind::Displacement);
  EXPECT_DOUBLE_EQ(d.scale_x, 2e-3);   // 2 ms
  EXPECT_DOUBLE_EQ(d.scale_y, 3e-3);   // 3 mm
  EXPECT_DOUBLE_EQ(d.t_start, 1e-3);   // 1 ms
  EXPECT_DOUBLE_EQ(d.t_stop, 4e-3);    // 4 ms
  const ImposedMotion& v = m.imposed[1];
  EXPECT_DOUBLE_EQ(v.scale_x, 1e-3);   // blank: 1 ms
  EXPECT_DOUBLE_EQ(v.scale_y, 1e3);    // blank: 1 rad/ms
}

// grnod_ID 0 on /IMPVEL and /IMPDISP names no node: the card acts on nothing, as the reference runs it (measured: the
// same energies as without it), with a warning that names the field.
TEST(LoadKeywords, ImposedMotionOnNoGroupActsOnNothing) {
  for (const char* keyword : {"/IMPVEL/4", "/IMPDISP/5"}) {
    std::string card = imposed(keyword, "X", R(0.0) + R(1.0));
    const std::string group = I(10);
    card.replace(card.find(group, card.find("imposed")), group.size(), I(0));
    test::TempDir dir;
    const Deck d = read_deck(test::write_deck(dir, card));
    EXPECT_TRUE(d.model.imposed.empty()) << keyword;
    std::string warnings;
    for (const auto& w : d.report.warnings) warnings += w.message + "\n";
    EXPECT_NE(warnings.find("grnod_ID"), std::string::npos) << warnings;
  }
}

TEST(LoadKeywords, ImpvelBadDirectionNamesDir) {
  test::TempDir dir;
  const std::string e = error_of(dir, imposed("/IMPVEL/4", "W", ""));
  EXPECT_NE(e.find("Dir"), std::string::npos) << e;
  EXPECT_NE(e.find("XX, YY, ZZ"), std::string::npos) << e;
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "", "")).find("Dir"), std::string::npos);
}

TEST(LoadKeywords, ImpvelFieldErrors) {
  test::TempDir dir;
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 0)).find("funct_IDT"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 9)).find("function 9 not defined"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 1, 0, 2)).find("Icoor"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 1, 0, 1)).find("cylindrical"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 1, 7)).find("frame_ID"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", "", 1, 0, 0, 3)).find("sensor_ID"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", R(-1.0))).find("Ascale_x"), std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", R(1.0) + R(1.0) + R(2.0) + R(1.0))).find("Tstop"),
            std::string::npos);
  EXPECT_NE(error_of(dir, imposed("/IMPVEL/4", "X", R("1.0.0"))).find("Ascale_x"), std::string::npos);
}

TEST(LoadKeywords, ImpvelTruncatedCard) {
  test::TempDir dir;
  const std::string card = imposed("/IMPVEL/4", "X", "");
  const std::string e = error_of(dir, card.substr(0, card.rfind('\n', card.size() - 2) + 1));
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  EXPECT_NE(e.find("Ascale_x"), std::string::npos) << e;
}

TEST(LoadKeywords, OtherFormsAndUnitIdsAreErrors) {
  test::TempDir dir;
  const std::string fgeo = error_of(dir, imposed("/IMPVEL/FGEO/4", "X", ""));
  EXPECT_NE(fgeo.find("/IMPVEL/FGEO form is not supported"), std::string::npos) << fgeo;
  const std::string unit = error_of(dir, imposed("/IMPVEL/4/2", "X", ""));
  EXPECT_NE(unit.find("unit_ID"), std::string::npos) << unit;
  EXPECT_EQ(error_of(dir, imposed("/IMPVEL/4/0", "X", "")), "");
}

// Columns 51-60 are blank in the Radioss 2021 /IMPDISP layout; a newer deck's frame there is not dropped silently.
TEST(LoadKeywords, ImpdispFrameColumnIsAnError) {
  test::TempDir dir;
  const std::string e = error_of(dir, imposed("/IMPDISP/5", "X", "", 1, 7));
  EXPECT_NE(e.find("field frame_ID (columns 51-60)"), std::string::npos) << e;
  EXPECT_NE(e.find("not supported by Crumple"), std::string::npos) << e;
}

// ---------------------------------------------------------------------------------------------------------------
// /CLOAD

TEST(LoadKeywords, CloadValuesAndUnits) {
  test::TempDir dir;
  const Model m = read(dir, cload("ZZ", R(0.0) + R(5.0)) + cload("X", "", 1, 4), gram_mm_ms_begin());
  ASSERT_EQ(m.imposed.size(), 2u);
  const ImposedMotion& moment = m.imposed[0];
  EXPECT_EQ(moment.kind, ImposedKind::Force);
  EXPECT_EQ(moment.user_id, 3);
  EXPECT_EQ(moment.dof, Dof::ZZ);
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(moment.node_group)].user_id, 11);
  EXPECT_DOUBLE_EQ(moment.scale_x, 1e-3);           // 0: 1 ms
  EXPECT_NEAR(moment.scale_y, 5e-3, 1e-18);         // 5 g mm^2 / ms^2 = 5e-3 N m
  EXPECT_DOUBLE_EQ(moment.t_stop, 1e30);
  EXPECT_NEAR(m.imposed[1].scale_y, 1.0, 1e-15);    // blank: 1 g mm / ms^2 = 1 N
}

TEST(LoadKeywords, CloadNeedsAFunction) {
  test::TempDir dir;
  const std::string e = error_of(dir, cload("X", "", 0));
  EXPECT_NE(e.find("funct_IDT"), std::string::npos) << e;
  EXPECT_NE(error_of(dir, cload("Q", "")).find("Dir"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------------------------
// /INIVEL/TRA

TEST(LoadKeywords, InivelTra) {
  test::TempDir dir;
  const Model m = read(dir, "/INIVEL/TRA/7\ninit\n" + R(-8.0) + R("") + R(0.5) + I(10) + I(0) + "\n");
  ASSERT_EQ(m.initial_velocities.size(), 1u);
  const InitialVelocity& iv = m.initial_velocities[0];
  EXPECT_EQ(iv.user_id, 7);
  EXPECT_EQ(iv.velocity, (Vec3{-8.0, 0.0, 0.5}));
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(iv.node_group)].nodes.size(), 6u);
}

TEST(LoadKeywords, InivelErrors) {
  test::TempDir dir;
  const std::string axis = error_of(dir, "/INIVEL/AXIS/7\ninit\n" + R(1.0) + R(0.0) + R(0.0) + I(10) + "\n");
  EXPECT_NE(axis.find("TRA, T+G or ROT"), std::string::npos) << axis;
  EXPECT_NE(error_of(dir, "/INIVEL/TRA/7\ninit\n" + R(1.0) + R(0.0) + R(0.0) + "\n").find("grnod_ID"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "/INIVEL/TRA/7\ninit\n" + R("fast") + "\n").find("Vx"), std::string::npos);
  EXPECT_NE(error_of(dir, "/INIVEL/TRA/7\ninit\n" + R(1.0) + R(0.0) + R(0.0) + I(10) + I(2) + "\n").find("Skew_ID"),
            std::string::npos);
  // Version 2025's second line: Tstart and sens_ID, which Crumple lacks, then nothing more.
  const std::string later = error_of(dir, "/INIVEL/TRA/7\ninit\n" + R(1.0) + R(0.0) + R(0.0) + I(10) + "\n1\n");
  EXPECT_NE(later.find("field Tstart"), std::string::npos) << later;
  const std::string extra =
      error_of(dir, "/INIVEL/TRA/7\ninit\n" + R(1.0) + R(0.0) + R(0.0) + I(10) + "\n" + R(0.0) + "\n1\n");
  EXPECT_NE(extra.find("no more data lines"), std::string::npos) << extra;
}

// /INIVEL/ROT: the nodes' angular velocity [1/T], in a skew when one is named; /INIVEL/T+G is /INIVEL/TRA on
// Crumple's Lagrangian nodes; version 2025's Tstart line at 0 is accepted.
TEST(LoadKeywords, InivelRotAndTranslationAndGrid) {
  test::TempDir dir;
  const Model m = read(dir, "/SKEW/FIX/3\nskew\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(0.0) + R(1.0) + R(0.0) +
                                "\n" + R(0.0) + R(0.0) + R(1.0) + "\n/INIVEL/ROT/7\nspin\n" + R(0.0) + R(0.0) +
                                R(2.0) + I(10) + I(3) + "\n/INIVEL/T+G/8\nmove\n" + R(1.0) + R(0.0) + R(0.0) +
                                I(10) + I(0) + "\n" + R(0.0) + I(0) + "\n");
  ASSERT_EQ(m.initial_velocities.size(), 2u);
  EXPECT_TRUE(m.initial_velocities[0].rotation);
  EXPECT_EQ(m.initial_velocities[0].velocity, (Vec3{0.0, 0.0, 2.0}));
  EXPECT_EQ(m.initial_velocities[0].skew, 0);
  EXPECT_FALSE(m.initial_velocities[1].rotation);
  EXPECT_EQ(m.initial_velocities[1].skew, -1);
}

// ---------------------------------------------------------------------------------------------------------------
// /GRAV

TEST(LoadKeywords, GravDefaultsAllNodesAlongZ) {
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, "/GRAV/2\ngravity\n\n"));
  ASSERT_EQ(d.model.gravity.size(), 1u);
  const Gravity& g = d.model.gravity[0];
  EXPECT_EQ(g.dof, Dof::Z);
  EXPECT_EQ(g.function, -1);    // constant
  EXPECT_EQ(g.node_group, -1);  // every node
  EXPECT_DOUBLE_EQ(g.scale_x, 1.0);
  EXPECT_DOUBLE_EQ(g.scale_y, 1.0);
  EXPECT_NE(warnings_of(dir, "/GRAV/2\ngravity\n\n").find("Fscale_Y blank"), std::string::npos);
}

TEST(LoadKeywords, GravValuesAndUnits) {
  test::TempDir dir;
  const Model m = read(dir, "/GRAV/2\ngravity\n" + I(1) + "         Y" + I(0) + I(0) + I(11) + test::blank(10) +
                                R(2.0) + R(-9.81e-3) + "\n",
                       gram_mm_ms_begin());
  const Gravity& g = m.gravity[0];
  EXPECT_EQ(g.dof, Dof::Y);
  EXPECT_EQ(m.functions[static_cast<std::size_t>(g.function)].user_id, 1);
  EXPECT_EQ(m.node_groups[static_cast<std::size_t>(g.node_group)].user_id, 11);
  EXPECT_DOUBLE_EQ(g.scale_x, 2e-3);
  EXPECT_NEAR(g.scale_y, -9.81, 1e-12);  // mm/ms^2 -> m/s^2
}

TEST(LoadKeywords, GravRotationIsAnError) {
  test::TempDir dir;
  const std::string e = error_of(dir, "/GRAV/2\ngravity\n" + I(0) + "        XX\n");
  EXPECT_NE(e.find("Dir"), std::string::npos) << e;
  EXPECT_NE(e.find("X, Y or Z"), std::string::npos) << e;
}

// ---------------------------------------------------------------------------------------------------------------
// /ADMAS

TEST(LoadKeywords, AdmasTypesZeroAndOne) {
  test::TempDir dir;
  const Model base = read(dir, "");
  const Model m =
      read(dir, "/ADMAS/0/1\nper node\n" + R(2.0) + I(11) + "\n" + "/ADMAS/1/2\ntotal\n" + R(6.0) + I(10) + "\n");
  ASSERT_EQ(m.added_masses.size(), 2u);
  EXPECT_EQ(m.added_masses[0].type, 0);
  EXPECT_EQ(m.added_masses[0].user_id, 1);  // /ADMAS/type/id: the id is the second number
  EXPECT_EQ(m.added_masses[1].type, 1);
  EXPECT_DOUBLE_EQ(m.added_mass, 2.0 * 2 + 6.0);
  EXPECT_NEAR(m.total_mass(), base.total_mass() + 10.0, 1e-12);
  EXPECT_NEAR(m.nodal_mass[0] - base.nodal_mass[0], 2.0 + 1.0, 1e-12);  // node 1: group 11 and a sixth of 6
  EXPECT_NEAR(m.nodal_mass[5] - base.nodal_mass[5], 1.0, 1e-12);
}

TEST(LoadKeywords, AdmasConvertsMass) {
  test::TempDir dir;
  const Model m = read(dir, "/ADMAS/0/1\nper node\n" + R(500.0) + I(11) + "\n", gram_mm_ms_begin());
  EXPECT_DOUBLE_EQ(m.added_masses[0].mass, 0.5);
  EXPECT_DOUBLE_EQ(m.added_mass, 1.0);
}

TEST(LoadKeywords, AdmasErrors) {
  test::TempDir dir;
  const std::string negative = error_of(dir, "/ADMAS/0/1\nm\n" + R(-1.0) + I(11) + "\n");
  EXPECT_NE(negative.find("Mass"), std::string::npos) << negative;
  EXPECT_NE(negative.find("non-negative"), std::string::npos) << negative;
  const std::string surface = error_of(dir, "/ADMAS/2/1\nm\n" + R(1.0) + I(1) + "\n");
  EXPECT_NE(surface.find("not supported"), std::string::npos) << surface;
  EXPECT_NE(error_of(dir, "/ADMAS/9/1\nm\n" + R(1.0) + I(11) + "\n").find("type"), std::string::npos);
  const std::string single = error_of(dir, "/ADMAS/7\nm\n" + R(1.0) + I(11) + "\n");
  EXPECT_NE(single.find("ambiguous"), std::string::npos) << single;
  const std::string empty = error_of(dir, "/ADMAS/1/1\nm\n" + R(1.0) + I(12) + "\n");
  EXPECT_NE(empty.find("node group 12 is empty"), std::string::npos) << empty;
  EXPECT_NE(error_of(dir, "/ADMAS/0/1\nm\n" + R(1.0) + "\n").find("grnod_ID"), std::string::npos);
}

namespace {

// /SENSOR/TIME (docs/cards/loads-output-engine.md): Tdelay in time units; Tstop from input version 2023 on.
std::string time_sensor(long long id, const std::string& delay, const std::string& stop = "") {
  return "/SENSOR/TIME/" + std::to_string(id) + "\ntimer\n" + delay + "\n" + (stop.empty() ? "" : stop + "\n");
}

}  // namespace

TEST(LoadKeywords, TimeSensorWindowReachesTheLoadsThatNameIt) {
  test::TempDir dir;
  const Model m = read(dir, time_sensor(3, R(2.0)) + imposed("/IMPVEL/4", "X", "", 1, 0, 0, 3), gram_mm_ms_begin());
  ASSERT_EQ(m.sensors.size(), 1u);
  EXPECT_DOUBLE_EQ(m.sensors[0].on, 2e-3);  // 2 ms in s
  EXPECT_TRUE(std::isinf(m.sensors[0].off));
  ASSERT_EQ(m.imposed.size(), 1u);
  EXPECT_DOUBLE_EQ(m.imposed[0].sensor.on, 2e-3);
  EXPECT_FALSE(m.imposed[0].sensor.holds(1.9e-3));
  EXPECT_TRUE(m.imposed[0].sensor.holds(2e-3));
  EXPECT_DOUBLE_EQ(m.imposed[0].sensor.clock(5e-3), 3e-3);
  // No sensor: always on, clock from 0.
  const Model plain = read(dir, imposed("/IMPVEL/4", "X", ""));
  EXPECT_TRUE(plain.imposed[0].sensor.holds(0.0));
  EXPECT_DOUBLE_EQ(plain.imposed[0].sensor.clock(1.0), 1.0);
}

TEST(LoadKeywords, TimeSensorStopFromVersion2023) {
  test::TempDir dir;
  const std::string card = time_sensor(3, R(1.0), R(4.0)) + cload("Z", R(0.0) + R(1.0));
  const Model m = read(dir, card, test::begin_card("TEST", 2023));
  EXPECT_DOUBLE_EQ(m.sensors[0].off, 4.0);
  // Before 2023 the card has no Tstop line: a second line is an error.
  EXPECT_NE(test::first_error(starter(dir, card)).find("/SENSOR/TIME/3"), std::string::npos);
  const std::string early = time_sensor(3, R(5.0), R(4.0));
  EXPECT_NE(test::first_error(starter(dir, early, test::begin_card("TEST", 2023))).find("Tstop"), std::string::npos);
}

TEST(LoadKeywords, SensorErrors) {
  test::TempDir dir;
  EXPECT_NE(error_of(dir, time_sensor(3, R(-1.0))).find("Tdelay"), std::string::npos);
  const std::string accel = "/SENSOR/ACCE/3\naccel\n" + R(0.0) + "\n";
  const std::string e = error_of(dir, accel);
  EXPECT_NE(e.find("TIME"), std::string::npos) << e;
  EXPECT_NE(e.find("ACCE"), std::string::npos) << e;
  EXPECT_NE(error_of(dir, time_sensor(3, R(0.0)) + time_sensor(3, R(1.0))).find("/SENSOR"), std::string::npos);
  const std::string missing = error_of(dir, imposed("/IMPVEL/4", "X", "", 1, 0, 0, 8));
  EXPECT_NE(missing.find("sensor_ID"), std::string::npos) << missing;
  EXPECT_NE(missing.find("sensor 8"), std::string::npos) << missing;
}

}  // namespace test_load_keywords
