// Resultant shell plasticity, N = 0 (docs/theory/materials.md, RP-1 to RP-3), against closed-form limits.
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/materials/resultant_plasticity.hpp"

namespace crumple::materials::test_resultant_plasticity {
namespace {

constexpr double kE = 2.0e11, kA = 2.0e8;

Material johnson_cook(double b, double n) {
  Material m;
  m.law = MaterialLaw::JohnsonCook;
  m.young = kE, m.poisson = 0.0;
  m.johnson_cook.a = kA, m.johnson_cook.b = b, m.johnson_cook.n = n;
  return m;
}

// nu = 0 makes uniaxial membrane strain and cylindrical bending uniaxial stress states, so that the limits are
// the textbook ones: N_p = sigma_y t and M_p = sigma_y t^2 / 4.
TEST(ResultantPlasticity, MembraneTensionFollowsTheUniaxialLaw) {
  const std::vector<Function> none;
  const Material m = johnson_cook(5e8, 0.4);
  const Hardening h = Hardening::of(m, none);
  const PlaneStressElastic elastic{kE, 0.0};
  double sm[3] = {0, 0, 0}, sb[3] = {0, 0, 0}, eps_p = 0.0, strain = 0.0;
  const double step = 2e-5;
  for (int k = 0; k < 5000; ++k) {
    const auto r = resultant_update(elastic, h, {{step, 0.0, 0.0}, {0.0, 0.0, 0.0}}, 0.0, eps_p, sm, sb);
    eps_p += r.plastic_strain_increment;
    strain += step;
    if (eps_p > 1e-3) {
      ASSERT_NEAR(sm[0], kA + 5e8 * std::pow(eps_p, 0.4), 1e-9 * sm[0]) << "step " << k;
      ASSERT_NEAR(eps_p, strain - sm[0] / kE, 1e-9) << "step " << k;
    }
    // Plastic flow conserves volume and with nu = 0 the elastic strain does not thin the sheet: the thickness
    // strain of a step is minus its plastic strain.
    ASSERT_NEAR(r.thickness_strain, -r.plastic_strain_increment, 1e-15);
  }
  EXPECT_GT(eps_p, 0.09);
  EXPECT_DOUBLE_EQ(sm[1], 0.0);
}

TEST(ResultantPlasticity, BendingSaturatesAtTheFullyPlasticMoment) {
  const std::vector<Function> none;
  const Material m = johnson_cook(0.0, 1.0);  // perfectly plastic
  const Hardening h = Hardening::of(m, none);
  const PlaneStressElastic elastic{kE, 0.0};
  const double t = 0.002;
  double sm[3] = {0, 0, 0}, sb[3] = {0, 0, 0}, eps_p = 0.0;
  // Outer-fibre bending strain increments (t/2) dkappa up to 10 times the first-yield strain.
  const double step = 1e-5;
  double moment = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const auto r = resultant_update(elastic, h, {{0.0, 0.0, 0.0}, {step, 0.0, 0.0}}, 0.0, eps_p, sm, sb);
    eps_p += r.plastic_strain_increment;
    EXPECT_NEAR(r.thickness_strain, 0.0, 1e-18);  // pure bending does not change the thickness
    moment = sb[0] * t * t / 6.0;
    // Elastic until the outer fibre reaches 1.5 sigma_y (the Ilyushin surface lies at M_p, not at first yield).
    if (sb[0] < 1.5 * kA * (1.0 - 1e-12)) {
      EXPECT_DOUBLE_EQ(eps_p, 0.0);
    }
  }
  EXPECT_NEAR(moment, kA * t * t / 4.0, 1e-12 * kA * t * t);
  EXPECT_GT(eps_p, 0.0);
}

// Combined membrane force and moment: every plastic state lies on S = sigma_y (RP-1).
TEST(ResultantPlasticity, CombinedLoadingStaysOnTheSurface) {
  const std::vector<Function> none;
  const Material m = johnson_cook(3e8, 0.3);
  const Hardening h = Hardening::of(m, none);
  const PlaneStressElastic elastic{kE, 0.3};
  double sm[3] = {0, 0, 0}, sb[3] = {0, 0, 0}, eps_p = 0.0;
  int plastic = 0;
  for (int k = 0; k < 400; ++k) {
    const auto r = resultant_update(elastic, h, {{1e-5, -0.4e-5, 0.3e-5}, {0.8e-5, 0.5e-5, -0.2e-5}}, 0.0, eps_p, sm, sb);
    eps_p += r.plastic_strain_increment;
    if (r.plastic_strain_increment > 0.0) {
      ++plastic;
      EXPECT_NEAR(resultant_equivalent_stress(sm, sb), h.yield(eps_p, 0.0), 1e-10 * kA);
    }
  }
  EXPECT_GT(plastic, 100);
}

}  // namespace
}  // namespace crumple::materials::test_resultant_plasticity
