// Trusses (/TRUSS with /PROP/TYPE2, docs/theory/truss.md) against the one-dimensional bar: the elastic wave of an
// impact (speed c = sqrt(E / rho), stress rho c v behind its front), the gap that lets a truss act in compression
// only (TR-5), and the elasto-plastic bar pulled past yield (TR-2, TR-2b, TR-3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace crumple::verification::test_truss {
namespace {

constexpr double kRho = 7800.0, kYoung = 2.1e11, kArea = 1e-4;  // steel [kg/m^3], [Pa], [m^2]
const double kWaveSpeed = std::sqrt(kYoung / kRho);              // 5188.7 m/s

// A bar of n trusses from the origin along `axis` (a unit vector), length `length`, nodes 1 .. n + 1, part 1 with
// property 1 (Area kArea, Gap_ini `gap`) and material 1.
std::string bar(int n, double length, const Vec3& axis, double gap, const std::string& material) {
  std::vector<NodeRow> nodes;
  for (int i = 0; i <= n; ++i) {
    const double x = length * i / n;
    nodes.push_back({i + 1, x * axis.x, x * axis.y, x * axis.z});
  }
  std::string s = node_cards(nodes) + "/TRUSS/1\n";
  for (int i = 1; i <= n; ++i) s += I(i) + I(i) + I(i + 1) + "\n";
  return s + part_card() + "/PROP/TRUSS/1\nbar\n" + R(kArea) + R(gap) + "\n" + material;
}

// /IMPVEL of speed v along `axis` on node group `group`: one card per global direction.
std::string imposed_along(const Vec3& axis, double v, long long group) {
  std::string s = unit_function(1);
  const char* dirs[3] = {"X", "Y", "Z"};
  const double c[3] = {axis.x, axis.y, axis.z};
  for (int d = 0; d < 3; ++d)
    if (c[d] != 0.0) s += imposed_velocity(d + 1, 1, dirs[d], group, v * c[d]);
  return s;
}

}  // namespace

// An oblique bar of 200 trusses (1 m along (1, 2, 2) / 3), its first node driven along it at v0 = 1 m/s, the rest
// free. The wave front (the node's axial velocity at v0 / 2) reaches the middle at 0.5 / c within 2 %: the lumped
// chain at 0.9 of its step keeps the front's middle at c, but spreads it over a few trusses, so that its half level
// is known to a truss or two (2 of the 100 before the middle; measured 1 % early). Behind it the force is A rho c v0 (4.05 kN): the chain rings behind a step front (the overshoot of the
// lumped-mass bar), and averaged over the trusses 10 to 40 it is within 1 %.
TEST(Truss, ImpactWaveSpeedAndStress) {
  test::TempDir dir;
  const Vec3 axis{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  const int n = 200;
  const double v0 = 1.0;
  std::string deck = bar(n, 1.0, axis, 0.0, elastic_material(kRho, kYoung, 0.0));
  deck += node_group(1, {1}) + imposed_along(axis, v0, 1);
  std::vector<double> t, v_mid;
  std::vector<double> force_behind;  // the mean force of trusses 10 to 40 at 0.4 / c
  const double sample_at = 0.4 / kWaveSpeed;
  bool sampled = false;
  run_deck(dir, deck, 0.7 / kWaveSpeed, 1e-12, [&](const Model& m, const SolverState& s) {
    const std::size_t k = node_index(m, n / 2 + 1);
    t.push_back(s.time);
    v_mid.push_back(s.nodes.vx[k] * axis.x + s.nodes.vy[k] * axis.y + s.nodes.vz[k] * axis.z);
    if (!sampled && s.time >= sample_at) {
      sampled = true;
      double sum = 0.0;
      for (int e = 10; e <= 40; ++e)
        sum += s.trusses.force[static_cast<std::size_t>(m.index.elements[static_cast<int>(ElementKind::Truss)].at(e))];
      force_behind.push_back(sum / 31.0);
    }
  });
  const double arrival = first_crossing(t, v_mid, 0.5 * v0);
  ASSERT_GT(arrival, 0.0);
  EXPECT_NEAR(arrival, 0.5 / kWaveSpeed, 0.02 * 0.5 / kWaveSpeed);
  ASSERT_EQ(force_behind.size(), 1u);
  const double expected = -kArea * kRho * kWaveSpeed * v0;  // compression: the driven end pushes into the bar
  EXPECT_NEAR(force_behind[0], expected, 0.01 * std::abs(expected));
  std::printf("arrival %.6e s (1 - c t / x = %.2e), force behind the front %.1f N (relative %.2e)\n", arrival,
              1.0 - kWaveSpeed * arrival / 0.5, force_behind[0], force_behind[0] / expected - 1.0);
}

// One truss of 1 m with Gap_ini 0.01 m, pushed shorter at 1 m/s: no force until it is 0.99 m long, then the
// compression E A ln(L / 0.99) of its strain counted from there (TR-1, TR-5), within one cycle's increment
// E A v dt / L (the cycle it closes in counts whole, measured). Pulled instead, it carries nothing. A truss with a
// gap bounds no step (TR-6): a truss of 0.25 m without one, apart, sets it.
TEST(Truss, GapActsInCompressionOnly) {
  for (const double v : {-1.0, 1.0}) {
    test::TempDir dir;
    std::string deck = bar(1, 1.0, {1.0, 0.0, 0.0}, 0.01, elastic_material(kRho, kYoung, 0.0));
    deck += node_cards({{11, 0.0, 1.0, 0.0}, {12, 0.25, 1.0, 0.0}}) + "/TRUSS/2\n" + I(11) + I(11) + I(12) + "\n";
    deck += "/PART/2\nclock\n" + I(2) + I(1) + "\n/PROP/TRUSS/2\nclock\n" + R(kArea) + R(0.0) + "\n";
    deck += node_group(1, {1, 11, 12}) + node_group(2, {2}) + boundary_condition(1, "111 000", 1) +
            imposed_along({1, 0, 0}, v, 2);
    double largest_open = 0.0, worst_closed = 0.0, step = 0.0;
    int closed_rows = 0;
    run_deck(dir, deck, 0.02, 1e-12, [&](const Model& m, const SolverState& s) {
      const double length = s.nodes.x[node_index(m, 2)] - s.nodes.x[node_index(m, 1)];
      const double force = s.trusses.force[static_cast<std::size_t>(m.index.elements[static_cast<int>(ElementKind::Truss)].at(1))];
      step = std::max(step, s.dt);
      if (length >= 0.99 - 1e-12 || v > 0.0) {
        largest_open = std::max(largest_open, std::abs(force));
      } else {
        ++closed_rows;
        worst_closed = std::max(worst_closed, std::abs(force - kYoung * kArea * std::log(length / 0.99)));
      }
    });
    EXPECT_EQ(largest_open, 0.0) << "v = " << v;
    if (v < 0.0) {
      EXPECT_GT(closed_rows, 10);
      EXPECT_LE(worst_closed, 1.01 * kYoung * kArea * std::abs(v) * step / 0.98) << "v = " << v;
    }
  }
}

// One truss of 1 m pulled at 2 m/s to 20 % with LAW2 (a = 200 MPa, b = 500 MPa, n = 1) and nu = 0.3: its force
// is the yield stress at its plastic strain times its area (TR-2b), within b times one cycle's plastic increment
// (the stress is the yield stress before the cycle's return, measured), and its area A0 (L0 / L)^(2 nu) (TR-3)
// within 1e-4. The plastic strain is the logarithmic strain less the elastic sigma / E, within 1e-3.
TEST(Truss, PlasticBarHardensAndThins) {
  test::TempDir dir;
  const double a = 2e8, b = 5e8, nu = 0.3, v = 2.0;
  std::string deck = bar(1, 1.0, {1.0, 0.0, 0.0}, 0.0, johnson_cook_material(kRho, kYoung, nu, a, b, 1.0));
  deck += node_group(1, {1}) + node_group(2, {2}) + boundary_condition(1, "111 000", 1) + imposed_along({1, 0, 0}, v, 2);
  double worst_force = 0.0, worst_area = 0.0, worst_eps = 0.0, length = 1.0;
  run_deck(dir, deck, 0.1, 1e-12, [&](const Model& m, const SolverState& s) {
    length = s.trusses.length[0];
    const double eps_p = s.trusses.eps_p[0];
    if (eps_p <= 0.0) return;
    const double area = s.trusses.area[0];
    worst_area = std::max(worst_area, std::abs(area / (kArea * std::pow(1.0 / length, 2.0 * nu)) - 1.0));
    worst_force = std::max(worst_force, std::abs(s.trusses.force[0] / area - (a + b * eps_p)));
    worst_eps = std::max(worst_eps, std::abs(eps_p - (std::log(length) - s.trusses.stress[0] / kYoung)));
    (void)m;
  });
  EXPECT_GT(length, 1.19);
  const double dt = 0.9 / kWaveSpeed, increment = v * dt / 1.0;  // the largest cycle's strain increment
  EXPECT_LE(worst_force, b * increment * 1.01);
  EXPECT_LE(worst_area, 1e-4);
  EXPECT_LE(worst_eps, 1e-3);
  std::printf("stress off the curve %.3e Pa (b de = %.3e), area %.2e, plastic strain %.2e\n", worst_force,
              b * increment, worst_area, worst_eps);
}

}  // namespace crumple::verification::test_truss
