// Patch tests of the 4-node Belytschko-Tsay shell on the distorted five-element patch of MacNeal and Harder
// (a 0.24 x 0.12 rectangle with four interior nodes at irregular places, docs/verification.md).
//
// Physics: a linear velocity field is a state of constant strain rate. An element passes the patch test when,
// on any (distorted) mesh, it reproduces that constant strain and the constant stress it implies in every
// element, and the assembled internal forces vanish at the interior nodes (the stresses are in equilibrium)
// while the boundary nodes carry exactly the consistent tractions: sum over the elements of A_e B_eI equals
// the boundary integral of N_I n, which is zero at an interior node. The one-point B-matrix of the
// Belytschko-Tsay element is the exact mean gradient of the bilinear field, so all of this holds to round-off
// for one increment. The hourglass shape vectors gamma are orthogonal to every linear field, so the hourglass
// forces must stay zero too.
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "crumple/elements/shell4.hpp"
#include "crumple/solver/solver.hpp"  // initial_state (the start state of a run)
#include "verification_support.hpp"

namespace crumple::verification::test_patch {
namespace {

// Relative round-off of one step: a few hundred ulps of double; in the mixed build the point stresses are rounded
// to single when stored (docs/theory/precision.md, eq. PR-2), a few ulps of single.
constexpr double kRoundOff = kMixedPrecision ? 1e-6 : 1e-12;

constexpr double kYoung = 1.0e6, kNu = 0.25, kRho = 1.0, kThickness = 0.001;

// MacNeal-Harder patch: corners 1-4, interior nodes 5-8, five elements numbered counter-clockwise.
std::vector<NodeRow> patch_nodes() {
  return {{1, 0.0, 0.0, 0.0},   {2, 0.24, 0.0, 0.0},  {3, 0.24, 0.12, 0.0}, {4, 0.0, 0.12, 0.0},
          {5, 0.04, 0.02, 0.0}, {6, 0.18, 0.03, 0.0}, {7, 0.16, 0.08, 0.0}, {8, 0.08, 0.08, 0.0}};
}
std::vector<ShellRow> patch_shells() {
  return {{1, 1, 2, 6, 5}, {2, 2, 3, 7, 6}, {3, 3, 4, 8, 7}, {4, 4, 1, 5, 8}, {5, 5, 6, 7, 8}};
}
// Ishell 12 runs with its numerical damping dn (eq. Q-8) practically off, and Ishell 24 with its membrane damping dm
// (S-9d, 0.015 by default as in the reference): each damping stress is proportional to the element's size, so on a
// distorted mesh under a uniform strain rate it is not a constant state and the patch cannot balance it (with the
// default dn = 0.001 the interior forces are 3e-6 of the boundary ones, with dm = 0.015 1.4e-5). The patch tests
// measure the stiffness.
std::string patch_starter(int points, int ishell, int ismstr = 0) {
  return node_cards(patch_nodes()) + shell_cards(1, patch_shells()) + part_card() +
         shell_property(kThickness, points, 0.0, ishell, ishell == 12 ? 1e-30 : 0.0, ismstr, 0,
                        ishell == 24 ? 1e-30 : 0.0) +
         elastic_material(kRho, kYoung, kNu);
}

// Plane-stress elasticity on engineering strains (exx, eyy, gxy).
std::array<double, 3> plane_stress(const std::array<double, 3>& e) {
  const double c = kYoung / (1.0 - kNu * kNu);
  return {c * (e[0] + kNu * e[1]), c * (e[1] + kNu * e[0]), c * 0.5 * (1.0 - kNu) * e[2]};
}

// Element frame of a flat element in the z = 0 plane (docs/theory/shell4.md, S-1): e1 along the mean of the
// sides 1-2 and 4-3. Returns (cos, sin) of the angle of e1 with the global x axis.
std::array<double, 2> element_axis(const NodalState& n, const std::int32_t* c) {
  const auto k = [&](int a) { return static_cast<std::size_t>(c[a]); };
  const double sx = (n.x[k(1)] - n.x[k(0)]) + (n.x[k(2)] - n.x[k(3)]);
  const double sy = (n.y[k(1)] - n.y[k(0)]) + (n.y[k(2)] - n.y[k(3)]);
  const double l = std::hypot(sx, sy);
  return {sx / l, sy / l};
}

// A symmetric in-plane tensor (xx, yy, xy) given in a frame at angle (c, s), expressed in the global frame.
std::array<double, 3> to_global(const std::array<double, 3>& t, double c, double s) {
  return {c * c * t[0] + s * s * t[1] - 2.0 * c * s * t[2], s * s * t[0] + c * c * t[1] + 2.0 * c * s * t[2],
          c * s * (t[0] - t[1]) + (c * c - s * s) * t[2]};
}

// The patch read from a generated deck, with the solver's own start state (initial_state) so that the
// kernel sees exactly what the time loop gives it.
struct Patch {
  Model model;
  SolverState solver;
  NodalState& nodes;
  ShellState& state;
  ShellGroupParameters p;
  const double* zeta;

  Patch(int points, int ishell, int ismstr = 0)
      : model(read_patch(points, ishell, ismstr)), solver(start(model)), nodes(solver.nodes), state(solver.shells) {
    p = solver.shell_groups.at(0);
    zeta = p.zeta;
  }
  static Model read_patch(int points, int ishell, int ismstr) {
    test::TempDir dir;
    return read_deck(dir.write("P_0000.rad", test::begin_card("P") + patch_starter(points, ishell, ismstr) + "/END\n"))
        .model;
  }
  static SolverState start(const Model& m) {
    std::vector<std::string> notes;
    return initial_state(m, notes);
  }
  std::size_t node(long long id) const { return node_index(model, id); }
  void step(double dt) {
    nodes.clear_forces();
    ASSERT_EQ(model.element_groups.size(), 1u);
    const GroupStepResult r = shell4_forces(model.elements[0], model.element_groups[0], p, nodes, state, dt);
    ASSERT_EQ(r.inverted, -1);
  }
};

// Integral of N_I n ds over the patch boundary for the corner nodes: half of each adjacent side, outward.
// (Interior nodes: zero.)
std::array<double, 2> boundary_weight(long long corner) {
  const double a = 0.24, b = 0.12;
  switch (corner) {
    case 1: return {-b / 2, -a / 2};
    case 2: return {b / 2, -a / 2};
    case 3: return {b / 2, a / 2};
    case 4: return {-b / 2, a / 2};
  }
  return {0.0, 0.0};
}

// Every patch test runs for the 4-node formulations that pass it: Belytschko-Tsay (Ishell 1), its elasto-plastic
// hourglass variant (Ishell 3) and the physically stabilised element (Ishell 24), whose hourglass modes must stay
// at rest under the linear fields of a patch, and the fully integrated Batoz shell (Ishell 12), which must
// reproduce the constant state at each of its four Gauss points. Ishell 2 does not orthogonalise its hourglass
// vector and fails on this distorted mesh by design (unit.Shell4Hourglass.Ishell2IsNotOrthogonalToLinearFields).
class PatchTest : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Ishell, PatchTest, ::testing::Values(1, 3, 12, 24));

// In-plane integration points (sections) of an element: four Gauss points for Ishell 12, one otherwise.
std::size_t sections(int ishell) { return ishell == 12 ? 4 : 1; }

TEST_P(PatchTest, MembraneConstantStrainOnDistortedMesh) {
  Patch patch(1, GetParam());
  // v = G x with a non-symmetric G: strain rates (exx, eyy, gxy) = (G11, G22, G12 + G21) and a spin
  // (G21 - G12) / 2 that must not produce stress.
  const double G[2][2] = {{1.0e-3, 0.4e-3}, {-0.7e-3, -0.3e-3}};
  for (std::size_t k = 0; k < patch.nodes.size(); ++k) {
    patch.nodes.vx[k] = G[0][0] * patch.nodes.x[k] + G[0][1] * patch.nodes.y[k];
    patch.nodes.vy[k] = G[1][0] * patch.nodes.x[k] + G[1][1] * patch.nodes.y[k];
  }
  const double dt = 1e-3;
  patch.step(dt);
  const std::array<double, 3> strain{G[0][0] * dt, G[1][1] * dt, (G[0][1] + G[1][0]) * dt};
  const std::array<double, 3> sigma = plane_stress(strain);
  const double scale = std::max({std::abs(sigma[0]), std::abs(sigma[1]), std::abs(sigma[2])});
  const double force_scale = scale * kThickness * 0.24;

  double worst_stress = 0.0, worst_interior = 0.0, worst_boundary = 0.0, worst_hourglass = 0.0;
  for (long long id = 1; id <= 5; ++id) {
    const std::size_t e = shell_index(patch.model, id);
    const auto [c, s] = element_axis(patch.nodes, patch.model.elements[0].nodes_of(e));
    for (std::size_t g = 0; g < sections(GetParam()); ++g) {
      const std::size_t ip = sections(GetParam()) * e + g;
      const std::array<double, 3> global = to_global({patch.state.sxx[ip], patch.state.syy[ip], patch.state.sxy[ip]}, c, s);
      for (int i = 0; i < 3; ++i) worst_stress = std::max(worst_stress, std::abs(global[i] - sigma[i]) / scale);
    }
    for (int m = 0; m < 5; ++m)
      worst_hourglass = std::max(worst_hourglass, std::abs(patch.state.hourglass[5 * e + m]) / force_scale);
  }
  for (long long id = 5; id <= 8; ++id) {
    const std::size_t k = patch.node(id);
    worst_interior = std::max({worst_interior, std::hypot(patch.nodes.fx[k], patch.nodes.fy[k]) / force_scale,
                               std::abs(patch.nodes.fz[k]) / force_scale});
  }
  for (long long id = 1; id <= 4; ++id) {
    const std::size_t k = patch.node(id);
    const auto [nx, ny] = boundary_weight(id);
    // nodes.f holds minus the internal force: the reaction the boundary must supply is t sigma . n ds.
    const double fx = -kThickness * (sigma[0] * nx + sigma[2] * ny);
    const double fy = -kThickness * (sigma[2] * nx + sigma[1] * ny);
    worst_boundary = std::max(worst_boundary, std::hypot(patch.nodes.fx[k] - fx, patch.nodes.fy[k] - fy) / force_scale);
  }
  // Internal energy of one increment (trapezoidal rule from zero stress): V sigma : eps / 2.
  double energy = 0.0;
  for (double w : patch.state.internal_energy) energy += w;
  const double expected_energy =
      0.5 * 0.24 * 0.12 * kThickness * (sigma[0] * strain[0] + sigma[1] * strain[1] + sigma[2] * strain[2]);

  RecordProperty("stress_error", std::to_string(worst_stress));
  EXPECT_LT(worst_stress, kRoundOff) << "element stresses differ from the constant plane-stress state";
  EXPECT_LT(worst_interior, kRoundOff) << "interior nodes are not in equilibrium";
  EXPECT_LT(worst_boundary, kRoundOff) << "boundary nodal forces are not the consistent tractions";
  EXPECT_LT(worst_hourglass, kRoundOff) << "a linear field excited the hourglass modes";
  EXPECT_NEAR(energy, expected_energy, kRoundOff * expected_energy);
  std::printf("[membrane patch] stress %.2e  interior force %.2e  boundary force %.2e  hourglass %.2e (relative)\n",
              worst_stress, worst_interior, worst_boundary, worst_hourglass);
}

TEST_P(PatchTest, BendingConstantCurvatureOnDistortedMesh) {
  // Five points through the thickness: the equally spaced rule integrates a linear stress profile exactly.
  Patch patch(5, GetParam());
  // Angular velocities linear in x, y give constant curvature rates (S-3):
  //   k_xx = d(thy)/dx = K[0],  k_yy = -d(thx)/dy = K[1],  k_xy = d(thy)/dy - d(thx)/dx = K[2].
  // The transverse shear of this field is the mean rotation of each element, which is not constant; a
  // constant-curvature Mindlin state needs a quadratic w, and the one-point shear of a non-parallelogram
  // element is not exact for a quadratic w. The bending part is tested alone, with the shear stiffness off.
  patch.p.shear_factor = 0.0;
  const double K[3] = {2.0e-3, -1.0e-3, 1.5e-3};
  for (std::size_t k = 0; k < patch.nodes.size(); ++k) {
    const double x = patch.nodes.x[k], y = patch.nodes.y[k];
    patch.nodes.wy[k] = K[0] * x + 0.6 * K[2] * y;
    patch.nodes.wx[k] = -K[1] * y - 0.4 * K[2] * x;
  }
  const double dt = 1e-3;
  patch.step(dt);
  const std::array<double, 3> kappa{K[0] * dt, K[1] * dt, K[2] * dt};
  const std::array<double, 3> unit_stress = plane_stress(kappa);  // stress per unit height z
  // Bending moments per unit length: t^3 / 12 times the stress gradient.
  const double t3 = kThickness * kThickness * kThickness / 12.0;
  const std::array<double, 3> moment{t3 * unit_stress[0], t3 * unit_stress[1], t3 * unit_stress[2]};
  const double scale = std::max({std::abs(unit_stress[0]), std::abs(unit_stress[1]), std::abs(unit_stress[2])}) *
                       0.5 * kThickness;  // surface stress
  const double moment_scale = scale * kThickness * kThickness / 6.0 * 0.24;

  double worst_stress = 0.0, worst_interior = 0.0, worst_boundary = 0.0, worst_force = 0.0;
  for (long long id = 1; id <= 5; ++id) {
    const std::size_t e = shell_index(patch.model, id);
    const auto [c, s] = element_axis(patch.nodes, patch.model.elements[0].nodes_of(e));
    for (std::size_t ip = sections(GetParam()) * e * 5; ip < sections(GetParam()) * (e + 1) * 5; ++ip) {
      const double z = patch.zeta[ip % 5] * kThickness;
      const std::array<double, 3> global = to_global({patch.state.sxx[ip], patch.state.syy[ip], patch.state.sxy[ip]}, c, s);
      for (int i = 0; i < 3; ++i) worst_stress = std::max(worst_stress, std::abs(global[i] - z * unit_stress[i]) / scale);
    }
  }
  for (std::size_t k = 0; k < patch.nodes.size(); ++k)
    worst_force = std::max(worst_force, std::abs(patch.nodes.fx[k]) + std::abs(patch.nodes.fy[k]) +
                                            std::abs(patch.nodes.fz[k]));
  for (long long id = 5; id <= 8; ++id) {
    const std::size_t k = patch.node(id);
    worst_interior = std::max(worst_interior, std::hypot(patch.nodes.mx[k], patch.nodes.my[k]) / moment_scale);
  }
  for (long long id = 1; id <= 4; ++id) {
    const std::size_t k = patch.node(id);
    const auto [nx, ny] = boundary_weight(id);
    // Internal nodal moments (S-7): (my, -mx) = M . (int N n ds); nodes.m holds minus them.
    const double my = -(moment[0] * nx + moment[2] * ny);
    const double mx = (moment[2] * nx + moment[1] * ny);
    worst_boundary = std::max(worst_boundary, std::hypot(patch.nodes.mx[k] - mx, patch.nodes.my[k] - my) / moment_scale);
  }
  double energy = 0.0;
  for (double w : patch.state.internal_energy) energy += w;
  const double expected_energy =
      0.5 * 0.24 * 0.12 * (moment[0] * kappa[0] + moment[1] * kappa[1] + moment[2] * kappa[2]);

  EXPECT_LT(worst_stress, kRoundOff) << "point stresses differ from the linear bending profile";
  EXPECT_LT(worst_interior, kRoundOff) << "interior nodes are not in moment equilibrium";
  EXPECT_LT(worst_boundary, kRoundOff) << "boundary nodal moments are not the consistent edge moments";
  EXPECT_LT(worst_force / (moment_scale / 0.24), kRoundOff) << "pure bending produced nodal forces";
  EXPECT_NEAR(energy, expected_energy, kRoundOff * expected_energy);
  std::printf("[bending patch] stress %.2e  interior moment %.2e  boundary moment %.2e (relative)\n", worst_stress,
              worst_interior, worst_boundary);
}

// The same membrane patch through the whole solver: the deck drives the four corners with /IMPVEL (a linear
// velocity field) and starts every node on that field with /INIVEL. When the patch test holds, the interior
// nodes feel no force and keep the linear field for the whole run, and every element carries the same stress.
// Two effects that are not errors of the element bound what "to round-off" means here:
//  - geometric non-linearity: element frames of different orientation turn at slightly different rates, so the
//    co-rotational stresses differ by O(strain) relative; the final strain is kept at 1e-7;
//  - coordinate round-off: x += dt v adds ~1e-17 m of rounding per cycle to coordinates of 0.1 m, against a
//    displacement of 2.4e-8 m: ~1e-7 relative after 2000 cycles. The velocities do not suffer from it.
TEST_P(PatchTest, MembranePatchThroughTheSolver) {
  test::TempDir dir;
  const double end_time = 0.08, strain = 1.0e-7, rate = strain / end_time;
  const double G[2][2] = {{rate, 0.5 * rate}, {-0.3 * rate, 0.6 * rate}};
  // Function 1 is 1, function 2 is 0: a zero Fscale_Y means 1 on /IMPVEL, so a zero velocity needs a zero function.
  std::string starter = patch_starter(1, GetParam()) + unit_function(1) + function_card(2, {{0.0, 0.0}, {1e3, 0.0}});
  const auto impose = [](long long id, const std::string& axis, long long group, double v) {
    return v == 0.0 ? imposed_velocity(id, 2, axis, group, 1.0) : imposed_velocity(id, 1, axis, group, v);
  };
  const std::vector<NodeRow> nodes = patch_nodes();
  for (const NodeRow& n : nodes) {
    const double vx = G[0][0] * n.x + G[0][1] * n.y, vy = G[1][0] * n.x + G[1][1] * n.y;
    starter += node_group(100 + n.id, {n.id}) + initial_velocity(n.id, vx, vy, 0.0, 100 + n.id);
    if (n.id <= 4) starter += impose(10 * n.id, "X", 100 + n.id, vx) + impose(10 * n.id + 1, "Y", 100 + n.id, vy);
  }
  // One observer call at the first cycle and one at the end time (the time-history interval is the end time).
  SolverState last;
  const RunResult run = run_deck(dir, starter, end_time, end_time, [&](const Model&, const SolverState& s) { last = s; });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_GT(run.summary.cycles, 1900);  // about 2000 (1988 with the skewed elements' T-1b length of Ishell 1 to 4)
  ASSERT_EQ(last.time, run.summary.time);  // the last history row is the run's end state
  ASSERT_LT(std::abs(last.time - end_time), run.summary.dt);  // within a step of the end time (T-0)
  const Model& m = run.model;
  const double T = last.time;
  double worst_position = 0.0, worst_velocity = 0.0;
  const double displacement_scale = rate * T * 0.24, velocity_scale = rate * 0.24;
  for (const NodeRow& n : nodes) {
    const std::size_t k = node_index(m, n.id);
    const double vx = G[0][0] * n.x + G[0][1] * n.y, vy = G[1][0] * n.x + G[1][1] * n.y;
    worst_position = std::max(worst_position, std::hypot(last.nodes.x[k] - n.x - vx * T,
                                                         last.nodes.y[k] - n.y - vy * T) / displacement_scale);
    worst_velocity = std::max(worst_velocity, std::hypot(last.nodes.vx[k] - vx, last.nodes.vy[k] - vy) / velocity_scale);
  }
  // The stress is the one of x^n, before the last position update: small-strain stress of G (T - dt).
  const double t_stress = T - last.dt;
  const std::array<double, 3> e{G[0][0] * t_stress, G[1][1] * t_stress, (G[0][1] + G[1][0]) * t_stress};
  const std::array<double, 3> sigma = plane_stress(e);
  const double scale = std::max({std::abs(sigma[0]), std::abs(sigma[1]), std::abs(sigma[2])});
  double worst_stress = 0.0;
  for (long long id = 1; id <= 5; ++id) {
    const std::size_t el = shell_index(m, id);
    const auto [c, s] = element_axis(last.nodes, m.elements[0].nodes_of(el));
    const std::size_t ip = first_point(m, last, el);
    const auto global = to_global({last.shells.sxx[ip], last.shells.syy[ip], last.shells.sxy[ip]}, c, s);
    for (int i = 0; i < 3; ++i) worst_stress = std::max(worst_stress, std::abs(global[i] - sigma[i]) / scale);
  }
  // The mixed build rounds every stored stress to single each cycle (docs/theory/precision.md, PR-2): a random walk
  // of about u sqrt(N) of the stress (u = 2^-24, N cycles; bound 4 u sqrt(N), 1.6e-5 here), and the interior nodes
  // feel their elements' different round-off as a force, 3e-4 to 5e-4 of this 1e-7 strain patch's velocity field
  // (3e-7 m/s) by the end, measured (PR-3). Positions keep their double accuracy.
  const bool mixed = kMixedPrecision;
  const double u = 0x1p-24, cycles = static_cast<double>(run.summary.cycles);
  EXPECT_LT(worst_velocity, mixed ? 1e-3 : 1e-7) << "interior nodes were accelerated: the patch is not in equilibrium";
  EXPECT_LT(worst_position, 1e-5) << "interior nodes left the linear field";
  EXPECT_LT(worst_stress, mixed ? 4.0 * u * std::sqrt(cycles) : 1e-6) << "element stresses differ from the constant state";
  // Energy: the corner reactions' work becomes strain energy. The balance compares the internal energy at t^n
  // with the external work through t^(n+1/2) (the impulse of the last cycle acts over the mean step): for an
  // energy growing like t^2 that lag alone is about 1/cycles relative (0.05 % here), inside the 0.1 % bound.
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[solver membrane patch] cycles %lld  velocity %.2e  position %.2e  stress %.2e (relative)  "
              "energy error %.3f %%\n",
              run.summary.cycles, worst_velocity, worst_position, worst_stress, run.summary.energy.error_percent);
}

// Two meshes tied by /INTER/TYPE2 (docs/theory/tied-interfaces.md): a coarse 2 x 2 mesh (main) and a fine 2 x 4 mesh
// (tied nodes along x = 0.12) of a 0.24 x 0.12 plate, both distorted, under the patch's linear velocity field
// imposed on the outer boundary. The fine edge's nodes nest the coarse ones (a 2:1 transition, the usual use), so
// the coarse edge's shape functions are sums of the fine edge's: the tie's transpose (TI-4) hands the coarse nodes
// exactly the forces of a constant stress, and the linear field is a constant state of the tied patch. (Where the
// fine nodes do not nest the coarse ones, a node-to-segment tie is not exact across a loaded edge, as any one-pass
// tie.) Every element must hold the constant stress and every free and tied node the linear field.
TEST(TiedPatch, TwoToOneMeshTransitionKeepsTheConstantState) {
  test::TempDir dir;
  const double end_time = 0.08, rate = 1.0e-7 / end_time;
  const double G[2][2] = {{rate, 0.5 * rate}, {-0.3 * rate, 0.6 * rate}};
  std::vector<NodeRow> nodes = {{1, 0.0, 0.0, 0.0},  {2, 0.06, 0.0, 0.0},   {3, 0.12, 0.0, 0.0},
                                {4, 0.0, 0.06, 0.0}, {5, 0.05, 0.07, 0.0},  {6, 0.12, 0.06, 0.0},
                                {7, 0.0, 0.12, 0.0}, {8, 0.06, 0.12, 0.0},  {9, 0.12, 0.12, 0.0}};
  const double fine_x[3] = {0.12, 0.18, 0.24};
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 3; ++i) {
      const bool interior = i == 1 && j > 0 && j < 4;
      nodes.push_back({101 + 3 * j + i, fine_x[i] + (interior ? 0.004 * (j - 2) : 0.0), 0.03 * j + (interior ? 0.003 : 0.0), 0.0});
    }
  std::vector<ShellRow> coarse = {{1, 1, 2, 5, 4}, {2, 2, 3, 6, 5}, {3, 4, 5, 8, 7}, {4, 5, 6, 9, 8}}, fine;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 2; ++i) {
      const long long n1 = 101 + 3 * j + i;
      fine.push_back({101 + 2 * j + i, n1, n1 + 1, n1 + 4, n1 + 3});
    }
  std::string starter = node_cards(nodes) + shell_cards(1, coarse) + shell_cards(2, fine) + part_card() +
                        "/PART/2\nfine\n" + I(1) + I(1) + "\n" + shell_property(kThickness, 1) +
                        elastic_material(kRho, kYoung, kNu) + unit_function(1) +
                        function_card(2, {{0.0, 0.0}, {1e3, 0.0}});
  const std::vector<long long> tied = {101, 104, 107, 110, 113};
  const std::vector<long long> boundary = {1, 2, 3, 4, 7, 8, 9, 102, 103, 106, 109, 112, 114, 115};
  starter += node_group(50, tied) + "/SURF/PART/51\ncoarse\n" + I(1) + "\n/INTER/TYPE2/1\ntransition\n" + I(50) +
             I(51) + I(0) + I(0) + "\n";
  for (const NodeRow& n : nodes) {
    const double vx = G[0][0] * n.x + G[0][1] * n.y, vy = G[1][0] * n.x + G[1][1] * n.y;
    starter += node_group(1000 + n.id, {n.id}) + initial_velocity(n.id, vx, vy, 0.0, 1000 + n.id);
    if (std::find(boundary.begin(), boundary.end(), n.id) == boundary.end()) continue;
    for (const auto& [axis, v, id] : {std::tuple{"X", vx, 10 * n.id}, std::tuple{"Y", vy, 10 * n.id + 1}})
      starter += v == 0.0 ? imposed_velocity(id, 2, axis, 1000 + n.id, 1.0) : imposed_velocity(id, 1, axis, 1000 + n.id, v);
  }
  SolverState last;
  const RunResult run = run_deck(dir, starter, end_time, end_time, [&](const Model&, const SolverState& s) { last = s; });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  const Model& m = run.model;
  ASSERT_EQ(m.type2_interfaces.at(0).ties.size(), tied.size());
  const double T = last.time;
  double worst_velocity = 0.0, worst_position = 0.0;
  for (const NodeRow& n : nodes) {
    const std::size_t k = node_index(m, n.id);
    const double vx = G[0][0] * n.x + G[0][1] * n.y, vy = G[1][0] * n.x + G[1][1] * n.y;
    worst_velocity = std::max(worst_velocity, std::hypot(last.nodes.vx[k] - vx, last.nodes.vy[k] - vy) / (rate * 0.24));
    worst_position = std::max(worst_position, std::hypot(last.nodes.x[k] - n.x - vx * T, last.nodes.y[k] - n.y - vy * T) /
                                                  (rate * T * 0.24));
  }
  const double t_stress = T - last.dt;
  const std::array<double, 3> sigma =
      plane_stress({G[0][0] * t_stress, G[1][1] * t_stress, (G[0][1] + G[1][0]) * t_stress});
  const double scale = std::max({std::abs(sigma[0]), std::abs(sigma[1]), std::abs(sigma[2])});
  double worst_stress = 0.0;
  for (const auto& rows : {coarse, fine})
    for (const ShellRow& row : rows) {
      const std::size_t el = shell_index(m, row.id);
      const auto [c, sn] = element_axis(last.nodes, m.elements[0].nodes_of(el));
      const std::size_t ip = first_point(m, last, el);
      const auto global = to_global({last.shells.sxx[ip], last.shells.syy[ip], last.shells.sxy[ip]}, c, sn);
      for (int i = 0; i < 3; ++i) worst_stress = std::max(worst_stress, std::abs(global[i] - sigma[i]) / scale);
    }
  // The same bounds as the one-mesh patch (MembranePatchThroughTheSolver), the mixed build's round-off included.
  const double u = 0x1p-24, cycles = static_cast<double>(run.summary.cycles);
  EXPECT_LT(worst_velocity, kMixedPrecision ? 1e-3 : 1e-7) << "the tied patch is not in equilibrium";
  EXPECT_LT(worst_position, 1e-5);
  EXPECT_LT(worst_stress, kMixedPrecision ? 4.0 * u * std::sqrt(cycles) : 1e-6);
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[tied patch] cycles %lld  velocity %.2e  position %.2e  stress %.2e (relative)  energy error %.3f %%\n",
              run.summary.cycles, worst_velocity, worst_position, worst_stress, run.summary.energy.error_percent);
}

// Idel2 (docs/theory/tied-interfaces.md, TI-15): a node of 1e-3 kg pushed by 1e-3 kN out of the plane of a shell
// that is stretched until it fails (its edge x = 10 pulled at 1 mm/ms; failure plastic strain 0.02). With Idel2 2
// the node is let go when the shell is deleted and accelerates at F / m = 1 mm/ms^2 (measured on the reference:
// 0.99987); by default it stays with the deleted shell's nodes, which are held out of plane. A second, held shell keeps
// the step once the first is gone (without it the step would grow by a tenth a cycle).
TEST(TiedRelease, NodeIsLetGoWhenItsMainShellIsDeletedWithIdel2) {
  auto run_with = [](int idel2, double& vz_end, double& vz_before, double& dt_rows) {
    test::TempDir dir;
    std::string starter = node_cards({{1, 0.0, 0.0, 0.0}, {2, 10.0, 0.0, 0.0}, {3, 10.0, 10.0, 0.0}, {4, 0.0, 10.0, 0.0},
                                      {5, 2.5, 3.0, 0.0}, {6, 100.0, 0.0, 0.0}, {7, 110.0, 0.0, 0.0},
                                      {8, 110.0, 10.0, 0.0}, {9, 100.0, 10.0, 0.0}}) +
                          shell_cards(1, {{1, 1, 2, 3, 4}, {2, 6, 7, 8, 9}}) + part_card() + shell_property(1.0, 1) +
                          "/MAT/PLAS_JOHNS/1\njc\n" + R(7.8e-6) + "\n" + R(210.0) + R(0.3) + I(0) + "\n" + R(0.2) +
                          R(0.4) + R(0.4) + R(0.02) + "\n" + unit_function(1) + node_group(10, {1, 4, 6, 7, 8, 9}) +
                          node_group(11, {2, 3}) + node_group(12, {5}) + boundary_condition(1, "111 111", 10) +
                          boundary_condition(2, "011 111", 11) + imposed_velocity(1, 1, "X", 11, 1.0) +
                          added_mass(1, 1e-3, 12) + "/CLOAD/1\npush\n" + I(1) + "         Z" + I(0) + I(0) + I(12) +
                          std::string(10, ' ') + R(1.0) + R(1e-3) + "\n/SURF/PART/20\nshell\n" + I(1) +
                          "\n/INTER/TYPE2/1\nweld\n" + I(12) + I(20) + I(0) + I(5) + I(0) + I(0) + I(idel2) + "\n";
    std::vector<std::pair<double, double>> vz;
    const RunResult run = run_deck(dir, starter, 0.6, 0.01, [&](const Model& m, const SolverState& s) {
      vz.push_back({s.time, s.nodes.vz[node_index(m, 5)]});
    });
    ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
    ASSERT_GT(vz.size(), 10u);
    // Rows before the last, whose step is cut to land on the end time (the velocities belong to the half steps).
    const std::size_t a = vz.size() - 7, b = vz.size() - 2;
    vz_end = vz[b].second, vz_before = vz[a].second, dt_rows = vz[b].first - vz[a].first;
  };
  double released_end = 0.0, released_before = 0.0, span = 0.0, kept_end = 1.0, kept_before = 0.0, unused = 0.0;
  run_with(2, released_end, released_before, span);
  run_with(0, kept_end, kept_before, unused);
  EXPECT_EQ(kept_end, 0.0) << "the default keeps the node tied to the deleted shell's held nodes";
  EXPECT_GT(released_end, 0.1);
  EXPECT_NEAR((released_end - released_before) / span, 1.0, 1e-3) << "the released node moves under F / m";
}

// With Ismstr 1 the reference's Ishell 1 does not orthogonalise its hourglass vector (docs/theory/shell4.md, S-15):
// on the distorted patch a constant strain rate then loads the membrane hourglass modes exactly as Ishell 2's plain
// vector does (the patch test is failed by design, as for Ishell 2), while with Ismstr 2 they stay at rest.
TEST(PatchSmallStrain, Ishell1WithIsmstr1TakesThePlainHourglassVector) {
  const double G[2][2] = {{1.0e-3, 0.4e-3}, {-0.7e-3, -0.3e-3}};
  auto hourglass_of = [&](int ishell, int ismstr) {
    Patch patch(1, ishell, ismstr);
    for (std::size_t k = 0; k < patch.nodes.size(); ++k) {
      patch.nodes.vx[k] = G[0][0] * patch.nodes.x[k] + G[0][1] * patch.nodes.y[k];
      patch.nodes.vy[k] = G[1][0] * patch.nodes.x[k] + G[1][1] * patch.nodes.y[k];
    }
    patch.step(1e-3);
    return patch.state.hourglass;
  };
  const std::vector<double> plain = hourglass_of(2, 1), small = hourglass_of(1, 1), large = hourglass_of(1, 2);
  ASSERT_EQ(plain.size(), small.size());
  double largest = 0.0, worst_difference = 0.0, worst_large = 0.0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    largest = std::max(largest, std::abs(plain[i]));
    worst_difference = std::max(worst_difference, std::abs(small[i] - plain[i]));
    worst_large = std::max(worst_large, std::abs(large[i]));
  }
  // sigma ~ E G dt = 1e-3, force scale sigma t 0.24 ~ 2.4e-7: the plain vector's hourglass forces are a sizeable
  // fraction of it on this mesh, the orthogonal ones round-off.
  const double force_scale = kYoung * 1.0e-6 * kThickness * 0.24;
  EXPECT_GT(largest, 1e-3 * force_scale);
  EXPECT_LE(worst_difference, 1e-12 * largest);
  EXPECT_LT(worst_large, 1e-12 * force_scale);
}

}  // namespace
}  // namespace crumple::verification::test_patch
