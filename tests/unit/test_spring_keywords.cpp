// /SPRING, /PROP/TYPE4 (/PROP/SPRING) and /DAMP, starter and engine (docs/theory/spring.md, damping.md): values,
// defaults, units, and the errors that name the field of an option Crumple lacks.
#include <gtest/gtest.h>

#include "crumple/elements/critical_step.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_spring_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

// Nodes 101 and 102 one unit apart along y, the spring 7 of part 20 between them (property 30, mass 2, K 1000,
// C `c`), node group 40 of both; `line1` .. `line4` replace the property's lines when given.
struct SpringDeck {
  std::string line1 = R(2.0), line2 = R(1000.0) + R(0.0), line3 = I(0), line4 = R(0.0), spring_line;
  std::string extra;
  std::string cards() const {
    std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(0.0) + R(1.0) + R(0.0) + "\n";
    s += "/SPRING/20\n" + (spring_line.empty() ? I(7) + I(101) + I(102) : spring_line) + "\n";
    s += "/PART/20\nsprings\n" + I(30) + I(0) + "\n";
    s += "/PROP/SPRING/30\nspring\n" + line1 + "\n" + line2 + "\n" + line3 + "\n" + line4 + "\n";
    s += "/GRNOD/NODE/40\nboth\n" + I(101) + I(102) + "\n";
    return s + extra;
  }
};

std::filesystem::path starter(const test::TempDir& dir, const SpringDeck& d, const std::string& engine = "") {
  if (!engine.empty()) dir.write("T_0001.rad", engine);
  return dir.write("T_0000.rad", test::begin_card("T") + d.cards() + "/END\n");
}

std::string error_of(const SpringDeck& d, const std::string& engine = "") {
  test::TempDir dir;
  return test::first_error(starter(dir, d, engine));
}

}  // namespace

TEST(SpringKeywords, ReadsTheSpringItsPropertyAndItsMass) {
  test::TempDir dir;
  SpringDeck d;
  d.line2 = R(1000.0) + R(20.0);
  d.line3 = I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') + R(-0.1) + R(0.2);
  const Model m = read_deck(starter(dir, d)).model;
  const ElementTable& springs = m.elements[static_cast<int>(ElementKind::Spring)];
  ASSERT_EQ(springs.size(), 1u);
  EXPECT_EQ(springs.user_id[0], 7);
  const SpringSection& s = m.properties[0].spring;
  EXPECT_EQ(m.properties[0].kind, PropertyKind::Spring);
  EXPECT_DOUBLE_EQ(s.mass, 2.0);
  EXPECT_DOUBLE_EQ(s.stiffness, 1000.0);
  EXPECT_DOUBLE_EQ(s.damping, 20.0);
  EXPECT_DOUBLE_EQ(s.delta_min, -0.1);
  EXPECT_DOUBLE_EQ(s.delta_max, 0.2);
  EXPECT_EQ(m.parts[0].material, -1);  // mat_ID 0: the property carries the law
  EXPECT_DOUBLE_EQ(m.element_mass, 2.0);
  EXPECT_DOUBLE_EQ(m.nodal_mass[0], 1.0);
  // eq. SP-4: M / (sqrt(K M + C^2) + C) = 2 / (sqrt(2400) + 20), the reference's 2.609e-2 / 0.9
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), 2.0 / (std::sqrt(2400.0) + 20.0), 1e-15);
}

TEST(SpringKeywords, ForceFunctionWithItsScales) {
  test::TempDir dir;
  SpringDeck d;
  d.line2 = R(10.0) + R(0.0) + R(2.0);  // K 10 bounds the step only; A 2
  d.line3 = I(8);
  d.line4 = R(0.0) + R(0.0) + R(0.5);  // Ascale 0.5
  d.extra = "/FUNCT/8\nforce\n" + R(-1.0) + R(-4000.0) + "\n" + R(0.0) + R(0.0) + "\n" + R(0.01) + R(20.0) + "\n" +
            R(1.0) + R(4000.0) + "\n";
  const Model m = read_deck(starter(dir, d)).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_EQ(s.function, 0);
  EXPECT_DOUBLE_EQ(s.function_scale, 2.0);
  EXPECT_DOUBLE_EQ(s.abscissa_scale, 0.5);
  // eq. SP-4b: the steepest segment, (4000 - 20) / 0.99 = 4020.2, times A / Ascale = 4
  const double k = 4.0 * 3980.0 / 0.99;
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), 2.0 / std::sqrt(2.0 * k), 1e-12);
}

TEST(SpringKeywords, BlankFailureElongationsNeverBreak) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, SpringDeck{})).model;
  EXPECT_LE(m.properties[0].spring.delta_min, -1e30);
  EXPECT_GE(m.properties[0].spring.delta_max, 1e30);
}

TEST(SpringKeywords, RefusedOptionsNameTheirField) {
  SpringDeck d;
  d.line1 = R(0.0);
  EXPECT_NE(error_of(d).find("Mass"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(5);  // no /FUNCT/5
  EXPECT_NE(error_of(d).find("fct_ID11"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(0) + I(6);
  EXPECT_NE(error_of(d).find("fct_ID21"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(5);
  EXPECT_NE(error_of(d).find("field H"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(8) + I(4);  // kinematic hardening without its lower curve
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  EXPECT_NE(error_of(d).find("fct_ID31"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(1);  // a hardening spring without its curve
  EXPECT_NE(error_of(d).find("fct_ID11"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(8) + I(1);  // isotropic hardening on a curve that is not odd about 0
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(0.0) + R(0.0) + "\n" + R(1.0) + R(20.0) + "\n";
  EXPECT_NE(error_of(d).find("odd about 0"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line2 = R(1000.0) + R(0.0) + R(1.0) + R(0.5);
  EXPECT_NE(error_of(d).find("field B"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line1 = R(2.0) + std::string(30, ' ') + I(0) + I(0) + I(1);
  EXPECT_NE(error_of(d).find("Ileng"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.spring_line = I(7) + I(101) + I(102) + std::string(60, ' ') + I(3);
  EXPECT_NE(error_of(d).find("Skew_ID"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line2 = R(0.0) + R(0.0);
  EXPECT_NE(error_of(d).find("K, C"), std::string::npos) << error_of(d);
}

TEST(SpringKeywords, MaterialZeroOnlyWhereThePropertyCarriesTheLaw) {
  test::TempDir dir;
  const auto path = dir.write("T_0000.rad", test::begin_card("T") + test::plate_cards() +
                                                "/PART/9\nno law\n" + I(1) + I(0) + "\n/END\n");
  const std::string error = test::first_error(path);
  EXPECT_NE(error.find("mat_ID"), std::string::npos) << error;
}

TEST(SpringKeywords, DampingStarterAndEngine) {
  test::TempDir dir;
  SpringDeck d;
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(0.0) + I(40) + I(0) + R(0.5) + R(0.0) + "\n";
  const Deck deck = read_deck(starter(dir, d, "/RUN/T/1\n1.0\n/DAMP/3\n        40         0\n"));
  ASSERT_EQ(deck.model.dampings.size(), 1u);
  const RayleighDamping& damping = deck.model.dampings[0];
  EXPECT_DOUBLE_EQ(damping.alpha, 4.0);
  EXPECT_DOUBLE_EQ(damping.start, 0.5);
  EXPECT_GE(damping.stop, 1e30);  // blank Tstop: for ever
  EXPECT_EQ(damping.node_group, 0);
  ASSERT_EQ(deck.model.run.damping_changes.size(), 1u);
  EXPECT_EQ(deck.model.run.damping_changes[0].damping, 0);
  EXPECT_DOUBLE_EQ(deck.model.run.damping_changes[0].alpha, 40.0);
}

TEST(SpringKeywords, DampingRefusesSkewsAndDirections) {
  SpringDeck d;
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(-0.01) + I(40) + "\n";
  EXPECT_NE(error_of(d).find("beta"), std::string::npos) << error_of(d);
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(0.0) + I(40) + I(2) + "\n";
  EXPECT_NE(error_of(d).find("skew_ID"), std::string::npos) << error_of(d);
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(0.0) + I(40) + "\n" + R(2.0) + R(0.0) + "\n";
  EXPECT_NE(error_of(d).find("alpha_y"), std::string::npos) << error_of(d);
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(0.0) + I(41) + "\n";
  EXPECT_NE(error_of(d).find("grnod_ID"), std::string::npos) << error_of(d);
  d.extra = "/DAMP/3\nrayleigh\n" + R(4.0) + R(0.0) + I(40) + "\n";
  EXPECT_NE(error_of(d, "/RUN/T/1\n1.0\n/DAMP/4\n40 0\n").find("damp_ID"), std::string::npos);
  EXPECT_NE(error_of(d, "/RUN/T/1\n1.0\n/DAMP/3\n40 -0.1\n").find("beta"), std::string::npos);
  EXPECT_NE(error_of(d, "/RUN/T/1\n1.0\n/DAMP/3\n40 0.1 0.5\n").find("alpha, beta"), std::string::npos);
  d.extra += "/AMS\n" + I(0) + "\n";  // selective mass scaling solves the nodes' updates together: not with /DAMP
  EXPECT_NE(error_of(d, "/RUN/T/1\n1.0\n/DT/AMS\n0.67 1e-5\n").find("no /DAMP together with /DT/AMS"),
            std::string::npos);
}

}  // namespace test_spring_keywords
