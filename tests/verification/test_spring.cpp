// Springs (/PROP/TYPE4, docs/theory/spring.md) and Rayleigh damping (/DAMP, docs/theory/damping.md) against the
// one-degree-of-freedom oscillator: node 1 fixed, node 2 (mass m = M/2 + the added mass) on a spring of stiffness K
// along y, released with velocity v0. Undamped: y(t) = (v0 / w) sin(w t), w = sqrt(K / m). Under /DAMP alpha:
// y(t) = (v0 / wd) exp(-alpha t / 2) sin(wd t), wd = sqrt(w^2 - alpha^2 / 4).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_spring {
namespace {

constexpr double kStiffness = 1000.0;  // K [N/m]
constexpr double kSpringMass = 1.0;    // M [kg]: the element step sqrt(M/K) is short against the period
constexpr double kAddedMass = 99.5;    // at node 2: m = 100 kg, w = sqrt(10) rad/s
constexpr double kMass = 0.5 * kSpringMass + kAddedMass;
constexpr double kV0 = 1.0;            // [m/s]

std::string oscillator(double alpha, double damping_c = 0.0, double beta = 0.0) {
  std::string s = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.0, 1.0, 0.0}});
  s += "/SPRING/1\n" + I(1) + I(1) + I(2) + "\n/PART/1\nspring\n" + I(1) + I(0) + "\n";
  s += "/PROP/SPRING/1\nspring\n" + R(kSpringMass) + "\n" + R(kStiffness) + R(damping_c) + "\n" + I(0) + "\n" +
       R(0.0) + "\n";
  s += node_group(1, {1}) + node_group(2, {2}) + node_group(3, {1, 2});
  s += boundary_condition(1, "111 111", 1) + boundary_condition(2, "101 111", 2);
  s += added_mass(1, kAddedMass, 2) + initial_velocity(1, 0.0, kV0, 0.0, 2);
  if (alpha > 0.0 || beta > 0.0) s += "/DAMP/1\ndamping\n" + R(alpha) + R(beta) + I(3) + "\n";
  return s;
}

struct Trace {
  std::vector<double> t, y, v;  // node 2's displacement y^(n+1) and velocity v^(n+1/2) after cycle n
};

Trace run(const test::TempDir& dir, double alpha, double end_time, double damping_c = 0.0, double beta = 0.0) {
  Trace trace;
  run_deck(dir, oscillator(alpha, damping_c, beta), end_time, 1e-9, [&](const Model& m, const SolverState& s) {
    trace.t.push_back(s.time);
    trace.y.push_back(s.nodes.y[node_index(m, 2)] - 1.0);
    trace.v.push_back(s.nodes.vy[node_index(m, 2)]);
  });
  return trace;
}

// The times of the positive peaks of y, by a parabola through the three samples around each.
std::vector<std::pair<double, double>> peaks(const Trace& tr) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t k = 1; k + 1 < tr.y.size(); ++k) {
    if (!(tr.y[k] > tr.y[k - 1] && tr.y[k] >= tr.y[k + 1] && tr.y[k] > 0.0)) continue;
    const double h = tr.t[k] - tr.t[k - 1], a = tr.y[k - 1], b = tr.y[k], c = tr.y[k + 1];
    const double shift = 0.5 * h * (a - c) / (a - 2.0 * b + c);
    out.push_back({tr.t[k] + shift, b - 0.25 * (a - c) * shift / h});
  }
  return out;
}

}  // namespace

// The period 2 pi / w within 0.2 % (central differences at w dt = 0.09 shorten it by (w dt)^2 / 24 = 0.03 %), the
// amplitude v0 / w within 0.5 %, and the energy the central difference scheme keeps exactly for a linear
// oscillator, m (v^(n+1/2))^2 / 2 + K y^n y^(n+1) / 2, to 1e-9 over five periods (the listing's internal and kinetic
// energies, half a step apart, oscillate by about w dt / 2 = 4.5 % around it at this step).
TEST(Spring, OscillatorPeriodAmplitudeAndEnergy) {
  test::TempDir dir;
  const double w = std::sqrt(kStiffness / kMass);
  const Trace tr = run(dir, 0.0, 5.0 * 2.0 * M_PI / w);
  const auto p = peaks(tr);
  ASSERT_GE(p.size(), 4u);
  const double period = (p.back().first - p.front().first) / static_cast<double>(p.size() - 1);
  EXPECT_NEAR(period, 2.0 * M_PI / w, 0.002 * 2.0 * M_PI / w);
  std::printf("period %.6e relative %.2e, first amplitude relative %.2e\n", period, period / (2.0 * M_PI / w) - 1.0,
              p.front().second / (kV0 / w) - 1.0);
  for (const auto& [t, y] : p) EXPECT_NEAR(y, kV0 / w, 0.005 * kV0 / w) << "peak at t = " << t;
  // From the second cycle on (the first is the half step from t = 0), at the constant step (not the last, shortened
  // to the end time).
  auto shadow = [&](std::size_t k) { return 0.5 * kMass * tr.v[k] * tr.v[k] + 0.5 * kStiffness * tr.y[k - 1] * tr.y[k]; };
  const double e1 = shadow(1);
  EXPECT_NEAR(e1, 0.5 * kMass * kV0 * kV0, 1e-3 * 0.5 * kMass * kV0 * kV0);
  for (std::size_t k = 2; k + 1 < tr.y.size(); ++k) ASSERT_NEAR(shadow(k), e1, 1e-9 * e1) << "after cycle " << k;
}

// The end state's energies (docs/theory/energy.md, E-3): the run ends a third of a period in, where the energy moves
// fastest between spring and mass. The summary's internal energy is the spring's at the final positions,
// K (y^N)^2 / 2, to 1e-9; its kinetic energy that of the velocity at t^N, v^(N-1/2) + (dt_last / 2) a^N with
// a^N = -K y^N / m, to 1e-9; the loop's own last kinetic energy, half a step behind, is off by several per cent.
TEST(Spring, EndStateEnergiesAreThoseOfTheEndTime) {
  test::TempDir dir;
  const double w = std::sqrt(kStiffness / kMass);
  Trace tr;
  const RunResult r = run_deck(dir, oscillator(0.0), 2.0 * M_PI / w / 3.0, 1e-9, [&](const Model& m, const SolverState& st) {
    tr.t.push_back(st.time), tr.y.push_back(st.nodes.y[node_index(m, 2)] - 1.0), tr.v.push_back(st.nodes.vy[node_index(m, 2)]);
  });
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  ASSERT_GE(tr.y.size(), 3u);
  const double y_end = tr.y.back(), ie = 0.5 * kStiffness * y_end * y_end;
  EXPECT_NEAR(r.summary.energy.internal, ie, 1e-9 * ie);
  const double dt_last = tr.t.back() - tr.t[tr.t.size() - 2];
  const double v_end = tr.v.back() - 0.5 * dt_last * kStiffness * y_end / kMass, ke = 0.5 * kMass * v_end * v_end;
  EXPECT_NEAR(r.summary.energy.kinetic_translational, ke, 1e-9 * ke);
  EXPECT_GT(std::abs(0.5 * kMass * tr.v.back() * tr.v.back() - ke), 0.02 * ke);  // what the summary showed before
  const double total = r.summary.energy.internal + r.summary.energy.kinetic_translational;
  std::printf("end: internal %.6g kinetic %.6g total %.6g (initial %.6g)\n", r.summary.energy.internal,
              r.summary.energy.kinetic_translational, total, 0.5 * kMass * kV0 * kV0);
  EXPECT_NEAR(total, 0.5 * kMass * kV0 * kV0, 0.005 * 0.5 * kMass * kV0 * kV0);
}

// /DAMP alpha = 0.5: the ratio of successive peaks is exp(-alpha T_d / 2) (0.607 per period) within 1 %, and the
// damped period 2 pi / wd within 0.2 %.
TEST(Spring, RayleighMassDampingDecayRate) {
  test::TempDir dir;
  constexpr double kAlpha = 0.5;
  const double w = std::sqrt(kStiffness / kMass), wd = std::sqrt(w * w - 0.25 * kAlpha * kAlpha);
  const double td = 2.0 * M_PI / wd;
  const Trace tr = run(dir, kAlpha, 4.0 * td);
  const auto p = peaks(tr);
  ASSERT_GE(p.size(), 3u);
  for (std::size_t k = 1; k < p.size(); ++k) {
    std::printf("damped period relative %.2e, peak ratio relative %.2e\n", (p[k].first - p[k - 1].first) / td - 1.0,
                p[k].second / p[k - 1].second / std::exp(-0.5 * kAlpha * td) - 1.0);
    EXPECT_NEAR(p[k].first - p[k - 1].first, td, 0.002 * td);
    EXPECT_NEAR(p[k].second / p[k - 1].second, std::exp(-0.5 * kAlpha * td), 0.01 * std::exp(-0.5 * kAlpha * td));
  }
}

// The spring's own dashpot C: the same decay with alpha = C / m, since the dashpot acts on node 2 alone.
TEST(Spring, DashpotDecayRate) {
  test::TempDir dir;
  const double c = 0.5 * kMass;  // alpha = 0.5 per second
  const double w = std::sqrt(kStiffness / kMass), wd = std::sqrt(w * w - 0.25 * (c / kMass) * (c / kMass));
  const double td = 2.0 * M_PI / wd;
  const Trace tr = run(dir, 0.0, 4.0 * td, c);
  const auto p = peaks(tr);
  ASSERT_GE(p.size(), 3u);
  for (std::size_t k = 1; k < p.size(); ++k)
    std::printf("dashpot peak ratio relative %.2e\n", p[k].second / p[k - 1].second / std::exp(-0.5 * (c / kMass) * td) - 1.0);
  for (std::size_t k = 1; k < p.size(); ++k)
    EXPECT_NEAR(p[k].second / p[k - 1].second, std::exp(-0.5 * (c / kMass) * td),
                0.01 * std::exp(-0.5 * (c / kMass) * td));
}

// /DAMP beta = 0.05 (stiffness damping, D-5): the fraction of critical damping zeta = beta w / 2 = 0.079, peaks in
// the ratio exp(-zeta w T_d) per damped period T_d = 2 pi / (w sqrt(1 - zeta^2)), within 1 % (the force follows the
// elements' force rate over the last step, an O(w dt) lag at w dt = 0.09).
TEST(Spring, RayleighStiffnessDampingDecayRate) {
  test::TempDir dir;
  constexpr double kBeta = 0.05;
  const double w = std::sqrt(kStiffness / kMass), zeta = 0.5 * kBeta * w;
  const double td = 2.0 * M_PI / (w * std::sqrt(1.0 - zeta * zeta));
  const Trace tr = run(dir, 0.0, 4.0 * td, 0.0, kBeta);
  const auto p = peaks(tr);
  ASSERT_GE(p.size(), 3u);
  const double expected = std::exp(-zeta * w * td);
  for (std::size_t k = 1; k < p.size(); ++k) {
    std::printf("stiffness damping peak ratio relative %.2e\n", p[k].second / p[k - 1].second / expected - 1.0);
    EXPECT_NEAR(p[k].second / p[k - 1].second, expected, 0.01 * expected);
  }
}

// A /PROP/TYPE8 general spring along y (SP-9): node 2 free in x and about x only, released at 1 m/s and 1 rad/s. The
// X law resists the sideways motion in the global axes, x(t) = (v0 / w) sin(w t), w = sqrt(Kx / m), m = M/2 + 99.5;
// the XX law the twist, theta(t) = (w0 / wr) sin(wr t), wr = sqrt(Kxx / (I / 2)). Both periods within 0.2 % (at
// /DT 0.1 the scheme shortens them by (w dt)^2 / 24, under 1e-4).
TEST(Spring, GeneralSpringSidewaysAndTorsionPeriods) {
  test::TempDir dir;
  constexpr double kKx = 1000.0, kKxx = 10.0, kInertia = 0.2;
  std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.0, 1.0, 0.0}});
  d += "/SPRING/1\n" + I(1) + I(1) + I(2) + "\n/PART/1\nspring\n" + I(1) + I(0) + "\n";
  d += "/PROP/TYPE8/1\ngeneral\n" + R(kSpringMass) + R(kInertia) + "\n";
  for (double k : {kKx, 0.0, 0.0, kKxx, 0.0, 0.0}) d += R(k) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  d += node_group(1, {1}) + node_group(2, {2});
  d += boundary_condition(1, "111 111", 1) + boundary_condition(2, "011 011", 2);
  d += added_mass(1, kAddedMass, 2) + initial_velocity(1, kV0, 0.0, 0.0, 2);
  d += "/INIVEL/ROT/2\nspin\n" + R(1.0) + R(0.0) + R(0.0) + I(2) + "\n";
  const double w = std::sqrt(kKx / kMass), wr = std::sqrt(kKxx / (0.5 * kInertia));
  Trace sideways, twist;
  run_deck(dir, d, 5.0 * 2.0 * M_PI / w, 1e-9,
           [&](const Model& m, const SolverState& s) {
             sideways.t.push_back(s.time), twist.t.push_back(s.time);
             sideways.y.push_back(s.nodes.x[node_index(m, 2)]);
             twist.y.push_back(s.springs.elongation[3]);  // the XX rotation of spring 1
           },
           "/DT\n0.1 0\n");
  for (const auto& [trace, omega, v0] : {std::tuple{&sideways, w, kV0}, std::tuple{&twist, wr, 1.0}}) {
    const auto p = peaks(*trace);
    ASSERT_GE(p.size(), 4u);
    const double period = (p.back().first - p.front().first) / static_cast<double>(p.size() - 1);
    std::printf("general spring period relative %.2e, amplitude relative %.2e\n", period / (2.0 * M_PI / omega) - 1.0,
                p.front().second / (v0 / omega) - 1.0);
    EXPECT_NEAR(period, 2.0 * M_PI / omega, 0.002 * 2.0 * M_PI / omega);
    EXPECT_NEAR(p.front().second, v0 / omega, 0.005 * v0 / omega);
  }
}

// A /PROP/TYPE13 beam-type spring as a cantilever (SP-16, SP-17): node 1 clamped, a constant force P across the
// spring at node 2, which is free. At rest the shear force is P and node 2's moment balances its half of the shear
// couple: K_Y (v - l theta / 2) = P and K_ZZ theta = P l / 2, so v = P / K_Y + P l^2 / (4 K_ZZ) and
// theta = P l / (2 K_ZZ). Damped to rest by /DAMP; within 0.5 % after it settles (a test of the coupling and of the
// signs: the moment the shear puts on node 2 turns it the way the beam bends).
TEST(Spring, BeamTypeSpringCantileverTip) {
  test::TempDir dir;
  constexpr double kShear = 1000.0, kBending = 100.0, kForce = 10.0;
  std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 1.0, 0.0, 0.0}});
  d += "/SPRING/1\n" + I(1) + I(1) + I(2) + "\n/PART/1\nspring\n" + I(1) + I(0) + "\n";
  d += "/PROP/TYPE13/1\nbeam\n" + R(1.0) + R(0.1) + "\n";
  for (double k : {5000.0, kShear, kShear, 100.0, kBending, kBending}) d += R(k) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  d += node_group(1, {1}) + node_group(2, {2}) + node_group(3, {1, 2});
  d += boundary_condition(1, "111 111", 1) + unit_function(9);
  d += "/CLOAD/1\nacross\n" + I(9) + "         Y" + I(0) + I(0) + I(2) + std::string(10, ' ') + R(0.0) + R(kForce) + "\n";
  d += "/DAMP/1\ndamping\n" + R(20.0) + R(0.0) + I(3) + "\n";
  double v = 0.0, theta = 0.0;
  run_deck(dir, d, 5.0, 0.5, [&](const Model& m, const SolverState& s) {
    v = s.nodes.y[node_index(m, 2)];
    theta = s.springs.elongation[5];  // the bending Z rotation, node 2's turn about z
  });
  const double v_expected = kForce / kShear + kForce / (4.0 * kBending), theta_expected = kForce / (2.0 * kBending);
  std::printf("beam-type spring tip: v relative %.2e, theta relative %.2e\n", v / v_expected - 1.0,
              theta / theta_expected - 1.0);
  EXPECT_NEAR(v, v_expected, 0.005 * v_expected);
  EXPECT_NEAR(theta, theta_expected, 0.005 * theta_expected);
}


// The rate effects (docs/theory/spring.md, SP-23) on a spring pulled at a constant rate v = 1 m/s: the curve
// f (10 N at 0.01 m, then 200 N/m) with A 2, B 0.5, D 0.01, g (fct_ID2, log-like: g(1) = 3, g(10) = 4) with E 3 and
// F 0.5, h = g with Hscale 2, and C 5. At every cycle the force is A f(delta) R / A + C v + Hscale h(v / F), R = A +
// B ln(v / D) + E g(v / F), to round-off (1e-9 relative: the rate is the elongation's change over the step, v to
// about 1e-12); at delta = 0.01994203 it is the reference solver's 174.695 N (its time history, single precision).
TEST(Spring, RateEffectsScaleTheCurveAndAddTheRateForce) {
  test::TempDir dir;
  const std::vector<std::pair<double, double>> curve = {{-1.0, -208.0}, {-0.01, -10.0}, {0.0, 0.0}, {0.01, 10.0},
                                                        {1.0, 208.0}};
  const std::vector<std::pair<double, double>> rate = {{-100.0, -5.0}, {-10.0, -4.0}, {-1.0, -3.0}, {-0.1, -2.0},
                                                       {-0.01, -1.0}, {0.0, 0.0}, {0.01, 1.0}, {0.1, 2.0},
                                                       {1.0, 3.0}, {10.0, 4.0}, {100.0, 5.0}};
  std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.5, 0.0, 0.0}});
  d += "/SPRING/1\n" + I(1) + I(1) + I(2) + "\n/PART/1\nspring\n" + I(1) + I(0) + "\n";
  d += "/PROP/SPRING/1\nspring\n" + R(0.0648) + "\n" + R(1000.0) + R(5.0) + R(2.0) + R(0.5) + R(0.01) + "\n" +
       I(10) + I(0) + I(20) + I(0) + I(20) + "\n" + R(0.5) + R(3.0) + R(0.0) + R(2.0) + "\n";
  d += function_card(10, curve) + function_card(20, rate) + unit_function(9);
  d += node_group(1, {1}) + node_group(2, {2}) + boundary_condition(1, "111 111", 1) +
       boundary_condition(2, "011 111", 2) + imposed_velocity(1, 9, "X", 2, 1.0);
  const auto f = [&](const std::vector<std::pair<double, double>>& pts, double x) {
    for (std::size_t k = 1; k < pts.size(); ++k)
      if (x <= pts[k].first || k + 1 == pts.size())
        return pts[k - 1].second + (x - pts[k - 1].first) * (pts[k].second - pts[k - 1].second) /
                                       (pts[k].first - pts[k - 1].first);
    return 0.0;
  };
  const double factor = 2.0 + 0.5 * std::log(1.0 / 0.01) + 3.0 * f(rate, 1.0 / 0.5);
  const double added = 5.0 * 1.0 + 2.0 * f(rate, 1.0 / 0.5);
  const auto expected = [&](double delta) { return 2.0 * f(curve, delta) * factor / 2.0 + added; };
  double worst = 0.0;
  int rows = 0;
  run_deck(dir, d, 0.02, 1e-9, [&](const Model&, const SolverState& s) {
    const double delta = s.springs.elongation[0];
    if (!(delta > 1e-6)) return;  // from the second cycle: the first has no rate yet
    worst = std::max(worst, std::abs(s.springs.force[0] / expected(delta) - 1.0));
    ++rows;
  });
  std::printf("rate effects: %d cycles, largest relative difference %.2e; at delta 0.01994203: %.4f N\n", rows, worst,
              expected(0.01994203));
  EXPECT_GT(rows, 200);
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(expected(0.01994203), 174.695, 0.001);  // the reference's, at its last row
}

// A general spring in a fixed skew turned 30 degrees about z (docs/theory/spring.md, SP-9b), node 2 driven at
// v = (1, 0.5, 0.2) m/s: each law's elongation is the offset's change along its axis, d . e_i, its force K_i d . e_i,
// and the force on node 2 is their sum along the axes, to round-off. Without the skew it would be K_i d_i.
TEST(Spring, GeneralSpringInASkewActsAlongItsAxes) {
  test::TempDir dir;
  const double c = std::cos(M_PI / 6.0), sn = std::sin(M_PI / 6.0);
  std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.5, 0.0, 0.0}});
  d += "/SPRING/1\n" + I(1) + I(1) + I(2) + "\n/PART/1\nspring\n" + I(1) + I(0) + "\n";
  d += "/PROP/TYPE8/1\ngeneral\n" + R(1e-3) + R(1e-3) + I(5) + "\n";
  for (double k : {1000.0, 3000.0, 5000.0, 0.0, 0.0, 0.0}) d += R(k) + "\n" + I(0) + "\n" + R(0.0) + "\n";
  d += "/SKEW/FIX/5\nturned\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(-sn) + R(c) + R(0.0) + "\n" + R(0.0) + R(0.0) +
       R(1.0) + "\n";
  d += unit_function(9) + node_group(1, {1}) + node_group(2, {2}) + boundary_condition(1, "111 111", 1) +
       boundary_condition(2, "000 111", 2);
  d += imposed_velocity(1, 9, "X", 2, 1.0) + imposed_velocity(2, 9, "Y", 2, 0.5) + imposed_velocity(3, 9, "Z", 2, 0.2);
  const Vec3 e[3] = {{c, sn, 0.0}, {-sn, c, 0.0}, {0.0, 0.0, 1.0}};
  const double k[3] = {1000.0, 3000.0, 5000.0};
  double worst = 0.0;
  Vec3 before{};  // the forces after a cycle are those of the positions it started from
  run_deck(dir, d, 0.01, 1e-9, [&](const Model& m, const SolverState& s) {
    const auto n2 = static_cast<std::size_t>(node_index(m, 2));
    for (std::size_t i = 0; i < 3; ++i) {
      const double expected = k[i] * dot(before, e[i]);
      worst = std::max(worst, std::abs(s.springs.force[i] - expected) / (k[0] * 0.01));
    }
    before = {s.nodes.x[n2] - 0.5, s.nodes.y[n2], s.nodes.z[n2]};
  });
  std::printf("general spring in a skew: largest force difference %.2e of K_X v t\n", worst);
  EXPECT_LT(worst, 1e-9);
}

// A spot weld tied to its plates (docs/theory/tied-interfaces.md, TI-6): the force each tie passes to its plate is
// the weld's force on the tied node, so the interface's FN + FT has the magnitude of the spring's force (its frame
// turns it, it does not change its length) at every history row, to round-off.
TEST(Spring, TiedInterfaceForceIsTheWeldsForce) {
  const auto deck = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "tests" / "regression" / "peer_decks" /
                    "tied_spot_weld_spotflag5" / "TIEDSW5_0000.rad";
  Deck d = read_deck(deck);
  test::TempDir dir;
  SimulationOptions options;
  options.name = "TIEDSW5";
  options.output_directory = dir.path();
  options.write_results = false;
  double worst = 0.0, largest = 0.0;
  int rows = 0;
  options.on_history_row = [&](const SolverState& s) {
    const TiedInterfaceState& tie = s.ties.interfaces.at(0);
    const Vec3 passed = tie.normal_force + tie.tangential_force;
    const double* f = &s.springs.force[0];
    const double weld = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    worst = std::max(worst, std::abs(norm(passed) - weld));
    largest = std::max(largest, weld);
    ++rows;
  };
  std::ostringstream console;
  const RunSummary summary = run_simulation(d.model, options, console);
  ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
  ASSERT_GT(rows, 100);
  ASSERT_GT(largest, 0.01);  // kN: the weld carries the pull
  EXPECT_LT(worst, 1e-9 * largest) << "largest weld force " << largest;
}


// A spherical joint (docs/theory/spring.md, SP-25) between a held body of 10 kg and a free one of 2 kg, both of unit
// inertia, their centres at the joint (d = 0): the automatic blocking stiffness is the mass term 2 m_min / (4.1 dt^2)
// at the /DTIX step, the damping Cr sqrt(K m1 m2 / (m1 + m2)). The free body, launched at 1 m/s along z, moves as the
// central-difference oscillator of those K and c: z_(n+1) - 2 z_n + z_(n-1) = -(K z_n + c (z_n - z_(n-1)) / dt) dt^2 / m2
// at every cycle from the second on (the first step is taken before the joint's stiffness), to round-off.
TEST(Spring, JointHoldsABodyOnItsAutomaticStiffness) {
  test::TempDir dir;
  const double dt = 1e-3, m1 = 10.0, m2 = 2.0, cr = 0.05;
  std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.0, 0.0, 0.0}, {5, 0.0, 0.0, 0.0}, {6, 0.0, 0.0, 0.0}});
  d += "/SPRING/1\n" + I(30) + I(1) + I(2) + "\n/PART/1\njoint\n" + I(1) + I(0) + "\n";
  d += "/PROP/TYPE45/1\njoint\n" + I(1) + R(0.0) + R(0.0) + R(cr) + "\n";
  for (int k = 0; k < 3; ++k) d += R(0.0) + "\n" + R(0.0) + "\n" + R(0.0) + "\n";
  d += node_group(8, {1}) + node_group(9, {2}) + node_group(3, {5}) + node_group(4, {6});
  for (int b = 1; b <= 2; ++b)
    d += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(b == 1 ? m1 : m2) + I(7 + b) +
         I(0) + I(3) + "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  d += boundary_condition(1, "111 111", 3) + initial_velocity(1, 0.0, 0.0, 1.0, 4);
  std::vector<double> z;
  const RunResult r = run_deck(dir, d, 0.05, 1e-9, [&](const Model& m, const SolverState& s) {
    z.push_back(s.nodes.z[node_index(m, 6)]);
  }, "/DTIX\n1e-3 1e-3\n");
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  const double k = 2.0 * std::min(m1, m2) / (4.1 * dt * dt), c = cr * std::sqrt(k * m1 * m2 / (m1 + m2));
  ASSERT_GT(z.size(), 40u);
  double worst = 0.0, largest = 0.0;
  for (std::size_t n = 2; n + 1 < z.size(); ++n) {
    const double expected = -(k * z[n] + c * (z[n] - z[n - 1]) / dt) * dt * dt / m2;
    worst = std::max(worst, std::abs(z[n + 1] - 2.0 * z[n] + z[n - 1] - expected));
    largest = std::max(largest, std::abs(z[n]));
  }
  std::printf("joint: K %.6g N/m, c %.6g N s/m, largest recurrence residual %.2e of the largest offset %.3e m\n", k, c,
              worst, largest);
  EXPECT_LT(worst, 1e-9 * largest);
}

// SP-25f: a joint's frame at rest from its /SPRING card's third and fourth nodes, against the reference's starter
// listing ("LOCAL SKEW (VECTORS)", 7 digits) for node 1 at the origin, node_ID3 at (0.3, 0.1, 1) and node_ID4 at
// (0.2, 1, 0.3): the revolute joint on its third node alone; the free and the cylindrical joint on both, (a, b, a x b)
// with a along node_ID3 and b towards node_ID4; the universal joint on both, (a x b, a, b); the revolute joint on its
// Skew_ID1 alone, the skew's axes.
TEST(Spring, JointFrameAtRestIsTheReferences) {
  const std::array<double, 9> axis_alone{0.2860388, 0.0953463, 0.9534626, 0.0, 0.9950372, -0.0995037,
                                         -0.9582180, 0.0284619, 0.2846192};
  const std::array<double, 9> plane{0.2860388, 0.0953463, 0.9534626, 0.0769846, 0.9895340, -0.1220488,
                                    -0.9551205, 0.1083126, 0.2757049};
  const std::array<double, 9> universal{-0.9551205, 0.1083126, 0.2757049, 0.2860388, 0.0953463, 0.9534626,
                                        0.0769846, 0.9895340, -0.1220488};
  // a /SKEW/FIX of Y' (1, 1, 0) and Z' towards (-1, 1, 0.2), the revolute joint's Skew_ID1 without node_ID3
  const std::array<double, 9> skew{0.0990148, -0.0990148, 0.9901475, 0.7071068, 0.7071068, 0.0,
                                   -0.7001400, 0.7001400, 0.1400280};
  // type, frame nodes given (0: a skew, 1: node_ID3, 2: node_ID3 and node_ID4), the reference's frame
  const std::vector<std::tuple<int, int, std::array<double, 9>>> cases{
      {2, 1, axis_alone}, {9, 2, plane}, {3, 2, plane}, {5, 2, universal}, {2, 0, skew}};
  for (const auto& [type, nodes, expected] : cases) {
    test::TempDir dir;
    std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.0, 0.0, 0.0}, {3, 0.3, 0.1, 1.0}, {4, 0.2, 1.0, 0.3},
                                {5, 0.0, 0.0, 0.0}, {6, 0.0, 0.0, 0.0}});
    d += "/SPRING/1\n" + I(30) + I(1) + I(2) + (nodes >= 1 ? I(3) : "") + (nodes == 2 ? I(4) : "") +
         "\n/PART/1\njoint\n" + I(1) + I(0) + "\n";
    // its free degrees of freedom without laws (SP-25g)
    d += "/PROP/TYPE45/1\njoint\n" + I(type) + R(0.0) + R(0.0) + R(0.0) + I(0) + I(nodes == 0 ? 7 : 0) + "\n";
    d += "/SKEW/FIX/7\nskew\n" + R(0.0) + R(0.0) + R(0.0) + "\n" + R(1.0) + R(1.0) + R(0.0) + "\n" + R(-1.0) + R(1.0) +
         R(0.2) + "\n";
    d += node_group(8, {1}) + node_group(9, {2});
    for (int b = 1; b <= 2; ++b)
      d += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(1.0) + I(7 + b) + I(0) +
           I(3) + "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
    std::vector<double> frame;
    const RunResult r = run_deck(dir, d, 2e-3, 1e-9, [&](const Model&, const SolverState& s) {
      if (frame.empty()) frame.assign(s.springs.joint_frame.begin(), s.springs.joint_frame.begin() + 9);
    }, "/DTIX\n1e-3 1e-3\n");
    ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
    ASSERT_EQ(frame.size(), 9u);
    for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(frame[k], expected[k], 6e-8) << "type " << type << " component " << k;
  }
}

// SP-25i: a given Kn holds the translations, ScF Kn the rotations (ScF blank: 10); above the automatic stiffness at
// the first step (here 2 m_min / (4.1 dt^2) = 9.756e5 N/m and I / (4.1 dt^2) = 2.439e5 N m/rad) the run stops at once
// with an error that names Kn.
TEST(Spring, JointGivenStiffnessActsUpToTheAutomaticOne) {
  const auto deck = [](double kn) {
    std::string d = node_cards({{1, 0.0, 0.0, 0.0}, {2, 0.0, 0.0, 0.0}, {5, 0.0, 0.0, 0.0}, {6, 0.0, 0.0, 0.0}});
    d += "/SPRING/1\n" + I(30) + I(1) + I(2) + "\n/PART/1\njoint\n" + I(1) + I(0) + "\n";
    d += "/PROP/TYPE45/1\njoint\n" + I(1) + R(kn) + "\n";
    d += node_group(8, {1}) + node_group(9, {2}) + node_group(3, {5}) + node_group(4, {6});
    for (int b = 1; b <= 2; ++b)
      d += "/RBODY/" + std::to_string(b) + "\nbody\n" + I(4 + b) + I(0) + I(0) + I(0) + R(b == 1 ? 10.0 : 2.0) +
           I(7 + b) + I(0) + I(3) + "\n" + R(1.0) + R(1.0) + R(1.0) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
    return d + boundary_condition(1, "111 111", 3) + initial_velocity(1, 0.0, 0.0, 1.0, 4);
  };
  {
    test::TempDir dir;
    std::vector<double> held;
    const RunResult r = run_deck(dir, deck(2e4), 0.01, 1e-9, [&](const Model&, const SolverState& s) {
      held.assign(s.springs.joint.begin(), s.springs.joint.begin() + 2);
    }, "/DTIX\n1e-3 1e-3\n");
    ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
    ASSERT_EQ(held.size(), 2u);
    EXPECT_DOUBLE_EQ(held[0], 2e4);
    EXPECT_DOUBLE_EQ(held[1], 2e5);
  }
  test::TempDir dir;
  std::string stop;
  try {
    const RunResult r = run_deck(dir, deck(3e4), 0.01, 1e-9, {}, "/DTIX\n1e-3 1e-3\n");  // its rotations' 3e5 > 2.439e5
    EXPECT_NE(r.summary.status, RunStatus::Normal);
    stop = r.summary.message;
  } catch (const DeckError& e) {
    stop = e.what();
  }
  EXPECT_NE(stop.find("field Kn"), std::string::npos) << stop;
}

}  // namespace crumple::verification::test_spring
