// Skews (docs/theory/skews.md) and the rigid body's centre choices (ICoG, docs/theory/rigid-bodies.md RB-0e):
// conditions, loads and initial velocities along a fixed skew's axes on free point masses, whose motion is known
// exactly; a moving skew carried by a spinning rigid body, and a free node's history written in it; the body's
// mass, centre and inertia for ICoG 1 to 4 against the reference solver's starter listing.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "crumple/output/history_reader.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_skews {
namespace {

std::string var(const std::string& name) { return name + std::string(10 - name.size(), ' '); }

std::string fixed_skew(long long id, Vec3 y_direction, Vec3 z_direction) {
  return "/SKEW/FIX/" + std::to_string(id) + "\nfixed skew\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(y_direction.x) +
         R(y_direction.y) + R(y_direction.z) + "\n" + R(z_direction.x) + R(z_direction.y) + R(z_direction.z) + "\n";
}

// /IMPVEL, /CLOAD or /GRAV line 1 with a skew: function, direction, skew, sensor, group.
std::string skewed_line(long long function, const std::string& dir, long long skew, long long group) {
  return I(function) + std::string(10 - dir.size(), ' ') + dir + I(skew) + I(0) + I(group);
}

// /RBODY with the card's mass and diagonal inertia, Ispher and ICoG.
std::string rigid_body(long long id, long long main_node, long long group, double mass, Vec3 inertia, int ispher,
                       int icog) {
  return "/RBODY/" + std::to_string(id) + "\nbody\n" + I(main_node) + I(0) + I(0) + I(ispher) + R(mass) + I(group) +
         I(0) + I(icog) + "\n" + R(inertia.x) + R(inertia.y) + R(inertia.z) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n" +
         I(0) + I(0) + "\n";
}

// Fixed skew 1: Y' along (1, 1, 0), Z'' along z, so X' = (1, -1, 0)/sqrt 2, Z' = z (eq. SK-1). Five free point
// masses of 2 kg, far apart (no element joins them):
//   node 1, /INIVEL/TRA in the skew (1, 2, 0);
//   node 2, /IMPVEL 3 m/s along X', /BCS fixing Y', /CLOAD 5 N along Y' (held) and 4 N along Z';
//   node 3, /CLOAD 6 N along X';
//   node 4, /GRAV 9 m/s^2 along Y';
//   node 5, /INIVEL/ROT (0, 0, 2) rad/s in the skew, and its rotation held about Z' by a /BCS: it keeps no spin.
TEST(Skews, ConditionsLoadsAndVelocitiesActAlongTheSkewAxes) {
  constexpr double m = 2.0, end = 0.01;
  std::string s = node_cards({{1, 0, 0, 0}, {2, 10, 0, 0}, {3, 20, 0, 0}, {4, 30, 0, 0}, {5, 40, 0, 0}});
  s += fixed_skew(1, {1, 1, 0}, {0, 0, 1}) + unit_function(1);
  for (long long n = 1; n <= 5; ++n) s += node_group(n, {n});
  s += node_group(9, {1, 2, 3, 4, 5}) + added_mass(1, m, 9);
  s += "/INIVEL/TRA/1\nin skew\n" + R(1.0) + R(2.0) + R(0.0) + I(1) + I(1) + "\n";
  s += "/IMPVEL/1\nalong X'\n" + skewed_line(1, "X", 1, 2) + "\n" + R(0.0) + R(3.0) + R(0.0) + R(0.0) + "\n";
  s += "/BCS/1\nY' held\n   010 000" + I(1) + I(2) + "\n";
  s += "/CLOAD/1\nheld\n" + skewed_line(1, "Y", 1, 2) + I(0) + R(0.0) + R(5.0) + "\n";
  s += "/CLOAD/2\nfree\n" + skewed_line(1, "Z", 1, 2) + I(0) + R(0.0) + R(4.0) + "\n";
  s += "/CLOAD/3\nfree\n" + skewed_line(1, "X", 1, 3) + I(0) + R(0.0) + R(6.0) + "\n";
  s += "/GRAV/1\nalong Y'\n" + skewed_line(1, "Y", 1, 4) + I(0) + R(0.0) + R(9.0) + "\n";
  s += "/INIVEL/ROT/2\nspin\n" + R(0.0) + R(0.0) + R(2.0) + I(5) + I(1) + "\n";
  s += "/BCS/2\nZ' rotation held\n   000 001" + I(1) + I(5) + "\n";
  std::vector<Vec3> velocity(5);
  std::vector<double> spin(5);
  double t = 0.0;
  test::TempDir dir;
  const RunResult run = run_deck(
      dir, s, end, 1e-9,
      [&](const Model& mm, const SolverState& st) {
        t = st.time;
        for (long long id = 1; id <= 5; ++id) {
          const std::size_t k = node_index(mm, id);
          velocity[static_cast<std::size_t>(id - 1)] = {st.nodes.vx[k], st.nodes.vy[k], st.nodes.vz[k]};
          spin[static_cast<std::size_t>(id - 1)] = norm(Vec3{st.nodes.wx[k], st.nodes.wy[k], st.nodes.wz[k]});
        }
      },
      "/DTIX\n1e-4 1e-4\n");
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_EQ(run.model.skews.size(), 1u);
  const double a = 1.0 / std::sqrt(2.0);
  const Vec3 X{a, -a, 0.0}, Y{a, a, 0.0}, Z{0.0, 0.0, 1.0};
  // Each node's velocity v^(n+1/2) after the last step, v0 + F t / m along the skew's axes (the loads are
  // constant; the first half step and the cycles' full steps sum to t = t^n + dt/2 of the last step).
  const double tv = t - 0.5e-4;
  const Vec3 expected[4] = {X + scaled(Y, 2.0), scaled(X, 3.0) + scaled(Z, 4.0 * tv / m), scaled(X, 6.0 * tv / m),
                            scaled(Y, 9.0 * tv)};
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(velocity[k][c], expected[k][c], 1e-9) << "node " << k + 1 << ", component " << c;
  EXPECT_EQ(spin[4], 0.0) << "the spin about Z' is held";
  // The loads' work is the kinetic energy they gave; the held load does no work (energy balance, loads.md). The end
  // row's work to t^N is the linear share of the next cycle's (energy.md, E-3): for constant loads it is off by
  // dt^2 / (4 t^2) of their work, 2.5e-5 of it here (the loop's own balance closes to round-off).
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 1e-4);
}

// A body spinning at 1 rad/s about z through its main node 10 (ICoG 3, the deck skew_mov_frame's arrangement),
// carrying massless nodes 11, 12, 13 that define moving skew 1: X' along 11-12 (the body's y at the start), Y'
// along 11-13 (z). Node 100, of 1 g, moves freely at 1 m/s along x; its /TH/NODE in skew 1 writes its displacement
// and position along the turning axes: X' = (-sin wt, cos wt, 0), Z' = (cos wt, sin wt, 0) (eq. SK-4).
TEST(Skews, MovingSkewTurnsWithItsNodesAndHistoriesAreWrittenInIt) {
  std::string s = node_cards({{10, 0, 0, 0}, {11, 0, 1, 0}, {12, 0, 2, 0}, {13, 0, 1, 1}, {100, 0, 0, 0}});
  s += "/SKEW/MOV/1\nturning\n" + I(11) + I(12) + I(13) + "\n";
  s += node_group(1, {10}) + node_group(2, {100}) + node_group(3, {11, 12, 13});
  s += "/INIVEL/ROT/1\nspin\n" + R(0.0) + R(0.0) + R(1.0) + I(1) + I(0) + "\n";
  s += initial_velocity(2, 1.0, 0.0, 0.0, 2) + added_mass(1, 0.001, 2);
  s += rigid_body(10, 10, 3, 10.0, {1.0, 1.0, 1.0}, 1, 3);
  s += "/TH/NODE/1\nin the skew\n" + var("D") + var("XYZ") + "\n" + I(100) + I(1) + "\n" + I(12) + I(1) + "\n";
  test::TempDir dir;
  dir.write("VERIF_0001.rad", "/RUN/VERIF/1\n3.0\n/TFILE\n0.1\n/DTIX\n0.01 0.01\n/PRINT/-100000\n");
  const auto path = dir.write("VERIF_0000.rad", test::begin_card("VERIF") + s + "/END\n");
  Model model = read_deck(path).model;
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  std::ostringstream console;
  const RunSummary summary = run_simulation(model, options, console);
  ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
  // The body's spin energy, 1/2 J w^2 with J = 1 (Ispher 1), and the free node's 1/2 m v^2.
  EXPECT_NEAR(summary.energy.kinetic_rotational, 0.5, 1e-12);
  EXPECT_NEAR(summary.energy.kinetic_translational, 0.5 * 0.001, 1e-12);
  const HistoryFile file(dir.path() / "VERIF.h5");
  std::map<std::string, std::pair<std::size_t, std::size_t>> where;
  for (std::size_t k = 0; k < file.series().size(); ++k)
    for (std::size_t c = 0; c < file.series()[k].columns.size(); ++c) where[file.series()[k].columns[c].label] = {k, c};
  auto series = [&](const std::string& label) {
    const auto [k, c] = where.at(label);
    std::vector<double> out;
    const std::vector<double> all = file.values(k);
    for (std::size_t r = 0; r < file.rows(); ++r) out.push_back(all[r * file.series()[k].columns.size() + c]);
    return out;
  };
  const std::vector<double> time = series("time"), dx = series("NODE_1/100/DX"), dz = series("NODE_1/100/DZ"),
                            dy = series("NODE_1/100/DY"), x12 = series("NODE_1/12/X"), z12 = series("NODE_1/12/Z");
  ASSERT_GE(time.size(), 20u);
  for (std::size_t r = 0; r < time.size(); ++r) {
    const double t = time[r];
    SCOPED_TRACE("time " + std::to_string(t));
    EXPECT_NEAR(dx[r], -t * std::sin(t), 1e-9);
    EXPECT_NEAR(dy[r], 0.0, 1e-12);
    EXPECT_NEAR(dz[r], t * std::cos(t), 1e-9);
    // Node 12 turns with the skew: always at 2 along X', 0 along Z' (a skew has no origin to take off).
    EXPECT_NEAR(x12[r], 2.0, 1e-9);
    EXPECT_NEAR(z12[r], 0.0, 1e-9);
  }
}

// The reference's starter listing for one body under each ICoG (measured with the reference solver on this deck,
// its "RIGID BODY INITIALIZATION" block: NEW X,Y,Z, NEW MASS, NEW INERTIA): main node 10 at (5, 0, 0) with 7 kg of
// /ADMAS and the card's 10 kg, secondary nodes 11, 12, 13 at (0,1,0), (0,2,0), (0,1,1) with 2 kg each, the card's
// inertia diag(1, 2, 3). The listing prints I_ij = -sum m r_i r_j off the diagonal, as Crumple stores it.
struct ReferenceBody {
  int icog;
  double mass;
  Vec3 centre;
  double inertia[6];  // xx yy zz xy yz zx
};
constexpr ReferenceBody kReferenceBodies[] = {
    {1, 23.0, {3.695652, 0.3478261, 0.08695652}, {12.04348, 114.6957, 123.0870, 29.56522, -1.304348, 7.391304}},
    {2, 23.0, {0.0, 1.333333, 0.3333333}, {3.666667, 3.333333, 4.333333, 0.0, 0.6666667, 0.0}},
    {3, 23.0, {5.0, 0.0, 0.0}, {15.0, 154.0, 165.0, 40.0, -2.0, 10.0}},
    {4, 17.0, {5.0, 0.0, 0.0}, {1.0, 2.0, 3.0, 0.0, 0.0, 0.0}},
};

TEST(Skews, RigidBodyCentreChoicesMatchTheReference) {
  for (const ReferenceBody& ref : kReferenceBodies) {
    SCOPED_TRACE("ICoG " + std::to_string(ref.icog));
    std::string s = node_cards({{10, 5, 0, 0}, {11, 0, 1, 0}, {12, 0, 2, 0}, {13, 0, 1, 1}});
    s += node_group(3, {11, 12, 13}) + node_group(4, {10}) + added_mass(1, 2.0, 3) + added_mass(2, 7.0, 4);
    s += rigid_body(10, 10, 3, 10.0, {1.0, 2.0, 3.0}, 2, ref.icog);
    test::TempDir dir;
    double mass = 0.0;
    Vec3 centre{};
    std::array<double, 9> inertia{};
    double total_mass = 0.0;
    const RunResult run = run_deck(
        dir, s, 1e-3, 1e-6,
        [&](const Model& m, const SolverState& st) {
          const std::size_t k = node_index(m, 10);
          mass = st.bodies[0].mass, centre = {st.nodes.x[k], st.nodes.y[k], st.nodes.z[k]};
          inertia = st.bodies[0].inertia_body, total_mass = st.mass_initial;
        },
        "/DTIX\n1e-4 1e-4\n");
    ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
    EXPECT_NEAR(mass, ref.mass, 1e-12);
    EXPECT_NEAR(total_mass, ref.mass, 1e-12) << "ICoG 4 drops the secondary nodes' masses, as the reference";
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], ref.centre[c], 1e-6 * (1.0 + std::abs(ref.centre[c])));
    const double listed[6] = {inertia[0], inertia[4], inertia[8], inertia[1], inertia[5], inertia[2]};
    for (std::size_t c = 0; c < 6; ++c)
      EXPECT_NEAR(listed[c], ref.inertia[c], 1e-6 * (1.0 + std::abs(ref.inertia[c]))) << "component " << c;
  }
}

}  // namespace
}  // namespace crumple::verification::test_skews
