// Beams (/BEAM with /PROP/TYPE3, docs/theory/beam.md) against the cantilever of beam theory: the tip deflection
// under a tip load (Euler-Bernoulli for a slender beam, Timoshenko's shear for a thick one) and the first bending
// frequency.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace crumple::verification::test_beam {
namespace {

constexpr double kRho = 7800.0, kYoung = 2.1e11, kNu = 0.3;
const double kShearModulus = kYoung / (2.0 * (1.0 + kNu));

// A cantilever of n beams along x (length `length`), node 1 clamped, the tip node n + 1; local y is global y
// (orientation node 999); df as given (blank: 0.01).
std::string cantilever(int n, double length, double area, double inertia, double df) {
  std::vector<NodeRow> nodes;
  for (int i = 0; i <= n; ++i) nodes.push_back({i + 1, length * i / n, 0.0, 0.0});
  nodes.push_back({999, 0.5 * length, 1.0, 0.0});
  std::string s = node_cards(nodes) + "/BEAM/1\n";
  for (int i = 1; i <= n; ++i) s += I(i) + I(i) + I(i + 1) + I(999) + "\n";
  s += part_card() + "/PROP/BEAM/1\nbeam\n" + std::string(10, ' ') + I(0) + "\n" + R(0.0) + R(df) + "\n" + R(area) +
       R(inertia) + R(inertia) + R(2.0 * inertia) + "\n   000 000" + I(0) + "\n";
  s += elastic_material(kRho, kYoung, kNu);
  s += node_group(1, {1, 999}) + boundary_condition(1, "111 111", 1) + node_group(2, {n + 1});
  return s;
}

// /CLOAD of `force` along y on node group 2, times function 1.
std::string tip_load(double force) {
  return "/CLOAD/1\ntip\n" + I(1) + "         Y" + I(0) + I(0) + I(2) + std::string(10, ' ') + R(1.0) + R(force) + "\n";
}

// The tip's mean deflection in y over [from, end] of a load ramped to `force` by t = ramp and held, the nodes
// 1 .. tip under the mass damping `alpha` (/DAMP) that settles them.
double settled_tip_deflection(const std::string& beams, int tip, double force, double ramp, double from, double end,
                              double alpha) {
  test::TempDir dir;
  std::vector<long long> all;
  for (long long k = 1; k <= tip; ++k) all.push_back(k);
  std::string deck = beams + function_card(1, {{0.0, 0.0}, {ramp, 1.0}, {1e3, 1.0}}) + tip_load(force);
  deck += node_group(3, all) + "/DAMP/1\ndamping\n" + R(alpha) + R(0.0) + I(3) + I(0) + R(0.0) + R(1e3) + "\n";
  double sum = 0.0;
  long long rows = 0;
  run_deck(dir, deck, end, 1e-12, [&](const Model& m, const SolverState& s) {
    if (s.time < from) return;
    sum += s.nodes.y[node_index(m, tip)] - 0.0, ++rows;
  });
  return rows > 0 ? sum / static_cast<double>(rows) : 0.0;
}

}  // namespace

// Ten slender beams (1 m, A = 1e-4, I = 1e-9), 1 N at the tip ramped over 0.5 s under a mass damping that settles
// them: the mean tip deflection over the last 0.2 s of a second is P L^3 / (3 E I) + P L / (k G A) within 0.2 %
// (the beam is exact for a tip load, BM-3; what is left is the damped ringing's remainder, e^(-alpha t / 2)
// of the ramp's end, below 1e-3 by then).
TEST(Beam, SlenderCantileverTipIsEulerBernoulli) {
  const double length = 1.0, area = 1e-4, inertia = 1e-9, force = 1.0;
  const double tip = settled_tip_deflection(cantilever(10, length, area, inertia, 0.0), 11, force, 0.5, 0.8, 1.0, 40.0);
  const double bending = force * length * length * length / (3.0 * kYoung * inertia);
  const double shear = force * length / (5.0 / 6.0 * kShearModulus * area);
  EXPECT_NEAR(tip, bending + shear, 0.002 * bending);
  std::printf("tip %.6e, Euler-Bernoulli %.6e (relative %.2e)\n", tip, bending + shear, tip / (bending + shear) - 1.0);
}

// One thick beam (0.1 m, A = 1e-2, I = 1e-5): the shear deflection is as large as the bending's, and the tip
// goes to P L^3 / (3 E I) + P L / (k G A), k = 5/6, within 0.5 % with a single element (BM-3, exact for a tip
// load; measured the same on the reference, 3.07302e-5 m for 1e5 N).
TEST(Beam, ThickCantileverTipHasTimoshenkosShear) {
  const double length = 0.1, area = 1e-2, inertia = 1e-5, force = 1e5;
  const double tip = settled_tip_deflection(cantilever(1, length, area, inertia, 0.0), 2, force, 0.02, 0.025, 0.04, 0.0);
  const double bending = force * length * length * length / (3.0 * kYoung * inertia);
  const double shear = force * length / (5.0 / 6.0 * kShearModulus * area);
  EXPECT_NEAR(tip, bending + shear, 0.005 * (bending + shear));
  std::printf("tip %.6e, Timoshenko %.6e (bending %.3e, shear %.3e; relative %.2e)\n", tip, bending + shear, bending,
              shear, tip / (bending + shear) - 1.0);
}

// Twenty slender beams (1 m), bent by a tip load under mass damping until 0.4 s, then let go with no damping (df
// 1e-9): the tip swings at the first bending frequency w1 = 1.8751^2 sqrt(E I / (rho A L^4)), within 1 %. The
// lumped masses of twenty beams and their nodes' rotational inertia (BM-6) lengthen the period by 0.21 % (the
// eigenvalue of the same discrete beam, computed apart); the second mode the release leaves shifts the zero
// crossings, by 0.6 % over two periods and 0.3 % over six (the same discrete beam integrated apart gives the same).
TEST(Beam, CantileverFirstFrequency) {
  const double length = 1.0, area = 1e-4, inertia = 1e-9;
  const double w1 = 1.8751 * 1.8751 * std::sqrt(kYoung * inertia / (kRho * area * std::pow(length, 4)));
  const double period = 2.0 * kPi / w1, release = 0.4;
  std::vector<long long> all;
  for (long long k = 1; k <= 21; ++k) all.push_back(k);
  std::string deck = cantilever(20, length, area, inertia, 1e-9) + node_group(3, all);
  deck += function_card(1, {{0.0, 0.0}, {0.2, 1.0}, {release, 1.0}, {release + 1e-9, 0.0}, {1e3, 0.0}}) + tip_load(1.0);
  deck += "/DAMP/1\ndamping\n" + R(40.0) + R(0.0) + I(3) + I(0) + R(0.0) + R(release) + "\n";
  test::TempDir dir;
  std::vector<double> t, y;
  run_deck(dir, deck, release + 6.3 * period, 1e-12, [&](const Model& m, const SolverState& s) {
    if (s.time < release) return;
    t.push_back(s.time), y.push_back(s.nodes.y[node_index(m, 21)]);
  });
  std::vector<double> crossings;  // the downward zero crossings after the release
  for (std::size_t k = 1; k < y.size(); ++k)
    if (y[k - 1] > 0.0 && y[k] <= 0.0) crossings.push_back(t[k - 1] + y[k - 1] / (y[k - 1] - y[k]) * (t[k] - t[k - 1]));
  ASSERT_GE(crossings.size(), 3u);
  const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  EXPECT_NEAR(measured, period, 0.01 * period);
  std::printf("first period %.6e s, theory %.6e s (relative %.2e)\n", measured, period, measured / period - 1.0);
}

}  // namespace crumple::verification::test_beam
