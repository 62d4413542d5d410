// /INTER/TYPE7: every line of the card (docs/cards/loads-output-engine.md §5), defaults, units, the conditional
// friction lines, and the errors for malformed cards and for options the contact module does not implement.
// /INTER/TYPE2 (§5b): its line in each input version, the ties found (docs/theory/tied-interfaces.md, TI-1, TI-2),
// and the errors for formulations Crumple lacks and for tied nodes that another condition moves.
#include <gtest/gtest.h>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_interface_keywords {

using namespace crumple;
using test::blank;
using test::I;
using test::R;

namespace {

std::string gram_mm_ms_begin() {
  return "/BEGIN\nTEST\n      2019         0\n" + R("g") + R("mm") + R("ms") + "\n" + R("kg") + R("m") + R("s") + "\n";
}

// Node group 10 (plate nodes 1-6) and surface 20 (part 1) for the interfaces to refer to.
std::string references() {
  return "/GRNOD/NODE/10\nsecondary\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + "\n/SURF/PART/20\nmain\n" + I(1) +
         "\n";
}

// The card as HyperCrash writes it (QA decks), one member per data line so that a test changes only what it needs.
struct Type7 {
  std::string keyword = "/INTER/TYPE7/7";
  std::string flags = I(10) + I(20) + I(0) + I(0) + I(0) + blank(10) + I(0) + I(0) + I(0) + I(0);
  std::string gap = R(0.0) + R(0.0) + R(0.0);
  std::string stiffness = R(0.0) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(0);
  std::string curvature;  // only when Icurv = 1, 2
  std::string contact = R(0.0) + R(0.0) + R(0.0) + R(0.0) + R(0.0);
  std::string damping = "       000" + blank(20) + I(0) + R(0.0) + R(0.0) + R(0.0);
  std::string friction = I(0) + I(0) + R(0.0) + I(0) + I(0) + I(0) + R(0.0) + I(0);
  std::string after;  // lines after the friction line (C1..C5, C6...)

  std::string card() const {
    std::string s = keyword + "\ncontact title\n" + flags + "\n" + gap + "\n" + stiffness + "\n";
    if (!curvature.empty()) s += curvature + "\n";
    return s + contact + "\n" + damping + "\n" + friction + "\n" + after;
  }
};

// Flags line: Slav_id Mast_id Istf Ithe Igap (Multimp) Ibag Idel Icurv Iadm.
std::string flags(long long istf, long long ithe, long long igap, long long multimp, long long ibag, long long idel,
                  long long icurv, long long iadm) {
  return I(10) + I(20) + I(istf) + I(ithe) + I(igap) + I(multimp) + I(ibag) + I(idel) + I(icurv) + I(iadm);
}

std::filesystem::path starter(const test::TempDir& dir, const std::string& cards,
                              const std::string& begin = test::begin_card()) {
  return dir.write("T_0000.rad", begin + test::plate_cards() + references() + cards + "/END\n");
}

Deck read(const test::TempDir& dir, const Type7& t, const std::string& begin = test::begin_card()) {
  return read_deck(starter(dir, t.card(), begin));
}

std::string error_of(const Type7& t) {
  test::TempDir dir;
  return test::first_error(starter(dir, t.card()));
}

std::string warnings(const Deck& d) {
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text() + "\n";
  return all;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(InterfaceKeywords, QaStyleCardKeepsZeroDefaults) {
  test::TempDir dir;
  const Deck d = read(dir, Type7{});
  ASSERT_EQ(d.model.type7_interfaces.size(), 1u);
  const Type7Interface& i = d.model.type7_interfaces[0];
  EXPECT_EQ(i.user_id, 7);
  EXPECT_EQ(i.title, "contact title");
  EXPECT_EQ(i.secondary_group_id, 10);
  EXPECT_EQ(i.main_surface_id, 20);
  EXPECT_EQ(i.secondary_group, 0);
  EXPECT_EQ(i.main_surface, 0);
  EXPECT_EQ(i.istf, 0);
  EXPECT_EQ(i.igap, 0);
  EXPECT_EQ(i.inacti, 0);
  EXPECT_EQ(i.iform, 0);
  EXPECT_EQ(i.stfac, 0.0);
  EXPECT_EQ(i.tstop, 0.0);
  EXPECT_EQ(i.viss, 0.0);
  EXPECT_EQ(i.bumult, 0.0);
  EXPECT_FALSE(i.ibc[0] || i.ibc[1] || i.ibc[2]);
  EXPECT_EQ(i.friction_c, (std::array<double, 6>{}));
  EXPECT_EQ(warnings(d), "");
}

TEST(InterfaceKeywords, EveryFieldIsRead) {
  test::TempDir dir;
  Type7 t;
  t.flags = flags(4, 0, 2, 0, 0, 2, 0, 0);
  t.gap = R(0.8) + R(0.002);
  t.stiffness = R(1e3) + R(1e9) + R(0.0) + R(1e-7) + I(1) + I(3);
  t.contact = R(2.0) + R(0.15) + R(0.001) + R(0.001) + R(0.002);
  t.damping = "       101" + blank(20) + I(6) + R(0.1) + R(0.5) + R(0.3);
  t.friction = I(2) + I(1) + R(0.5) + I(1) + I(0) + I(0) + R(1.0) + I(0);
  t.after = R(1.0) + R(2.0) + R(3.0) + R(4.0) + R(5.0) + "\n" + R(6.0) + "\n";
  const Type7Interface i = read(dir, t).model.type7_interfaces.at(0);
  EXPECT_EQ(i.istf, 4);
  EXPECT_EQ(i.igap, 2);
  EXPECT_EQ(i.ibag, 0);
  EXPECT_EQ(i.idel, 2);
  EXPECT_DOUBLE_EQ(i.fscale_gap, 0.8);
  EXPECT_DOUBLE_EQ(i.gap_max, 0.002);
  EXPECT_DOUBLE_EQ(i.stmin, 1e3);
  EXPECT_DOUBLE_EQ(i.stmax, 1e9);
  EXPECT_DOUBLE_EQ(i.dtmin, 1e-7);
  EXPECT_EQ(i.irem_gap, 1);
  EXPECT_EQ(i.irem_i2, 3);
  EXPECT_DOUBLE_EQ(i.stfac, 2.0);
  EXPECT_DOUBLE_EQ(i.fric, 0.15);
  EXPECT_DOUBLE_EQ(i.gapmin, 0.001);
  EXPECT_DOUBLE_EQ(i.tstart, 0.001);
  EXPECT_DOUBLE_EQ(i.tstop, 0.002);
  EXPECT_TRUE(i.ibc[0]);
  EXPECT_FALSE(i.ibc[1]);
  EXPECT_TRUE(i.ibc[2]);
  EXPECT_EQ(i.inacti, 6);
  EXPECT_DOUBLE_EQ(i.viss, 0.1);
  EXPECT_DOUBLE_EQ(i.visf, 0.5);
  EXPECT_DOUBLE_EQ(i.bumult, 0.3);
  EXPECT_EQ(i.ifric, 2);
  EXPECT_EQ(i.ifiltr, 1);
  EXPECT_DOUBLE_EQ(i.xfreq, 0.5);
  EXPECT_EQ(i.iform, 1);
  EXPECT_DOUBLE_EQ(i.ascale_f, 1.0);
  EXPECT_EQ(i.friction_c, (std::array<double, 6>{1, 2, 3, 4, 5, 6}));
}

// The manual writes 1000 for "default" in Istf, Igap, Idel and Inacti; the model keeps 0 for default.
TEST(InterfaceKeywords, ThousandCodesMeanDefault) {
  test::TempDir dir;
  Type7 t;
  t.flags = flags(1000, 0, 1000, 0, 0, 1000, 0, 0);
  t.damping = "       000" + blank(20) + I(1000) + R(0.0) + R(0.0) + R(0.0);
  const Type7Interface i = read(dir, t).model.type7_interfaces.at(0);
  EXPECT_EQ(i.istf, 0);
  EXPECT_EQ(i.igap, 0);
  EXPECT_EQ(i.idel, 0);
  EXPECT_EQ(i.inacti, 0);
}

TEST(InterfaceKeywords, ValuesConvertedToWorkingUnits) {
  test::TempDir dir;
  Type7 t;
  t.flags = flags(1, 0, 1, 0, 0, 0, 0, 0);
  t.gap = R(0.0) + R(3.0);                                  // Gap_max 3 mm
  t.stiffness = R(0.0) + R(0.0) + R(0.0) + R(0.5);           // dtmin 0.5 ms
  t.contact = R(10.0) + R(0.2) + R(1.0) + R(2.0) + R(4.0);  // Stfac 10 g/ms^2 (Istf = 1), Gapmin 1 mm, 2 ms, 4 ms
  t.friction = I(1) + I(3) + R(2.0) + I(0);                  // Ifric 1; Ifiltr 3: Xfreq 2 per ms
  t.after = R(1.0) + R(1.0) + R(1.0) + R(1.0) + R(1.0) + "\n";
  const Type7Interface i = read(dir, t, gram_mm_ms_begin()).model.type7_interfaces.at(0);
  EXPECT_NEAR(i.gap_max, 3e-3, 1e-15);
  EXPECT_NEAR(i.dtmin, 5e-4, 1e-15);
  EXPECT_NEAR(i.stfac, 1e4, 1e-9);  // g/ms^2 = 1e-3 kg / 1e-6 s^2 = 1e3 N/m
  EXPECT_DOUBLE_EQ(i.fric, 0.2);
  EXPECT_NEAR(i.gapmin, 1e-3, 1e-15);
  EXPECT_NEAR(i.tstart, 2e-3, 1e-15);
  EXPECT_NEAR(i.tstop, 4e-3, 1e-15);
  EXPECT_NEAR(i.xfreq, 2e3, 1e-9);  // a frequency: 2 / ms = 2000 / s
  // Generalized viscous law: C1 [1/P] (1/MPa -> 1e-6 /Pa), C2 [1/V] (mm/ms = m/s), C5 [1/V^2].
  EXPECT_NEAR(i.friction_c[0], 1e-6, 1e-18);
  EXPECT_NEAR(i.friction_c[1], 1.0, 1e-12);
  EXPECT_NEAR(i.friction_c[4], 1.0, 1e-12);
}

TEST(InterfaceKeywords, StfacIsAFactorUnlessIstfIsOne) {
  test::TempDir dir;
  Type7 t;
  t.contact = R(10.0);
  EXPECT_DOUBLE_EQ(read(dir, t, gram_mm_ms_begin()).model.type7_interfaces.at(0).stfac, 10.0);
}

// C1..C5 follow when Ifric > 0, C6 only when Ifric > 1: with Ifric = 1 the next line belongs to the next card.
TEST(InterfaceKeywords, FrictionLawLinesDependOnIfric) {
  test::TempDir dir;
  Type7 t;
  t.friction = I(1) + I(0) + R(0.0) + I(0);
  t.after = R(0.1) + R(0.2) + R(0.3) + R(0.4) + R(0.5) + "\n";
  const Deck d = read_deck(starter(dir, t.card() + "/GRNOD/NODE/11\nnext card\n" + I(1) + "\n"));
  const Type7Interface& i = d.model.type7_interfaces.at(0);
  EXPECT_EQ(i.friction_c, (std::array<double, 6>{0.1, 0.2, 0.3, 0.4, 0.5, 0.0}));
  EXPECT_EQ(d.model.node_groups.size(), 2u);

  t.after += R(0.6) + "\n";  // a C6 line with Ifric = 1 is one line too many
  const std::string e = error_of(t);
  EXPECT_TRUE(contains(e, "no more data lines")) << e;

  Type7 renard;
  renard.friction = I(3) + I(0) + R(0.0) + I(0);
  renard.after = R(0.1) + "\n";  // C1..C5 line present, C6 missing
  const std::string truncated = test::first_error(starter(dir, renard.card()));
  EXPECT_TRUE(contains(truncated, "C6 (Ifric = 3)")) << truncated;
}

TEST(InterfaceKeywords, MissingLineIsATruncatedCard) {
  Type7 t;
  t.friction.clear();
  std::string card = t.card();
  card = card.substr(0, card.rfind('\n', card.size() - 2) + 1);  // drop the (empty) friction line
  test::TempDir dir;
  const std::string e = test::first_error(starter(dir, card));
  EXPECT_TRUE(contains(e, "truncated")) << e;
  EXPECT_TRUE(contains(e, "Ifric")) << e;
}

// Icurv = 1 or 2 adds a line of two node ids; the card is placed correctly and then rejected by name.
TEST(InterfaceKeywords, CurvatureLineIsReadThenRejectedByName) {
  Type7 t;
  t.flags = flags(0, 0, 0, 0, 0, 0, 2, 0);
  t.curvature = I(1) + I(2);
  const std::string e = error_of(t);
  EXPECT_TRUE(contains(e, "Icurv")) << e;
  EXPECT_TRUE(contains(e, "not supported")) << e;
}

namespace {
struct Unsupported {
  const char* field;
  void (*change)(Type7&);
};
}  // namespace

TEST(InterfaceKeywords, OptionsWithoutImplementationAreErrorsNamingTheField) {
  const Unsupported cases[] = {
      {"Ithe", [](Type7& t) { t.flags = flags(0, 1, 0, 0, 0, 0, 0, 0); }},
      {"Ibag", [](Type7& t) { t.flags = flags(0, 0, 0, 0, 1, 0, 0, 0); }},
      {"Icurv", [](Type7& t) { t.flags = flags(0, 0, 0, 0, 0, 0, 3, 0); }},
      {"Iadm", [](Type7& t) { t.flags = flags(0, 0, 0, 0, 0, 0, 0, 1); }},
      {"Fpenmax", [](Type7& t) { t.gap = R(0.0) + R(0.0) + R(0.5); }},
      {"Itied", [](Type7& t) { t.gap = R(0.0) + R(0.0) + R(0.0) + blank(20) + I(1); }},
      {"%mesh_size", [](Type7& t) { t.stiffness = R(0.0) + R(0.0) + R(0.4); }},
      {"Irem_gap", [](Type7& t) { t.stiffness = R(0.0) + R(0.0) + R(0.0) + R(0.0) + I(2); }},
      {"Ibag", [](Type7& t) { t.flags = flags(0, 0, 0, 0, 2, 0, 0, 0); }},
      {"fct_IDf", [](Type7& t) { t.friction = I(0) + I(0) + R(0.0) + I(0) + I(0) + I(5); }},
      {"AscaleF", [](Type7& t) { t.friction = I(0) + I(0) + R(0.0) + I(0) + I(0) + I(0) + R(2.0); }},
      {"fric_ID", [](Type7& t) { t.friction = I(0) + I(0) + R(0.0) + I(0) + I(0) + I(0) + R(0.0) + I(5); }},
  };
  for (const auto& c : cases) {
    Type7 t;
    c.change(t);
    const std::string e = error_of(t);
    EXPECT_TRUE(contains(e, std::string("field ") + c.field)) << c.field << ": " << e;
    EXPECT_TRUE(contains(e, "not supported")) << c.field << ": " << e;
  }
}

// sens_ID: the interface acts only while the sensor is on (docs/theory/loads.md, L-7); a missing sensor is an error.
TEST(InterfaceKeywords, SensorBoundsTheInterfacesWindow) {
  Type7 t;
  t.friction = I(0) + I(0) + R(0.0) + I(0) + I(5);
  const std::string e = error_of(t);
  EXPECT_TRUE(contains(e, "sens_ID")) << e;
  EXPECT_TRUE(contains(e, "sensor 5")) << e;
  test::TempDir dir;
  t.after = "/SENSOR/TIME/5\ntimer\n" + R(0.25) + "\n";
  const Deck d = read(dir, t);
  ASSERT_EQ(d.model.type7_interfaces.size(), 1u);
  EXPECT_DOUBLE_EQ(d.model.type7_interfaces[0].sensor.on, 0.25);
  EXPECT_FALSE(d.model.type7_interfaces[0].sensor.holds(0.2));
}

TEST(InterfaceKeywords, ValuesOutOfRangeAreErrorsNamingTheField) {
  const Unsupported cases[] = {
      {"Slav_id", [](Type7& t) { t.flags = I(0) + I(20); }},
      {"Mast_id", [](Type7& t) { t.flags = I(10) + I(-3); }},
      {"Istf", [](Type7& t) { t.flags = flags(6, 0, 0, 0, 0, 0, 0, 0); }},
      {"Igap", [](Type7& t) { t.flags = flags(0, 0, 3, 0, 0, 0, 0, 0); }},
      {"Idel", [](Type7& t) { t.flags = flags(0, 0, 0, 0, 0, -1, 0, 0); }},
      {"Stmax", [](Type7& t) { t.stiffness = R(10.0) + R(5.0); }},
      {"dtmin", [](Type7& t) { t.stiffness = R(0.0) + R(0.0) + R(0.0) + R(-1e-6); }},
      {"Gap_max", [](Type7& t) { t.gap = R(0.0) + R(-1.0); }},
      {"Stfac", [](Type7& t) { t.contact = R(-1.0); }},
      {"Fric", [](Type7& t) { t.contact = R(0.0) + R(-0.1); }},
      {"Gapmin", [](Type7& t) { t.contact = R(0.0) + R(0.0) + R(-0.001); }},
      {"Tstop", [](Type7& t) { t.contact = R(0.0) + R(0.0) + R(0.0) + R(2.0) + R(1.0); }},
      {"Stfac", [](Type7& t) { t.contact = R("abc"); }},
      {"IBC", [](Type7& t) { t.damping = "111"; }},
      {"IBC y", [](Type7& t) { t.damping = "       121"; }},
      {"Inacti", [](Type7& t) { t.damping = "       000" + blank(20) + I(4); }},
      {"Inacti", [](Type7& t) { t.damping = "       000" + std::string("         1"); }},
      {"VisS", [](Type7& t) { t.damping = "       000" + blank(20) + I(0) + R(-0.05); }},
      {"VisF", [](Type7& t) { t.damping = "       000" + blank(20) + I(0) + R(0.0) + R(-1.0); }},
      {"Bumult", [](Type7& t) { t.damping = "       000" + blank(20) + I(0) + R(0.0) + R(0.0) + R(-0.2); }},
      {"Ifric", [](Type7& t) { t.friction = I(4); }},
      {"Ifiltr", [](Type7& t) { t.friction = I(0) + I(4); }},
      {"Xfreq", [](Type7& t) { t.friction = I(0) + I(1) + R(0.0); }},
      {"Xfreq", [](Type7& t) { t.friction = I(0) + I(1) + R(1.5); }},
      {"Iform", [](Type7& t) { t.friction = I(0) + I(0) + R(0.0) + I(3); }},
  };
  for (const auto& c : cases) {
    Type7 t;
    c.change(t);
    const std::string e = error_of(t);
    EXPECT_TRUE(contains(e, std::string("field ") + c.field)) << c.field << ": " << e;
  }
}

TEST(InterfaceKeywords, KeywordPathIsChecked) {
  Type7 unit;
  unit.keyword = "/INTER/TYPE7/7/3";
  EXPECT_TRUE(contains(error_of(unit), "unit_ID")) << error_of(unit);
  Type7 missing;
  missing.keyword = "/INTER/TYPE7";
  EXPECT_TRUE(contains(error_of(missing), "an id in the keyword line")) << error_of(missing);
}

TEST(InterfaceKeywords, UndefinedGroupAndSurfaceAreNamed) {
  Type7 t;
  t.flags = I(99) + I(98);
  const std::string e = error_of(t);
  EXPECT_TRUE(contains(e, "Slav_id")) << e;
  EXPECT_TRUE(contains(e, "node group 99 not defined")) << e;
}

TEST(InterfaceKeywords, DuplicateInterfaceIdsAreAnError) {
  test::TempDir dir;
  const std::string e = test::first_error(starter(dir, Type7{}.card() + Type7{}.card()));
  EXPECT_TRUE(contains(e, "duplicate")) << e;
}

// Values Radioss reads but does not use with the flags given are reported, not dropped silently.
TEST(InterfaceKeywords, UnusedValuesAreWarnings) {
  test::TempDir dir;
  Type7 t;
  t.flags = flags(1, 0, 0, 4, 0, 0, 0, 0);
  t.gap = R(0.5) + R(0.01);
  t.stiffness = R(1.0) + R(2.0);
  const std::string w = warnings(read(dir, t));
  EXPECT_TRUE(contains(w, "Multimp")) << w;
  EXPECT_TRUE(contains(w, "Fscale_gap")) << w;
  EXPECT_TRUE(contains(w, "Gap_max")) << w;
  EXPECT_TRUE(contains(w, "Stmin and Stmax")) << w;
}

// ---- /INTER/TYPE2: node 7 above the first shell of the plate (0..0.01 x 0..0.01), tied to the plate's surface 20.
namespace {

std::string tied_node(double x = 0.0025, double y = 0.005, double z = 0.0002) {
  return "/NODE\n" + I(7) + R(x) + R(y) + R(z) + "\n/GRNOD/NODE/11\ntied\n" + I(7) + "\n";
}

// grnd_IDs surf_IDm Ignore Spotflag Level Isearch Idel2 (blank) dsearch
std::string type2(long long ignore = 0, long long spotflag = 1, long long level = 0, long long idel2 = 0,
                  double dsearch = 0.0, const std::string& after = "", long long id = 2) {
  return "/INTER/TYPE2/" + std::to_string(id) + "\nweld\n" + I(11) + I(20) + I(ignore) + I(spotflag) + I(level) +
         I(0) + I(idel2) + blank(10) + R(dsearch) + "\n" + after;
}

std::string type2_error(const std::string& cards, int input_version = 2019) {
  test::TempDir dir;
  return test::first_error(starter(dir, tied_node() + cards, test::begin_card("T", input_version)));
}

}  // namespace

TEST(TiedInterfaceKeywords, NodeIsTiedToItsNearestSegmentWithBilinearWeights) {
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, tied_node() + type2()));
  ASSERT_EQ(d.model.type2_interfaces.size(), 1u);
  const Type2Interface& i = d.model.type2_interfaces[0];
  EXPECT_EQ(i.spotflag, 1);
  ASSERT_EQ(i.ties.size(), 1u);
  const Tie& tie = i.ties[0];
  EXPECT_EQ(tie.segment, 0);
  // (0.0025, 0.005) in the shell 0..0.01 x 0..0.01: s = -0.5, t = 0; the node is not moved onto the plate.
  EXPECT_NEAR(tie.s, -0.5, 1e-12);
  EXPECT_NEAR(tie.t, 0.0, 1e-12);
  const double expected[4] = {0.375, 0.125, 0.125, 0.375};
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(tie.weight[static_cast<std::size_t>(a)], expected[a], 1e-12);
  EXPECT_NEAR(tie.distance, 0.0002, 1e-12);
}

// dsearch 0: the root mean square of the main segments' edges, here 0.01 (measured on the reference, TI-2).
TEST(TiedInterfaceKeywords, NodeBeyondTheSearchDistanceIsAnErrorUnlessIgnored) {
  {
    test::TempDir dir;
    EXPECT_EQ(read_deck(starter(dir, tied_node(0.0025, 0.005, 0.0099) + type2())).model.type2_interfaces[0].ties.size(), 1u);
  }
  test::TempDir dir;
  const std::string e = test::first_error(starter(dir, tied_node(0.0025, 0.005, 0.0101) + type2()));
  EXPECT_TRUE(contains(e, "Ignore")) << e;
  EXPECT_TRUE(contains(e, "no main segment within 0.01")) << e;
  test::TempDir ignored;
  const Deck d = read_deck(starter(ignored, tied_node(0.0025, 0.005, 0.0101) + type2(1)));
  EXPECT_TRUE(d.model.type2_interfaces[0].ties.empty());
  EXPECT_TRUE(contains(warnings(d), "left out of the tie")) << warnings(d);
  // An explicit dsearch replaces the default.
  EXPECT_TRUE(contains(type2_error(type2(0, 1, 0, 0, 0.0001)), "no main segment within 0.0001"));
}

// Input versions before 110 have no Ignore: its columns are not read (measured: the reference's version 100 reads
// a 1 there as the default, and refuses the far node).
TEST(TiedInterfaceKeywords, OldVersionsDoNotReadIgnore) {
  test::TempDir dir;
  const std::string e =
      test::first_error(starter(dir, tied_node(0.0025, 0.005, 0.0101) + type2(1), test::begin_card("T", 100)));
  EXPECT_TRUE(contains(e, "no main segment")) << e;
}

TEST(TiedInterfaceKeywords, FormulationsCrumpleLacksAreNamed) {
  for (long long spotflag : {3, 20, 21, 22, 25, 27, 28, 30}) {
    const std::string e = type2_error(type2(0, spotflag));
    EXPECT_TRUE(contains(e, "Spotflag")) << spotflag << ": " << e;
  }
  {
    test::TempDir dir;
    const Deck d = read_deck(starter(dir, tied_node() + type2(0, 1, 1)));  // Level acts on chains only
    EXPECT_TRUE(contains(warnings(d), "Level: no effect")) << warnings(d);
  }
  {
    test::TempDir dir;  // Idel2 releases ties (TI-15); with Spotflag 2 the reference ignores it, said by a warning
    EXPECT_EQ(read_deck(starter(dir, tied_node() + type2(0, 1, 0, 2))).model.type2_interfaces[0].idel2, 2);
    test::TempDir again;
    const Deck d = read_deck(starter(again, tied_node() + type2(0, 2, 0, 1)));
    EXPECT_EQ(d.model.type2_interfaces[0].idel2, 0);
    EXPECT_TRUE(contains(warnings(d), "Idel2: no effect with Spotflag 2")) << warnings(d);
  }
  EXPECT_TRUE(contains(type2_error(type2(0, 1, 0, 0, 0.0, I(1) + R(1.0) + "\n")), "Ithe"));
  test::TempDir dir;
  const Deck d = read_deck(starter(dir, tied_node() + type2(1000, 0, 0, 1000)));  // the manual's explicit defaults
  EXPECT_EQ(d.model.type2_interfaces[0].ignore, 0);
  EXPECT_EQ(d.model.type2_interfaces[0].idel2, 0);
}

TEST(TiedInterfaceKeywords, TiedNodesMovedByAnotherConditionAreRefused) {
  EXPECT_TRUE(contains(type2_error(type2() + type2(0, 1, 0, 0, 0.0, "", 3)), "tied by /INTER/TYPE2/2"));
  EXPECT_TRUE(contains(type2_error(type2() + "/BCS/1\nheld\n   111 000" + I(0) + I(11) + "\n"), "/BCS/1"));
  // A tie's segment node that is tied elsewhere (a tie of ties).
  const std::string chained = "/GRNOD/NODE/12\nplate node\n" + I(1) + "\n/SURF/SEG/21\nnode 7 and others\n" + I(1) +
                              I(7) + I(2) + I(5) + I(4) + "\n/INTER/TYPE2/3\nchain\n" + I(12) + I(21) + I(0) + I(1) + "\n";
  EXPECT_TRUE(contains(type2_error(type2() + chained), "hierarchy")) << type2_error(type2() + chained);
}

TEST(TiedInterfaceKeywords, IdsAreSharedWithContactInterfaces) {
  Type7 t;
  t.keyword = "/INTER/TYPE7/2";
  EXPECT_TRUE(contains(type2_error(t.card() + type2()), "duplicate"));
}

}  // namespace test_interface_keywords
