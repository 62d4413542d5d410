// Johnson-Cook plasticity: one shell element in uniaxial tension (docs/verification.md, "Johnson-Cook").
//
// Physics: the element is pulled along x at a constant strain rate (velocity imposed on one edge, the other
// edge held in x, one corner held in y): the lateral contraction is free, so the stress state is uniaxial,
// sigma_xx = the flow stress and sigma_yy = sigma_xy = 0. With c = 0 (no strain-rate effect) the Johnson-Cook
// law gives the flow stress sigma_y = a + b eps_p^n, and in uniaxial tension the equivalent plastic strain is
// the axial plastic strain: eps_p = ln(l / l0) - sigma_xx / E (logarithmic total strain minus the elastic part;
// the rate-form strain sum of d dt is the logarithmic strain). The run is quasi-static: the lateral nodes are
// driven only by their inertia, whose dynamic stress is rho c Delta v_y ~ 1e-4 of the flow stress at this rate.
// With c > 0 the flow stress is multiplied by 1 + c ln(rate / rate0), the rate being the equivalent rate of the
// total strain increment, which is the axial rate d = v / l in incompressible uniaxial flow.
#include <algorithm>
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_johnson_cook {
namespace {

// `plastic_share`: the plastic strain the return assigns per unit of inelastic strain ln(l/l0) - sigma/E in
// uniaxial tension: 1 for the exact plane-stress return (Iplas 1) and for law 2's radial return (Iplas 2, PS-5),
// whose trial stress along x exceeds the flow stress by E d_eps and which divides that excess by E.
void uniaxial_tension(double c, double rate0, double f_cut, int iplas, double plastic_share = 1.0) {
  constexpr double E = 2.1e11, nu = 0.3, rho = 7800.0, a = 2.0e8, b = 5.0e8, n = 0.4;
  constexpr double l0 = 0.01, rate = 1.0, ramp = 2e-3, end_time = 0.24;  // log strain ~0.24
  const std::vector<NodeRow> nodes{{1, 0.0, 0.0, 0.0}, {2, l0, 0.0, 0.0}, {3, l0, l0, 0.0}, {4, 0.0, l0, 0.0}};
  std::string starter = node_cards(nodes) + shell_cards(1, {{1, 1, 2, 3, 4}}) + part_card() +
                        shell_property(0.001, 3, 0.0, 1, 0.0, 0, iplas) +
                        johnson_cook_material(rho, E, nu, a, b, n, c, rate0, f_cut);
  // Edge 2-3 pulled along x (velocity ramped up over `ramp` to limit the start-up transient), edge 1-4 held in
  // x, node 1 held in y; no out-of-plane motion.
  starter += node_group(1, {1}) + node_group(2, {4}) + node_group(3, {2, 3}) + boundary_condition(1, "111 111", 1) +
             boundary_condition(2, "101 111", 2) + boundary_condition(3, "001 111", 3) +
             function_card(1, {{0.0, 0.0}, {ramp, 1.0}, {1e3, 1.0}}) + imposed_velocity(1, 1, "X", 3, rate * l0);

  struct Sample {
    double sxx, syy, sxy, eps_p, strain, rate;
  };
  std::vector<Sample> samples;
  test::TempDir dir;
  const RunResult run = run_deck(dir, starter, end_time, 5e-4, [&](const Model& m, const SolverState& s) {
    const std::size_t ip = first_point(m, s, shell_index(m, 1));
    // Stresses are those of x^n (before the last position update): measure the length there too.
    const std::size_t k1 = node_index(m, 1), k2 = node_index(m, 2);
    const double l = (s.nodes.x[k2] - s.nodes.x[k1]) - s.dt * (s.nodes.vx[k2] - s.nodes.vx[k1]);
    const double d = (s.nodes.vx[k2] - s.nodes.vx[k1]) / l;  // axial strain rate of the last stress update
    samples.push_back({s.shells.sxx[ip], s.shells.syy[ip], s.shells.sxy[ip], s.shells.eps_p[ip], std::log(l / l0), d});
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;

  double worst_law = 0.0, worst_uniaxial = 0.0, worst_strain = 0.0, last_eps = 0.0;
  int plastic = 0;
  for (const Sample& p : samples) {
    if (p.eps_p < 2e-3) continue;  // past the elastic-plastic transition
    ++plastic;
    const double factor = c > 0.0 ? 1.0 + c * std::log(std::max(p.rate / rate0, 1.0)) : 1.0;
    const double law = (a + b * std::pow(p.eps_p, n)) * factor;
    worst_law = std::max(worst_law, std::abs(p.sxx - law) / law);
    worst_uniaxial = std::max(worst_uniaxial, std::hypot(p.syy, p.sxy) / p.sxx);
    worst_strain = std::max(worst_strain, std::abs(p.eps_p - plastic_share * (p.strain - p.sxx / E)) / p.eps_p);
    last_eps = p.eps_p;
  }
  ASSERT_GT(plastic, 100);
  ASSERT_GT(last_eps, 0.2 * plastic_share);
  // Tolerance of issue 4: the stress-plastic strain curve within 0.5 % of the law. The same 0.5 % bounds the
  // uniaxiality of the stress state and the plastic strain against the kinematics of the element.
  EXPECT_LT(worst_law, 0.005) << "sigma_xx differs from a + b eps_p^n";
  EXPECT_LT(worst_uniaxial, 0.005) << "the stress state is not uniaxial";
  EXPECT_LT(worst_strain, 0.005) << "eps_p differs from ln(l/l0) - sigma/E";
  // Energy: the work of the imposed velocity becomes stored elastic energy and plastic dissipation.
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[johnson-cook c=%g Iplas %d] cycles %lld  eps_p up to %.3f  law %.2e  uniaxial %.2e  strain %.2e (relative)  "
              "energy error %.4f %%\n",
              c, iplas, run.summary.cycles, last_eps, worst_law, worst_uniaxial, worst_strain, run.summary.energy.error_percent);
}

TEST(JohnsonCook, UniaxialTensionFollowsTheLaw) { uniaxial_tension(0.0, 0.0, 0.0, 1); }

// The same with the strain-rate term: rate factor 1 + 0.05 ln(1 / 1e-3) = 1.345 at the 1/s of the test (falling
// to 0.8/s as the element lengthens), and the strain-rate filter a deck would ask for (Fsmooth = 1, Fcut =
// 10 kHz, the Radioss default cut-off of law 36).
// Without the filter (eq. RF of docs/theory/materials.md) the rate term acts as an explicit viscosity far
// beyond its stability limit and sigma_xx overshoots the law by 15 % (docs/verification.md, "Solver issues found").
TEST(JohnsonCook, UniaxialTensionWithStrainRateEffect) { uniaxial_tension(0.05, 1e-3, 1.0e4, 1); }
// The radial return of Iplas 2, the reference's default: in uniaxial tension it gives the exact return's stress and
// plastic strain. Measured on the reference solver (2026-12-07, one 5 mm element pulled to 1.8 %, a 0.3, b 0.5, n
// 0.3): plastic strain 0.01575 at 0.5 ms, Crumple 0.01570; a return dividing by 3 G, as Crumple's did before,
// gives 2 (1 + nu) / 3 of it (0.01365).
TEST(JohnsonCook, RadialReturnUniaxialTension) { uniaxial_tension(0.0, 0.0, 0.0, 2); }

}  // namespace
}  // namespace crumple::verification::test_johnson_cook
