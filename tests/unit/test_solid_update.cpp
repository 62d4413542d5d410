// 3-D stress update (docs/theory/materials.md, "Solids"): Hooke's law, the J2 radial return with isotropic
// Johnson-Cook and tabulated hardening, the Hughes-Winget rotation of the stress.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "crumple/materials/solid_update.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_solid_update {

using namespace crumple;
using namespace crumple::materials;

namespace {

constexpr double kE = 210e9, kNu = 0.3;

Material johnson_cook(double a, double b, double n) {
  Material m;
  m.law = MaterialLaw::JohnsonCook;
  m.density = 7800.0, m.young = kE, m.poisson = kNu;
  m.johnson_cook.a = a, m.johnson_cook.b = b, m.johnson_cook.n = n;
  return m;
}

double pressure(const double* s) { return (s[0] + s[1] + s[2]) / 3.0; }

// 3x3 rotation about the unit axis u by the angle t.
std::array<std::array<double, 3>, 3> rotation(std::array<double, 3> u, double t) {
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& v : u) v /= n;
  const double c = std::cos(t), s = std::sin(t), k = 1.0 - c;
  return {{{c + u[0] * u[0] * k, u[0] * u[1] * k - u[2] * s, u[0] * u[2] * k + u[1] * s},
           {u[1] * u[0] * k + u[2] * s, c + u[1] * u[1] * k, u[1] * u[2] * k - u[0] * s},
           {u[2] * u[0] * k - u[1] * s, u[2] * u[1] * k + u[0] * s, c + u[2] * u[2] * k}}};
}

}  // namespace

TEST(SolidUpdate, ElasticIncrementIsHookesLaw) {
  const std::vector<Function> functions;
  Material m;
  m.young = kE, m.poisson = kNu;
  const Hardening h = Hardening::of(m, functions);
  const SolidElastic el{kE, kNu};
  const double de[6] = {1e-4, -3e-5, 2e-5, 4e-5, -1e-5, 6e-5};
  double s[6] = {1e6, 2e6, -3e6, 4e5, 5e5, -6e5};
  const double s0[6] = {1e6, 2e6, -3e6, 4e5, 5e5, -6e5};
  const auto r = solid_update(el, h, de, 1.0, 0.0, s);
  EXPECT_EQ(r.plastic_strain_increment, 0.0);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double tr = de[0] + de[1] + de[2];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s[k], s0[k] + lambda * tr + 2 * mu * de[k], 1e-12 * kE * 1e-4);
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(s[k], s0[k] + mu * de[k], 1e-12 * kE * 1e-4);
}

TEST(SolidUpdate, ReturnMappingEndsOnTheYieldSurface) {
  const std::vector<Function> functions;
  const Material m = johnson_cook(250e6, 600e6, 0.35);
  const Hardening h = Hardening::of(m, functions);
  const SolidElastic el{kE, kNu};
  const double G = el.shear();
  for (double eps_p : {0.0, 1e-4, 0.05, 0.4}) {
    // A general increment, large enough to yield from a stress on the current yield surface or inside it.
    double s[6] = {100e6, -20e6, 30e6, 40e6, 0.0, -10e6};
    const double de[6] = {4e-3, -1e-3, -1.5e-3, 2e-3, 1e-3, -5e-4};
    double trial[6];
    std::copy(s, s + 6, trial);
    const SolidUpdateResult elastic_only = solid_update(el, Hardening{}, de, 0.0, 0.0, trial);  // law 1: trial
    EXPECT_EQ(elastic_only.plastic_strain_increment, 0.0);
    const auto r = solid_update(el, h, de, 0.0, eps_p, s);
    const double dg = r.plastic_strain_increment;
    ASSERT_GT(dg, 0.0);
    const double yield = h.yield(eps_p + dg, 0.0);
    // On the yield surface of the hardened state (consistency with the hardening law).
    EXPECT_NEAR(von_mises(s), yield, 1e-12 * yield) << "eps_p " << eps_p;
    // Radial: the pressure is the trial pressure, the deviator is the trial deviator scaled down by 3 G dg.
    EXPECT_NEAR(pressure(s), pressure(trial), 1e-9 * yield);
    const double q_trial = von_mises(trial);
    EXPECT_NEAR(dg, (q_trial - von_mises(s)) / (3.0 * G), 1e-12 * dg);
    const double ratio = von_mises(s) / q_trial;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(s[k] - pressure(s), ratio * (trial[k] - pressure(trial)), 1e-9 * yield);
    for (int k = 3; k < 6; ++k) EXPECT_NEAR(s[k], ratio * trial[k], 1e-9 * yield);
  }
}

TEST(SolidUpdate, StressBelowYieldStaysElastic) {
  const std::vector<Function> functions;
  const Material m = johnson_cook(250e6, 600e6, 0.35);
  const Hardening h = Hardening::of(m, functions);
  double s[6] = {0, 0, 0, 0, 0, 0};
  const double de[6] = {1e-4, -3e-5, -3e-5, 0, 0, 0};
  EXPECT_EQ(solid_update(SolidElastic{kE, kNu}, h, de, 0.0, 0.0, s).plastic_strain_increment, 0.0);
  EXPECT_LT(von_mises(s), 250e6);
}

TEST(SolidUpdate, TabulatedHardeningIsConsistent) {
  // Law 36, one curve: piecewise linear sigma_y(eps_p); the return must land on the curve, also across a kink.
  std::vector<Function> functions(1);
  functions[0].x = {0.0, 0.01, 0.05, 1.0};
  functions[0].y = {300e6, 350e6, 380e6, 500e6};
  Material m;
  m.law = MaterialLaw::Tabulated;
  m.young = kE, m.poisson = kNu;
  m.tabulated.function = {0};
  m.tabulated.scale = {1.0};
  m.tabulated.strain_rate = {0.0};
  const Hardening h = Hardening::of(m, functions);
  for (double size : {2e-3, 1e-2, 4e-2}) {
    double s[6] = {0, 0, 0, 0, 0, 0};
    const double de[6] = {size, -0.5 * size, -0.5 * size, 0.3 * size, 0, 0};
    const auto r = solid_update(SolidElastic{kE, kNu}, h, de, 0.0, 0.0, s);
    EXPECT_NEAR(von_mises(s), h.yield(r.plastic_strain_increment, 0.0), 1e-12 * 500e6) << size;
  }
}

TEST(SolidUpdate, UniaxialStrainPathFollowsJohnsonCook) {
  // Incompressible plastic flow under a strain path with lateral contraction -1/2 (plastic) and the elastic part
  // chosen to keep the lateral stresses at zero: then s_xx = sigma_y(eps_p) at every step.
  const std::vector<Function> functions;
  const Material m = johnson_cook(250e6, 600e6, 0.35);
  const Hardening h = Hardening::of(m, functions);
  const SolidElastic el{kE, kNu};
  double s[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0.0;
  for (int step = 0; step < 400; ++step) {
    const double dx = 5e-4;
    // Lateral strain from a secant iteration on s_yy = 0 (the point's state is copied for each try).
    double lateral[2] = {-kNu * dx, -0.5 * dx}, residual[2];
    for (int k = 0; k < 2; ++k) {
      double t[6];
      std::copy(s, s + 6, t);
      const double de[6] = {dx, lateral[k], lateral[k], 0, 0, 0};
      solid_update(el, h, de, 0.0, eps_p, t);
      residual[k] = t[1];
    }
    double guess = lateral[1];
    for (int it = 0; it < 30; ++it) {
      if (residual[1] == residual[0]) break;
      guess = lateral[1] - residual[1] * (lateral[1] - lateral[0]) / (residual[1] - residual[0]);
      double t[6];
      std::copy(s, s + 6, t);
      const double de[6] = {dx, guess, guess, 0, 0, 0};
      solid_update(el, h, de, 0.0, eps_p, t);
      lateral[0] = lateral[1], residual[0] = residual[1];
      lateral[1] = guess, residual[1] = t[1];
      if (std::abs(t[1]) < 1e-6) break;
    }
    const double de[6] = {dx, guess, guess, 0, 0, 0};
    eps_p += solid_update(el, h, de, 0.0, eps_p, s).plastic_strain_increment;
    ASSERT_NEAR(s[1], 0.0, 1.0);
  }
  EXPECT_NEAR(s[0], h.yield(eps_p, 0.0), 1e-9 * s[0]);
  EXPECT_NEAR(eps_p, 400 * 5e-4 - s[0] / kE, 1e-3 * eps_p);  // plastic strain = total - elastic
}

TEST(SolidUpdate, HughesWingetRotationIsExact) {
  // With W dt = 2 (R - I)(R + I)^-1 (the spin of an exact rotation increment on the mid-step geometry), the
  // Cayley transform gives back R, so the stress is rotated exactly: s' = R s R^T.
  const auto R = rotation({0.3, -0.5, 0.8}, 0.7);
  // S = (R - I)(R + I)^-1 is skew; its axial vector is w / 2.
  double a[3][3], b[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = R[i][j] - (i == j), b[i][j] = R[i][j] + (i == j);
  // Inverse of b by cofactors.
  double inv[3][3];
  const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                     b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      inv[i][j] = (b[i1][j1] * b[i2][j2] - b[i1][j2] * b[i2][j1]) / det;
    }
  double S[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) S[i][j] += a[i][k] * inv[k][j];
  const double wx = 2.0 * S[2][1], wy = 2.0 * S[0][2], wz = 2.0 * S[1][0];
  EXPECT_NEAR(S[2][1], -S[1][2], 1e-14);
  double s[6] = {100.0, -40.0, 25.0, 30.0, -15.0, 60.0};
  const double T[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  const double before_vm = von_mises(s), before_p = pressure(s);
  rotate_stress(s, wx, wy, wz);
  double expected[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) expected[i][j] += R[i][k] * T[k][l] * R[j][l];
  EXPECT_NEAR(s[0], expected[0][0], 1e-12);
  EXPECT_NEAR(s[1], expected[1][1], 1e-12);
  EXPECT_NEAR(s[2], expected[2][2], 1e-12);
  EXPECT_NEAR(s[3], expected[0][1], 1e-12);
  EXPECT_NEAR(s[4], expected[1][2], 1e-12);
  EXPECT_NEAR(s[5], expected[2][0], 1e-12);
  EXPECT_NEAR(von_mises(s), before_vm, 1e-12);
  EXPECT_NEAR(pressure(s), before_p, 1e-12);
}

TEST(SolidUpdate, SmallSpinIsTheJaumannRate) {
  // To first order the rotation adds (W s - s W) dt.
  double s[6] = {100.0, -40.0, 25.0, 30.0, -15.0, 60.0};
  const double w[3] = {1e-7, -2e-7, 3e-7};
  const double W[3][3] = {{0, -w[2], w[1]}, {w[2], 0, -w[0]}, {-w[1], w[0], 0}};
  const double T[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double J[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) J[i][j] += W[i][k] * T[k][j] - T[i][k] * W[k][j];
  rotate_stress(s, w[0], w[1], w[2]);
  // |W| ~ 3e-7, |s| ~ 100: the increment is ~ 3e-5, the second-order remainder ~ 1e-11.
  EXPECT_NEAR(s[0] - T[0][0], J[0][0], 1e-10);
  EXPECT_NEAR(s[3] - T[0][1], J[0][1], 1e-10);
  EXPECT_NEAR(s[4] - T[1][2], J[1][2], 1e-10);
}

}  // namespace test_solid_update
