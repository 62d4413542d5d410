// /SPRING, /PROP/TYPE4 (/PROP/SPRING) and /DAMP, starter and engine (docs/theory/spring.md, damping.md): values,
// defaults, units, and the errors that name the field of an option Crumple lacks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "crumple/elements/critical_step.hpp"
#include "crumple/elements/spring.hpp"
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
  EXPECT_DOUBLE_EQ(s.dof[0].stiffness, 1000.0);
  EXPECT_DOUBLE_EQ(s.dof[0].damping, 20.0);
  EXPECT_DOUBLE_EQ(s.dof[0].delta_min, -0.1);
  EXPECT_DOUBLE_EQ(s.dof[0].delta_max, 0.2);
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
  EXPECT_EQ(s.dof[0].function, 0);
  EXPECT_DOUBLE_EQ(s.dof[0].function_scale, 2.0);
  EXPECT_DOUBLE_EQ(s.dof[0].abscissa_scale, 0.5);
  // eq. SP-4b: the steepest segment, (4000 - 20) / 0.99 = 4020.2, times A / Ascale = 4
  const double k = 4.0 * 3980.0 / 0.99;
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), 2.0 / std::sqrt(2.0 * k), 1e-12);
}

TEST(SpringKeywords, BlankFailureElongationsNeverBreak) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, SpringDeck{})).model;
  EXPECT_LE(m.properties[0].spring.dof[0].delta_min, -1e30);
  EXPECT_GE(m.properties[0].spring.dof[0].delta_max, 1e30);
}

TEST(SpringKeywords, RefusedOptionsNameTheirField) {
  SpringDeck d;
  d.line1 = R(0.0);
  EXPECT_NE(error_of(d).find("Mass"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(5);  // no /FUNCT/5
  EXPECT_NE(error_of(d).find("fct_ID11"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(8) + I(0) + I(6);  // a rate function that does not exist
  d.extra = "/FUNCT/8\nforce\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  EXPECT_NE(error_of(d).find("fct_ID21"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(4);  // H 4 without its curve: the reference's error 231
  EXPECT_NE(error_of(d).find("fct_ID11"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line2 = R(1000.0) + R(0.0) + R(-1.0);  // a negative function scale (the reference's step is then NaN)
  EXPECT_NE(error_of(d).find("field A"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(3);
  EXPECT_NE(error_of(d).find("field H"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(8) + I(5);  // hardening 5 without its residual elongation function (the reference's error 231)
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  EXPECT_NE(error_of(d).find("fct_ID31"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(8) + I(4);  // kinematic hardening without its lower curve
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  EXPECT_NE(error_of(d).find("fct_ID31"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line3 = I(0) + I(1);  // a hardening flag without its curve: linear, as the reference (measured), with a warning
  {
    test::TempDir dir;
    const Deck r = read_deck(starter(dir, d));
    EXPECT_EQ(r.model.properties[0].spring.dof[0].hardening, 0);
    bool warned = false;
    for (const auto& w : r.report.warnings) warned = warned || w.message.find("without a curve") != std::string::npos;
    EXPECT_TRUE(warned);
  }
  d = SpringDeck{};
  d.line3 = I(8) + I(1);  // isotropic hardening on a curve that is not odd about 0
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(0.0) + R(0.0) + "\n" + R(1.0) + R(20.0) + "\n";
  EXPECT_NE(error_of(d).find("odd about 0"), std::string::npos) << error_of(d);
  d = SpringDeck{};  // on a linear spring: B and D ignored, as the reference ignores them, each with a warning
  d.line2 = R(1000.0) + R(0.0) + R(1.0) + R(0.5) + R(3.0);
  {
    test::TempDir dir;
    const Deck r = read_deck(starter(dir, d));
    int warned = 0;
    for (const auto& w : r.report.warnings) warned += w.message.find("logarithmic rate effect") != std::string::npos;
    EXPECT_EQ(warned, 2);
  }
  d = SpringDeck{};
  d.line1 = R(2.0) + std::string(30, ' ') + I(0) + I(0) + I(2);
  EXPECT_NE(error_of(d).find("Ileng"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.spring_line = I(7) + I(101) + I(102) + std::string(60, ' ') + I(3);
  EXPECT_NE(error_of(d).find("Skew_ID"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line2 = R(0.0) + R(0.0);
  EXPECT_NE(error_of(d).find("K, C"), std::string::npos) << error_of(d);
}

// The rate effects (SP-23): B over A, |D|, g's scale E over A, F and Hscale read with their defaults and units; the
// step takes h's steepest slope over F, times Hscale, as a dashpot (SP-23b); on a linear spring B, g and E are
// warnings and dropped, h stays.
TEST(SpringKeywords, RateEffectsReadTheirScalesAndStep) {
  const std::string functions = "/FUNCT/8\nforce\n" + R(-1.0) + R(-20.0) + "\n" + R(0.0) + R(0.0) + "\n" + R(0.01) +
                                R(10.0) + "\n" + R(1.0) + R(208.0) + "\n/FUNCT/9\nrate\n" + R(-1.0) + R(-3.0) + "\n" +
                                R(0.0) + R(0.0) + "\n" + R(0.01) + R(1.0) + "\n" + R(1.0) + R(3.0) + "\n";
  SpringDeck d;
  d.line2 = R(1000.0) + R(5.0) + R(2.0) + R(0.5) + R(-0.01);
  d.line3 = I(8) + I(0) + I(9) + I(0) + I(9);
  d.line4 = R(0.5) + R(3.0) + R(0.0) + R(2.0);
  d.extra = functions;
  {
    test::TempDir dir;
    const Model m = read_deck(starter(dir, d)).model;
    const SpringLaw& law = m.properties[0].spring.dof[0];
    EXPECT_DOUBLE_EQ(law.log_rate, 0.25);  // B / A
    EXPECT_DOUBLE_EQ(law.log_rate_reference, 0.01);  // |D|
    EXPECT_DOUBLE_EQ(law.rate_factor_scale, 1.5);  // E / A
    EXPECT_DOUBLE_EQ(law.rate_scale, 0.5);
    EXPECT_DOUBLE_EQ(law.rate_force_scale, 2.0);
    EXPECT_EQ(law.rate_factor_function, 1);
    EXPECT_EQ(law.rate_force_function, 1);
    // SP-4 with K_e = max(K, A max|f'|) = 2000 and C_e = C + Hscale max|h'| / F = 5 + 2 100 / 0.5 = 405
    EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), 2.0 / (std::sqrt(2.0 * 2000.0 + 405.0 * 405.0) + 405.0),
                1e-15);
    const SpringDofParameters p = spring_parameters(m.properties[0].spring, m.functions).dof[0];
    // g(2) = 3 + 2 / 0.99 on its last segment, extended; g(-0.01) = -0.03 and h(-2) = -6 on its first
    EXPECT_NEAR(spring_rate_factor(p, 1.0), 1.0 + 0.25 * std::log(100.0) + 1.5 * (3.0 + 2.0 / 0.99), 1e-12);
    EXPECT_NEAR(spring_rate_factor(p, -0.005), 1.0 + 1.5 * -0.03, 1e-15);  // below D no log term; g signed
    EXPECT_NEAR(spring_rate_force(p, -1.0), 2.0 * -6.0, 1e-12);
  }
  d.line3 = I(0) + I(0) + I(9) + I(0) + I(9);  // linear: B, D, g, E dropped with warnings; h acts
  {
    test::TempDir dir;
    const Deck r = read_deck(starter(dir, d));
    const SpringLaw& law = r.model.properties[0].spring.dof[0];
    EXPECT_EQ(law.log_rate, 0.0);
    EXPECT_EQ(law.rate_factor_function_id, 0);
    EXPECT_EQ(law.rate_force_function, 1);
    std::string fields;
    for (const auto& w : r.report.warnings) fields += w.message + "\n";
    for (const char* field : {"field B", "field D", "field fct_ID21", "field E", "field A"})
      EXPECT_NE(fields.find(field), std::string::npos) << field << " in\n" << fields;
  }
}

// sens_ID and Isflag (SP-24): the sensor's window resolved onto the spring; Isflag outside 0 to 2, a sensor that does
// not exist, a sensor on a hardening law, are errors naming the field; Isflag without a sensor a warning.
TEST(SpringKeywords, SensorSwitchesTheSpring) {
  const std::string sensor = "/SENSOR/TIME/5\nsensor\n" + R(0.25) + "\n";
  SpringDeck d;
  d.line1 = R(2.0) + std::string(30, ' ') + I(5) + I(2);
  d.extra = sensor;
  {
    test::TempDir dir;
    const SpringSwitch sw = read_deck(starter(dir, d)).model.properties[0].spring.sensor;  // a copy: the deck goes
    EXPECT_EQ(sw.sensor_id, 5);
    EXPECT_EQ(sw.flag, 2);
    EXPECT_DOUBLE_EQ(sw.on, 0.25);
  }
  d.line1 = R(2.0) + std::string(30, ' ') + I(5) + I(3);
  EXPECT_NE(error_of(d).find("Isflag"), std::string::npos) << error_of(d);
  d.line1 = R(2.0) + std::string(30, ' ') + I(6) + I(0);
  EXPECT_NE(error_of(d).find("sens_ID"), std::string::npos) << error_of(d);
  d.line1 = R(2.0) + std::string(30, ' ') + I(5) + I(0);
  d.line3 = I(8) + I(1);  // a hardening law
  d.extra = sensor + "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  EXPECT_NE(error_of(d).find("sens_ID"), std::string::npos) << error_of(d);
  d = SpringDeck{};
  d.line1 = R(2.0) + std::string(30, ' ') + I(0) + I(1);
  test::TempDir dir;
  std::string warnings;
  for (const auto& w : read_deck(starter(dir, d)).report.warnings) warnings += w.message;
  EXPECT_NE(warnings.find("Isflag"), std::string::npos) << warnings;
}

// A hardening spring's K below its curve's steepest slope unloads at that slope, as the reference runs it (SP-4c),
// with a warning; a nonlinear elastic spring (H 0) takes the slope for its step only.
TEST(SpringKeywords, HardeningStiffnessRaisedToTheCurvesSlope) {
  test::TempDir dir;
  SpringDeck d;
  d.line2 = R(500.0) + R(0.0) + R(2.0);  // K 500, A 2
  d.line3 = I(8) + I(2);
  d.line4 = R(0.0) + R(0.0) + R(0.5);  // Ascale 0.5: the slope A 2000 / Ascale = 8000
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-515.0) + "\n" + R(-0.01) + R(-20.0) + "\n" + R(0.0) + R(0.0) + "\n" +
            R(0.01) + R(20.0) + "\n" + R(1.0) + R(515.0) + "\n";
  const Deck r = read_deck(starter(dir, d));
  bool warned = false;
  for (const auto& w : r.report.warnings) warned = warned || w.message.find("steepest slope") != std::string::npos;
  EXPECT_TRUE(warned);
  const SpringGroupParameters p = spring_parameters(r.model.properties[0].spring, r.model.functions);
  EXPECT_DOUBLE_EQ(p.dof[0].stiffness, 8000.0);
  EXPECT_DOUBLE_EQ(p.dof[0].step_stiffness, 8000.0);
  d.line3 = I(8) + I(0);  // H 0: the force is the curve's; K only bounds the step
  const Deck e = read_deck(starter(dir, d));
  const SpringGroupParameters elastic = spring_parameters(e.model.properties[0].spring, e.model.functions);
  EXPECT_DOUBLE_EQ(elastic.dof[0].stiffness, 500.0);
  EXPECT_DOUBLE_EQ(elastic.dof[0].step_stiffness, 8000.0);
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

// A /PROP/TYPE8 card: line 1 (Mass 0.5, Inertia `inertia`, then flags), six laws of three lines, the rate line.
std::string general_property(const std::array<std::string, 6>& k_c, double inertia = 0.01, const std::string& flags = "",
                             const std::string& law2_x = I(0)) {
  std::string s = "/PROP/TYPE8/30\ngeneral\n" + R(0.5) + R(inertia) + flags + "\n";
  for (std::size_t d = 0; d < 6; ++d)
    s += (k_c[d].empty() ? R(0.0) : k_c[d]) + "\n" + (d == 0 ? law2_x : I(0)) + "\n" + R(0.0) + "\n";
  return s + I(0) + R(0.0) + "\n";
}

std::string general_deck(const std::string& property) {
  std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(0.0) + R(1.0) + R(0.0) + "\n";
  s += "/SPRING/20\n" + I(7) + I(101) + I(102) + "\n/PART/20\nsprings\n" + I(30) + I(0) + "\n" + property;
  return s + "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
}

std::string general_error(const std::string& property) {
  test::TempDir dir;
  return test::first_error(dir.write("T_0000.rad", test::begin_card("T") + general_deck(property) + "/END\n"));
}

// SP-9, SP-10: six laws in the global axes; the translations step as one of mass M with their largest K and C, the
// rotations as one of inertia I (measured on the reference: K 1000 on X beside C 3 on Y steps as K 1000 with C 3).
TEST(SpringKeywords, GeneralSpringReadsSixLawsAndSteps) {
  test::TempDir dir;
  const std::string property =
      general_property({R(1000.0), R(200.0) + R(3.0), "", R(100.0), R(0.0) + R(0.05), ""});
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + general_deck(property) + "/END\n")).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_EQ(s.frame, SpringFrame::Global);
  EXPECT_DOUBLE_EQ(s.inertia, 0.01);
  EXPECT_DOUBLE_EQ(s.dof[1].damping, 3.0);
  EXPECT_DOUBLE_EQ(s.dof[3].stiffness, 100.0);
  const double translation = 0.5 / (std::sqrt(1000.0 * 0.5 + 9.0) + 3.0);    // 1.9561e-2, the reference's
  const double rotation = 0.01 / (std::sqrt(100.0 * 0.01 + 0.0025) + 0.05);  // 9.5125e-3, the reference's
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), std::min(translation, rotation), 1e-15);
  EXPECT_NEAR(rotation, 9.5124921972504e-3, 1e-13);
}

// Ileng 1 (SP-21): the spring of rest length L0 = 0.5 (nodes moved apart) is the one of M L0, K / L0, C / L0, its
// curve of the strain; its limit stays a length. The reference's starter step for M 1, K 1e6, L0 0.5 is 5e-4.
TEST(SpringKeywords, InputPerUnitLengthScalesByTheRestLength) {
  test::TempDir dir;
  SpringDeck d;
  d.line1 = R(1.0) + std::string(30, ' ') + I(0) + I(0) + I(1);
  d.line2 = R(1e6);
  d.line3 = I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') + R(0.0) + R(0.01);
  d.spring_line = I(7) + I(101) + I(103);
  d.extra = "/NODE\n" + I(103) + R(0.0) + R(0.5) + R(0.0) + "\n";
  const Model m = read_deck(starter(dir, d)).model;
  EXPECT_TRUE(m.properties[0].spring.per_unit_length);
  EXPECT_DOUBLE_EQ(m.element_mass, 0.5);
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), 5e-4, 1e-15);
  const SpringGroupParameters group = spring_parameters(m.properties[0].spring, m.functions);
  const SpringGroupParameters p = spring_of_length(group, 0.5);
  EXPECT_DOUBLE_EQ(p.dof[0].stiffness, 2e6);
  EXPECT_DOUBLE_EQ(p.dof[0].delta_max, 0.01);  // a 1-D spring's limit is not scaled (measured)
  EXPECT_DOUBLE_EQ(spring_of_length(p, 0.5).dof[0].stiffness, 2e6);  // scaled once: p is a spring's own
  SpringGroupParameters beam = group;  // a beam-type spring's elongation limits are strains; its curves' too
  beam.frame = SpringFrame::Beam, beam.dof[0].abscissa_scale = 1.0;
  const SpringGroupParameters q = spring_of_length(beam, 2.0);
  EXPECT_DOUBLE_EQ(q.dof[0].delta_max, 0.02);
  EXPECT_DOUBLE_EQ(q.dof[0].abscissa_scale, 2.0);
  EXPECT_DOUBLE_EQ(q.dof[1].delta_max, 1e30);  // no limit stays none
  // A beam-type spring between coincident nodes has no length to scale by.
  std::string beam_property = "/PROP/TYPE13/30\nbeam\n" + R(2.0) + R(1.0) + I(0) + I(0) + I(0) + I(0) + I(1) + "\n";
  for (double k : {100.0, 100.0, 100.0, 10.0, 10.0, 10.0}) beam_property += R(k) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  std::string coincident = general_deck(beam_property);
  coincident.replace(coincident.find(I(102) + R(0.0) + R(1.0)), 60, I(102) + R(0.0) + R(0.0));
  test::TempDir other;
  const std::string error = test::first_error(other.write("T_0000.rad", test::begin_card("T") + coincident + "/END\n"));
  EXPECT_NE(error.find("Ileng 1"), std::string::npos) << error;
}

// /PROP/SPR_PRE (SP-22): F1, D1, E1, K1 resolved from the two given, as the reference's starter echoes them (F1 100
// and D1 0.1, or D1 and K1, or E1 and K1: F1 100, D1 0.1, E1 5, K1 1000); more than two, an unknown force function,
// a sensor that turns off are errors naming the field; the step is the 1-D spring's of M and K0.
TEST(SpringKeywords, PretensionerResolvesItsForceStrokeEnergyAndStiffness) {
  auto deck = [](const std::string& line2, const std::string& line3 = "", const std::string& sensor_off = "") {
    std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(1.0) + R(0.0) + R(0.0) + "\n";
    s += "/SPRING/20\n" + I(7) + I(101) + I(102) + "\n/PART/20\npretensioner\n" + I(30) + I(0) + "\n";
    s += "/PROP/SPR_PRE/30\npretensioner\n" + R(0.001) + std::string(30, ' ') + I(4) + I(2) + "\n" + line2 + "\n" + line3 + "\n";
    return s + "/SENSOR/TIME/4\nsensor\n" + R(0.01) + sensor_off + "\n";
  };
  for (const std::string& given : {R(1e5) + R(100.0) + R(0.1), R(1e5) + R(0.0) + R(0.1) + R(0.0) + R(1000.0),
                                   R(1e5) + R(0.0) + R(0.0) + R(5.0) + R(1000.0)}) {
    test::TempDir dir;
    const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + deck(given) + "/END\n")).model;
    const SpringPretension& p = m.properties[0].spring.pretension;
    EXPECT_TRUE(p.on);
    EXPECT_TRUE(p.lock);
    EXPECT_DOUBLE_EQ(p.activation_time, 0.01);
    EXPECT_NEAR(p.force, 100.0, 1e-9);
    EXPECT_NEAR(p.force / p.stiffness, 0.1, 1e-12);  // the stroke D1
    EXPECT_NEAR(p.energy, 5.0, 1e-9);
    EXPECT_NEAR(p.stiffness, 1000.0, 1e-9);
    EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), std::sqrt(0.001 / 1e5), 1e-15);
  }
  auto error = [&](const std::string& d, int version = 2019) {
    test::TempDir dir;
    return test::first_error(dir.write("T_0000.rad", test::begin_card("T", version) + d + "/END\n"));
  };
  EXPECT_NE(error(deck(R(1e5) + R(100.0) + R(0.1) + R(5.0))).find("F1, D1, E1, K1"), std::string::npos);
  EXPECT_NE(error(deck(R(1e5) + R(100.0), I(5))).find("fct_ID1"), std::string::npos);  // no /FUNCT/5
  EXPECT_NE(error(deck(R(1e5) + R(100.0), "", "\n" + R(0.5)), 2023).find("sens_ID"), std::string::npos);
  EXPECT_NE(error(deck(R(0.0) + R(100.0))).find("K0"), std::string::npos);
}

// /PROP/SPR_PRE in function mode (SP-22b, SP-22c): the functions and their scales read, D1 the stroke, F1, E1 and K1
// warnings; the energy stored from t = 0 as the reference's starter takes it (its probes e_fb_D0.04: 3.85556,
// e_fb_sd2: 2.25, m_f2_100: 0.05, m_f1f2: 450).
TEST(SpringKeywords, PretensionerInFunctionModeStoresTheReferencesEnergy) {
  // f1 (-1, -950) (-0.06, 0) (-0.03, 100) (0, 100) (1, 100), the reference probes' "fb"; f2 (0, 100) (1, 100).
  std::string functions = "/FUNCT/71\nf1\n";
  for (const auto& [x, y] : {std::pair{-1.0, -950.0}, {-0.06, 0.0}, {-0.03, 100.0}, {0.0, 100.0}, {1.0, 100.0}})
    functions += R(x) + R(y) + "\n";
  functions += "/FUNCT/72\nf2\n" + R(0.0) + R(100.0) + "\n" + R(1.0) + R(100.0) + "\n";
  auto energy = [&](const std::string& line2, const std::string& line3, std::string* warnings = nullptr) {
    std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(1.0) + R(0.0) + R(0.0) + "\n";
    s += "/SPRING/20\n" + I(7) + I(101) + I(102) + "\n/PART/20\npretensioner\n" + I(30) + I(0) + "\n";
    s += "/PROP/SPR_PRE/30\npretensioner\n" + R(0.001) + "\n" + line2 + "\n" + line3 + "\n" + functions;
    test::TempDir dir;
    const Deck d = read_deck(dir.write("T_0000.rad", test::begin_card("T") + s + "/END\n"));
    if (warnings != nullptr)
      for (const auto& w : d.report.warnings) *warnings += w.message + "\n";
    return pretension_stored_energy(spring_parameters(d.model.properties[0].spring, d.model.functions));
  };
  std::string warnings;
  // D1 0.04: the area over [-0.04, 0], 3.8333, and (f1(-0.04))^2 / (2 K0) = 66.667^2 / 2e5
  EXPECT_NEAR(energy(R(1e5) + R(100.0) + R(0.04) + R(5.0), I(71), &warnings), 3.85556, 1e-5);
  for (const char* field : {"field F1", "field E1"}) EXPECT_NE(warnings.find(field), std::string::npos) << warnings;
  // no D1, f1 <= 0 at its first point: from there, its negative segment left out, no extra term; Scale_d 2 divides
  EXPECT_NEAR(energy(R(1e5), I(71) + I(0) + std::string(20, ' ') + R(0.0) + R(2.0)), 2.25, 1e-9);
  EXPECT_NEAR(energy(R(1e5), I(0) + I(72)), 100.0 * 100.0 / 2e5, 1e-12);
  EXPECT_NEAR(energy(R(1e5), I(71) + I(72)), 450.0, 1e-9);  // S = f2's first ordinate 100 times the area 4.5
  test::TempDir dir;
  const std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(1.0) + R(0.0) + R(0.0) +
                        "\n/SPRING/20\n" + I(7) + I(101) + I(102) + "\n/PART/20\np\n" + I(30) + I(0) +
                        "\n/PROP/SPR_PRE/30\np\n" + R(0.001) + "\n" + R(1e5) + R(0.0) + R(-0.3) + "\n" + I(71) + I(72) +
                        std::string(20, ' ') + R(2.0) + R(0.5) + R(3.0) + "\n" + functions;
  const Deck d = read_deck(dir.write("T_0000.rad", test::begin_card("T") + s + "/END\n"));
  const SpringPretension& p = d.model.properties[0].spring.pretension;
  EXPECT_TRUE(p.by_functions());
  EXPECT_DOUBLE_EQ(p.stroke, 0.3);
  EXPECT_DOUBLE_EQ(p.time_scale, 2.0);
  EXPECT_DOUBLE_EQ(p.stroke_scale, 0.5);
  EXPECT_DOUBLE_EQ(p.force_scale, 3.0);
  EXPECT_EQ(p.stroke_function, 0);
  EXPECT_EQ(p.time_function, 1);
}

TEST(SpringKeywords, GeneralSpringRefusalsNameTheirField) {
  EXPECT_NE(general_error(general_property({R(1000.0), "", "", R(100.0), "", ""}, 0.0)).find("Inertia"),
            std::string::npos);
  EXPECT_NE(general_error(general_property({R(1000.0), "", "", "", "", ""}, 0.01, I(5))).find("skew_ID"),
            std::string::npos);
  // Ifail is 0 (each law on its own) or 1 (combined, SP-5b); the reference runs a general spring's 2 as 1.
  EXPECT_NE(general_error(general_property({R(1000.0), "", "", "", "", ""}, 0.01, I(0) + I(0) + I(0) + I(3)))
                .find("Ifail"),
            std::string::npos);
  // The second degree of freedom's hardening names its own field.
  const std::string y_hardening = general_property({R(1000.0), R(1000.0), "", "", "", ""}, 0.01, "", I(0));
  std::string bad = y_hardening;
  const std::string y_line = "\n" + R(1000.0) + "\n" + I(0) + "\n";
  bad.replace(bad.find(y_line, bad.find(y_line) + 1), y_line.size(), "\n" + R(1000.0) + "\n" + I(8) + I(3) + "\n");
  EXPECT_NE(general_error(bad).find("H2"), std::string::npos) << general_error(bad);
}

// SP-11, H 5: loading on the curve, unloading from the peak along P to the residual elongation g(peak), reloading
// along S; the compression side its mirror, on its own.
TEST(SpringKeywords, ResidualHardeningFollowsItsCurves) {
  Function f, g;
  f.x = {-1.0, -0.01, 0.0, 0.01, 1.0}, f.y = {-515.0, -20.0, 0.0, 20.0, 515.0};
  g.x = {-1.0, 0.0, 1.0}, g.y = {-0.5, 0.0, 0.5};
  SpringDofParameters p;
  p.stiffness = 2000.0, p.function = &f, p.hardening = 5, p.lower_function = &g;
  double a = 0.0, b = 0.0, force = 0.0, delta = 0.0;
  auto go = [&](double to) { force = spring_elastic_force(p, to, delta, force, a, b), delta = to; };
  go(0.05);
  EXPECT_DOUBLE_EQ(force, 40.0);  // on the curve
  EXPECT_DOUBLE_EQ(a, 0.05);
  go(0.049);  // the unloading curve P leaves the peak at slope K: 40 - 2000 * 0.001, to first order
  const double n = 2000.0 * 0.025 / 40.0, x = (0.049 - 0.025) / 0.025;
  EXPECT_NEAR(force, 40.0 * std::pow(x, n), 1e-12);
  go(0.02);  // below the residual elongation 0.025: no force
  EXPECT_DOUBLE_EQ(force, 0.0);
  go(0.045);  // reloading along S, the line from (0.025, 0) to the peak
  EXPECT_NEAR(force, 40.0 * (0.045 - 0.025) / 0.025, 1e-12);
  go(-0.05);  // compression: its own virgin curve
  EXPECT_DOUBLE_EQ(force, -40.0);
  EXPECT_DOUBLE_EQ(b, -0.05);
  EXPECT_DOUBLE_EQ(a, 0.05);
}

// SP-12 to SP-14: H 6 unloads along fct_ID31 inside its isotropic yield band, H 7 loads on f and unloads held above
// fct_ID31 with no permanent elongation, H 8 reads f at the total length.
TEST(SpringKeywords, UnloadingCurveHysteresisAndTotalLength) {
  Function f, g;
  f.x = {-1.0, -0.01, 0.0, 0.01, 1.0}, f.y = {-515.0, -20.0, 0.0, 20.0, 515.0};
  g.x = {-1.0, -0.01, 0.0, 0.01, 1.0}, g.y = {-200.0, -5.0, 0.0, 5.0, 200.0};
  SpringDofParameters p;
  p.stiffness = 2000.0, p.function = &f, p.lower_function = &g;
  double a = 0.0, b = 0.0, force = 0.0, delta = 0.0;
  auto go = [&](double to) { force = spring_elastic_force(p, to, delta, force, a, b, 1.0), delta = to; };
  p.hardening = 6;
  go(0.05);
  EXPECT_DOUBLE_EQ(force, 40.0);  // the first loading: on f, x = 0.05
  go(0.04);  // unloading at the slope of g's segment holding 40 N, 195/0.99 N/m
  EXPECT_NEAR(force, 40.0 - 0.01 * 195.0 / 0.99, 1e-12);
  p.hardening = 7, a = 0.0, force = 0.0, delta = 0.0;
  go(0.05);
  EXPECT_DOUBLE_EQ(force, 40.0);  // loading at K 2000, capped by f
  go(0.049);
  EXPECT_DOUBLE_EQ(force, 38.0);  // unloading at K, above g (9.7 N)
  go(0.02);
  EXPECT_NEAR(force, 5.0 + 195.0 * 0.01 / 0.99, 1e-12);  // held on g
  p.hardening = 8;
  go(0.0);  // the curve at the length at rest, 1 m: 515 N
  EXPECT_DOUBLE_EQ(force, 515.0);
}

TEST(SpringKeywords, HysteresisWithoutItsUnloadingCurveRunsAsUncoupled) {
  test::TempDir dir;
  SpringDeck d;
  d.line3 = I(8) + I(7);
  d.extra = "/FUNCT/8\nyield\n" + R(-1.0) + R(-30.0) + "\n" + R(1.0) + R(30.0) + "\n";
  const Deck r = read_deck(starter(dir, d));
  EXPECT_EQ(r.model.properties[0].spring.dof[0].hardening, 2);
  bool warned = false;
  for (const auto& w : r.report.warnings) warned = warned || w.message.find("H 7") != std::string::npos;
  EXPECT_TRUE(warned);
  // A general spring's law takes no total length (H 8).
  const std::string y_line = "\n" + R(1000.0) + "\n" + I(0) + "\n";
  std::string bad = general_property({R(1000.0), R(1000.0), "", "", "", ""});
  bad.replace(bad.find(y_line, bad.find(y_line) + 1), y_line.size(), "\n" + R(1000.0) + "\n" + I(8) + I(8) + "\n");
  EXPECT_NE(general_error(bad).find("H2"), std::string::npos) << general_error(bad);
}

// SP-18: a beam-type spring's rotations step with their largest stiffness plus the shear's times l^2, and likewise
// the damping (measured on the reference's starter: shear 100 beside bending 10 at l = 1, I = 1, steps as sqrt(1/110)).
TEST(SpringKeywords, BeamTypeSpringReadsItsLawsAndSteps) {
  test::TempDir dir;
  std::string property = "/PROP/TYPE13/30\nbeam\n" + R(2.0) + R(1.0) + "\n";
  for (double k : {0.0, 100.0, 0.0, 0.0, 10.0, 0.0}) property += R(k) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  property += R(1.0) + R(1.0) + "\n";
  for (int d = 0; d < 6; ++d) property += "\n" + R(0.0) + R(0.0) + R(1.0) + R(2.0) + "\n";  // blank lines between
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + general_deck(property) + "/END\n")).model;
  EXPECT_EQ(m.properties[0].spring.frame, SpringFrame::Beam);
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Spring, 0), std::min(2.0 / std::sqrt(200.0), 1.0 / std::sqrt(110.0)),
              1e-15);
  EXPECT_NEAR(1.0 / std::sqrt(110.0), 0.095346, 1e-6);  // the reference's starter step
  std::string garbled = property;  // the failure lines are read as numbers although Ifail2 0 ignores them
  garbled.replace(garbled.rfind(R(0.0) + R(0.0) + R(1.0)), 20, std::string(19, ' ') + "x");
  EXPECT_NE(general_error(garbled).find("field c"), std::string::npos) << general_error(garbled);
  std::string skewed = property;  // a skew that does not exist: an error naming skew_ID
  skewed.replace(skewed.find(R(1.0) + "\n"), R(1.0).size(), R(1.0) + I(5));
  EXPECT_NE(general_error(skewed).find("skew_ID"), std::string::npos) << general_error(skewed);
}

// A field holding two numbers (a misaligned deck) reads the first, as the reference does; anything else is an error.
TEST(SpringKeywords, FieldOfTwoNumbersReadsTheFirst) {
  test::TempDir dir;
  SpringDeck d;
  d.line3 = I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') + R(0.0) + "0.03      .000000000";
  EXPECT_DOUBLE_EQ(read_deck(starter(dir, d)).model.properties[0].spring.dof[0].delta_max, 0.03);
  d.line3 = I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') + R(0.0) + "0.03      x";
  EXPECT_NE(error_of(d).find("delta_max"), std::string::npos) << error_of(d);
}

// node_ID3 orients a beam-type spring (SP-15) and is refused on the other types, naming the field.
TEST(SpringKeywords, OrientationNodeOnlyForBeamTypeSprings) {
  SpringDeck d;
  d.spring_line = I(7) + I(101) + I(102) + I(101);
  EXPECT_NE(error_of(d).find("node_ID3"), std::string::npos) << error_of(d);
  test::TempDir dir;
  std::string property = "/PROP/TYPE13/30\nbeam\n" + R(2.0) + R(1.0) + "\n";
  for (int k = 0; k < 6; ++k) property += R(100.0) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  std::string deck = general_deck(property);
  deck.replace(deck.find(I(7) + I(101) + I(102)), 30, I(7) + I(101) + I(102) + I(103));
  deck += "/NODE\n" + I(103) + R(0.0) + R(0.0) + R(1.0) + "\n";
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + deck + "/END\n")).model;
  const ElementTable& springs = m.elements[static_cast<int>(ElementKind::Spring)];
  ASSERT_EQ(springs.orientation_node.size(), 1u);
  EXPECT_EQ(springs.orientation_node[0], m.index.nodes.at(103));
}


}  // namespace test_spring_keywords

namespace test_spring_keywords {

// /PROP/TYPE25 (SP-20): TYPE25's layout (F at columns 41-60 of a law's second line, Ascale first on its third), held as
// TYPE13's six laws with shear Y = Z and bending Y = Z; the rate and failure tail may be absent.
TEST(SpringKeywords, AxisymmetricSpringIsABeamTypeSpringWithRadialLaws) {
  auto law = [](double k, double ascale, double delta_max) {
    return R(k) + R(0.0) + R(1.0) + R(0.0) + R(0.0) + "\n" + I(0) + I(0) + I(0) + I(0) + R(1.0) + R(0.0) +
           R(delta_max) + "\n" + R(ascale) + R(0.0) + I(0) + R(0.0) + "\n";
  };
  const std::string cards = "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) + R(0.0) +
                            "\n/SPRING/20\n" + I(7) + I(1) + I(2) + "\n/PART/20\nspring\n" + I(30) + I(0) +
                            "\n/PROP/TYPE25/30\naxi\n" + R(0.01) + R(0.001) + "\n" + law(1e4, 0.0, 0.0) +
                            law(2000.0, 2.0, 0.05) + law(30.0, 0.0, 0.0) + law(40.0, 0.0, 0.25);
  test::TempDir dir;
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + cards + "/END\n")).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_TRUE(s.radial);
  EXPECT_EQ(s.frame, SpringFrame::Beam);
  EXPECT_EQ(s.card(), "SPR_AXI");
  const std::array<double, 6> stiffness{1e4, 2000.0, 2000.0, 30.0, 40.0, 40.0};
  for (std::size_t d = 0; d < 6; ++d) EXPECT_DOUBLE_EQ(s.dof[d].stiffness, stiffness[d]) << d;
  EXPECT_DOUBLE_EQ(s.dof[2].abscissa_scale, 2.0);  // the shear's Ascale, first on its third line
  EXPECT_DOUBLE_EQ(s.dof[1].delta_max, 0.05);
  EXPECT_DOUBLE_EQ(s.dof[5].delta_max, 0.25);  // the bending's limit, on its magnitude (SP-20)
}

// /PROP/TYPE25 with Ifail2 (SP-5b): its limits read as moments with Ifail2 2, Vo and Wo, and the four failure lines
// (tension, shear, torsion, bending) on TYPE13's slots, the radial ones on both of theirs.
TEST(SpringKeywords, AxisymmetricSpringFailureLinesFollowItsFourLaws) {
  auto law = [](double k, double delta_max) {
    return R(k) + R(0.0) + R(1.0) + R(0.0) + R(0.0) + "\n" + I(0) + I(0) + I(0) + I(0) + R(1.0) + R(0.0) +
           R(delta_max) + "\n" + R(1.0) + R(0.0) + I(0) + R(0.0) + "\n";
  };
  std::string cards = "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) + R(0.0) +
                      "\n/SPRING/20\n" + I(7) + I(1) + I(2) + "\n/PART/20\nspring\n" + I(30) + I(0) +
                      "\n/PROP/TYPE25/30\naxi\n" + R(0.01) + R(0.001) + I(0) + I(0) + I(0) + I(0) + I(0) + I(2) + "\n";
  cards += law(1e4, 100.0) + law(2000.0, 50.0) + law(30.0, 0.0) + law(40.0, 6.0);
  cards += R(0.5) + R(4.0) + "\n";
  for (int d = 1; d <= 4; ++d) cards += R(0.1 * d) + R(d) + R(0.0) + R(0.0) + "\n";
  test::TempDir dir;
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + cards + "/END\n")).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_EQ(s.failure.measure, SpringFailureMeasure::Force);
  EXPECT_TRUE(s.failure.rate_effect);
  EXPECT_DOUBLE_EQ(s.failure.translation_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.failure.rotation_rate, 4.0);
  const std::array<double, 6> c{0.1, 0.2, 0.2, 0.3, 0.4, 0.4}, n{1.0, 2.0, 2.0, 3.0, 4.0, 4.0};
  for (std::size_t d = 0; d < 6; ++d) {
    EXPECT_DOUBLE_EQ(s.dof[d].rate_c, c[d]) << d;
    EXPECT_DOUBLE_EQ(s.dof[d].rate_n, n[d]) << d;
    EXPECT_DOUBLE_EQ(s.dof[d].alpha, 1.0) << d;
    EXPECT_DOUBLE_EQ(s.dof[d].beta, 2.0) << d;
  }
  EXPECT_DOUBLE_EQ(s.dof[5].delta_max, 6.0);  // the bending's limit, a moment
}


}  // namespace test_spring_keywords

namespace test_spring_keywords {

// Ifail and Ifail2 of /PROP/TYPE13 (SP-5b): Ifail 1 combines the laws; Ifail2 2 compares forces, its limits read in
// force units, raised by c (|rate| / Vo)^n from the failure lines, whose blank n, alpha, beta are 1, 1, 2.
TEST(SpringKeywords, BeamTypeSpringFailureCriteria) {
  auto law = [](double k, double delta_max) {
    return R(k) + R(0.0) + R(1.0) + R(0.0) + R(0.0) + "\n" + I(0) + I(0) + I(0) + I(0) + I(0) + std::string(10, ' ') +
           R(0.0) + R(delta_max) + "\n" + R(0.0) + R(0.0) + R(1.0) + R(0.0) + "\n";
  };
  std::string cards = "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) + R(0.0) +
                      "\n/SPRING/20\n" + I(7) + I(1) + I(2) + "\n/PART/20\nspring\n" + I(30) + I(0) +
                      "\n/PROP/TYPE13/30\nweld\n" + R(0.01) + R(0.001) + I(0) + I(0) + I(0) + I(1) + I(0) + I(2) + "\n";
  cards += law(1e4, 60.0);
  for (int d = 1; d < 6; ++d) cards += law(100.0, 0.0);
  cards += R(0.5) + R(0.0) + "\n" + R(20.0) + R(0.0) + R(0.0) + R(3.0) + "\n";
  test::TempDir dir;
  const Model m = read_deck(dir.write("T_0000.rad", test::begin_card("T") + cards + "/END\n")).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_TRUE(s.failure.combined);
  EXPECT_EQ(s.failure.measure, SpringFailureMeasure::Force);
  EXPECT_TRUE(s.failure.rate_effect);
  EXPECT_DOUBLE_EQ(s.failure.translation_rate, 0.5);
  EXPECT_DOUBLE_EQ(s.failure.rotation_rate, 1.0);  // Wo blank: 1
  EXPECT_DOUBLE_EQ(s.dof[0].delta_max, 60.0);
  EXPECT_DOUBLE_EQ(s.dof[0].rate_c, 20.0);
  EXPECT_DOUBLE_EQ(s.dof[0].rate_n, 1.0);
  EXPECT_DOUBLE_EQ(s.dof[0].alpha, 1.0);
  EXPECT_DOUBLE_EQ(s.dof[0].beta, 3.0);
}


namespace {
// Two rigid bodies of masses 10 and 2 (their /RBODY masses, Jxx = Jyy = Jzz = 1) and their joint 30 (property 31)
// between node 1 of body 1 and node 2 of body 2, both at the origin; `line1` and `rotation` replace the property's
// line 1 and its first free rotation's three lines.
std::string joint_deck(const std::string& line1, const std::string& rotation, bool node_2_on_body = true) {
  const std::string free_rotation = R(5.0) + I(0) + R(0.0) + R(0.0) + I(0) + "\n" + R(0.5) + I(0) + "\n" + R(0.0) +
                                    R(0.0) + I(0) + "\n";
  std::string s = "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(0.0) + R(0.0) + R(0.0) + "\n";
  s += I(3) + R(0.0) + R(0.0) + R(0.0) + "\n";
  s += I(5) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(6) + R(0.0) + R(0.0) + R(0.0) + "\n";
  s += "/SPRING/20\n" + I(30) + I(1) + I(2) + "\n/PART/20\njoint\n" + I(31) + I(0) + "\n";
  s += "/PROP/TYPE45/31\njoint\n" + line1 + "\n" + rotation + free_rotation + free_rotation;
  s += "/GRNOD/NODE/8\nbody 1\n" + I(1) + "\n/GRNOD/NODE/9\nbody 2\n" + I(node_2_on_body ? 2 : 3) + "\n";
  for (int b = 1; b <= 2; ++b)
    s += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(b == 1 ? 10.0 : 2.0) +
         I(7 + b) + I(0) + I(3) + I(0) + "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  return s;
}
std::string joint_rotation(const std::string& first, const std::string& second = R(0.0) + I(0),
                           const std::string& third = R(0.0) + R(0.0) + I(0)) {
  return first + "\n" + second + "\n" + third + "\n";
}
std::filesystem::path joint_starter(const test::TempDir& dir, const std::string& cards) {
  return dir.write("J_0000.rad", test::begin_card("J") + cards + "/END\n");
}
}  // namespace

// /PROP/TYPE45 (docs/theory/spring.md, SP-25): ScF 0 is 1, Cr 0 is 0.05, each free rotation's linear law acts; every
// option Crumple lacks is an error that names its field, and so is a joint node off every rigid body.
TEST(SpringKeywords, JointReadsItsDefaultsAndRefusesTheRest) {
  const std::string plain = joint_rotation(R(3.0) + I(0) + R(0.0) + R(0.0) + I(0), R(0.25) + I(0));
  {
    test::TempDir dir;
    const Model m = read_deck(joint_starter(dir, joint_deck(I(1) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(0) + I(0), plain))).model;
    const SpringSection& s = m.properties[0].spring;
    EXPECT_TRUE(s.joint.on);
    EXPECT_EQ(s.frame, SpringFrame::Global);
    EXPECT_DOUBLE_EQ(s.joint.stiffness_scale, 1.0);
    EXPECT_DOUBLE_EQ(s.joint.critical_damping, 0.05);
    EXPECT_DOUBLE_EQ(s.dof[3].stiffness, 3.0);
    EXPECT_DOUBLE_EQ(s.dof[3].damping, 0.25);
    EXPECT_DOUBLE_EQ(s.dof[4].stiffness, 5.0);
    EXPECT_DOUBLE_EQ(s.dof[0].stiffness, 0.0);  // the blocking stiffness is the engine's (SP-25c)
    EXPECT_EQ(s.mass, 0.0);
  }
  {
    test::TempDir dir;
    const Model m = read_deck(joint_starter(dir, joint_deck(I(1) + R(0.0) + R(2.0) + R(0.2) + I(0) + I(0) + I(0), plain))).model;
    EXPECT_DOUBLE_EQ(m.properties[0].spring.joint.stiffness_scale, 2.0);
    EXPECT_DOUBLE_EQ(m.properties[0].spring.joint.critical_damping, 0.2);
  }
  const auto error = [](const std::string& cards) {
    test::TempDir dir;
    return test::first_error(joint_starter(dir, cards));
  };
  const std::string line1 = I(1) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(0) + I(0);
  EXPECT_NE(error(joint_deck(I(0) + R(0.0) + R(0.0) + R(0.0), plain)).find("field Type"), std::string::npos);
  EXPECT_NE(error(joint_deck(I(10) + R(0.0) + R(0.0) + R(0.0), plain)).find("field Type"), std::string::npos);
  EXPECT_NE(error(joint_deck(I(1) + R(-1.0), plain)).find("field Kn"), std::string::npos);
  {  // a given Kn: ScF blank is 10 (SP-25i)
    test::TempDir dir;
    const SpringSection s = read_deck(joint_starter(dir, joint_deck(I(1) + R(1e5), plain))).model.properties[0].spring;
    EXPECT_DOUBLE_EQ(s.joint.blocking_stiffness, 1e5);
    EXPECT_DOUBLE_EQ(s.joint.stiffness_scale, 10.0);
  }
  EXPECT_NE(error(joint_deck(I(1) + R(0.0) + R(0.0) + R(0.0) + I(4), plain)).find("field sens_ID"), std::string::npos);
  EXPECT_NE(error(joint_deck(I(1) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(3), plain)).find("field Skew_ID1"),
            std::string::npos);  // no such skew
  const std::string moving = "/SKEW/MOV/3\nmoving\n" + I(1) + I(5) + I(6) + "\n";
  EXPECT_NE(error(joint_deck(I(1) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(3), plain) + moving).find("field Skew_ID1"),
            std::string::npos);  // a moving skew
  EXPECT_NE(error(joint_deck(I(1) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(0) + I(3), plain) + moving).find("field Skew_ID2"),
            std::string::npos);
  EXPECT_NE(error(joint_deck(line1, joint_rotation(R(3.0) + I(7)))).find("field fct_Kr1"), std::string::npos);
  EXPECT_NE(error(joint_deck(line1, joint_rotation(R(3.0) + I(0) + R(-0.1)))).find("field SA1-"), std::string::npos);
  EXPECT_NE(error(joint_deck(line1, joint_rotation(R(3.0), R(0.0) + I(7)))).find("field fct_Cr1"), std::string::npos);
  EXPECT_NE(error(joint_deck(line1, joint_rotation(R(3.0), R(0.0) + I(0), R(0.0) + R(5.0)))).find("field FM1"),
            std::string::npos);
  const std::string off_body = error(joint_deck(line1, plain, false));
  EXPECT_NE(off_body.find("/RBODY of its own"), std::string::npos) << off_body;
}


// /PROP/TYPE45 Type 2 (SP-25, SP-25f): one free rotation's three lines; the /SPRING card's third node sets the axis,
// and a revolute joint without it is an error that names node_ID3.
TEST(SpringKeywords, RevoluteJointReadsItsAxisNode) {
  auto deck = [](bool axis_node) {
    std::string s = "/NODE\n";
    for (const auto& [id, z] : {std::pair{1, 0.0}, {2, 0.0}, {3, 1.0}, {5, 0.0}, {6, 0.0}})
      s += I(id) + R(0.0) + R(0.0) + R(z) + "\n";
    s += "/SPRING/20\n" + I(30) + I(1) + I(2) + (axis_node ? I(3) : "") + "\n/PART/20\njoint\n" + I(31) + I(0) + "\n";
    s += "/PROP/TYPE45/31\nhinge\n" + I(2) + R(0.0) + R(0.0) + R(0.0) + "\n" + R(7.0) + I(0) + "\n" + R(0.3) + I(0) +
         "\n" + R(0.0) + "\n";
    s += "/GRNOD/NODE/8\nbody 1\n" + I(1) + "\n/GRNOD/NODE/9\nbody 2\n" + I(2) + "\n";
    for (int b = 1; b <= 2; ++b)
      s += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(1.0) + I(7 + b) + I(0) + I(3) +
           "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
    return test::begin_card("J") + s + "/END\n";
  };
  test::TempDir dir;
  const Model m = read_deck(dir.write("J_0000.rad", deck(true))).model;
  const SpringSection& s = m.properties[0].spring;
  EXPECT_EQ(s.joint.type, 2);
  EXPECT_TRUE(s.joint.free(3));
  EXPECT_FALSE(s.joint.free(4));
  EXPECT_DOUBLE_EQ(s.dof[3].stiffness, 7.0);
  EXPECT_DOUBLE_EQ(s.dof[3].damping, 0.3);
  const ElementTable& springs = m.elements[static_cast<int>(ElementKind::Spring)];
  ASSERT_FALSE(springs.orientation_node.empty());
  EXPECT_EQ(m.nodes.user_id[static_cast<std::size_t>(springs.orientation_node[0])], 3);
  test::TempDir other;
  const std::string error = test::first_error(other.write("J_0000.rad", deck(false)));
  EXPECT_NE(error.find("node_ID3"), std::string::npos) << error;
}

// /PROP/TYPE45 Types 3 to 9 (SP-25g): the free translations' line groups come first, in the order of their axes, then
// the free rotations'; each is named as the manual names it (Kt1, SD2-, FF3; Kr1), and the rigid joint has none. The
// universal joint's fourth node (SP-25f) must be given, off the line of the first and third.
TEST(SpringKeywords, JointTypesReadTheirFreeDegreesOfFreedom) {
  const auto group = [](double k, double c) {
    return R(k) + I(0) + R(0.0) + R(0.0) + I(0) + "\n" + R(c) + I(0) + "\n" + R(0.0) + R(0.0) + I(0) + "\n";
  };
  // node_ID4 `fourth` (0: none) at (0, 1, 0), or node 7 on the line of nodes 1 and 3
  const auto deck = [](int type, const std::string& groups, int fourth = 4) {
    std::string s = "/NODE\n";
    for (const auto& [id, y, z] : {std::tuple{1, 0.0, 0.0}, {2, 0.0, 0.0}, {3, 0.0, 1.0}, {4, 1.0, 0.0}, {5, 0.0, 0.0},
                                   {6, 0.0, 0.0}, {7, 0.0, 2.0}})
      s += I(id) + R(0.0) + R(y) + R(z) + "\n";
    s += "/SPRING/20\n" + I(30) + I(1) + I(2) + I(3) + I(fourth) + "\n/PART/20\njoint\n" + I(31) + I(0) + "\n";
    s += "/PROP/TYPE45/31\njoint\n" + I(type) + R(0.0) + R(0.0) + R(0.0) + "\n" + groups;
    s += "/GRNOD/NODE/8\nbody 1\n" + I(1) + "\n/GRNOD/NODE/9\nbody 2\n" + I(2) + "\n";
    for (int b = 1; b <= 2; ++b)
      s += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(1.0) + I(7 + b) + I(0) + I(3) +
           "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
    return test::begin_card("J") + s + "/END\n";
  };
  // type, its free degrees of freedom in the order of their line groups
  const std::vector<std::pair<int, std::vector<std::size_t>>> types{
      {3, {0, 3}}, {4, {1, 2, 3}}, {5, {4, 5}}, {6, {0}}, {7, {1, 2}}, {8, {}}, {9, {0, 1, 2, 3, 4, 5}}};
  for (const auto& [type, free] : types) {
    std::string groups;
    for (std::size_t k = 0; k < free.size(); ++k) groups += group(100.0 * static_cast<double>(k + 1), 0.5 * static_cast<double>(k + 1));
    test::TempDir dir;
    const SpringSection s = read_deck(dir.write("J_0000.rad", deck(type, groups))).model.properties[0].spring;
    for (std::size_t d = 0; d < 6; ++d) {
      const auto at = std::find(free.begin(), free.end(), d);
      EXPECT_EQ(s.joint.free(d), at != free.end()) << "type " << type << " dof " << d;
      const double k = at == free.end() ? 0.0 : 100.0 * static_cast<double>(at - free.begin() + 1);
      EXPECT_DOUBLE_EQ(s.dof[d].stiffness, k) << "type " << type << " dof " << d;
      EXPECT_DOUBLE_EQ(s.dof[d].damping, k / 200.0) << "type " << type << " dof " << d;
    }
  }
  {  // a card that ends after line 1: the free ones without stiffness or damping, as the reference reads it
    test::TempDir dir;
    const SpringSection s = read_deck(dir.write("J_0000.rad", deck(3, ""))).model.properties[0].spring;
    EXPECT_TRUE(s.joint.free(0));
    EXPECT_DOUBLE_EQ(s.dof[0].stiffness, 0.0);
    EXPECT_DOUBLE_EQ(s.dof[3].damping, 0.0);
  }
  const auto error = [&deck](int type, const std::string& groups, int fourth = 4) {
    test::TempDir dir;
    return test::first_error(dir.write("J_0000.rad", deck(type, groups, fourth)));
  };
  const std::string two = group(1.0, 0.0) + group(1.0, 0.0);
  EXPECT_NE(error(5, two, 0).find("node_ID4"), std::string::npos);  // the universal joint needs its fourth node
  EXPECT_NE(error(5, two, 7).find("node_ID4"), std::string::npos);  // off the line of the first and third
  const std::string stop = R(1.0) + I(0) + R(-0.1) + "\n" + R(0.0) + I(0) + "\n" + R(0.0) + I(0) + "\n";
  EXPECT_NE(error(6, stop).find("field SD1-"), std::string::npos);
  const std::string friction = R(1.0) + "\n" + R(0.0) + "\n" + R(0.0) + R(4.0) + "\n";
  EXPECT_NE(error(7, friction + group(1.0, 0.0)).find("field FF2"), std::string::npos);
  EXPECT_NE(error(3, group(-1.0, 0.0) + group(1.0, 0.0)).find("field Kt1"), std::string::npos);
  EXPECT_NE(error(4, group(1.0, 0.0)).find("truncated"), std::string::npos);  // groups given, but not all
}

}  // namespace test_spring_keywords
