#include <gtest/gtest.h>

#include "crumple/deck/units.hpp"
#include "deck_files.hpp"

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
