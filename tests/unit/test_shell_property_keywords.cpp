// /PROP/SHELL (= /PROP/TYPE1) and /DEF_SHELL: column positions, defaults, the flags that act only on the elements
// or the materials they are meant for, and the warnings (docs/theory/shell4.md, "Formulation flags"). The refused
// values have bad-input decks (tests/badinput/decks).
#include <gtest/gtest.h>

#include <string>

#include "deck_files.hpp"

using namespace crumple;
using test::I;
using test::R;

namespace {

// The plate of deck_files.hpp with its property replaced: flags line, hourglass line, section line as written.
std::string plate_with_property(const std::string& flags, const std::string& hourglass, const std::string& section,
                                const std::string& material = "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) +
                                                              R(0.3) + "\n") {
  std::string s = test::plate_cards();
  const auto from = s.find("/PROP/SHELL/1");  // the property and the material are the last cards
  s = s.substr(0, from) + "/PROP/SHELL/1\nshell\n" + flags + "\n" + hourglass + "\n" + section + "\n" + material;
  return s;
}
Deck read(const test::TempDir& dir, const std::string& starter, const std::string& before = "") {
  dir.write("P_0001.rad", test::engine_cards());
  return read_deck(dir.write("P_0000.rad", test::begin_card() + before + starter + "/END\n"));
}
std::string warnings(const Deck& d) {
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text() + "\n";
  return all;
}
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The 2019 layout: Ithick in columns 71-80 and Iplas in 81-90 (columns 61-70 blank), P_thick_fail in 61-80.
TEST(ShellPropertyKeywords, ThirdLineColumns) {
  test::TempDir dir;
  const Deck d = read(dir, plate_with_property(I(1) + I(0) + I(0) + I(0) + test::blank(20) + R(0.0), R(0.0),
                                               I(3) + I(0) + R(0.001) + R(0.8) + test::blank(10) + I(1) + I(1)));
  const ShellSection& s = d.model.properties[0].shell;
  EXPECT_EQ(s.ithick, 1);
  EXPECT_EQ(s.iplas, 1);
  EXPECT_DOUBLE_EQ(s.ashear, 0.8);
}

// Ismstr 0 resolves to 2 (switchable), as in the reference; a property without triangles may carry Ish3n 30 (the
// twisted_beam deck does), which has nothing to act on.
TEST(ShellPropertyKeywords, DefaultsAndIsh3nWithoutTriangles) {
  test::TempDir dir;
  const Deck d = read(dir, plate_with_property(I(12) + I(0) + I(30) + I(0), R(0.01), I(0) + I(1) + R(0.001)));
  EXPECT_EQ(d.model.formulations[0].ishell, 12);
  EXPECT_EQ(d.model.formulations[0].ismstr, 2);
  EXPECT_EQ(d.model.formulations[0].ish3n, 30);
  EXPECT_TRUE(contains(warnings(d), "Istrain 1 (strain output) has no effect")) << warnings(d);
}

// Ishell 2 with N = 1 runs as Ishell 1, Ismstr 3 with another Ishell as Ismstr 2: both said in a warning.
TEST(ShellPropertyKeywords, ReferenceRewritesAreWarnings) {
  test::TempDir dir;
  const Deck a = read(dir, plate_with_property(I(2) + I(0) + I(0) + I(0), R(0.0), I(1) + I(0) + R(0.001)));
  EXPECT_EQ(a.model.formulations[0].ishell, 1);
  EXPECT_TRUE(contains(warnings(a), "Ishell 2 with N = 1 runs as Ishell 1")) << warnings(a);
  const Deck b = read(dir, plate_with_property(I(24) + I(3) + I(0) + I(0), R(0.0), I(3) + I(0) + R(0.001)));
  EXPECT_EQ(b.model.formulations[0].ismstr, 2);
  EXPECT_TRUE(contains(warnings(b), "Ismstr 3 is for Ishell 2 only")) << warnings(b);
}

// Only the first /DEF_SHELL counts; its flags are the defaults of the properties that leave them 0.
TEST(ShellPropertyKeywords, FirstDefShellCounts) {
  test::TempDir dir;
  const std::string def = "/DEF_SHELL\n" + I(12) + I(4) + "\n/DEF_SHELL\n" + I(1) + I(1) + "\n";
  const Deck d = read(dir, plate_with_property(I(0) + I(0) + I(0) + I(0), R(0.0), I(3) + I(0) + R(0.001)), def);
  EXPECT_EQ(d.model.formulations[0].ishell, 12);
  EXPECT_EQ(d.model.formulations[0].ismstr, 4);
  EXPECT_TRUE(contains(warnings(d), "only the first /DEF_SHELL counts")) << warnings(d);
}

// Iplas acts on plastic sections only: Iplas 2 with an elastic law has nothing to act on; with a plastic law and
// points it is refused (bad-input decks iplas_*), with N = 0 accepted (the radial return on the resultants).
TEST(ShellPropertyKeywords, IplasActsOnPlasticSectionsOnly) {
  test::TempDir dir;
  const std::string section2 = I(3) + I(0) + R(0.001) + R(0.0) + test::blank(10) + I(0) + I(2);
  EXPECT_NO_THROW(read(dir, plate_with_property(I(24) + I(0) + I(0) + I(0), R(0.0), section2)));
  const std::string jc = "/MAT/PLAS_JOHNS/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + I(0) + "\n" +
                         R(2.5e8) + R(4.5e8) + R(0.5) + "\n" + R(0.0) + R(0.0) + I(0) + I(0) + R(0.0) + R(0.0) + "\n";
  const std::string resultants2 = I(0) + I(0) + R(0.001) + R(0.0) + test::blank(10) + I(0) + I(2);
  const Deck d = read(dir, plate_with_property(I(24) + I(0) + I(0) + I(0), R(0.0), resultants2, jc));
  EXPECT_EQ(d.model.properties[0].shell.iplas, 2);
  EXPECT_TRUE(contains(test::first_error(dir.write("Q_0000.rad", test::begin_card() +
                                                                    plate_with_property(I(24) + I(0) + I(0) + I(0),
                                                                                        R(0.0), section2, jc) +
                                                                    "/END\n")),
                       "field Iplas (columns 81-90): expected 0 or 1 for the plastic points"));
}

}  // namespace
