#include <gtest/gtest.h>

#include "crumple/deck/units.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_units {

using namespace crumple;

TEST(Units, CodesAndNumbers) {
  EXPECT_DOUBLE_EQ(*parse_unit("kg", 0), 1.0);
  EXPECT_DOUBLE_EQ(*parse_unit("g", 0), 1e-3);
  EXPECT_DOUBLE_EQ(*parse_unit("Mg", 0), 1e3);
  EXPECT_DOUBLE_EQ(*parse_unit("t", 0), 1e3);
  EXPECT_DOUBLE_EQ(*parse_unit("mm", 1), 1e-3);
  EXPECT_DOUBLE_EQ(*parse_unit("in", 1), 0.0254);
  EXPECT_DOUBLE_EQ(*parse_unit("ms", 2), 1e-3);
  EXPECT_DOUBLE_EQ(*parse_unit("mus", 2), 1e-6);
  EXPECT_DOUBLE_EQ(*parse_unit("0.001", 1), 1e-3);
  EXPECT_FALSE(parse_unit("furlong", 1).has_value());
  EXPECT_FALSE(parse_unit("mm", 0).has_value());  // a length code in the mass column
  EXPECT_FALSE(parse_unit("-1", 2).has_value());
}

// The names shown for a deck's working units (core/units.hpp): its base units, and force, energy and stress by
// their SI names where a prefix of a power of 1000 fits, else composed of the base units.
TEST(Units, WorkingUnitsAreShownByName) {
  struct Case {
    double si[3];
    const char* described;
  };
  const Case cases[] = {
      {{1.0, 1e-3, 1e-3}, "mass kg, length mm, time ms, force kN, energy J, stress GPa"},
      {{1e3, 1e-3, 1.0}, "mass Mg, length mm, time s, force N, energy mJ, stress MPa"},
      {{1e-3, 1e-3, 1e-3}, "mass g, length mm, time ms, force N, energy mJ, stress MPa"},
      {{1.0, 1.0, 1.0}, "mass kg, length m, time s, force N, energy J, stress Pa"},
      {{1e-3, 1e-2, 1e-6}, "mass g, length cm, time us, force g cm/us^2, energy g cm/us^2 cm, stress g cm/us^2/cm^2"},
      {{0.45359237, 0.0254, 1.0}, "mass lb, length in, time s, force lb in/s^2, energy lb in/s^2 in, stress lb in/s^2/in^2"},
      {{2.5, 1e-3, 1e-3}, "mass 2.5 kg, length mm, time ms, force 2.5 kg mm/ms^2, energy 2.5 kg mm/ms^2 mm, "
       "stress 2.5 kg mm/ms^2/mm^2"},
  };
  for (const Case& c : cases) EXPECT_EQ(describe(unit_names(c.si)), c.described);
  // Read back with the same table the /BEGIN codes are read with.
  const double deck[3] = {*parse_unit("Mg", 0), *parse_unit("mm", 1), *parse_unit("mus", 2)};
  EXPECT_EQ(describe(unit_names(deck)), "mass Mg, length mm, time us, force TN, energy GJ, stress EPa");
  const double imperial[3] = {*parse_unit("lb", 0), *parse_unit("ft", 1), *parse_unit("min", 2)};
  EXPECT_EQ(describe(unit_names(imperial)).substr(0, 30), "mass lb, length ft, time min, ");
}

// A history column's unit: its dimension letters, each named in the working units.
TEST(Units, DimensionLettersBecomeUnitNames) {
  const double si[3] = {1.0, 1e-3, 1e-3};
  const UnitNames n = unit_names(si);
  EXPECT_EQ(unit_name("T", n), "ms");
  EXPECT_EQ(unit_name("E", n), "J");
  EXPECT_EQ(unit_name("F", n), "kN");
  EXPECT_EQ(unit_name("F/L^2", n), "GPa");
  EXPECT_EQ(unit_name("F L", n), "kN mm");
  EXPECT_EQ(unit_name("L/T^2", n), "mm/ms^2");
  EXPECT_EQ(unit_name("M L^2/T", n), "kg mm^2/ms");
  EXPECT_EQ(unit_name("1/T", n), "1/ms");
  EXPECT_EQ(unit_name("M/L^3", n), "kg/mm^3");
  EXPECT_EQ(unit_name("-", n), "");
  EXPECT_EQ(unit_name("", n), "");
}

TEST(Units, FactorsCombineDimensions) {
  UnitSystem u;
  u.input[0] = 1e-3;  // g
  u.input[1] = 1e-3;  // mm
  u.input[2] = 1e-3;  // ms
  // g/mm^3 -> kg/m^3: 1e-3 / 1e-9 = 1e6 ; g/(mm ms^2) (stress, MPa for g-mm-ms) -> Pa: 1e-3/(1e-3 * 1e-6) = 1e6
  EXPECT_NEAR(u.factor(dim::density), 1e6, 1e-6);
  EXPECT_NEAR(u.factor(dim::pressure), 1e6, 1e-6);
  EXPECT_NEAR(u.factor(dim::velocity), 1.0, 1e-12);
  EXPECT_NEAR(u.factor(dim::force), 1.0, 1e-12);  // g mm / ms^2 = 1e-3 * 1e-3 / 1e-6 N
}

// A deck in g, mm, ms read into SI working units: coordinates, density and modulus are converted once.
TEST(Units, DeckConvertedAtReadTime) {
  test::TempDir dir;
  using test::I;
  using test::R;
  std::string deck = "/BEGIN\nUNITS\n      2019         0\n" + R("g") + R("mm") + R("ms") + "\n" + R("kg") + R("m") +
                     R("s") + "\n";
  deck += "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(10.0) + R(0.0) + R(0.0) + "\n" + I(3) +
          R(10.0) + R(10.0) + R(0.0) + "\n" + I(4) + R(0.0) + R(10.0) + R(0.0) + "\n";
  deck += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(3) + I(4) + "\n/PART/1\np\n" + I(1) + I(1) + "\n";
  deck += "/PROP/SHELL/1\ns\n" + I(0) + "\n\n" + I(0) + I(0) + R(1.0) + "\n";
  deck += "/MAT/ELAST/1\nsteel\n" + R(0.0078) + "\n" + R(210000.0) + R(0.3) + "\n/END\n";
  const auto path = dir.write("U_0000.rad", deck);
  const Deck d = read_deck(path);
  EXPECT_DOUBLE_EQ(d.model.nodes.x[1], 0.01);
  EXPECT_NEAR(d.model.materials[0].density, 7800.0, 1e-9);
  EXPECT_NEAR(d.model.materials[0].young, 2.1e11, 1.0);
  EXPECT_NEAR(d.model.properties[0].shell.thickness, 1e-3, 1e-15);
  // mass = rho * t * A = 7800 * 1e-3 * 1e-4
  EXPECT_NEAR(d.model.total_mass(), 7800.0 * 1e-3 * 1e-4, 1e-12);
}

// /UNIT (docs/deck-format.md, "Units"): a card that names a /UNIT reads its values in it; a blank unit field is
// /BEGIN's input unit. The reference reads the same: a /MAT/ELAST in (g, cm, s) under /BEGIN kg mm ms gives the
// plate the mass of its twin in kg mm ms (7.85e-4 kg), an /IMPVEL in (g, cm, s) has Fscale 0.01 mm/ms and Ascale_x
// 1000 ms in its starter listing, and a blank mass unit under /BEGIN g mm ms reads a density in grams.
namespace {

std::string unit_deck(const std::string& begin_mass, const std::string& units, const std::string& material_path,
                      const std::string& nodes_path = "/NODE") {
  using test::I;
  using test::R;
  std::string deck = "/BEGIN\nUNITS\n      2019         0\n" + R(begin_mass) + R("mm") + R("ms") + "\n" + R("kg") +
                     R("mm") + R("ms") + "\n" + units;
  deck += nodes_path + "\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) + R(1.0) + R(0.0) + R(0.0) + "\n" + I(3) +
          R(1.0) + R(1.0) + R(0.0) + "\n" + I(4) + R(0.0) + R(1.0) + R(0.0) + "\n";
  deck += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(3) + I(4) + "\n/PART/1\np\n" + I(1) + I(1) + "\n";
  deck += "/PROP/SHELL/1\ns\n" + I(0) + "\n\n" + I(0) + I(0) + R(1.0) + "\n";
  return deck + material_path + "\nsteel\n" + R(7.85) + "\n" + R(2.1e12) + R(0.3) + "\n/END\n";
}

std::string unit_card(long long id, const std::string& mass, const std::string& length, const std::string& time) {
  return "/UNIT/" + std::to_string(id) + "\nlocal\n" + test::R(mass) + test::R(length) + test::R(time) + "\n";
}

}  // namespace

TEST(Units, CardsReadInTheirOwnUnitSystem) {
  test::TempDir dir;
  // 7.85 g/cm^3 = 7.85e-6 kg/mm^3; 2.1e12 g/(cm s^2) = 2.1e12 * 1e-3 / (10 * 1e6) = 210 kg/(mm ms^2).
  const Deck d = read_deck(dir.write("U_0000.rad", unit_deck("kg", unit_card(7, "g", "cm", "s"), "/MAT/ELAST/1/7")));
  EXPECT_NEAR(d.model.materials[0].density, 7.85e-6, 1e-18);
  EXPECT_NEAR(d.model.materials[0].young, 210.0, 1e-9);
  EXPECT_DOUBLE_EQ(d.model.nodes.x[1], 1.0);  // /NODE without a unit id: the deck's input units
  // Nodes in their own unit: 1 cm = 10 mm.
  std::string deck = unit_deck("kg", unit_card(3, "", "cm", ""), "/MAT/ELAST/1/7", "/NODE/3");
  deck.insert(deck.rfind("/END"), unit_card(7, "g", "cm", "s"));  // after the card that names it
  const Deck n = read_deck(dir.write("U_0000.rad", deck));
  EXPECT_DOUBLE_EQ(n.model.nodes.x[1], 10.0);
  EXPECT_NEAR(n.model.materials[0].density, 7.85e-6, 1e-18) << "a /UNIT after the card that names it";
}

TEST(Units, BlankUnitFieldIsTheInputUnit) {
  test::TempDir dir;
  // /BEGIN input g: a blank mass unit is the gram, 7.85 g/cm^3 = 7.85e-3 g/mm^3 = 7.85e-6 kg/mm^3.
  const Deck d = read_deck(dir.write("U_0000.rad", unit_deck("g", unit_card(7, "", "cm", "s"), "/MAT/ELAST/1/7")));
  EXPECT_NEAR(d.model.materials[0].density, 7.85e-6, 1e-18);
}

TEST(Units, UnitErrorsNameTheField) {
  test::TempDir dir;
  auto error = [&](const std::string& units, const std::string& material = "/MAT/ELAST/1/7") {
    return test::first_error(dir.write("U_0000.rad", unit_deck("kg", units, material)));
  };
  EXPECT_NE(error("", "/MAT/ELAST/1/9").find("unit 9 not defined"), std::string::npos);
  EXPECT_NE(error(unit_card(7, "furlong", "cm", "s")).find("mass_unit"), std::string::npos);
  EXPECT_NE(error(unit_card(7, "g", "cm", "s") + unit_card(7, "g", "cm", "s")).find("also the id"), std::string::npos);
  EXPECT_NE(error(unit_card(7, "1e300", "cm", "s")).find("finite"), std::string::npos);
}

// Before input version 100 (and /BEGIN/0, as old decks write /BEGIN): /UNIT/LENGTH/1, /UNIT/MASS/1, /UNIT/TIME/1 keep
// /BEGIN's units (the reference's listing of such a deck: input units 1, 1, 1), each a named warning; another code
// is an error naming it.
TEST(Units, OldUnitCardsOfCodeOne) {
  test::TempDir dir;
  const auto deck = [&](const std::string& units) {
    return dir.write("U_0000.rad", "/BEGIN/0\nOLD\n" + test::I(90) + test::I(0) + "\n" + units + test::plate_cards() +
                                       "/END\n");
  };
  const Deck d = read_deck(deck("/UNIT/LENGTH/1\n/UNIT/MASS/1\n/UNIT/TIME/1\n"));
  EXPECT_EQ(d.model.input_version, 90);
  EXPECT_DOUBLE_EQ(d.model.units.input[1], d.model.units.work[1]);
  int notes = 0;
  for (const auto& w : d.report.warnings) notes += w.message.find("code 1") != std::string::npos;
  EXPECT_EQ(notes, 3);
  EXPECT_NE(test::first_error(deck("/UNIT/LENGTH/2\n")).find("code"), std::string::npos);
  EXPECT_NE(test::first_error(dir.write("U_0000.rad", "/BEGIN/7\nX\n" + test::I(2019) + "\n" + test::plate_cards() +
                                                          "/END\n")).find("/BEGIN"),
            std::string::npos);
}

}  // namespace test_units
