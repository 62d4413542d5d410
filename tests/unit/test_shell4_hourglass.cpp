// Hourglass treatments of the one-point 4-node shell (docs/theory/shell4.md, S-5, S-17 to S-20): Ishell 1
// orthogonalises the hourglass vector against the linear fields, Ishell 2 does not, Ishell 3 limits the hourglass
// stresses by the yield stress of the section, takes the rigid rotation of a warped element off its rates and
// damps its rotation modes viscously.
#include "elements/shell4_hourglass.hpp"  // kRotationHourglassViscosity (eq. S-19)
#include "shell4_element.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell4_hourglass {

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
// vector), with the stiffness of S-5: membrane 2 hm E t whatever the shape (the reference's, shell4.md, S-5a).
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
  // rate gamma . v = 1 (gamma = h / 4 on a rectangle); t = 0.01
  EXPECT_NEAR(q[0], 0.01 * 2.0 * kE * 0.01, 1e-9 * q[0]);
  EXPECT_NEAR(q[1], q[0], 1e-12 * q[0]);
}

// The hourglass modes of Ishell 1 to 3 (eqs. S-5, S-5a, S-5b), on the 0.2 x 0.1 rectangle (rates gamma . v = 1 m/s):
// the transverse mode stores hf kappa G t^3 / 3 * 16 / (d1^2 + d2^2) per unit rate and time with bending points (N = 0
// or more than 1), 2 hf E t on a membrane (N = 1), as measured on the reference solver on squares, rectangles,
// parallelograms and trapezoids (shell4.md, S-5a). With bending points Ishell 1 also damps it, c q^2 with
// c = (800 / sqrt 3) hf rho t^2 sqrt(kappa / (1 + nu)) (2.885 N here), and the membrane modes, 800 hm rho t sqrt(A) q^2
// (88.25 N here); a membrane does not.
TEST(Shell4Hourglass, TransverseModeTakesTheShearModulus) {
  const double t = 0.01, area = 0.02, G = kE / (2.0 * (1.0 + kNu)), dt = 1e-6;
  const double diagonals = 2.0 * (0.2 * 0.2 + 0.1 * 0.1);  // d1^2 + d2^2
  for (const int n_points : {0, 1, 3}) {
    for (const int mode : {0, 2}) {  // membrane along x, transverse
      Element el(kRectangle, t, n_points);
      el.one_point(1);
      el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
      constexpr double h[4] = {1, -1, 1, -1};
      for (std::size_t k = 0; k < 4; ++k) (mode == 0 ? el.nodes.vx : el.nodes.vz)[k] = h[k];
      const GroupStepResult step = shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
      const bool membrane = n_points == 1;
      const double stiffness = mode == 0 || membrane ? 0.01 * 2.0 * kE * t
                                                     : 0.01 * (5.0 / 6.0) * G * t * t * t / 3.0 * 16.0 / diagonals;
      const std::size_t m = static_cast<std::size_t>(mode);
      EXPECT_NEAR(el.state.hourglass[m], stiffness * dt, 1e-9 * stiffness * dt) << "N = " << n_points;
      const double damping = membrane ? 0.0
                             : mode == 0 ? 800.0 * 0.01 * kRho * t * std::sqrt(area)
                                         : 800.0 / std::sqrt(3.0) * 0.01 * kRho * t * t * std::sqrt((5.0 / 6.0) / 1.3);
      EXPECT_NEAR(damping, membrane ? 0.0 : mode == 0 ? 88.25 : 2.885, 1e-2);
      const double work = 0.5 * stiffness * dt * dt + damping * dt;
      EXPECT_NEAR(step.hourglass_energy, work, 1e-9 * work) << "N = " << n_points << " mode " << mode;
      const double force = 0.25 * (stiffness * dt + damping);
      EXPECT_NEAR(-(mode == 0 ? el.nodes.fx : el.nodes.fz)[0], force, 1e-9 * force);
    }
  }
}

// Ishell 1 and 2 damp their rotation hourglass modes, as the reference does (its hr is printed as the "shell
// hourglass rotational damping"; eq. S-19): the mode theta_x = h omega on the 0.2 x 0.1 rectangle (t = 0.01,
// rho = 7800, hr = 0.01) has the rate q = h . theta = 4 omega and gets at each node h_a M about the local x axis,
// M = C hr rho t^2 A q^2 = 0.9021 * 0.01 * 7800 * 1e-4 * 0.02 * 16 = 2.2517e-3 for omega = 1; nothing is stored, so the
// mode at rest again carries no moment (an elastic stiffness would hold a restoring one), and the work of the
// moments, M q dt, is hourglass energy. The other rotation axis too.
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
}

// Ishell 3's rotation modes are purely viscous, linear and quadratic in the rate, as the reference solver's
// (eq. S-18b): the mode theta_x = h omega (omega = 1) on the 0.2 x 0.1 rectangle (t = 0.01, rho = 7800, E = 2e11,
// hr = 0.1) has q = 4 and gets h_a M at node a with M = q (c_l + c_q |q|), rho t^2 A / (32 sqrt 3) = 2.81458e-4,
// c_l = sqrt(0.1) 2.81458e-4 sqrt(2e11 / 7800) = 0.450693, c_q = 100 * 0.1 * 2.81458e-4 = 2.81458e-3: M = 1.847806.
// Nothing is stored, the mode at rest carries no moment, the work M q dt is hourglass energy; a linear rotation
// field (constant curvature) has h . theta = 0 on the rectangle and no hourglass moment.
TEST(Shell4Hourglass, Ishell3RotationModesAreViscous) {
  constexpr double h[4] = {1, -1, 1, -1};
  const double dt = 1e-6, expected = 1.847806;
  for (const int axis : {0, 1}) {
    Element el(kRectangle, 0.01, 3);
    el.one_point(3);
    el.p.hr = 0.1;  // the figures below are for hr 0.1 (the default is 0.01)
    el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
    for (std::size_t k = 0; k < 4; ++k) (axis == 0 ? el.nodes.wx : el.nodes.wy)[k] = h[k];
    const GroupStepResult moving = shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_NEAR(-(axis == 0 ? el.nodes.mx : el.nodes.my)[k], h[k] * expected, 1e-5 * expected) << "node " << k;
    EXPECT_NEAR(moving.hourglass_energy, expected * 4.0 * dt, 1e-5 * expected * 4.0 * dt);
    EXPECT_EQ(el.state.hourglass[3 + static_cast<std::size_t>(axis)], 0.0);
    el.nodes.clear_forces();
    for (std::size_t k = 0; k < 4; ++k) el.nodes.wx[k] = el.nodes.wy[k] = 0.0;
    shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ((axis == 0 ? el.nodes.mx : el.nodes.my)[k], 0.0);
  }
  Element bent(kRectangle, 0.01, 3);
  bent.one_point(3);
  bent.p.zeta = bent.zeta, bent.p.membrane_weight = bent.wn, bent.p.bending_weight = bent.wb;
  for (std::size_t k = 0; k < 4; ++k) bent.nodes.wy[k] = 2.0 * bent.nodes.x[k] + 0.5;
  EXPECT_EQ(shell4_forces(bent.table, bent.group, bent.p, bent.nodes, bent.state, dt).hourglass_energy, 0.0);
}

// A rigid rotation of a warped element (corners 6 mm off its mean plane) about in-plane axes moves its corners in
// the plane by the rotation times their heights, a membrane hourglass pattern: Ishell 1 reads it as hourglass
// deformation and pushes back; Ishell 3 takes it off the rates (eq. S-18a) and, like the element's strains, sees
// nothing. Its hourglass forces on a warped element are self-equilibrated, moments included, for any motion.
TEST(Shell4Hourglass, Ishell3IgnoresTheRigidRotationOfAWarpedElement) {
  const double omega[3] = {1.0, 0.5, 0.0}, dt = 1e-6;
  double membrane[2];
  for (const int ishell : {1, 3}) {
    Element el(kWarped, 0.01, 3);
    el.one_point(ishell);
    el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
    double centre[3] = {0, 0, 0};
    for (std::size_t k = 0; k < 4; ++k)
      centre[0] += el.nodes.x[k] / 4, centre[1] += el.nodes.y[k] / 4, centre[2] += el.nodes.z[k] / 4;
    for (std::size_t k = 0; k < 4; ++k) {
      const double r[3] = {el.nodes.x[k] - centre[0], el.nodes.y[k] - centre[1], el.nodes.z[k] - centre[2]};
      el.nodes.vx[k] = omega[1] * r[2] - omega[2] * r[1];
      el.nodes.vy[k] = omega[2] * r[0] - omega[0] * r[2];
      el.nodes.vz[k] = omega[0] * r[1] - omega[1] * r[0];
      el.nodes.wx[k] = omega[0], el.nodes.wy[k] = omega[1], el.nodes.wz[k] = omega[2];
    }
    shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
    membrane[ishell == 1 ? 0 : 1] = std::hypot(el.state.hourglass[0], el.state.hourglass[1]);
  }
  EXPECT_GT(membrane[0], 1e-2) << "Ishell 1 loads its membrane hourglass modes in a rigid rotation";
  EXPECT_LT(membrane[1], 1e-9 * membrane[0]) << "Ishell 3 does not";

  Element el(kWarped, 0.01, 3);
  el.one_point(3);
  std::array<double, 24> u{};
  for (std::size_t j = 0; j < 24; ++j) u[j] = std::sin(1.7 * static_cast<double>(j) + 0.3);
  const auto f = el.response(u, 1e-4);
  double force[3] = {0, 0, 0}, moment[3] = {0, 0, 0}, largest = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const double x[3] = {el.nodes.x[k], el.nodes.y[k], el.nodes.z[k]}, *fk = &f[6 * k], *mk = &f[6 * k + 3];
    for (int i = 0; i < 3; ++i) force[i] += fk[i], moment[i] += mk[i], largest = std::max(largest, std::abs(fk[i]));
    moment[0] += x[1] * fk[2] - x[2] * fk[1];
    moment[1] += x[2] * fk[0] - x[0] * fk[2];
    moment[2] += x[0] * fk[1] - x[1] * fk[0];
  }
  ASSERT_GT(largest, 0.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(force[i], 0.0, 1e-12 * largest) << "force " << i;
    EXPECT_NEAR(moment[i], 0.0, 1e-12 * largest) << "moment " << i;
  }
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
    const double membrane_cap = 2.0 * 0.1 * sigma_y * t * std::sqrt(area), transverse_cap = 0.1 * sigma_y * t * t;
    const double membrane_elastic = 0.1 * 2.0 * kE * t * 50 * 1e-4;
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

}  // namespace test_shell4_hourglass
