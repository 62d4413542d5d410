// /TRUSS, /PROP/TYPE2 (/PROP/TRUSS) and /TH/TRUSS (docs/theory/truss.md): values, mass, step, and the errors and
// warnings of the materials a truss takes.
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/elements/critical_step.hpp"
#include "crumple/model/history_variables.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_truss_keywords {

using namespace crumple;
using test::I;
using test::R;

namespace {

// Truss 7 of part 20 between nodes 101 and 102, 2 m apart along z; property 30 (`property_line`), material 40.
std::string truss_deck(const std::string& property_line, const std::string& material, const std::string& extra = "") {
  std::string s = "/NODE\n" + I(101) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(102) + R(0.0) + R(0.0) + R(2.0) + "\n";
  s += "/TRUSS/20\n" + I(7) + I(101) + I(102) + "\n/PART/20\nbar\n" + I(30) + I(40) + "\n";
  s += "/PROP/TRUSS/30\nbar\n" + property_line + "\n" + material + extra;
  return s;
}
const std::string kElastic = "/MAT/LAW1/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
std::string johnson_cook(double c, double chard) {
  return "/MAT/LAW2/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + R(2e8) + R(5e8) + R(0.5) + R(0.0) +
         R(0.0) + "\n" + R(c) + R(1.0) + I(0) + I(0) + R(0.0) + R(chard) + "\n";
}

std::filesystem::path starter(const test::TempDir& dir, const std::string& cards) {
  return dir.write("T_0000.rad", test::begin_card("T") + cards + "/END\n");
}
std::string error_of(const std::string& cards) {
  test::TempDir dir;
  return test::first_error(starter(dir, cards));
}
std::string warnings(const Deck& d) {
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text() + "\n";
  return all;
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// rho A L0 / 2 at each node; the step L0 / sqrt(E / rho) (TR-6; the reference's starter prints 1.9272e-4 for a
// steel truss of 1 m, measured).
TEST(TrussKeywords, ReadsTheTrussItsSectionItsMassAndItsStep) {
  test::TempDir dir;
  const Model m = read_deck(starter(dir, truss_deck(R(1e-4) + R(0.005), kElastic))).model;
  const ElementTable& trusses = m.elements[static_cast<int>(ElementKind::Truss)];
  ASSERT_EQ(trusses.size(), 1u);
  EXPECT_EQ(trusses.user_id[0], 7);
  EXPECT_EQ(m.properties[0].kind, PropertyKind::Truss);
  EXPECT_DOUBLE_EQ(m.properties[0].truss.area, 1e-4);
  EXPECT_DOUBLE_EQ(m.properties[0].truss.gap, 0.005);
  EXPECT_NEAR(m.nodal_mass[0], 0.5 * 7800.0 * 1e-4 * 2.0, 1e-12);
  EXPECT_NEAR(m.nodal_mass[1], 0.5 * 7800.0 * 1e-4 * 2.0, 1e-12);
  test::TempDir no_gap;
  const Model n = read_deck(starter(no_gap, truss_deck(R(1e-4), kElastic))).model;
  EXPECT_NEAR(initial_element_time_step(n, ElementKind::Truss, 0), 2.0 / std::sqrt(2.1e11 / 7800.0), 1e-15);
  // A truss with a gap bounds no step (TR-6, measured).
  EXPECT_GT(initial_element_time_step(m, ElementKind::Truss, 0), 1e20);
}

TEST(TrussKeywords, AreaMustBePositive) {
  const std::string e = error_of(truss_deck(R(0.0), kElastic));
  EXPECT_TRUE(contains(e, "/PROP/TRUSS/30")) << e;
  EXPECT_TRUE(contains(e, "Area")) << e;
}

// LAW1 and LAW2 only, as the reference (its error 3046 for LAW36 on a truss, measured); LAW2's c does nothing on a
// truss there (a warning), and its kinematic hardening Chard is refused.
TEST(TrussKeywords, MaterialsATrussTakes) {
  const std::string tab = "/MAT/PLAS_TAB/40\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + I(1) + I(0) +
                          R(0.0) + R(0.0) + "\n" + I(0) + R(0.0) + I(0) + "\n" + I(50) + "\n" + R(1.0) + "\n" +
                          R(0.0) + "\n/FUNCT/50\ncurve\n" + R(0.0) + R(2e8) + "\n" + R(1.0) + R(4e8) + "\n";
  const std::string e = error_of(truss_deck(R(1e-4), tab));
  EXPECT_TRUE(contains(e, "/PART/20")) << e;
  EXPECT_TRUE(contains(e, "mat_ID")) << e;
  EXPECT_TRUE(contains(e, "LAW36")) << e;
  const std::string k = error_of(truss_deck(R(1e-4), johnson_cook(0.0, 0.5)));
  EXPECT_TRUE(contains(k, "Chard")) << k;
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, truss_deck(R(1e-4), johnson_cook(0.05, 0.0))));
  EXPECT_TRUE(contains(warnings(d), "c (strain rate) does nothing on the trusses of part 20")) << warnings(d);
  // A truss part needs a material: mat_ID 0 is for properties that carry their law.
  const std::string none = error_of("/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) +
                                    R(0.0) + "\n/TRUSS/20\n" + I(7) + I(1) + I(2) + "\n/PART/20\nbar\n" + I(30) + I(0) +
                                    "\n/PROP/TRUSS/30\nbar\n" + R(1e-4) + "\n");
  EXPECT_TRUE(contains(none, "mat_ID")) << none;
}

TEST(TrussKeywords, TimeHistoryVariables) {
  const HistorySelection all = select_history_variables(HistoryObject::Truss, {"DEF", "A", "L"});
  std::vector<std::string> names;
  for (const HistoryVariable* v : all.variables) names.emplace_back(v->name);
  EXPECT_EQ(names, (std::vector<std::string>{"OFF", "F", "IE", "PLAS", "A", "L"}));
}

}  // namespace test_truss_keywords
