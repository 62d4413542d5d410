// The fields of the field frames (docs/output-format.md, "/frames/NNNN"): every /ANIM request written for every
// element kind from a hand-made state of a tiny model, the fields nobody asked for left out, the deleted elements
// hidden for ParaView, the part ids as cell data; and through the solver, the frame at t = 0, the last frame at
// an end time off the /ANIM/DT grid, and the recorded nodal forces and accelerations of a real run.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "crumple/elements/shell4.hpp"
#include "crumple/output/results_file.hpp"
#include "crumple/output/results_reader.hpp"
#include "crumple/output/run_recorder.hpp"
#include "crumple/state/element_status.hpp"
#include "crumple/output/run.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_frame_fields {

using namespace crumple;
using test::I;
using test::R;

namespace {

// The plate of test::write_deck (shells 1, 2 of part 1), a triangle (shell3 9 of part 1) and a cube (brick8 5 of
// part 2, /PROP/SOLID 2, Isolid 1) on shell 1: 11 nodes.
std::string all_kinds_cards() {
  std::string s = "/NODE\n" + I(7) + R(0.03) + R(0.0) + R(0.0) + "\n";
  s += I(11) + R(0.0) + R(0.0) + R(0.01) + "\n" + I(12) + R(0.01) + R(0.0) + R(0.01) + "\n";
  s += I(13) + R(0.01) + R(0.01) + R(0.01) + "\n" + I(14) + R(0.0) + R(0.01) + R(0.01) + "\n";
  s += "/SH3N/1\n" + I(9) + I(3) + I(7) + I(6) + "\n";
  s += "/BRICK/2\n" + I(5) + I(1) + I(2) + I(5) + I(4) + I(11) + I(12) + I(13) + I(14) + "\n";
  s += "/PART/2\ncube\n" + I(2) + I(1) + "\n/PROP/SOLID/2\nsolid\n" + I(1) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  return s;
}

const std::string kEveryRequest =
    "/ANIM/ELEM/VONM\n/ANIM/ELEM/P\n/ANIM/ELEM/ENER\n/ANIM/ELEM/HOURG\n/ANIM/ELEM/DT\n"
    "/ANIM/SHELL/TENS/STRESS/BEND\n/ANIM/SHELL/TENS/STRESS/UPPER\n/ANIM/VECT/CONT\n/ANIM/VECT/ACC\n"
    "/ANIM/VECT/FINT\n/ANIM/VECT/FEXT\n/ANIM/VECT/VROT\n/ANIM/MASS\n/ANIM/NODA/DMAS\n";

std::size_t group_of(const Model& m, ElementKind kind) {
  for (std::size_t g = 0; g < m.element_groups.size(); ++g)
    if (m.element_groups[g].kind == kind) return g;
  ADD_FAILURE() << "no group of kind " << static_cast<int>(kind);
  return 0;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The text of grid `name` of the last frame of NAME.xdmf.
std::string last_grid(const std::string& xdmf, const std::string& name) {
  const auto at = xdmf.rfind("<Grid Name=\"" + name + "\"");
  return at == std::string::npos ? std::string() : xdmf.substr(at, xdmf.find("</Grid>", at) - at);
}

// Where a plate shell's sxx, syy, sxy land in its global tensor (sxx syy szz sxy syz szx): the test plate lies in
// the global xy plane with its first side along x, so its frame is the global one.
constexpr std::size_t kPlateComponent[3] = {0, 1, 3};

double plane_von_mises(double sx, double sy, double sxy) { return std::sqrt(sx * sx + sy * sy - sx * sy + 3 * sxy * sxy); }

// Shell point k of element e: a stress that differs per point and component.
void set_shell_point(ShellState& s, std::size_t k, std::size_t e, std::size_t j) {
  s.sxx[k] = 1e6 * static_cast<double>(1 + j + 3 * e);
  s.syy[k] = -2e5 * static_cast<double>(j + 1);
  s.sxy[k] = 3e5 * static_cast<double>(e + 1) * (j == 2 ? 2.0 : 1.0);
  s.eps_p[k] = 0.01 * static_cast<double>(j + 1) + 0.1 * static_cast<double>(e);
}

struct Written {
  test::TempDir dir;
  Model model;
  SolverState state;
  std::filesystem::path h5;
};

// The all-kinds model with every request, and a state with known values in every array a field reads.
void write_every_field(Written& w) {
  w.model = read_deck(test::write_deck(w.dir, all_kinds_cards(), test::engine_cards() + kEveryRequest)).model;
  const Model& m = w.model;
  std::vector<std::string> notes;
  w.state = initial_state(m, notes);
  SolverState& s = w.state;
  const std::size_t g4 = group_of(m, ElementKind::Shell4), g3 = group_of(m, ElementKind::Shell3);
  ASSERT_EQ(s.shells.points[g4], 3);  // N = 3: zeta -1/2, 0, 1/2
  ASSERT_EQ(s.shells3.points[g3], 3);
  for (std::size_t e = 0; e < 2; ++e)
    for (std::size_t j = 0; j < 3; ++j) set_shell_point(s.shells, s.shells.point_offset[g4] + 3 * e + j, e, j);
  for (std::size_t j = 0; j < 3; ++j) set_shell_point(s.shells3, s.shells3.point_offset[g3] + j, 0, j);
  // The triangle as an N = 0 element: its bending stress is the one it keeps, its surfaces membrane +- bending.
  s.shell_groups[g3].resultant_plasticity = true;
  s.shells3.bending_stress = {5e5, -1e5, 2e5};
  BrickState& b = s.bricks;
  b.sxx[0] = 1e6, b.syy[0] = 2e6, b.szz[0] = -3e6, b.sxy[0] = 4e5, b.syz[0] = 5e5, b.szx[0] = 6e5, b.eps_p[0] = 0.05;
  s.shells.internal_energy = {2.0, 4.0}, s.shells.hourglass_energy = {0.5, 0.25}, s.shells.critical_dt = {1e-7, 2e-7};
  s.shells3.internal_energy = {1.0}, s.shells3.hourglass_energy = {0.125}, s.shells3.critical_dt = {3e-7};
  b.internal_energy = {6.0}, b.hourglass_energy = {0.75}, b.critical_dt = {4e-7};
  s.shells.deleted[1] = kElementDeleted;
  s.shells3.deleted[0] = kElementInRigidBody;  // there, only not computed: shown
  b.deleted[0] = kElementDeleted;
  const std::size_t n = m.nodes.size();
  for (auto* v : {&s.recorded.acceleration, &s.recorded.internal_force, &s.recorded.external_force}) v->resize(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) {
    s.recorded.acceleration[i] = 1.0 + static_cast<double>(i);
    s.recorded.internal_force[i] = -2.0 * static_cast<double>(i);
    s.recorded.external_force[i] = 0.5 * static_cast<double>(i);
  }
  for (std::size_t i = 0; i < n; ++i)
    s.nodes.wx[i] = static_cast<double>(i), s.nodes.wy[i] = -1.0, s.nodes.wz[i] = 2.0 * static_cast<double>(i);
  s.nodes.mass[3] += 0.5;  // as if mass scaling had added it
  w.h5 = w.dir.path() / "TEST.h5";
  ResultsFile file(w.h5, m);
  file.write_frame(2e-4, 7, m, s);
  file.close();
}

}  // namespace

TEST(FrameFields, EveryRequestedNodalFieldIsTheStateValue) {
  Written w;
  write_every_field(w);
  const ResultsReader h5(w.h5);
  const std::size_t n = w.model.nodes.size();
  ASSERT_EQ(n, 11u);
  const std::string f = "/frames/0000/";
  EXPECT_EQ(h5.doubles(f + "acceleration"), w.state.recorded.acceleration);
  EXPECT_EQ(h5.doubles(f + "internal_force"), w.state.recorded.internal_force);
  EXPECT_EQ(h5.doubles(f + "external_force"), w.state.recorded.external_force);
  EXPECT_EQ(h5.shape(f + "acceleration"), (std::vector<std::size_t>{n, 3}));
  // No interface: the contact force asked for is zero.
  EXPECT_EQ(h5.doubles(f + "contact_force"), std::vector<double>(3 * n, 0.0));
  const auto w_rot = h5.doubles(f + "angular_velocity");
  EXPECT_DOUBLE_EQ(w_rot[3 * 4 + 0], 4.0);
  EXPECT_DOUBLE_EQ(w_rot[3 * 4 + 1], -1.0);
  EXPECT_DOUBLE_EQ(w_rot[3 * 4 + 2], 8.0);
  EXPECT_EQ(h5.doubles(f + "mass"), w.state.nodes.mass);
  const auto added = h5.doubles(f + "added_mass");
  ASSERT_EQ(added.size(), n);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(added[i], i == 3 ? 0.5 : 0.0, 1e-15) << "node " << i;  // mass minus the initial nodal mass
}

TEST(FrameFields, EveryRequestedShellFieldIsComputedFromThePoints) {
  Written w;
  write_every_field(w);
  const ResultsReader h5(w.h5);
  const std::string f = "/frames/0000/shell4/";
  // The N = 3 rule: membrane weights 1/4 1/2 1/4; bending 6 sum b_i sigma_i with b = -1/12 0 1/12.
  const auto stress = h5.doubles(f + "stress"), bending = h5.doubles(f + "bending_stress");
  const auto upper = h5.doubles(f + "stress_upper"), lower = h5.doubles(f + "stress_lower");
  const auto vm = h5.doubles(f + "von_mises"), pressure = h5.doubles(f + "pressure");
  const ShellState& s = w.state.shells;
  for (std::size_t e = 0; e < 2; ++e) {
    const std::size_t k = 3 * e;
    const std::vector<double>* comps[3] = {&s.sxx, &s.syy, &s.sxy};
    for (std::size_t d = 0; d < 3; ++d) {
      const auto& c = *comps[d];
      const std::size_t at = 6 * e + kPlateComponent[d];
      EXPECT_NEAR(stress[at], 0.25 * c[k] + 0.5 * c[k + 1] + 0.25 * c[k + 2], 1e-9) << e << d;
      EXPECT_NEAR(bending[at], 0.5 * (c[k + 2] - c[k]), 1e-9) << e << d;
      EXPECT_EQ(upper[at], c[k + 2]);
      EXPECT_EQ(lower[at], c[k]);
    }
    for (const auto* tensor : {&stress, &bending, &upper, &lower})
      for (std::size_t d : {2, 4, 5}) EXPECT_EQ((*tensor)[6 * e + d], 0.0) << e << d;  // szz syz szx: plane stress
    double largest = 0.0;
    for (std::size_t j = 0; j < 3; ++j) largest = std::max(largest, plane_von_mises(s.sxx[k + j], s.syy[k + j], s.sxy[k + j]));
    EXPECT_DOUBLE_EQ(vm[e], largest);
    EXPECT_NEAR(pressure[e], -(stress[6 * e] + stress[6 * e + 1]) / 3.0, 1e-9);
    EXPECT_DOUBLE_EQ(h5.doubles(f + "plastic_strain")[e], 0.03 + 0.1 * static_cast<double>(e));
  }
  EXPECT_DOUBLE_EQ(h5.doubles(f + "energy_density")[1], 4.0 / s.mass[1]);
  EXPECT_GT(s.mass[1], 0.0);
  EXPECT_EQ(h5.doubles(f + "hourglass_energy"), (std::vector<double>{0.5, 0.25}));
  EXPECT_EQ(h5.doubles(f + "time_step"), (std::vector<double>{1e-7, 2e-7}));
  EXPECT_EQ(h5.bytes(f + "deleted"), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(h5.bytes(f + "vtkGhostType"), (std::vector<std::uint8_t>{0, 32}));  // HIDDENCELL: ParaView hides it

  // The "N = 0" triangle: surfaces are membrane +- its kept bending stress; von Mises the larger of the two.
  const std::string t = "/frames/0000/shell3/";
  const auto m3 = h5.doubles(t + "stress");
  const std::vector<double> kept{5e5, -1e5, 0.0, 2e5, 0.0, 0.0};
  const auto bending3 = h5.doubles(t + "bending_stress");
  ASSERT_EQ(bending3.size(), kept.size());
  for (std::size_t d = 0; d < 6; ++d) EXPECT_NEAR(bending3[d], kept[d], 1e-9) << d;  // its frame: e1 = x to 1 ulp
  const auto up3 = h5.doubles(t + "stress_upper"), low3 = h5.doubles(t + "stress_lower");
  for (std::size_t d = 0; d < 6; ++d) {
    EXPECT_NEAR(up3[d], m3[d] + kept[d], 1e-9);
    EXPECT_NEAR(low3[d], m3[d] - kept[d], 1e-9);
  }
  EXPECT_DOUBLE_EQ(h5.doubles(t + "von_mises")[0], std::max(plane_von_mises(up3[0], up3[1], up3[3]),
                                                           plane_von_mises(low3[0], low3[1], low3[3])));
  EXPECT_DOUBLE_EQ(h5.doubles(t + "energy_density")[0], 1.0 / w.state.shells3.mass[0]);
  EXPECT_EQ(h5.bytes(t + "deleted"), (std::vector<std::uint8_t>{0}));  // in a rigid body: not deleted
  EXPECT_EQ(h5.bytes(t + "vtkGhostType"), (std::vector<std::uint8_t>{0}));
}

// A shell's stress in its co-rotational frame (e1 along its first sides, e3 its normal) as a tensor in the global
// axes: a square in a plane at 45 degrees, e1 = y, e2 = (x + z) / sqrt 2. sigma = 3 e1 e1 + 5 e2 e2 + 2 (e1 e2 +
// e2 e1): xx = zz = zx = 2.5, yy = 3, xy = yz = sqrt 2; the triangle of three of its corners has the same frame.
TEST(FrameFields, AShellStressIsATensorInTheGlobalAxes) {
  const Vec3 square[4] = {{0, 0, 0}, {0, 1, 0}, {1, 1, 1}, {1, 0, 1}}, triangle[3] = {square[0], square[1], square[3]};
  const double local[3] = {3.0, 5.0, 2.0};
  const double r2 = std::sqrt(2.0);
  for (const auto& [x, n] : {std::pair{square, 4}, std::pair{triangle, 3}}) {
    const std::array<double, 6> s = shell_stress_in_global_axes(x, n, local);
    const std::array<double, 6> expected{2.5, 3.0, 2.5, r2, r2, 2.5};  // xx yy zz xy yz zx
    for (std::size_t d = 0; d < 6; ++d) EXPECT_NEAR(s[d], expected[d], 1e-14) << n << " nodes, component " << d;
  }
  const Vec3 line[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // no normal: no frame, no stress shown
  EXPECT_EQ(shell_stress_in_global_axes(line, 3, local), (std::array<double, 6>{}));
}

TEST(FrameFields, EveryRequestedBrickFieldIsComputedFromThePoints) {
  Written w;
  write_every_field(w);
  const ResultsReader h5(w.h5);
  const std::string f = "/frames/0000/brick8/";
  EXPECT_EQ(h5.shape(f + "stress"), (std::vector<std::size_t>{1, 6}));
  EXPECT_EQ(h5.doubles(f + "stress"), (std::vector<double>{1e6, 2e6, -3e6, 4e5, 5e5, 6e5}));  // sxx syy szz sxy syz szx
  // sqrt(((sx-sy)^2 + (sy-sz)^2 + (sz-sx)^2) / 2 + 3 (sxy^2 + syz^2 + szx^2)) = sqrt(21 + 2.31) MPa
  EXPECT_NEAR(h5.doubles(f + "von_mises")[0], std::sqrt(23.31) * 1e6, 1e-6);
  EXPECT_NEAR(h5.doubles(f + "pressure")[0], 0.0, 1e-9);  // -(1 + 2 - 3) / 3 MPa
  EXPECT_DOUBLE_EQ(h5.doubles(f + "plastic_strain")[0], 0.05);
  const double cube_mass = 7800.0 * 1e-6;
  EXPECT_NEAR(w.state.bricks.mass[0], cube_mass, 1e-15);
  EXPECT_DOUBLE_EQ(h5.doubles(f + "energy_density")[0], 6.0 / w.state.bricks.mass[0]);
  EXPECT_EQ(h5.doubles(f + "hourglass_energy"), (std::vector<double>{0.75}));
  EXPECT_EQ(h5.doubles(f + "time_step"), (std::vector<double>{4e-7}));
  EXPECT_EQ(h5.bytes(f + "deleted"), (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(h5.bytes(f + "vtkGhostType"), (std::vector<std::uint8_t>{32}));
  EXPECT_FALSE(h5.exists(f + "thickness"));  // a shell field
}

TEST(FrameFields, PartIdsAreCellDataAndTheTitlesAreInBothFiles) {
  Written w;
  write_every_field(w);
  const ResultsReader h5(w.h5);
  EXPECT_EQ(h5.longs("/mesh/shell4/part_id"), (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(h5.longs("/mesh/shell3/part_id"), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(h5.longs("/mesh/brick8/part_id"), (std::vector<std::int64_t>{2}));
  EXPECT_EQ(h5.longs("/mesh/parts/ids"), (std::vector<std::int64_t>{1, 2}));
  const std::string xdmf = read_text(w.dir.path() / "TEST.xdmf");
  EXPECT_NE(xdmf.find("<Information Name=\"part 1\" Value=\"plate\"/>"), std::string::npos) << xdmf.substr(0, 400);
  EXPECT_NE(xdmf.find("<Information Name=\"part 2\" Value=\"cube\"/>"), std::string::npos);
  for (const char* kind : {"shell4", "shell3", "brick8"}) {
    const std::string grid = last_grid(xdmf, kind);
    EXPECT_NE(grid.find("Name=\"part_id\" AttributeType=\"Scalar\" Center=\"Cell\""), std::string::npos) << grid;
    EXPECT_NE(grid.find(std::string("Dimensions=\"") + (std::string(kind) == "shell4" ? "2" : "1") +
                        "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">TEST.h5:/mesh/" + kind + "/part_id"),
              std::string::npos)
        << grid;
  }
}

TEST(FrameFields, XdmfDescribesEveryFieldOnItsGridWithTheGhostFlagsLast) {
  Written w;
  write_every_field(w);
  const std::string xdmf = read_text(w.dir.path() / "TEST.xdmf");
  const std::string bricks = last_grid(xdmf, "brick8"), shells = last_grid(xdmf, "shell4");
  EXPECT_NE(bricks.find("Name=\"stress\" AttributeType=\"Matrix\" Center=\"Cell\""), std::string::npos) << bricks;
  EXPECT_NE(bricks.find("Dimensions=\"1 6\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">TEST.h5:/frames/0000/"
                        "brick8/stress"),
            std::string::npos);
  // Shell stresses are tensors too (6 components: ParaView names them XX YY ZZ XY YZ XZ, not a vector's X Y Z).
  EXPECT_NE(shells.find("Name=\"stress\" AttributeType=\"Matrix\" Center=\"Cell\""), std::string::npos) << shells;
  EXPECT_NE(shells.find("Name=\"bending_stress\" AttributeType=\"Matrix\" Center=\"Cell\""), std::string::npos);
  EXPECT_NE(shells.find("Dimensions=\"2 6\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">TEST.h5:/frames/0000/"
                        "shell4/stress"),
            std::string::npos)
      << shells;
  for (const std::string* grid : {&bricks, &shells}) {
    // The geometry is the frame's deformed positions, not an attribute: ParaView draws the deformed shape.
    EXPECT_NE(grid->find("<Geometry GeometryType=\"XYZ\">\n"), std::string::npos) << *grid;
    EXPECT_NE(grid->find("Format=\"HDF\">TEST.h5:/frames/0000/coordinates</DataItem>\n"), std::string::npos);
    EXPECT_EQ(grid->find("/mesh/coordinates"), std::string::npos);
    EXPECT_EQ(grid->find("Name=\"coordinates\""), std::string::npos);
    EXPECT_NE(grid->find("Name=\"acceleration\" AttributeType=\"Vector\" Center=\"Node\""), std::string::npos);
    EXPECT_NE(grid->find("Name=\"added_mass\" AttributeType=\"Scalar\" Center=\"Node\""), std::string::npos);
    EXPECT_NE(grid->find("Name=\"energy_density\" AttributeType=\"Scalar\" Center=\"Cell\""), std::string::npos);
    // ParaView's XDMF reader makes the first scalar of a grid the active one: the ghost flags come last.
    EXPECT_EQ(grid->rfind("<Attribute "), grid->find("<Attribute Name=\"vtkGhostType\" AttributeType=\"Scalar\""));
    EXPECT_NE(grid->find("NumberType=\"UChar\" Precision=\"1\" Format=\"HDF\">TEST.h5:/frames/0000/"),
              std::string::npos);
  }
  EXPECT_EQ(shells.find("/brick8/"), std::string::npos);  // each grid names only its own cells
}

TEST(FrameFields, FieldsNobodyAskedForAreNotWritten) {
  test::TempDir dir;
  const Model m = read_deck(test::write_deck(dir, all_kinds_cards())).model;
  std::vector<std::string> notes;
  const SolverState s = initial_state(m, notes);
  {
    ResultsFile file(dir.path() / "TEST.h5", m);
    file.write_frame(0.0, 0, m, s);
  }
  const ResultsReader h5(dir.path() / "TEST.h5");
  for (const char* every : {"coordinates", "displacement", "velocity", "shell4/stress", "shell4/von_mises",
                            "shell4/plastic_strain", "shell4/thickness", "shell4/deleted", "shell4/vtkGhostType",
                            "brick8/stress", "brick8/von_mises", "brick8/plastic_strain", "brick8/deleted",
                            "brick8/vtkGhostType"})
    EXPECT_TRUE(h5.exists(std::string("/frames/0000/") + every)) << every;
  for (const char* asked : {"contact_force", "acceleration", "internal_force", "external_force", "angular_velocity",
                            "mass", "added_mass", "shell4/bending_stress", "shell4/stress_upper",
                            "shell4/energy_density", "brick8/pressure", "brick8/time_step"})
    EXPECT_FALSE(h5.exists(std::string("/frames/0000/") + asked)) << asked;
}

TEST(FrameFields, AStateWithoutAnAskedForArrayIsRejectedBeforeTheFrameIsWritten) {
  Written w;
  write_every_field(w);
  ResultsFile file(w.dir.path() / "B.h5", w.model);
  SolverState s = w.state;
  s.bricks.critical_dt.clear();
  try {
    file.write_frame(0.0, 0, w.model, s);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("element critical steps has 0 values, the frame needs 1"), std::string::npos)
        << e.what();
  }
  s.bricks.critical_dt = {1e-7};
  s.recorded.acceleration.resize(5);
  EXPECT_THROW(file.write_frame(0.0, 0, w.model, s), std::runtime_error);
  EXPECT_EQ(file.frames(), 0u);
  s.recorded.acceleration.clear();  // not recorded: not written
  file.write_frame(0.0, 0, w.model, s);
  EXPECT_EQ(file.frames(), 1u);
}

// ---------------------------------------------------------------------------------------------------------------
// Through the solver

namespace {

const std::string kAllNodes = "/GRNOD/NODE/11\nall\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + "\n";

// The plate moving at 1 m/s along z, run to 1e-3 s with `engine_extra` after /RUN and /ANIM/DT `anim`.
RunSummary run_plate(const test::TempDir& dir, const std::string& anim, const std::string& starter_extra = "",
                     const std::string& engine_extra = "") {
  const std::string engine = "/RUN/TEST/1\n1e-3\n/ANIM/DT\n" + anim + "\n" + engine_extra;
  const std::string motion = kAllNodes + "/INIVEL/TRA/1\nup\n" + R(0.0) + R(0.0) + R(1.0) + I(11) + I(0) + "\n";
  const Deck d = read_deck(test::write_deck(dir, motion + starter_extra, engine));
  SimulationOptions options;
  options.output_directory = dir.path();
  std::ostringstream console;
  return run_simulation(d.model, options, console);
}

std::string frame(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%04zu", k);
  return name;
}

std::size_t frame_count(const ResultsReader& h5) {
  std::size_t k = 0;
  while (h5.exists(frame(k))) ++k;
  return k;
}

}  // namespace

// /ANIM/DT 0 4e-4 with the end at 1e-3: frames at 0 (the initial state, before any cycle), at the first cycles
// past 4e-4 and 8e-4, and at the end time, which is off the grid.
TEST(FrameFields, FramesStartAtTimeZeroAndEndAtTheEndTimeOffTheGrid) {
  test::TempDir dir;
  const RunSummary summary = run_plate(dir, "0 4e-4");
  ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
  const ResultsReader h5(dir.path() / "TEST.h5");
  ASSERT_EQ(frame_count(h5), 4u);
  EXPECT_EQ(h5.attribute<double>(frame(0), "time"), 0.0);
  EXPECT_EQ(h5.attribute<std::int64_t>(frame(0), "cycle"), 0);
  for (double u : h5.doubles(frame(0) + "/displacement")) EXPECT_EQ(u, 0.0);
  const auto v0 = h5.doubles(frame(0) + "/velocity");
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(v0[3 * i + 2], 1.0);  // the initial velocity
  const double t1 = h5.attribute<double>(frame(1), "time"), t2 = h5.attribute<double>(frame(2), "time");
  EXPECT_TRUE(t1 >= 4e-4 && t1 < 4.1e-4) << t1;
  EXPECT_TRUE(t2 >= 8e-4 && t2 < 8.1e-4) << t2;
  // T-0: no step is cut to land on the end time; the last frame (near 8e-4) is more than 100 cycles back, so the
  // run ends at the first cycle past 1e-3, and its frame is that state.
  EXPECT_GE(summary.time, 1e-3);
  EXPECT_LT(summary.time - summary.dt, 1e-3) << summary.time;
  EXPECT_EQ(h5.attribute<double>(frame(3), "time"), summary.time);
  EXPECT_EQ(h5.attribute<std::int64_t>(frame(3), "cycle"), summary.cycles);
  // The plate flies at 1 m/s: at the end it has moved 1 m/s times the end state's time.
  EXPECT_NEAR(h5.doubles(frame(3) + "/displacement")[2], summary.time, 1e-12);
}

// On the grid, the end time's frame is the one the last cycle wrote: it is not written twice.
TEST(FrameFields, AnEndTimeOnTheGridIsWrittenOnce) {
  test::TempDir dir;
  const RunSummary summary = run_plate(dir, "0 5e-4");
  const ResultsReader h5(dir.path() / "TEST.h5");
  ASSERT_EQ(frame_count(h5), 3u);
  EXPECT_EQ(h5.attribute<double>(frame(0), "time"), 0.0);
  EXPECT_GE(h5.attribute<double>(frame(2), "time"), 1e-3);  // T-0: its last frame 100 cycles back, one past the end
  EXPECT_EQ(h5.attribute<double>(frame(2), "time"), summary.time);
  EXPECT_EQ(h5.attribute<std::int64_t>(frame(2), "cycle"), summary.cycles);
  EXPECT_LT(h5.attribute<std::int64_t>(frame(1), "cycle"), summary.cycles);
}

// Tstart past 0: the frames start at Tstart, none at 0; the end time still gets its frame.
TEST(FrameFields, FramesStartAtTstart) {
  test::TempDir dir;
  run_plate(dir, "3e-4 5e-4");
  const ResultsReader h5(dir.path() / "TEST.h5");
  ASSERT_EQ(frame_count(h5), 3u);
  const double t0 = h5.attribute<double>(frame(0), "time");
  EXPECT_TRUE(t0 >= 3e-4 && t0 < 3.1e-4) << t0;
  EXPECT_GE(h5.attribute<double>(frame(2), "time"), 1e-3);  // T-0: the end frame, one cycle past the end time
}

// A run's recorded nodal results: the external force is the gravity load m g, and every node, free of
// conditions, has the acceleration (internal + external force) / mass of its velocity change.
TEST(FrameFields, RecordedForcesAndAccelerationsOfARunAgree) {
  test::TempDir dir;
  const std::string gravity = "/FUNCT/1\nconstant\n" + R(0.0) + R(1.0) + "\n" + R(1.0) + R(1.0) + "\n" +
                              "/GRAV/2\ngravity\n" + I(1) + "         Z" + I(0) + I(0) + I(11) + test::blank(10) +
                              R(1.0) + R(-9.81) + "\n";
  const RunSummary summary = run_plate(dir, "0 5e-4", gravity,
                                       "/ANIM/VECT/ACC\n/ANIM/VECT/FINT\n/ANIM/VECT/FEXT\n/ANIM/MASS\n");
  ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
  const ResultsReader h5(dir.path() / "TEST.h5");
  ASSERT_EQ(frame_count(h5), 3u);
  for (const char* name : {"acceleration", "internal_force", "external_force"}) {
    for (double v : h5.doubles(frame(0) + "/" + name)) EXPECT_EQ(v, 0.0) << name;  // before the first cycle
  }
  const auto mass = h5.doubles(frame(2) + "/mass");
  const auto a = h5.doubles(frame(2) + "/acceleration"), fi = h5.doubles(frame(2) + "/internal_force"),
             fe = h5.doubles(frame(2) + "/external_force");
  ASSERT_EQ(mass.size(), 6u);
  double largest_internal = 0.0;
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(fe[3 * i], 0.0);
    EXPECT_EQ(fe[3 * i + 2], mass[i] * -9.81) << "node " << i;
    for (std::size_t d = 0; d < 3; ++d) {
      const double expected = (fi[3 * i + d] + fe[3 * i + d]) / mass[i];
      EXPECT_NEAR(a[3 * i + d], expected, 1e-9 * (std::abs(expected) + 9.81)) << "node " << i << " dof " << d;
      largest_internal = std::max(largest_internal, std::abs(fi[3 * i + d]));
    }
  }
  EXPECT_LT(largest_internal, 1e-9);  // rigid translation: the elements carry no force
}

// The end of a run writes its last state when frames are asked for, also when none was written before (a run
// resumed past the last grid time), but not before Tstart; a state already written is not written again.
TEST(FrameFields, TheEndOfARunWritesItsLastStateOnce) {
  const auto frames_after_close = [](const std::string& anim, double time, bool write_before) {
    test::TempDir dir;
    const Model m = read_deck(test::write_deck(dir, "", "/RUN/TEST/1\n1e-3\n/ANIM/DT\n" + anim + "\n")).model;
    std::vector<std::string> notes;
    SolverState s = initial_state(m, notes);
    s.time = time, s.cycle = 40;
    {
      RunRecorder recorder(m, dir.path(), "TEST", true);
      if (write_before) recorder.frame(s);
      recorder.close(s, false);
    }
    const ResultsReader h5(dir.path() / "TEST.h5");
    return frame_count(h5);
  };
  EXPECT_EQ(frames_after_close("0 4e-4", 1e-3, false), 1u);
  EXPECT_EQ(frames_after_close("2e-3 4e-4", 1e-3, false), 0u);  // Tstart past the end: no frame at all
  EXPECT_EQ(frames_after_close("0 4e-4", 1e-3, true), 1u);      // that cycle's frame is there already
}

}  // namespace test_frame_fields
