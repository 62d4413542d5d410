// Input versions (docs/deck-format.md, "Input versions"): 51 and later are read with the 2017 widths, with the few
// layout differences Crumple reads (the /SKEW/FIX origin line from 120 on); 41 to 44 are refused at /BEGIN.
#include <gtest/gtest.h>

#include "deck_files.hpp"

using namespace crumple;
using test::I;
using test::R;

namespace {

std::string begin(int version) {
  char line[32];
  std::snprintf(line, sizeof line, "%10d         0\n", version);
  return "/BEGIN\nTEST\n" + std::string(line) + R("kg") + R("m") + R("s") + "\n" + R("kg") + R("m") + R("s") + "\n";
}

std::filesystem::path deck(const test::TempDir& dir, int version, const std::string& extra) {
  return dir.write("T_0000.rad", begin(version) + test::plate_cards() + extra + "/END\n");
}

// A fixed skew turned 90 degrees about z: Y' along -x, Z' along z; before 120 without its origin line.
std::string skew_card(int version) {
  std::string s = "/SKEW/FIX/4\nturned\n";
  if (version >= 120) s += R(5.0) + R(5.0) + R(5.0) + "\n";
  return s + R(-1.0) + R(0.0) + R(0.0) + "\n" + R(0.0) + R(0.0) + R(1.0) + "\n";
}

}  // namespace

TEST(InputVersions, FiftyOneAndLaterAreReadWithTheirLayouts) {
  for (int version : {51, 90, 100, 110, 120, 130, 140, 2017, 2026}) {
    SCOPED_TRACE("Invers " + std::to_string(version));
    test::TempDir dir;
    const auto d = read_deck(deck(dir, version, skew_card(version)));
    EXPECT_EQ(d.model.input_version, version);
    ASSERT_EQ(d.model.skews.size(), 1u);
    const Skew& s = d.model.skews[0];
    EXPECT_EQ(s.y_direction, (Vec3{-1.0, 0.0, 0.0}));
    EXPECT_EQ(s.z_direction, (Vec3{0.0, 0.0, 1.0}));
    EXPECT_EQ(s.origin, version >= 120 ? (Vec3{5.0, 5.0, 5.0}) : (Vec3{0.0, 0.0, 0.0}));
    const SkewAxes a = skew_axes(s, d.model.nodes.x, d.model.nodes.y, d.model.nodes.z);
    EXPECT_NEAR(a.axis[0].y, 1.0, 1e-15);  // X' = Y' x Z = (-x) x z = y
    EXPECT_NEAR(a.axis[1].x, -1.0, 1e-15);
    EXPECT_NEAR(a.axis[2].z, 1.0, 1e-15);
  }
}

TEST(InputVersions, EightColumnLayoutsAreRefusedAtBegin) {
  for (int version : {41, 42, 44}) {
    test::TempDir dir;
    const std::string e = test::first_error(deck(dir, version, ""));
    EXPECT_NE(e.find("T_0000.rad:3: /BEGIN: field Invers"), std::string::npos) << e;
    EXPECT_NE(e.find("8- and 16-column layouts of versions 41 to 44"), std::string::npos) << e;
  }
}

// /SKEW/MOV's Dir picks the axis N1 N2 gives (eq. SK-2); /SKEW/MOV2 is Dir = Z.
TEST(InputVersions, MovingSkewAxesFollowDir) {
  const Vec3 along{0.0, 1.0, 0.0}, in_plane{0.0, 0.0, 1.0};
  const SkewAxes x = axes_from_directions(0, along, in_plane);  // X' = y, Y' = z, Z' = x ("YZX")
  EXPECT_EQ(x.axis[0], (Vec3{0, 1, 0}));
  EXPECT_EQ(x.axis[1], (Vec3{0, 0, 1}));
  EXPECT_EQ(x.axis[2], (Vec3{1, 0, 0}));
  const SkewAxes z = axes_from_directions(2, along, in_plane);  // Z' = y, X' in the plane (z), Y' = Z' x X' = x
  EXPECT_EQ(z.axis[2], (Vec3{0, 1, 0}));
  EXPECT_EQ(z.axis[0], (Vec3{0, 0, 1}));
  EXPECT_EQ(z.axis[1], (Vec3{1, 0, 0}));
}
