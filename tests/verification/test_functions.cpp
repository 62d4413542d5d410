// Functions beyond their end points and /MOVE_FUNCT (docs/deck-format.md, "Functions"), against the reference solver.
// The decks are a free 2 x 2 plate of 1 mm shells (10 x 10 mm, 7.85e-4 kg), written here in kg m s, run by the
// reference in kg mm ms (`/opt/openradioss/run-or.sh MFA/MFA_0000.rad OUT`, its listing's kinetic and internal
// energies at the times below):
// - /IMPVEL along Z of every node with the function (-4, 1), (-3.8, 2) [ms, mm/ms] (MFC): 0.2259 J at 0.598 ms, the
//   function extrapolated along its last segment (v = 1 + 5 (t + 4) = 23.99 mm/ms). Crumple held the last value
//   (1.6e-3 J) before this test.
// - the same with /MOVE_FUNCT Ascale_x 2, Fscale_y 3, Ashift_x 8, Fshift_y -3, which turns the points into (0, 0),
//   (0.4, 3) (MFD, MFA): 1.874e-3 J at 0.2913 ms, 7.896e-3 J at 0.598 ms (extrapolated: v = 4.485). A line of four
//   zeros leaves the function as it is (MFB: 0.2259 J at 0.598 ms, as without the card).
// - /MAT/PLAS_TAB with the yield curve (0, 0.2), (0.01, 0.22) [-, GPa] stretched to 18 % along X (TAB36): internal
//   energy 6.913 J at 9.035 ms, the curve extrapolated along its last slope (a yield held at 0.22 GPa gives 4.45 J).
// The kinetic energies agree within 0.4 % (the imposed velocity is taken at the mid-step, the listing's row at the
// step's start), the internal energy within 0.6 %.
#include <gtest/gtest.h>

#include "verification_support.hpp"

namespace crumple::verification::test_functions {
namespace {

Strip plate() {
  Strip strip;
  strip.nx = 2, strip.ny = 2, strip.length = 0.01, strip.width = 0.01;
  return strip;
}

std::string plate_cards(const std::string& material) {
  const Strip strip = plate();
  return node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() + shell_property(0.001, 5, 0.0, 24) +
         material + node_group(1, strip.all());
}

// The function of the MF decks in seconds and m/s, with a /MOVE_FUNCT line when one is given.
std::string moved_function(const std::string& move_line) {
  std::string s = function_card(2, {{-4e-3, 1.0}, {-3.8e-3, 2.0}});
  if (!move_line.empty()) s += "/MOVE_FUNCT/2\nmove\n" + move_line + "\n";
  return s;
}

// Kinetic energy of the plate [J] at each of `times` [s] (the first output at or after each).
std::vector<double> kinetic_energy(const std::string& starter, const std::vector<double>& times) {
  test::TempDir dir;
  std::vector<double> energy(times.size(), -1.0);
  run_deck(dir, starter, times.back() + 1e-6, 1e-7, [&](const Model&, const SolverState& s) {
    for (std::size_t k = 0; k < times.size(); ++k) {
      if (energy[k] >= 0.0 || s.time < times[k]) continue;
      double e = 0.0;
      for (std::size_t n = 0; n < s.nodes.size(); ++n) e += 0.5 * s.nodes.mass[n] * s.nodes.vz[n] * s.nodes.vz[n];
      energy[k] = e;
    }
  });
  return energy;
}

const std::string kSteel = elastic_material(7850.0, 2.1e11, 0.3);

}  // namespace

TEST(Functions, ALoadCurveGoesOnAlongItsLastSegment) {
  const std::string deck = plate_cards(kSteel) + moved_function("") + imposed_velocity(1, 2, "Z", 1, 1.0);
  const auto e = kinetic_energy(deck, {0.598e-3});
  EXPECT_NEAR(e[0], 0.2259, 0.004 * 0.2259);  // reference MFC
}

TEST(Functions, MoveFunctScalesThenShifts) {
  const std::string move = R(2.0) + R(3.0) + R(8e-3) + R(-3.0);
  const std::string deck = plate_cards(kSteel) + moved_function(move) + imposed_velocity(1, 2, "Z", 1, 1.0);
  const auto e = kinetic_energy(deck, {0.2913e-3, 0.598e-3});
  EXPECT_NEAR(e[0], 1.874e-3, 0.004 * 1.874e-3);  // reference MFD
  EXPECT_NEAR(e[1], 7.896e-3, 0.004 * 7.896e-3);  // reference MFA, beyond the moved function's last point
  const std::string zeros = R(0.0) + R(0.0) + R(0.0) + R(0.0);
  const auto same = kinetic_energy(plate_cards(kSteel) + moved_function(zeros) + imposed_velocity(1, 2, "Z", 1, 1.0),
                                   {0.598e-3});
  EXPECT_NEAR(same[0], 0.2259, 0.004 * 0.2259);  // reference MFB: scales of 0 are 1
}

// TAB36: the plate's left edge held along X (its nodes along Z too), the right edge pulled at 0.2 m/s.
TEST(Functions, AYieldCurveGoesOnAlongItsLastSlope) {
  const Strip strip = plate();
  const std::string tabulated = "/MAT/PLAS_TAB/1\nsteel\n" + R(7850.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + I(1) +
                                I(0) + R(0.0) + R(0.0) + "\n" + I(0) + R(0.0) + I(0) + "\n" + I(5) + "\n" + R(1.0) +
                                "\n" + R(0.0) + "\n" + function_card(5, {{0.0, 2e8}, {0.01, 2.2e8}});
  const std::string deck = plate_cards(tabulated) + node_group(2, strip.column(0)) + node_group(3, strip.column(2)) +
                           boundary_condition(1, "100 000", 2) + boundary_condition(2, "011 000", 1) +
                           unit_function(7) + imposed_velocity(1, 7, "X", 3, 0.2);
  test::TempDir dir;
  double internal = -1.0;
  const RunResult r = run_deck(dir, deck, 9.04e-3, 1e-5, [&](const Model&, const SolverState& s) {
    if (internal < 0.0 && s.time >= 9.035e-3) internal = s.energy.internal;
  });
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  EXPECT_NEAR(internal, 6.913, 0.01 * 6.913);  // reference TAB36; a yield held at its last value: 4.45 J
}

}  // namespace crumple::verification::test_functions

namespace crumple::verification::test_functions {

// /IMPDISP/FGEO (docs/theory/loads.md, L-9): every node of the free plate driven to (1.01 x + 1 mm, y, 0) along the
// ramp f = t / 1 ms, a stretch of 1 % and a shift of 1 mm. The reference (FGALL, input version 2019; the same card
// read in version 120 gives the same listing) lists an internal energy of 0.2442 J at 0.4604 ms and 1.147 J at
// 0.9985 ms, and a kinetic energy of 4.332e-4 J throughout. (With the right edge alone driven, the plate's free
// vibration, which Crumple's and the reference's Ishell 24 do not damp alike, would hide the card's effect.)
TEST(Functions, FinalGeometryDrivesTheNodesToTheirPositions) {
  const Strip strip = plate();
  std::string fgeo = "/IMPDISP/FGEO/10\nfgeo\n" + I(1) + I(0) + I(0) + I(0) + "\n" + R(0.0) + R(0.0) + R(0.0) +
                     R(0.0) + "\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) fgeo += I(strip.node(i, j)) + R(0.00505 * i + 0.001) + R(0.005 * j) + R(0.0) + "\n";
  const std::string deck = plate_cards(kSteel) + function_card(1, {{0.0, 0.0}, {1e-3, 1.0}}) + fgeo;
  test::TempDir dir;
  double internal_mid = -1.0, internal = -1.0, kinetic = -1.0, x_error = 0.0;
  const RunResult r = run_deck(dir, deck, 1.0e-3, 1e-7, [&](const Model& m, const SolverState& s) {
    if (internal_mid < 0.0 && s.time >= 0.4604e-3) internal_mid = s.energy.internal;
    if (internal < 0.0 && s.time >= 0.9985e-3) {
      internal = s.energy.internal;
      kinetic = s.energy.kinetic_translational;
    }
    // Each node on its straight line, at f(t) of the way (u = f(t^n) d, the step's start).
    const double share = s.time / 1e-3;
    const std::size_t k = node_index(m, strip.node(2, 1));
    x_error = std::max(x_error, std::abs(s.nodes.x[k] - (0.01 + share * 0.0011)));
  });
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  EXPECT_NEAR(internal_mid, 0.2442, 0.01 * 0.2442);
  EXPECT_NEAR(internal, 1.147, 0.01 * 1.147);
  EXPECT_NEAR(kinetic, 4.332e-4, 1e-3 * 4.332e-4);
  EXPECT_LT(x_error, 1e-12);
}

}  // namespace crumple::verification::test_functions
