// /BEAM, /PROP/TYPE3 (/PROP/BEAM) and /TH/BEAM (docs/theory/beam.md): values, defaults, mass, inertia, step, and
// the errors that name what Crumple lacks.
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/elements/beam.hpp"
#include "crumple/elements/critical_step.hpp"
#include "crumple/model/history_variables.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_beam_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

// Beam 7 of part 20 between nodes 101 and 102, 1 m apart along x, oriented by node 103; property 30, material 40.
struct BeamDeck {
  std::string beam_line = I(7) + I(101) + I(102) + I(103);
  std::string flags = std::string(10, ' ') + I(0), damping = R(0.0) + R(0.0);
  std::string section = R(1e-4) + R(1e-9) + R(2e-9) + R(3e-9), releases = "   000 000" + I(0);
  std::string material = "/MAT/LAW1/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  std::string cards() const {
    std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(1.0) + R(0.0) + R(0.0) + "\n" +
                    I(103) + R(0.0) + R(0.0) + R(1.0) + "\n";
    s += "/BEAM/20\n" + beam_line + "\n/PART/20\nbar\n" + I(30) + I(40) + "\n";
    return s + "/PROP/BEAM/30\nbeam\n" + flags + "\n" + damping + "\n" + section + "\n" + releases + "\n" + material;
  }
};
std::string johnson_cook(double c, double eps_max) {
  return "/MAT/LAW2/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + R(2e8) + R(5e8) + R(0.5) +
         R(eps_max) + R(0.0) + "\n" + R(c) + R(1.0) + I(0) + I(0) + R(0.0) + R(0.0) + "\n";
}

std::filesystem::path starter(const test::TempDir& dir, const BeamDeck& d) {
  return dir.write("T_0000.rad", test::begin_card("T") + d.cards() + "/END\n");
}
std::string error_of(const BeamDeck& d) {
  test::TempDir dir;
  return test::first_error(starter(dir, d));
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// rho A L / 2 at each node; df blank is 0.01, and the step (L / c)(sqrt(1 + 2 d^2) - sqrt(2) d) with it (the
// reference's starter prints 1.9001855e-4 for a steel beam of 1 m, measured, BM-8).
TEST(BeamKeywords, ReadsTheBeamItsSectionItsMassAndItsStep) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, BeamDeck{})).model;
  const ElementTable& beams = m.elements[static_cast<int>(ElementKind::Beam)];
  ASSERT_EQ(beams.size(), 1u);
  EXPECT_EQ(beams.user_id[0], 7);
  ASSERT_EQ(beams.orientation_node.size(), 1u);
  EXPECT_EQ(beams.orientation_node[0], 2);
  const BeamSection& b = m.properties[0].beam;
  EXPECT_EQ(m.properties[0].kind, PropertyKind::Beam);
  EXPECT_DOUBLE_EQ(b.area, 1e-4);
  EXPECT_DOUBLE_EQ(b.iyy, 1e-9);
  EXPECT_DOUBLE_EQ(b.izz, 2e-9);
  EXPECT_DOUBLE_EQ(b.ixx, 3e-9);
  EXPECT_DOUBLE_EQ(b.df_or_default(), 0.01);
  EXPECT_NEAR(m.nodal_mass[0], 0.5 * 7800.0 * 1e-4, 1e-12);
  EXPECT_NEAR(initial_element_time_step(m, ElementKind::Beam, 0), 1.9001855e-4, 1e-11);
}

// BM-6: the nodes' rotational inertia, measured on the reference's starter (0.0561639 for the section 1e-4, 1e-9,
// 1e-9, 2e-9 of 1 m; rho L Ixx / 2 when that is larger).
TEST(BeamKeywords, NodeInertiaAsTheReferenceLumpsIt) {
  BeamGroupParameters p;
  p.density = 7800.0, p.area = 1e-4, p.iyy = 1e-9, p.izz = 1e-9, p.ixx = 2e-9;
  EXPECT_NEAR(beam_node_inertia(p, 1.0), 0.0561639, 1e-7);
  p.iyy = 3e-9, p.izz = 2e-9;
  EXPECT_NEAR(beam_node_inertia(p, 1.0), 0.0561717, 1e-7);
  p.area = 1e-2, p.iyy = p.izz = 1e-5, p.ixx = 2e-3;
  EXPECT_NEAR(beam_node_inertia(p, 0.1), 0.78, 1e-9);
}

TEST(BeamKeywords, SectionValuesMustBePositive) {
  BeamDeck d;
  d.section = R(1e-4) + R(0.0) + R(2e-9) + R(3e-9);
  const std::string e = error_of(d);
  EXPECT_TRUE(contains(e, "/PROP/BEAM/30")) << e;
  EXPECT_TRUE(contains(e, "Iyy")) << e;
}

TEST(BeamKeywords, OptionsCrumpleLacksAreNamed) {
  BeamDeck released;
  released.releases = "   000 010" + I(0);
  EXPECT_TRUE(contains(error_of(released), "Wy2")) << error_of(released);
  BeamDeck ismstr;
  ismstr.flags = std::string(10, ' ') + I(2);
  EXPECT_TRUE(contains(error_of(ismstr), "Ismstr")) << error_of(ismstr);
  // LAW2's strain rate and failure act on beams (BM-5c, BM-9): no error.
  BeamDeck rate;
  rate.material = johnson_cook(0.05, 0.2);
  EXPECT_EQ(error_of(rate), "");
  BeamDeck tabulated;  // the reference refuses LAW36 on a beam (its error 3047)
  tabulated.material = "/MAT/PLAS_TAB/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + I(1) + I(0) +
                       R(0.0) + R(0.0) + "\n" + I(0) + R(0.0) + I(0) + "\n" + I(50) + "\n" + R(1.0) + "\n" + R(0.0) +
                       "\n/FUNCT/50\ncurve\n" + R(0.0) + R(2e8) + "\n" + R(1.0) + R(4e8) + "\n";
  const std::string e = error_of(tabulated);
  EXPECT_TRUE(contains(e, "LAW36") && contains(e, "mat_ID")) << e;
}

// BM-0: a vector along the beam orients nothing, said in a warning (the reference's 3090); a vector across it is
// read.
TEST(BeamKeywords, OrientationVectorAlongTheBeamIsWarned) {
  BeamDeck along;
  along.beam_line = I(7) + I(101) + I(102) + I(0) + R(2.0) + R(0.0) + R(0.0);
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, along));
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text() + "\n";
  EXPECT_TRUE(contains(all, "its vector Vx, Vy, Vz lies along it")) << all;
  BeamDeck across;
  across.beam_line = I(7) + I(101) + I(102) + I(0) + R(0.0) + R(1.0) + R(1.0);
  test::TempDir other;
  const Model m = read_deck(starter(other, across)).model;
  const ElementTable& beams = m.elements[static_cast<int>(ElementKind::Beam)];
  ASSERT_EQ(beams.orientation_vector.size(), 3u);
  EXPECT_DOUBLE_EQ(beams.orientation_vector[2], 1.0);
}

TEST(BeamKeywords, TimeHistoryVariables) {
  const HistorySelection all = select_history_variables(HistoryObject::Beam, {"DEF"});
  std::vector<std::string> names;
  for (const HistoryVariable* v : all.variables) names.emplace_back(v->name);
  EXPECT_EQ(names, (std::vector<std::string>{"OFF", "F1", "F2", "F3", "M1", "M2", "M3", "IE"}));
}

}  // namespace test_beam_keywords
