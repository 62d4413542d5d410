// Physically stabilised 4-node shell, Ishell 24 (docs/theory/shell4.md, eqs. S-10 to S-14): the hourglass
// modes carry the energy of the deformation they stand for, exactly for rectangles, with the section's plane-stress
// modulus A11 = E / (1 - nu^2) as the reference's QEPH takes it (S-11), and as internal energy (S-12a).
#include <gtest/gtest.h>

#include <cmath>

#include "crumple/elements/shell4.hpp"
#include "crumple/materials/hardening.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell4_qeph {

using namespace crumple;
using test::I;
using test::R;

namespace {

constexpr double kE = 2.0e11, kNu = 0.3, kThickness = 0.01;
constexpr double kA11 = kE / (1.0 - kNu * kNu);  // the hourglass modes' modulus (eq. S-11)

struct Quad {
  Model model;
  NodalState nodes;
  ShellState state;
  ShellGroupParameters p;
  double zeta[5], wn[5], wb[5];
  double a, b;  // half lengths along x and y
  GroupStepResult step(double dt) {
    return shell4_forces(model.elements[0], model.element_groups[0], p, nodes, state, dt);
  }
  // Local coordinates of node k from the centre.
  double x(std::size_t k) const { return nodes.x[k] - a; }
  double y(std::size_t k) const { return nodes.y[k] - b; }
};

// One rectangle 2a x 2b in z = 0, steel, elastic, 5 points through the thickness, Ishell 24 or 1.
void make_quad(Quad& q, double a, double b, int ishell) {
  test::TempDir dir;
  std::string deck = test::begin_card() + "/NODE\n";
  const double xy[4][2] = {{0.0, 0.0}, {2 * a, 0.0}, {2 * a, 2 * b}, {0.0, 2 * b}};
  for (int k = 0; k < 4; ++k) deck += I(k + 1) + R(xy[k][0]) + R(xy[k][1]) + R(0.0) + "\n";
  deck += "/SHELL/1\n" + I(7) + I(1) + I(2) + I(3) + I(4) + "\n/PART/1\np\n" + I(1) + I(1) + "\n";
  deck += "/PROP/SHELL/1\ns\n" + I(ishell) + "\n\n" + I(5) + I(0) + R(kThickness) + "\n";
  deck += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(kE) + R(kNu) + "\n/END\n";
  q.model = read_deck(dir.write("Q_0000.rad", deck)).model;
  q.a = a, q.b = b;
  q.nodes.resize(4);
  q.nodes.x = q.model.nodes.x, q.nodes.y = q.model.nodes.y, q.nodes.z = q.model.nodes.z;
  q.state.resize_points(5);
  q.state.resize_elements(1, kThickness);
  through_thickness_rule(5, q.zeta, q.wn, q.wb);
  q.p.hardening = materials::Hardening::of(q.model.materials[0], q.model.functions);
  q.p.young = kE, q.p.poisson = kNu, q.p.density = 7800.0, q.p.points = 5;
  q.p.zeta = q.zeta, q.p.membrane_weight = q.wn, q.p.bending_weight = q.wb;
  q.p.physical_hourglass = ishell == 24;
  q.p.numerical_damping = 0.0;  // the energies below are elastic
}

// In-plane bending of a beam of length 2a and depth 2b: u = kappa x y (the nodal field is the x hourglass mode);
// the exact strain energy is 1/2 A11 I kappa^2 L = (2/3) A11 t a b^3 kappa^2 with the reference's modulus. The
// centre is unstrained, so all of it is the hourglass stresses' work: internal energy for Ishell 24, hourglass
// energy for Ishell 1.
double in_plane_bending_energy(Quad& q, double kappa, double dt) {
  for (std::size_t k = 0; k < 4; ++k) q.nodes.vx[k] = kappa / dt * q.x(k) * q.y(k);
  const GroupStepResult r = q.step(dt);
  return r.internal_energy + r.hourglass_energy;
}

TEST(Shell4Qeph, InPlaneBendingEnergyIsExactForRectangles) {
  const double kappa = 1e-4, dt = 1e-7;
  for (const double aspect : {1.0, 4.0, 0.25}) {
    Quad q;
    const double b = 0.05, a = aspect * b;
    make_quad(q, a, b, 24);
    const double exact = 2.0 / 3.0 * kA11 * kThickness * a * b * b * b * kappa * kappa;
    EXPECT_NEAR(in_plane_bending_energy(q, kappa, dt), exact, 1e-10 * exact) << "aspect " << aspect;
  }
}

// The same field in a square Belytschko-Tsay element with the default hm = 0.01 carries 1.4 % of it
// (2 hm E t = 0.02 E t against A11 t 4b / 3a = 1.47 E t): a coarse mesh of Ishell 1 is far too soft in in-plane
// bending, which is what physical stabilisation mends. Imposed over a long step, so that the hourglass modes'
// quadratic damping (S-5b), which grows as the rate cubed, takes no measurable part.
TEST(Shell4Qeph, BelytschkoTsayHourglassIsMuchSofterInBending) {
  const double kappa = 1e-4, dt = 1e-2, a = 0.05, b = 0.05;
  Quad qeph, bt;
  make_quad(qeph, a, b, 24);
  make_quad(bt, a, b, 1);
  const double ratio = in_plane_bending_energy(bt, kappa, dt) / in_plane_bending_energy(qeph, kappa, dt);
  EXPECT_NEAR(ratio, 0.02 * (1.0 - kNu * kNu) / (4.0 / 3.0), 1e-9);
}

// Plate bending by the rotation hourglass: theta_y = c x y gives kappa_xx = c y; exact energy
// 1/2 (A11 t^3 / 12) c^2 (4/3) a b^3 (beam-like, the reference's modulus), internal energy.
TEST(Shell4Qeph, RotationHourglassCarriesTheBendingEnergy) {
  const double c = 1e-3, dt = 1e-7, a = 0.1, b = 0.05;
  Quad q;
  make_quad(q, a, b, 24);
  for (std::size_t k = 0; k < 4; ++k) q.nodes.wy[k] = c / dt * q.x(k) * q.y(k);
  const double energy = q.step(dt).internal_energy;
  const double exact = 0.5 * kA11 * std::pow(kThickness, 3) / 12.0 * c * c * 4.0 / 3.0 * a * b * b * b;
  EXPECT_NEAR(energy, exact, 1e-10 * exact);
}

// A thin plate in Kirchhoff twist, w = c x y with theta_x = c x, theta_y = -c y: the bilinear w is explained by
// the rotations, so the transverse-shear hourglass mode stays at rest (no shear locking in twist, eq. S-13).
TEST(Shell4Qeph, KirchhoffTwistLeavesTheShearModeAtRest) {
  const double c = 1e-2, dt = 1e-7;
  for (const double aspect : {1.0, 3.0}) {
    Quad q;
    make_quad(q, aspect * 0.05, 0.05, 24);
    for (std::size_t k = 0; k < 4; ++k) {
      q.nodes.vz[k] = c / dt * q.x(k) * q.y(k);
      q.nodes.wx[k] = c / dt * q.x(k), q.nodes.wy[k] = -c / dt * q.y(k);
    }
    const auto r = q.step(dt);
    for (int m = 0; m < 5; ++m) EXPECT_NEAR(q.state.hourglass[static_cast<std::size_t>(m)], 0.0, 1e-9) << "mode " << m;
    EXPECT_NEAR(r.hourglass_energy, 0.0, 1e-12 * r.internal_energy);
    EXPECT_GT(r.internal_energy, 0.0);  // the twist itself is resisted by the curvature kxy
  }
}

// Rigid motion (translation plus rotation about an axis in the plane and about the normal) gives no force.
TEST(Shell4Qeph, RigidRotationGivesNoHourglassForce) {
  Quad q;
  make_quad(q, 0.08, 0.05, 24);
  const double w[3] = {0.3, -0.2, 0.5}, v0[3] = {1.0, 2.0, -0.5};
  for (std::size_t k = 0; k < 4; ++k) {
    const double r[3] = {q.nodes.x[k], q.nodes.y[k], q.nodes.z[k]};
    q.nodes.vx[k] = v0[0] + w[1] * r[2] - w[2] * r[1];
    q.nodes.vy[k] = v0[1] + w[2] * r[0] - w[0] * r[2];
    q.nodes.vz[k] = v0[2] + w[0] * r[1] - w[1] * r[0];
    q.nodes.wx[k] = w[0], q.nodes.wy[k] = w[1], q.nodes.wz[k] = w[2];
  }
  q.step(1e-7);
  for (int m = 0; m < 5; ++m) EXPECT_NEAR(q.state.hourglass[static_cast<std::size_t>(m)], 0.0, 1e-6) << "mode " << m;
}

}  // namespace

}  // namespace test_shell4_qeph
