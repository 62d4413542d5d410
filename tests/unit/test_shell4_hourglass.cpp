// Hourglass treatments of the one-point 4-node shell (docs/theory/shell4.md, S-5, S-17, S-18): Ishell 1
// orthogonalises the hourglass vector against the linear fields, Ishell 2 does not, Ishell 3 limits the hourglass
// stresses by the yield stress of the section.
#include "shell4_element.hpp"

using namespace crumple;
using namespace crumple::test;

namespace {

const std::array<std::array<double, 3>, 4> kRectangle{{{0, 0, 0}, {0.2, 0, 0}, {0.2, 0.1, 0}, {0, 0.1, 0}}};

// The in-plane velocity v = G x, a constant strain rate: no hourglass deformation.
std::array<double, 24> linear_field(const Element& el) {
  const double G[2][2] = {{1.0e-3, 0.4e-3}, {-0.7e-3, -0.3e-3}};
  std::array<double, 24> u{};
  for (std::size_t k = 0; k < 4; ++k) {
    u[6 * k] = G[0][0] * el.nodes.x[k] + G[0][1] * el.nodes.y[k];
    u[6 * k + 1] = G[1][0] * el.nodes.x[k] + G[1][1] * el.nodes.y[k];
  }
  return u;
}
double largest_hourglass_stress(const Element& el) {
  double worst = 0.0;
  for (double q : el.state.hourglass) worst = std::max(worst, std::abs(q));
  return worst;
}

// Ishell 2 keeps the plain hourglass vector h / 4: on a distorted element a constant strain rate loads its
// hourglass modes (it fails the patch test there, as the reference manual warns), on a parallelogram it does not
// (h is then orthogonal to the linear fields). Ishell 1 leaves them at rest on both.
TEST(Shell4Hourglass, Ishell2IsNotOrthogonalToLinearFields) {
  for (const bool distorted : {true, false}) {
    for (const int ishell : {1, 2}) {
      Element el(distorted ? kDistorted : kRectangle, 0.01, 3);
      el.one_point(ishell);
      el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
      const auto u = linear_field(el);
      for (std::size_t k = 0; k < 4; ++k) el.nodes.vx[k] = u[6 * k], el.nodes.vy[k] = u[6 * k + 1];
      shell4_forces(el.table, el.group, el.p, el.nodes, el.state, 1e-3);
      const double q = largest_hourglass_stress(el);
      if (ishell == 2 && distorted) EXPECT_GT(q, 1e-3) << "the hourglass modes should see the linear field";
      else EXPECT_LT(q, 1e-12) << "ishell " << ishell << " distorted " << distorted;
    }
  }
}

// The hourglass mode itself is resisted by Ishell 1 and 2 alike on a rectangle (where h / 4 is the orthogonal
// vector), with the stiffness of S-5: membrane hm E t A |B|^2.
TEST(Shell4Hourglass, Ishell2ResistsTheHourglassModeAsIshell1) {
  double q[2];
  for (const int ishell : {1, 2}) {
    Element el(kRectangle, 0.01, 3);
    el.one_point(ishell);
    el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
    constexpr double h[4] = {1, -1, 1, -1};
    for (std::size_t k = 0; k < 4; ++k) el.nodes.vx[k] = h[k];
    shell4_forces(el.table, el.group, el.p, el.nodes, el.state, 1.0);
    q[ishell - 1] = el.state.hourglass[0];
  }
  // A = 0.02, |B|^2 = sum (b1^2 + b2^2) = 4 (1 / 0.2^2 + 1 / 0.1^2) / 4 = 125; rate gamma . v = 1.
  EXPECT_NEAR(q[0], 0.01 * kE * 0.01 * 0.02 * 125.0, 1e-9 * q[0]);
  EXPECT_NEAR(q[1], q[0], 1e-12 * q[0]);
}

// Ishell 3: with an elastic law the hourglass stresses grow with the deformation (no limit); with a plastic law
// the membrane ones stop at 2 hm sigma_y t sqrt(A) and the transverse one at hf sigma_y t^2 (eq. S-18). The
// hourglass rates (1 for the membrane mode, 1e5 for the transverse one) over 50 steps of 1e-4 would give 2.5e6 and
// 2.6e4 elastically, against the limits 8.5e4 and 300.
TEST(Shell4Hourglass, Ishell3LimitsTheHourglassStressesByTheYieldStress) {
  const double t = 0.01, area = 0.02, sigma_y = 3.0e8;
  for (const bool plastic : {false, true}) {
    Element el(kRectangle, t, 0);
    if (plastic) {
      el.material.law = MaterialLaw::JohnsonCook;
      el.material.johnson_cook.a = sigma_y, el.material.johnson_cook.b = 0.0, el.material.johnson_cook.n = 1.0;
      el.p.hardening = materials::Hardening::of(el.material, el.functions);
    }
    el.one_point(3);
    el.p.resultant_plasticity = true;
    el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
    constexpr double h[4] = {1, -1, 1, -1};
    for (int cycle = 0; cycle < 50; ++cycle) {
      for (std::size_t k = 0; k < 4; ++k) el.nodes.vx[k] = h[k], el.nodes.vz[k] = 1e5 * h[k];
      shell4_forces(el.table, el.group, el.p, el.nodes, el.state, 1e-4);
    }
    const double membrane_cap = 2.0 * 0.1 * sigma_y * t * std::sqrt(area), transverse_cap = 0.01 * sigma_y * t * t;
    const double membrane_elastic = 0.1 * kE * t * area * 125.0 * 50 * 1e-4;
    if (plastic) {
      EXPECT_NEAR(el.state.hourglass[0], membrane_cap, 1e-12 * membrane_cap);
      EXPECT_NEAR(el.state.hourglass[2], transverse_cap, 1e-12 * transverse_cap);
    } else {
      EXPECT_NEAR(el.state.hourglass[0], membrane_elastic, 1e-9 * membrane_elastic);
      EXPECT_GT(el.state.hourglass[2], 10.0 * transverse_cap);
    }
  }
}

}  // namespace
