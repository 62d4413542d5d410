// Input versions (docs/deck-format.md, "Input versions"): 51 and later are read with the 2017 widths, with the few
// layout differences Crumple reads (the /SKEW/FIX origin line from 120 on); 41 to 44 in their narrow layout.
#include <gtest/gtest.h>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_input_versions {

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

// One model in the 2017 layout and in the narrow layout of versions 41 to 44 (8-column integers and texts, 16-column
// reals, the title on the keyword line; /BCS codes in columns 2-8; /CLOAD, /GRAV with Fscale_Y before the group and
// no Ascale_x; /IMPVEL's second line without Ascale_x), as the reference's card descriptions give them.
std::string tiny_model(bool narrow) {
  const auto i = [narrow](const std::string& v) { return std::string((narrow ? 8 : 10) - v.size(), ' ') + v; };
  const auto r = [narrow](const std::string& v) { return std::string((narrow ? 16 : 20) - v.size(), ' ') + v; };
  const auto head = [narrow](const std::string& key, const std::string& title) {
    return narrow ? key + "/" + title + "\n" : key + "\n" + title + "\n";
  };
  std::string s = head("/MAT/PLAS_JOHNS/1", "steel") + r("7.85e-06") + "\n" + r("210") + r("0.3") + "\n" + r("0.21") +
                  r("0.45") + r("0.45") + "\n" + r("0") + r("0") + i("1") + "\n" + r("0") + "\n";
  s += head("/PROP/SHELL/1", "plate") + i("24") + i("2") + "\n" + r("0") + "\n" + i("3") + i("0") + r("1.5") + r("0") +
       i("") + i("1") + i("1") + "\n";
  s += head("/PART/1", "plate") + i("1") + i("1") + "\n/NODE\n";
  for (int n = 0; n < 6; ++n)
    s += i(std::to_string(n + 1)) + r(std::to_string(10 * (n % 3))) + r(std::to_string(10 * (n / 3))) + r("0") + "\n";
  s += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(5) + I(4) + "\n" + I(2) + I(2) + I(3) + I(6) + I(5) + "\n";
  s += head("/GRNOD/NODE/1", "left") + i("1") + i("4") + "\n" + head("/GRNOD/NODE/2", "right") + i("3") + i("6") + "\n";
  s += head("/BCS/1", "fixed") + (narrow ? " 111 011" : "   111 011") + i("0") + i("1") + "\n";
  s += head("/FUNCT/1", "ramp") + r("0") + r("0") + "\n" + r("1") + r("2") + "\n";
  s += head("/IMPVEL/1", "pull") + i("1") + i("X") + i("0") + i("0") + i("2") + "\n" +
       (narrow ? r("3") + r("0.1") + r("5") : r("0") + r("3") + r("0.1") + r("5")) + "\n";
  s += head("/CLOAD/2", "push") + i("1") + i("Z") + i("0") + i("0") +
       (narrow ? r("4") + i("2") : i("2") + i("") + r("0") + r("4")) + "\n";
  s += head("/GRAV/3", "down") + i("1") + i("Y") + i("0") + i("0") +
       (narrow ? r("-9.81") + i("1") : i("1") + i("") + r("0") + r("-9.81")) + "\n";
  s += head("/TH/NODE/1", "n") + std::string(narrow ? "DEF     " : "DEF       ") + "\n" + i("3") + i("0") + "\n";
  // LAW36: no pressure line in versions 41 to 44 (Ipfun and Eps_f end the control line in 44).
  s += head("/MAT/PLAS_TAB/2", "tab") + r("7.85e-06") + "\n" + r("210") + r("0.3") + r("0.5") + "\n" + i("1") +
       i("0") + r("0") + r("0") + "\n";
  if (!narrow) s += i("0") + r("0") + i("0") + r("0") + r("0") + "\n";
  s += i("1") + "\n" + r("0.25") + "\n" + r("0") + "\n";
  // TYPE7: versions 41 to 44 have no gap and stiffness lines; IBC in columns 6-8 (8-10 in 2017).
  s += head("/SURF/PART/3", "plate") + i("1") + "\n" + head("/INTER/TYPE7/7", "contact") + i("2") + i("3") + i("0") +
       i("") + i("0") + i("0") + i("0") + i("2") + "\n";
  if (!narrow) s += r("0") + r("0") + r("0") + "\n" + r("0") + r("0") + r("0") + r("0") + i("0") + i("0") + "\n";
  s += r("1.5") + r("0.1") + r("0.5") + r("0") + r("0") + "\n";
  s += std::string(narrow ? "     011" : "       011") + i("") + i("") + i("0") + r("0.05") + r("1.0") + r("0.2") + "\n";
  s += i("0") + i("0") + r("0") + i("0") + "\n";
  return s;
}

TEST(InputVersions, NarrowLayoutsOfVersions41To44ReadAsThe2017Ones) {
  test::TempDir dir;
  const Model wide = read_deck(dir.write("W_0000.rad", begin(2017) + tiny_model(false) + "/END\n")).model;
  for (int version : {41, 42, 44}) {
    SCOPED_TRACE("Invers " + std::to_string(version));
    const Model m = read_deck(dir.write("N_0000.rad", begin(version) + tiny_model(true) + "/END\n")).model;
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[0].title, "steel");
    EXPECT_EQ(m.materials[0].density, wide.materials[0].density);
    EXPECT_EQ(m.materials[0].young, wide.materials[0].young);
    EXPECT_EQ(m.materials[0].johnson_cook.b, wide.materials[0].johnson_cook.b);
    EXPECT_EQ(m.properties[0].shell.thickness, wide.properties[0].shell.thickness);
    EXPECT_EQ(m.formulations[0].ishell, 24);
    EXPECT_EQ(m.formulations[0].n_points, wide.formulations[0].n_points);
    EXPECT_EQ(m.properties[0].shell.ithick, 1);
    EXPECT_EQ(m.nodes.x, wide.nodes.x);
    EXPECT_EQ(m.nodes.y, wide.nodes.y);
    EXPECT_EQ(m.parts[0].title, "plate");
    ASSERT_EQ(m.boundary_conditions.size(), 1u);
    EXPECT_EQ(m.boundary_conditions[0].fixed_translation, wide.boundary_conditions[0].fixed_translation);
    EXPECT_EQ(m.boundary_conditions[0].fixed_rotation, (std::array<bool, 3>{false, true, true}));
    ASSERT_EQ(m.imposed.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(m.imposed[k].dof, wide.imposed[k].dof);
      EXPECT_EQ(m.imposed[k].scale_x, wide.imposed[k].scale_x);
      EXPECT_EQ(m.imposed[k].scale_y, wide.imposed[k].scale_y);
      EXPECT_EQ(m.imposed[k].node_group, wide.imposed[k].node_group);
      EXPECT_EQ(m.imposed[k].t_start, wide.imposed[k].t_start);
      EXPECT_EQ(m.imposed[k].t_stop, wide.imposed[k].t_stop);
    }
    ASSERT_EQ(m.gravity.size(), 1u);
    EXPECT_EQ(m.gravity[0].scale_y, wide.gravity[0].scale_y);
    EXPECT_EQ(m.gravity[0].node_group, wide.gravity[0].node_group);
    EXPECT_EQ(m.functions[0](0.5), wide.functions[0](0.5));
    ASSERT_EQ(m.materials.size(), 2u);
    EXPECT_EQ(m.materials[1].tabulated.eps_p_max, wide.materials[1].tabulated.eps_p_max);
    EXPECT_EQ(m.materials[1].tabulated.function_id, wide.materials[1].tabulated.function_id);
    EXPECT_EQ(m.materials[1].tabulated.scale, wide.materials[1].tabulated.scale);
    EXPECT_EQ(m.histories[0].object_ids, wide.histories[0].object_ids);
    ASSERT_EQ(m.type7_interfaces.size(), 1u);
    const Type7Interface &a = m.type7_interfaces[0], &b = wide.type7_interfaces[0];
    EXPECT_EQ(a.title, "contact");
    EXPECT_EQ(a.idel, 2);
    EXPECT_EQ(a.stfac, b.stfac);
    EXPECT_EQ(a.fric, b.fric);
    EXPECT_EQ(a.gapmin, b.gapmin);
    EXPECT_EQ(a.ibc, (std::array<bool, 3>{false, true, true}));
    EXPECT_EQ(a.viss, b.viss);
    EXPECT_EQ(a.bumult, b.bumult);
  }
}

// Cards whose old layout is another one (lines, fields) are refused in versions 41 to 44, naming the version.
TEST(InputVersions, OldLayoutsCrumpleDoesNotReadAreErrors) {
  test::TempDir dir;
  const auto path = dir.write("N_0000.rad", begin(44) + tiny_model(true) + "/SECT/9/cut\n       1       2\n/END\n");
  const std::string e = test::first_error(path);
  EXPECT_NE(e.find("/SECT/9/cut: field layout"), std::string::npos) << e;
  EXPECT_NE(e.find("versions 41 to 44 is not supported by Crumple"), std::string::npos) << e;
  EXPECT_NE(test::first_error(dir.write("O_0000.rad", begin(40) + "/END\n")).find("41 or later"), std::string::npos);
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

// /SURF/GRSHEL: the shells of the groups as segments, each once; /GRNOD/SURF: the nodes of a surface's segments.
TEST(SurfaceKeywords, ShellGroupSurfacesAndSurfaceNodeGroups) {
  test::TempDir dir;
  const std::string extra = "/GRSHEL/SHEL/4\nfirst\n" + I(1) + "\n/GRSHEL/PART/5\nall\n" + I(1) +
                            "\n/SURF/GRSHEL/6\nsurface\n" + I(4) + I(5) + "\n/GRNOD/SURF/7\nits nodes\n" + I(6) + "\n";
  const Model m = read_deck(deck(dir, 2019, extra)).model;
  const Surface& s = m.surfaces.at(static_cast<std::size_t>(m.index.surfaces.at(6)));
  ASSERT_EQ(s.segments.size(), 2u);  // shell 1 in both groups counts once
  EXPECT_EQ(s.segments[0].owner.kind, ElementKind::Shell4);
  const NodeGroup& g = m.node_groups.at(static_cast<std::size_t>(m.index.node_groups.at(7)));
  EXPECT_EQ(g.nodes.size(), 6u);  // every node of the plate's two shells
  EXPECT_NE(test::first_error(deck(dir, 2019, "/SURF/GRSHEL/6\ns\n" + I(9) + "\n")).find("shell group 9 not defined"),
            std::string::npos);
}

}  // namespace test_input_versions
