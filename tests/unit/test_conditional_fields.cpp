// Values that act only with another setting (found by the field probe, docs/validation.md "Field probe"): each is
// a named warning where that setting is missing, never a value silently dropped.
#include <gtest/gtest.h>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_conditional_fields {

using namespace crumple;
using test::I;
using test::R;

namespace {

std::string warnings_of(const std::string& plate_property, const std::string& extra) {
  test::TempDir dir;
  std::string plate = test::plate_cards();
  const auto at = plate.find("/PROP/SHELL/1");
  const auto end = plate.find("/MAT/ELAST/1");
  plate.replace(at, end - at, plate_property);
  dir.write("TEST_0001.rad", test::engine_cards());
  const auto path = dir.write("TEST_0000.rad", test::begin_card() + plate + extra + "/END\n");
  std::string all;
  for (const auto& w : read_deck(path).report.warnings) all += w.text() + "\n";
  return all;
}

std::string shell_property(int ishell, double hm, double dn) {
  return "/PROP/SHELL/1\nshell\n" + I(ishell) + "\n" + R(hm) + R(0.0) + R(0.0) + R(0.0) + R(dn) + "\n" + I(3) + I(0) +
         R(0.001) + "\n";
}

}  // namespace

TEST(ConditionalFields, ShellDampingAndHourglassOutsideTheirFormulationsAreNamed) {
  // dn damps QEPH and QBAT only: the reference's box_crush with Ishell 1 and dn 0.3 has the same energies
  // (measured); QBAT's nodal step under /DT/NODA/CST follows its dn (time-step.md, T-2b).
  EXPECT_NE(warnings_of(shell_property(1, 0.0, 0.3), "").find("dn acts only on 4-node shells with Ishell 24 or 12"),
            std::string::npos);
  EXPECT_EQ(warnings_of(shell_property(24, 0.0, 0.3), "").find("dn acts only"), std::string::npos);
  EXPECT_EQ(warnings_of(shell_property(12, 0.0, 0.3), "").find("dn acts only"), std::string::npos);
  EXPECT_NE(warnings_of(shell_property(24, 0.1, 0.0), "").find("hm, hf and hr act only with Ishell 1 to 4"),
            std::string::npos);
  EXPECT_EQ(warnings_of(shell_property(1, 0.1, 0.0), "").find("hm, hf and hr"), std::string::npos);
}

// 3-node shells have no hourglass modes: hm, hf, hr on a property of triangles alone act on nothing, as in the
// reference (a bent plate of triangles, hm = hf = hr 0.01 and 0.5: the same listing to the last digit).
TEST(ConditionalFields, HourglassCoefficientsOfTrianglesAloneAreNamed) {
  const std::string triangles = "/PROP/SHELL/2\ntriangles\n" + I(0) + "\n" + R(0.1) + R(0.1) + R(0.1) + R(0.0) +
                                R(0.0) + "\n" + I(3) + I(0) + R(0.001) + "\n/PART/2\ntriangles\n" + I(2) + I(1) +
                                "\n/SH3N/2\n" + I(7) + I(1) + I(2) + I(5) + "\n";
  const std::string w = warnings_of(shell_property(1, 0.0, 0.0), triangles);
  EXPECT_NE(w.find("/PROP/SHELL/2: hm, hf and hr act only on 4-node shells"), std::string::npos) << w;
  EXPECT_EQ(w.find("/PROP/SHELL/1: hm"), std::string::npos) << w;
}

TEST(ConditionalFields, DefaultsWithoutTheirElementsAreNamed) {
  const std::string def_solid = "/DEF_SOLID\n" + I(14) + "\n";
  EXPECT_NE(warnings_of(shell_property(24, 0.0, 0.0), def_solid).find("/DEF_SOLID: no brick in the model"),
            std::string::npos);
}

}  // namespace test_conditional_fields
