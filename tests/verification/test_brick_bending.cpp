// Coarse brick cantilever under a quasi-static tip load against Timoshenko beam theory (docs/verification.md,
// "Brick cantilever"; docs/theory/brick8.md).
//
// Physics: a cantilever of length L, square section h x h (L / h = 10), clamped at x = 0, carries a tip force P
// along z. Timoshenko's beam gives the tip deflection
//     delta = P L^3 / (3 E I) + P L / (k G A),   I = h^4 / 12,  A = h^2,  k = 5/6 (rectangle),
// the shear part being 0.6 % of the bending part here. nu = 0 keeps the element free of any Poisson effect
// through the thickness (docs/theory/brick8.md, eq. B-9a), so that the test measures bending and transverse shear.
// The mesh has 10 bricks along the length, one across the width and 1 or 2 through the thickness.
//
// Quasi-static loading without damping: the load follows P (1 - cos(pi t / T_r)) / 2 over T_r = 5 first-mode
// periods T_1, then holds. A smooth ramp that slow leaves a free vibration of relative amplitude below 1e-3
// (the response to a ramp of n periods falls as 1 / n^3 for this one), and the deflection is then averaged over
// three periods of the hold, which removes what is left of it. No damping is needed, so none changes the static
// answer. The tip deflection is the mean z displacement of the tip nodes.
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_brick_bending {
namespace {

constexpr double kE = 2.1e11, kRho = 7800.0, kH = 0.1, kL = 1.0, kP = 5000.0;

struct BeamMesh {
  int nx = 10, nz = 1;  // elements along x and through the thickness; one across the width
  long long node(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + 2 * k); }
  double x(int i) const { return kL * i / nx; }
};

std::string brick_beam_cards(const BeamMesh& m) {
  std::vector<NodeRow> nodes;
  for (int k = 0; k <= m.nz; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= m.nx; ++i) nodes.push_back({m.node(i, j, k), m.x(i), kH * j, kH * k / m.nz});
  std::string s = node_cards(nodes) + "/BRICK/1\n";
  long long id = 1;
  for (int k = 0; k < m.nz; ++k)
    for (int i = 0; i < m.nx; ++i) {
      s += I(id++);
      for (int kk : {k, k + 1})
        for (auto [ii, jj] : {std::pair{i, 0}, std::pair{i + 1, 0}, std::pair{i + 1, 1}, std::pair{i, 1}})
          s += I(m.node(ii, jj, kk));
      s += "\n";
    }
  return s;
}

std::vector<long long> section(const BeamMesh& m, int i, int k_first, int k_last) {
  std::vector<long long> v;
  for (int k = k_first; k <= k_last; ++k)
    for (int j = 0; j <= 1; ++j) v.push_back(m.node(i, j, k));
  return v;
}

// /CLOAD along z on a node group, each node carrying scale * f(t).
std::string tip_load(long long id, long long function, long long group, double scale) {
  return "/CLOAD/" + std::to_string(id) + "\ntip load\n" + I(function) + "         Z" + I(0) + I(0) + I(group) +
         std::string(10, ' ') + R(0.0) + R(scale) + "\n";
}

double first_period() {
  const double I2 = kH * kH * kH * kH / 12.0, A = kH * kH;
  const double omega = 1.875104068711961 * 1.875104068711961 * std::sqrt(kE * I2 / (kRho * A)) / (kL * kL);
  return 2.0 * kPi / omega;
}

// Timoshenko's tip deflection with the bending stiffness E I times `bending_factor`.
double timoshenko_deflection(double bending_factor = 1.0) {
  const double I2 = kH * kH * kH * kH / 12.0, A = kH * kH, G = kE / 2.0;
  return kP * kL * kL * kL / (3.0 * kE * I2 * bending_factor) + kP * kL / (5.0 / 6.0 * G * A);
}

// Mean tip deflection over the hold, and the run's energy error [%].
struct Bending {
  double deflection = 0.0, energy_error = 0.0;
  long long cycles = 0;
};

Bending bend(int isolid, int layers) {
  BeamMesh m;
  m.nz = layers;
  const double period = first_period(), ramp = 5.0 * period, end_time = ramp + 3.5 * period;
  std::vector<std::pair<double, double>> ramp_points;
  for (int k = 0; k <= 40; ++k) {
    const double t = ramp * k / 40.0;
    ramp_points.push_back({t, 0.5 * (1.0 - std::cos(kPi * t / ramp))});
  }
  ramp_points.push_back({1e3, 1.0});
  std::string starter = brick_beam_cards(m) + part_card() + "/PROP/SOLID/1\nsolid\n" + I(isolid) + "\n" +
                        R(0.0) + R(0.0) + R(0.0) + "\n" + elastic_material(kRho, kE, 0.0) +
                        node_group(1, section(m, 0, 0, m.nz)) + boundary_condition(1, "111 000", 1) +
                        function_card(1, ramp_points);
  // Tip force: the consistent nodal shares of a uniform traction on the end face (linear elements).
  if (layers == 1) {
    starter += node_group(2, section(m, m.nx, 0, 1)) + tip_load(1, 1, 2, kP / 4.0);
  } else {
    starter += node_group(2, section(m, m.nx, 1, layers - 1)) + tip_load(1, 1, 2, kP / (2.0 * layers));
    std::vector<long long> edges = section(m, m.nx, 0, 0), top = section(m, m.nx, layers, layers);
    edges.insert(edges.end(), top.begin(), top.end());
    starter += node_group(3, edges) + tip_load(2, 1, 3, kP / (4.0 * layers));
  }
  const std::vector<long long> tip = section(m, m.nx, 0, m.nz);
  double sum = 0.0;
  int samples = 0;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, end_time, period / 200.0, [&](const Model& model, const SolverState& s) {
    if (s.time < ramp + 0.5 * period) return;
    for (long long id : tip) sum += s.nodes.z[node_index(model, id)] - model.nodes.z[node_index(model, id)];
    ++samples;
  });
  EXPECT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  EXPECT_GT(samples, 500);
  return {sum / (samples * static_cast<double>(tip.size())), run.summary.energy.error_percent, run.summary.cycles};
}

struct BendingCase {
  int isolid, layers;
  double stiffness;  // expected bending stiffness / E I (0: no static stiffness)
};

class BrickCantilever : public ::testing::TestWithParam<BendingCase> {};
// Isolid 24 and 14 bend like the beam. Isolid 1's one-point elements carry no bending inside an element (the
// bending field is an hourglass mode, resisted only by viscous forces, eq. B-6): n layers represent the section
// by n fibres at the layer centres, I_n = I (1 - 1 / n^2). Two layers: 3/4 of E I, the deflection +33 %; one
// layer: no static stiffness, the viscous forces alone carry the load and the beam creeps.
INSTANTIATE_TEST_SUITE_P(Isolid, BrickCantilever,
                         ::testing::Values(BendingCase{24, 1, 1.0}, BendingCase{24, 2, 1.0}, BendingCase{14, 1, 1.0},
                                           BendingCase{14, 2, 1.0}, BendingCase{1, 2, 0.75}, BendingCase{1, 1, 0.0}));

TEST_P(BrickCantilever, TipDeflectionMatchesTimoshenko) {
  const BendingCase c = GetParam();
  const Bending b = bend(c.isolid, c.layers);
  const double exact = timoshenko_deflection();
  std::printf("[brick cantilever Isolid %d, %d layer(s)] cycles %lld  delta %.6e  Timoshenko %.6e (%+.2f %%)  "
              "energy error %.3f %%\n",
              c.isolid, c.layers, b.cycles, b.deflection, exact, 100.0 * (b.deflection / exact - 1.0),
              b.energy_error);
  if (c.stiffness > 0.0) {
    EXPECT_LT(std::abs(b.deflection / timoshenko_deflection(c.stiffness) - 1.0), 0.05);
  } else {
    EXPECT_GT(b.deflection, 100.0 * exact);  // a mechanism
  }
  EXPECT_LT(std::abs(b.energy_error), 0.1);
}

}  // namespace
}  // namespace crumple::verification::test_brick_bending
