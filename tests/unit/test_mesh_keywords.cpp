#include <gtest/gtest.h>

#include "crumple/core/geometry.hpp"

#include "crumple/model/mass.hpp"
#include "crumple/elements/critical_step.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_mesh_keywords {

using namespace crumple;
using test::I;
using test::R;

TEST(MeshKeywords, PlateDeckReads) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  EXPECT_EQ(m.nodes.size(), 6u);
  EXPECT_EQ(m.elements[static_cast<int>(ElementKind::Shell4)].size(), 2u);
  EXPECT_EQ(m.element_groups.size(), 1u);
  EXPECT_EQ(m.parts.size(), 1u);
  EXPECT_EQ(m.formulations[0].ishell, 24);
  // 2 elements of 1e-4 m^2, 1 mm thick, 7800 kg/m^3; a corner node carries a quarter of one element.
  EXPECT_NEAR(m.total_mass(), 2 * 7800.0 * 1e-3 * 1e-4, 1e-12);
  EXPECT_NEAR(m.nodal_mass[0], 0.25 * 7800.0 * 1e-3 * 1e-4, 1e-15);
  EXPECT_NEAR(m.nodal_mass[1], 0.5 * 7800.0 * 1e-3 * 1e-4, 1e-15);
}

TEST(MeshKeywords, NodeOfIdZeroIsSkippedWithAWarning) {
  // The reference keeps a /NODE of id 0 (its QA deck of the KJOINT2 joint has one); no card can name it.
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir, "/NODE\n" + I(0) + R(5.0) + R(5.0) + R(5.0) + "\n"));
  EXPECT_EQ(d.model.nodes.size(), 6u);
  std::string warnings;
  for (const auto& w : d.report.warnings) warnings += w.message + "\n";
  EXPECT_NE(warnings.find("a node of id 0"), std::string::npos) << warnings;
}

TEST(MeshKeywords, ElementsOrderedByPartInGroupsOfAtMost128) {
  test::TempDir dir;
  std::string extra = "/NODE\n";
  // A strip of 300 shells in part 2 after the plate's part 1.
  for (int i = 0; i <= 300; ++i)
    extra += I(100 + i) + R(0.01 * i) + R(1.0) + R(0.0) + "\n" + I(1000 + i) + R(0.01 * i) + R(1.01) + R(0.0) + "\n";
  extra += "/SHELL/2\n";
  for (int i = 0; i < 300; ++i) extra += I(500 + i) + I(100 + i) + I(101 + i) + I(1001 + i) + I(1000 + i) + "\n";
  extra += "/PART/2\nstrip\n" + I(1) + I(1) + "\n";
  const Deck d = read_deck(test::write_deck(dir, extra));
  const auto& groups = d.model.element_groups;
  ASSERT_EQ(groups.size(), 4u);  // 2 | 128 128 44
  EXPECT_EQ(groups[0].end - groups[0].begin, 2);
  for (const auto& g : groups) {
    EXPECT_LE(g.end - g.begin, kElementGroupSize);
    for (int e = g.begin; e < g.end; ++e)
      EXPECT_EQ(d.model.elements[0].part[static_cast<std::size_t>(e)], g.part);
  }
}

TEST(MeshKeywords, IncludeIsExpandedRelativeToTheIncludingFile) {
  test::TempDir dir;
  dir.write("parts/mat.inc", "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n");
  std::string plate = test::plate_cards();
  plate = plate.substr(0, plate.find("/MAT/ELAST"));
  dir.write("TEST_0001.rad", test::engine_cards());
  const auto path = dir.write("TEST_0000.rad", test::begin_card() + plate + "#include parts/mat.inc\n/END\n");
  const Deck d = read_deck(path);
  EXPECT_EQ(d.model.materials.size(), 1u);
  EXPECT_EQ(d.report.files.size(), 3u);
}

TEST(MeshKeywords, SmallestTimeStepNamesTheElement) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const ControllingElement c = smallest_element_time_step(d.model);
  // The plate's 10 mm squares are Ishell 24 (QEPH): the reference's length (eq. T-1d) times the factor of its
  // default dn 0.015 (eq. T-1c) over the bar speed.
  const double wave = std::sqrt(2.1e11 / 7800.0), damping = std::sqrt(1.0 + 0.015 * 0.015) - 0.015;
  const double length = geometry::qeph_length({0, 0, 0}, {0.01, 0, 0}, {0.01, 0.01, 0}, {0, 0.01, 0});
  EXPECT_NEAR(c.time_step, length * damping / wave, 1e-12);
  EXPECT_EQ(c.part_user_id, 1);
}

// A shell's thickness: its own on /SHELL (columns 71-90 after the angle), else the property's (1 mm); the mass
// follows, as the reference's part masses (measured). /PART's Thick, a virtual thickness for contact gaps, is an
// option Crumple lacks.
TEST(MeshKeywords, ShellThicknessOverridesThePropertys) {
  test::TempDir dir;
  std::string s = test::begin_card() + "/NODE\n";
  const double xs[3] = {0.0, 0.01, 0.02};
  int id = 1;
  for (double y : {0.0, 0.01})
    for (double x : xs) s += I(id++) + R(x) + R(y) + R(0.0) + "\n";
  s += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(5) + I(4) + R(0.0) + R(0.003) + "\n";  // 3 mm of its own
  s += "/SHELL/2\n" + I(2) + I(2) + I(3) + I(6) + I(5) + "\n";
  s += "/PART/1\nown\n" + I(1) + I(1) + "\n/PART/2\nproperty's\n" + I(1) + I(1) + "\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + "\n\n" + I(0) + I(0) + R(0.001) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  const Model m = read_deck(dir.write("T_0000.rad", s + "/END\n")).model;
  EXPECT_EQ(shell_thickness(m, ElementKind::Shell4, 0), 0.003);
  EXPECT_EQ(shell_thickness(m, ElementKind::Shell4, 1), 0.001);
  EXPECT_NEAR(m.total_mass(), 3.12e-3, 1e-15);  // the reference's starter listing: 3.12e-3 kg
}

}  // namespace test_mesh_keywords
