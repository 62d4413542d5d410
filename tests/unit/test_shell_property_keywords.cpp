// /PROP/SHELL (= /PROP/TYPE1) and /DEF_SHELL: column positions, defaults, the flags that act only on the elements
// or the materials they are meant for, and the warnings (docs/theory/shell4.md, "Formulation flags"). The refused
// values have bad-input decks (tests/badinput/decks).
#include <gtest/gtest.h>

#include <string>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell_property_keywords {

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

const std::string kJohnsonCook = "/MAT/PLAS_JOHNS/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + I(0) + "\n" +
                                 R(2.5e8) + R(4.5e8) + R(0.5) + "\n" + R(0.0) + R(0.0) + I(0) + I(0) + R(0.0) +
                                 R(0.0) + "\n";
// /MAT/PLAS_TAB with the hardening curve /FUNCT/5 (written before the property, see plate_with_property).
const std::string kTabulated = "/MAT/PLAS_TAB/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + I(1) +
                               I(0) + R(0.0) + R(0.0) + "\n" + I(0) + R(0.0) + I(0) + "\n" + I(5) + "\n" + R(1.0) +
                               "\n" + R(0.0) + "\n/FUNCT/5\nhardening\n" + R(0.0) + R(2e8) + "\n" + R(1.0) + R(4e8) +
                               "\n";

// Iplas acts on plastic sections only: Iplas 2 with an elastic law has nothing to act on; with a plastic law and
// points it is refused (bad-input decks iplas_*), with resultants (N = 0, /MAT/PLAS_TAB) accepted (the radial
// return on the resultants). N = 0 with /MAT/PLAS_JOHNS runs 3 points, so Iplas 2 is refused there too, and the
// message says where the points come from.
// Iplas at plastic points: 2 (the default: Iplas 0, as the manual says for explicit decks) runs the radial return
// and 1 the iterative projection (materials.md PS-5, PS-3); on plastic resultants (N = 0) only the radial return
// exists, so Iplas 1 there is an option Crumple lacks.
TEST(ShellPropertyKeywords, IplasChoosesThePlaneStressReturn) {
  test::TempDir dir;
  const auto section = [](int n, int iplas) { return I(n) + I(0) + R(0.001) + R(0.0) + test::blank(10) + I(0) + I(iplas); };
  const auto formulation = [&](int n, int iplas, const std::string& material) {
    return read(dir, plate_with_property(I(24) + I(0) + I(0) + I(0), R(0.0), section(n, iplas), material)).model.formulations[0];
  };
  EXPECT_EQ(formulation(3, 0, kJohnsonCook).iplas, 2);
  EXPECT_EQ(formulation(3, 1, kJohnsonCook).iplas, 1);
  EXPECT_EQ(formulation(3, 2, kJohnsonCook).iplas, 2);
  EXPECT_EQ(formulation(0, 2, kTabulated).iplas, 2);
  EXPECT_EQ(formulation(0, 1, kJohnsonCook).iplas, 1);  // N = 0 with Johnson-Cook runs 3 points
  EXPECT_TRUE(contains(test::first_error(dir.write("S_0000.rad", test::begin_card() +
                                                                    plate_with_property(I(24) + I(0) + I(0) + I(0), R(0.0),
                                                                                        section(0, 1), kTabulated) +
                                                                    "/END\n")),
                       "field Iplas (columns 81-90): expected 0 or 2 for the plastic resultants"));
}

// N = 0 asks for global integration. The reference solver does not integrate /MAT/PLAS_JOHNS globally: it runs 3
// points and warns (its warning 1912 in the starter listings of ball_on_wall, contact_idel and friction). Crumple
// resolves such a property to 3 points with a warning; elastic and tabulated laws keep N = 0.
TEST(ShellPropertyKeywords, GlobalIntegrationOfJohnsonCookRunsThreePoints) {
  test::TempDir dir;
  const std::string flags = I(1) + I(0) + I(0) + I(0), global = I(0) + I(0) + R(0.001);
  const Deck jc = read(dir, plate_with_property(flags, R(0.0), global, kJohnsonCook));
  EXPECT_EQ(jc.model.formulations[0].n_points, 3);
  EXPECT_EQ(jc.model.properties[0].shell.n_points, 0);  // the deck's value is kept as read
  EXPECT_TRUE(contains(warnings(jc), "N = 0 (global integration) with /MAT/PLAS_JOHNS/1: the reference solver does "
                                     "not integrate this law globally and runs 3 points through the thickness"))
      << warnings(jc);
  EXPECT_EQ(read(dir, plate_with_property(flags, R(0.0), global)).model.formulations[0].n_points, 0);
  EXPECT_EQ(read(dir, plate_with_property(flags, R(0.0), global, kTabulated)).model.formulations[0].n_points, 0);
  // Points asked for explicitly stay as asked.
  EXPECT_EQ(read(dir, plate_with_property(flags, R(0.0), I(5) + I(0) + R(0.001), kJohnsonCook)).model.formulations[0].n_points,
            5);
}

}  // namespace

}  // namespace test_shell_property_keywords
