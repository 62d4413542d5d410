// Moving rigid walls (docs/verification.md, "Moving rigid walls"; docs/theory/rigid-walls.md, RW-2).
//
// Physics: a rigid mass M at speed V0 strikes the end of a free elastic bar (impedance Z = rho c A). Until the
// wave reflected at the far end comes back (t < 2 L / c), the end moves with the mass and pushes with the force
// Z v, so M dV/dt = -Z V: V(t) = V0 exp(-Z t / M) (Saint-Venant's impact of a mass on a bar). With M equal to the
// bar's mass rho A L, Z / M = c / L, so V = V0 exp(-c t / L). The wall is the rigid mass: /RWALL/PLANE carried
// by a lone node with the wall's Mass and initial velocity VX_0. The exchange is exact in momentum whatever the
// wall's shape, and a wall whose node is driven (an imposed velocity) keeps its motion.
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_moving_wall {
namespace {

constexpr double kE = 2.1e11, kRho = 7800.0, kThick = 0.001;

struct WallCard {
  std::string shape = "PLANE";
  long long node = 0;
  int slide = 0;
  long long group = 0;
  double diameter = 0.0, mass = 0.0;
  std::array<double, 3> velocity{}, m1{}, m2{};
};

// /RWALL/shape/id carried by `node` (a moving wall: line 4 is Mass, VX_0, VY_0, VZ_0).
std::string moving_wall(long long id, const WallCard& w) {
  std::string s = "/RWALL/" + w.shape + "/" + std::to_string(id) + "\nmoving wall\n" + I(w.node) + I(w.slide) +
                  I(w.group) + I(0) + "\n" + R(0.0) + R(0.0) + R(w.diameter) + R(0.0) + I(0) + "\n" + R(w.mass) +
                  R(w.velocity[0]) + R(w.velocity[1]) + R(w.velocity[2]) + "\n";
  if (w.shape != "SPHER") s += R(w.m1[0]) + R(w.m1[1]) + R(w.m1[2]) + "\n";
  if (w.shape == "PARAL") s += R(w.m2[0]) + R(w.m2[1]) + R(w.m2[2]) + "\n";
  return s;
}

double momentum_x(const SolverState& s) {
  double p = 0.0;
  for (std::size_t k = 0; k < s.nodes.size(); ++k) p += s.nodes.mass[k] * s.nodes.vx[k];
  return p;
}

// A membrane bar along x of nx shells (nu = 0: c = sqrt(E / rho)) at rest, and its mass.
struct Bar {
  Strip strip;
  double mass = 0.0;
  explicit Bar(int nx, double length) {
    strip.nx = nx, strip.ny = 1, strip.length = length, strip.width = length / nx;
    mass = kRho * kThick * length * strip.width;
  }
  std::string cards() const {
    return node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() + shell_property(kThick, 1) +
           elastic_material(kRho, kE, 0.0);
  }
};

TEST(MovingWall, MassOnABarSlowsDownExponentially) {
  constexpr double L = 1.0, v0 = 5.0;
  const double c = std::sqrt(kE / kRho);
  const Bar bar(400, L);
  WallCard w;
  w.node = 9999, w.group = 1, w.mass = bar.mass, w.velocity = {-v0, 0.0, 0.0}, w.m1 = {0.0, 0.5 * bar.strip.width, 0.0};
  const std::string starter = bar.cards() + node_cards({{9999, L, 0.5 * bar.strip.width, 0.0}}) +
                              node_group(1, bar.strip.column(bar.strip.nx)) + moving_wall(1, w);
  std::vector<double> t, v;
  double p0 = 0.0, worst_momentum = 0.0;
  test::TempDir dir;
  const double step = 0.9 * bar.strip.width / c;
  const RunResult run = run_deck(dir, starter, 1.9 * L / c, 0.5 * step, [&](const Model&, const SolverState& s) {
    if (t.empty()) p0 = momentum_x(s);
    worst_momentum = std::max(worst_momentum, std::abs(momentum_x(s) - p0) / (bar.mass * v0));
    t.push_back(s.time - 0.5 * s.dt);  // v is the half-step velocity
    v.push_back(s.walls.at(0).velocity[0]);
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_GT(t.size(), 100u);
  // The wall's kinetic energy is in the balance from the start: E_kin0 = M V0^2 / 2.
  EXPECT_NEAR(p0, -bar.mass * v0, 1e-12 * bar.mass * v0);
  double worst = 0.0;
  for (double fraction : {0.25, 0.5, 1.0, 1.5, 1.8}) {
    const double at = fraction * L / c;
    std::size_t k = 0;
    while (k + 1 < t.size() && t[k + 1] <= at) ++k;
    const double exact = -v0 * std::exp(-c * t[k] / L);
    worst = std::max(worst, std::abs(v[k] / exact - 1.0));
  }
  // Tolerances: the wall velocity within 1 % of V0 exp(-c t / L) (the discrete bar's end node adds its mass
  // m / 2 nx to the wall's from the first cycle: 0.1 % here); momentum exchanged exactly (round-off); energy
  // within 0.5 % (the half-step kinetic energy against the whole-step strain energy while the wave runs).
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(worst_momentum, 1e-12);
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.5);
  std::printf("[moving wall] cycles %lld  worst V/(V0 exp(-ct/L)) - 1 = %.3e  momentum %.1e  energy error %.4f %%\n",
              run.summary.cycles, worst, worst_momentum, run.summary.energy.error_percent);
}

// Every shape: a free shell plate (16 x 16 shells, 0.1 m) at rest, struck face-on by a moving wall of its own mass
// at 2 m/s; momentum exchanged exactly, no node behind the wall, the plate moving afterwards. The flat walls
// stop the plate as a whole (a perfectly plastic impact: both at V0 / 2, half the energy lost as the walls'
// work); the round ones strike its centre and start bending waves, into which energy flows fast enough for the
// balance's half-step kinetic energy to be off by a few tenths of a percent (cylinder: 0.92 % on an 8 x 8 plate,
// 0.36 % on 16 x 16: it falls with the mesh, an artifact of the measure, not of the exchange).
struct ShapeCase {
  const char* shape;
  double diameter;
};
class MovingWallShapes : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(MovingWallShapes, ExchangeMomentumExactly) {
  const ShapeCase& shape = GetParam();
  Strip plate;
  plate.nx = 16, plate.ny = 16, plate.length = 0.1, plate.width = 0.1;
  const double plate_mass = kRho * kThick * 0.01, v0 = 2.0, gap = 1e-4;
  WallCard w;
  w.shape = shape.shape, w.node = 9999, w.group = 1, w.mass = plate_mass, w.diameter = shape.diameter;
  w.velocity = {0.0, 0.0, -v0};
  // The wall node sits above the plate's centre (a sphere's centre, a cylinder's axis along y, a plane's or a
  // parallelogram's point); the flat walls face down (normal M -> M1 along -z).
  const double z_node = shape.diameter > 0.0 ? 0.5 * shape.diameter + gap : gap;
  std::array<double, 3> node{0.05, 0.05, z_node};
  if (w.shape == "CYL") w.m1 = {0.05, 1.0, z_node};
  if (w.shape == "PLANE") w.m1 = {0.05, 0.05, z_node - 1.0};
  if (w.shape == "PARAL") node = {-0.05, -0.05, gap}, w.m1 = {-0.05, 0.25, gap}, w.m2 = {0.25, -0.05, gap};
  const std::string starter = node_cards(plate.nodes()) + shell_cards(1, plate.shells()) + part_card() +
                              shell_property(kThick, 3) + elastic_material(kRho, kE, 0.3) +
                              node_cards({{9999, node[0], node[1], node[2]}}) + node_group(1, plate.all()) +
                              moving_wall(1, w);
  double p0 = 0.0, worst_momentum = 0.0, lowest_clearance = 1e300, plate_vz = 0.0;
  bool first = true;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 2e-4, 1e-9, [&](const Model& m, const SolverState& s) {
    double p = 0.0, pv = 0.0;
    for (std::size_t k = 0; k < s.nodes.size(); ++k) p += s.nodes.mass[k] * s.nodes.vz[k];
    if (first) p0 = p, first = false;
    worst_momentum = std::max(worst_momentum, std::abs(p - p0) / (plate_mass * v0));
    const std::size_t wall = node_index(m, 9999);
    for (long long id : plate.all()) {
      const std::size_t k = node_index(m, id);
      pv += s.nodes.mass[k] * s.nodes.vz[k];
      if (w.shape == "SPHER" || w.shape == "CYL") {
        const double dx = s.nodes.x[k] - s.nodes.x[wall], dz = s.nodes.z[k] - s.nodes.z[wall];
        const double dy = w.shape == "SPHER" ? s.nodes.y[k] - s.nodes.y[wall] : 0.0;
        lowest_clearance = std::min(lowest_clearance, std::sqrt(dx * dx + dy * dy + dz * dz) - 0.5 * shape.diameter);
      } else {
        lowest_clearance = std::min(lowest_clearance, s.nodes.z[wall] - s.nodes.z[k]);
      }
    }
    plate_vz = pv / plate_mass;
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_LT(worst_momentum, 1e-12);
  EXPECT_GT(lowest_clearance, -1e-12);  // no node ends a step behind the wall
  EXPECT_LT(plate_vz, -0.02 * v0);      // the wall has pushed the plate
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 1.0);
  std::printf("[moving wall %s] momentum %.1e  clearance %.2e  plate vz %.3f  energy error %.4f %%\n", shape.shape,
              worst_momentum, lowest_clearance, plate_vz, run.summary.energy.error_percent);
}

INSTANTIATE_TEST_SUITE_P(Shapes, MovingWallShapes,
                         ::testing::Values(ShapeCase{"PLANE", 0.0}, ShapeCase{"CYL", 0.2}, ShapeCase{"SPHER", 0.2},
                                           ShapeCase{"PARAL", 0.0}),
                         [](const auto& p) { return std::string(p.param.shape); });

// A wall whose node carries an imposed velocity is driven: it keeps that velocity whatever it pushes, and the
// tied nodes (Slide 1) move with it from their first touch.
TEST(MovingWall, DrivenWallKeepsItsImposedVelocityAndCarriesTiedNodes) {
  constexpr double L = 0.1, v = 3.0;
  const Bar bar(20, L);
  WallCard w;
  w.node = 9999, w.slide = 1, w.group = 1, w.m1 = {0.0, 0.5 * bar.strip.width, 0.0};
  const std::string starter = bar.cards() + node_cards({{9999, L, 0.5 * bar.strip.width, 0.0}}) +
                              node_group(1, bar.strip.column(bar.strip.nx)) + node_group(2, {9999}) +
                              unit_function(1) + imposed_velocity(1, 1, "X", 2, -v) + moving_wall(1, w);
  double worst_wall = 0.0, worst_tied = 0.0;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 1e-5, 1e-9, [&](const Model& m, const SolverState& s) {
    const std::size_t wall = node_index(m, 9999);
    worst_wall = std::max(worst_wall, std::abs(s.nodes.vx[wall] + v));
    for (long long id : bar.strip.column(bar.strip.nx))
      worst_tied = std::max(worst_tied, std::abs(s.nodes.vx[node_index(m, id)] - s.nodes.vx[wall]));
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_LT(worst_wall, 1e-12 * v);
  EXPECT_LT(worst_tied, 1e-12 * v);
}

// A wall whose secondary node is a rigid body's main node holds the body (eq. RW-3): a plate made rigid, at rest,
// struck face-on by a moving wall of the plate's mass at v0, through its main node only (its secondary nodes are
// off the wall, Ikrem = 0). A perfectly plastic impact of two equal masses: both go on at v0 / 2, momentum kept.
// Before, the wall went through the main node and the body never moved (issue 27).
TEST(MovingWall, HoldsARigidBodyThroughItsMainNode) {
  Strip plate;
  plate.nx = 4, plate.ny = 4, plate.length = 0.1, plate.width = 0.1;
  const double plate_mass = kRho * kThick * 0.01, v0 = 2.0, gap = 1e-4;
  WallCard w;
  w.node = 9999, w.group = 2, w.mass = plate_mass, w.velocity = {0.0, 0.0, -v0};
  w.m1 = {0.05, 0.05, gap - 1.0};  // the plane faces down, its normal from M to M1 along -z
  const std::string body = "/RBODY/1\nplate made rigid\n" + I(1000) + I(0) + I(0) + I(0) + R(0.0) + I(1) + I(0) +
                           I(0) + I(0) + "\n" + R(0.0) + "\n" + R(0.0) + "\n" + I(0) + I(0) + "\n";
  const std::string starter = node_cards(plate.nodes()) + shell_cards(1, plate.shells()) + part_card() +
                              shell_property(kThick, 3) + elastic_material(kRho, kE, 0.3) +
                              node_cards({{1000, 0.05, 0.05, 0.0}, {9999, 0.05, 0.05, gap}}) +
                              node_group(1, plate.all()) + node_group(2, {1000}) + body + moving_wall(1, w);
  double body_vz = 0.0, wall_vz = 0.0, momentum_first = 0.0, worst_momentum = 0.0;
  bool first = true;
  test::TempDir dir;
  // Every element is in the body: /DTIX gives the step (1e-6 s).
  const RunResult run = run_deck(dir, starter, 1e-3, 1e-5, [&](const Model& m, const SolverState& s) {
    body_vz = s.bodies[0].velocity[2];
    wall_vz = s.nodes.vz[node_index(m, 9999)];
    const double p = s.bodies[0].mass * body_vz + s.nodes.mass[node_index(m, 9999)] * wall_vz;
    if (first) momentum_first = p, first = false;
    worst_momentum = std::max(worst_momentum, std::abs(p - momentum_first) / (plate_mass * v0));
  }, "/DTIX\n0 1e-6\n");
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_NEAR(body_vz, -0.5 * v0, 1e-9 * v0) << "the body moves on with the wall";
  EXPECT_NEAR(wall_vz, -0.5 * v0, 1e-9 * v0);
  EXPECT_LT(worst_momentum, 1e-12);
  std::printf("[moving wall on a rigid body] body vz %.6f  wall vz %.6f  momentum %.1e  energy error %.3f %%\n", body_vz,
              wall_vz, worst_momentum, run.summary.energy.error_percent);
}

// A light moving wall (1e-10 kg) with two free plates behind its plane (0.5 mm inside it), one moving deeper (-z), the
// other out (+z), at 1 m/s. The first pushes the wall along; the second is left alone (RW-1). Held, its nodes carried
// the wall's own velocity, and the exchange with so light a wall drove it to 1e5 m/s: 193 J of kinetic energy out of
// 7.85e-4 J, with an energy error of 0 % (measured before the fix; the same mechanism threw the light wall of the QA
// deck SUBMODEL/TRANSF). The reference (RWI, the same scene in kg mm ms) stops the first plate and lets the second go:
// 3.925e-4 J. Crumple keeps the momentum of the first plate, which the wall carries on: 7.85e-4 J, no energy made.
TEST(MovingWall, ALightWallIsNotDraggedByNodesLeavingIt) {
  const double a = 0.005;  // shell size
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> shells;
  for (long long offset : {0LL, 100LL})
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) nodes.push_back({offset + 1 + i + 3 * j, (offset == 0 ? 0.0 : 0.02) + a * i, a * j, 0.0});
  for (long long offset : {0LL, 100LL})
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const long long n1 = offset + 1 + i + 3 * j;
        shells.push_back({offset + 1 + i + 2 * j, n1, n1 + 1, n1 + 4, n1 + 3});
      }
  std::vector<long long> first, second;
  for (long long n = 1; n <= 9; ++n) first.push_back(n), second.push_back(100 + n);
  std::vector<long long> both = first;
  both.insert(both.end(), second.begin(), second.end());
  WallCard w;
  w.node = 1000, w.group = 1, w.mass = 1e-10;
  w.m1 = {0.005, 0.005, 0.0015};  // normal +z from M = node 1000 at z = 0.5 mm
  const std::string starter = node_cards(nodes) + shell_cards(1, shells) + part_card() + shell_property(kThick, 3) +
                              elastic_material(7850.0, kE, 0.3) + node_cards({{1000, 0.005, 0.005, 0.0005}}) +
                              node_group(1, both) + node_group(2, first) + node_group(3, second) +
                              initial_velocity(1, 0.0, 0.0, -1.0, 2) + initial_velocity(2, 0.0, 0.0, 1.0, 3) +
                              moving_wall(1, w);
  double initial = -1.0, largest = 0.0, wall_speed = 0.0;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, 2e-3, 1e-5, [&](const Model& m, const SolverState& s) {
    const double e = s.energy.internal + s.energy.kinetic_translational + s.energy.kinetic_rotational;
    if (initial < 0.0) initial = e;
    largest = std::max(largest, e);
    wall_speed = std::max(wall_speed, std::abs(s.nodes.vz[node_index(m, 1000)]));
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_NEAR(initial, 7.85e-4, 1e-9);
  EXPECT_LT(largest, initial * (1.0 + 1e-9)) << "energy out of nothing";
  EXPECT_LT(wall_speed, 1.0 + 1e-9) << "the wall moves no faster than the plate that pushes it";
}

}  // namespace
}  // namespace crumple::verification::test_moving_wall
