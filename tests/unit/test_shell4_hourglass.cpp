// Hourglass treatments of the one-point 4-node shell (docs/theory/shell4.md, S-5, S-17, S-18): Ishell 1
// orthogonalises the hourglass vector against the linear fields, Ishell 2 does not, Ishell 3 limits the hourglass
// stresses by the yield stress of the section.
#include "elements/shell4_hourglass.hpp"  // kRotationHourglassViscosity (eq. S-19)
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

// Ishell 1 and 2 damp their rotation hourglass modes, as the reference does (its hr is printed as the "shell
// hourglass rotational damping"; eq. S-19): the mode theta_x = h omega on the 0.2 x 0.1 rectangle (t = 0.01,
// rho = 7800, hr = 0.01) has the rate q = h . theta = 4 omega and gets at each node h_a M about the local x axis,
// M = C hr rho t^2 A q^2 = 0.9021 * 0.01 * 7800 * 1e-4 * 0.02 * 16 = 2.2517e-3 for omega = 1; nothing is stored, so the
// mode at rest again carries no moment (an elastic stiffness would hold a restoring one), and the work of the
// moments, M q dt, is hourglass energy. The other rotation axis and Ishell 3, which keeps its stiffness, for contrast.
TEST(Shell4Hourglass, Ishell1And2DampTheirRotationModes) {
  constexpr double h[4] = {1, -1, 1, -1};
  const double t = 0.01, area = 0.02, dt = 1e-6;
  const double expected = shell_hourglass::kRotationHourglassViscosity * 0.01 * kRho * t * t * area * 16.0;
  EXPECT_NEAR(expected, 2.2517e-3, 1e-7);
  for (const int ishell : {1, 2}) {
    for (const int axis : {0, 1}) {
      Element el(kRectangle, t, 3);
      el.one_point(ishell);
      el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
      for (std::size_t k = 0; k < 4; ++k) (axis == 0 ? el.nodes.wx : el.nodes.wy)[k] = h[k];
      const GroupStepResult moving = shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
      // The element lies in the global x-y plane with e1 = x, e2 = y: moments are global. The curvature of the mode
      // is zero at the centre and the transverse shear sees its mean, zero: only the hourglass moment acts.
      for (std::size_t k = 0; k < 4; ++k) {
        const double m = -(axis == 0 ? el.nodes.mx : el.nodes.my)[k];
        EXPECT_NEAR(m, h[k] * expected, 1e-9 * expected) << "ishell " << ishell << " axis " << axis << " node " << k;
      }
      EXPECT_NEAR(moving.hourglass_energy, expected * 4.0 * dt, 1e-9 * expected * 4.0 * dt);
      EXPECT_EQ(el.state.hourglass[3 + static_cast<std::size_t>(axis)], 0.0);
      // At rest again: no moment.
      el.nodes.clear_forces();
      for (std::size_t k = 0; k < 4; ++k) el.nodes.wx[k] = el.nodes.wy[k] = 0.0;
      shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
      for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(el.nodes.mx[k], 0.0);
        EXPECT_EQ(el.nodes.my[k], 0.0);
      }
    }
  }
  Element stiff(kRectangle, t, 3);
  stiff.one_point(3);
  stiff.p.zeta = stiff.zeta, stiff.p.membrane_weight = stiff.wn, stiff.p.bending_weight = stiff.wb;
  for (std::size_t k = 0; k < 4; ++k) stiff.nodes.wx[k] = h[k];
  shell4_forces(stiff.table, stiff.group, stiff.p, stiff.nodes, stiff.state, dt);
  EXPECT_NE(stiff.state.hourglass[3], 0.0) << "Ishell 3 keeps the elastic rotation stiffness of S-5";
}

// The damper never reverses the motion it resists (eq. S-20): at a rotation rate where C hr rho t^2 A q^2 would
// exceed it, the moment is the one that stops the mode within the step on the element's share of the nodal
// inertia, I |q| / (|g|^2 dt) with I = rho t A (t^2 / 12 + A / 9) / 4 (eq. S-8) and |g|^2 = |h|^2 = 4 on the
// rectangle.
TEST(Shell4Hourglass, RotationDampingStopsButNeverReversesTheMode) {
  constexpr double h[4] = {1, -1, 1, -1};
  const double t = 0.01, area = 0.02, dt = 1e-3, omega = 1e4;
  Element el(kRectangle, t, 3);
  el.one_point(1);
  el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
  for (std::size_t k = 0; k < 4; ++k) el.nodes.wx[k] = h[k] * omega;
  shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
  const double inertia = kRho * t * area * (t * t / 12.0 + area / 9.0) / 4.0, q = 4.0 * omega;
  const double viscous = shell_hourglass::kRotationHourglassViscosity * 0.01 * kRho * t * t * area * q * q;
  const double limit = inertia * q / (4.0 * dt);
  ASSERT_GT(viscous, 10.0 * limit);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(-el.nodes.mx[k], h[k] * limit, 1e-12 * limit);
  // The rate after the step on that inertia: q - 4 M dt / I = 0.
  EXPECT_NEAR(q - 4.0 * limit * dt / inertia, 0.0, 1e-9 * q);
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
