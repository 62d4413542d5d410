// 3-node C0 shell kernel: constant membrane strain, zero forces under rigid motion, balanced nodal forces.
#include <gtest/gtest.h>

#include "crumple/elements/shell4.hpp"
#include "crumple/materials/hardening.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell3 {

using namespace crumple;
using test::I;
using test::R;

namespace {

struct Triangle {
  Model model;
  NodalState nodes;
  ShellState state;
  ShellGroupParameters p;
  double zeta[3], wn[3], wb[3];
};

// One triangle (0,0) (2,0) (0.5,1.5) in the z = 0.3 plane, steel, 3 points through 0.01 thickness.
void make_triangle(Triangle& t) {
  test::TempDir dir;
  std::string deck = test::begin_card() + "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.3) + "\n" + I(2) + R(2.0) +
                     R(0.0) + R(0.3) + "\n" + I(3) + R(0.5) + R(1.5) + R(0.3) + "\n";
  deck += "/SH3N/1\n" + I(7) + I(1) + I(2) + I(3) + "\n/PART/1\np\n" + I(1) + I(1) + "\n";
  deck += "/PROP/SHELL/1\ns\n" + I(0) + "\n\n" + I(3) + I(0) + R(0.01) + "\n";
  deck += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.0e11) + R(0.25) + "\n/END\n";
  t.model = read_deck(dir.write("T_0000.rad", deck)).model;
  t.nodes.resize(3);
  t.nodes.x = t.model.nodes.x, t.nodes.y = t.model.nodes.y, t.nodes.z = t.model.nodes.z;
  t.state.resize_points(3);
  t.state.resize_elements(1, 0.01);
  through_thickness_rule(3, t.zeta, t.wn, t.wb);
  t.p.hardening = materials::Hardening::of(t.model.materials[0], t.model.functions);
  t.p.young = 2.0e11, t.p.poisson = 0.25, t.p.density = 7800.0, t.p.points = 3;
  t.p.zeta = t.zeta, t.p.membrane_weight = t.wn, t.p.bending_weight = t.wb;
}

}  // namespace

TEST(Shell3, UniformStretchGivesConstantStressAndBalancedForces) {
  Triangle t;
  make_triangle(t);
  const double rate = 1e-3, dt = 1e-6;
  for (std::size_t k = 0; k < 3; ++k) t.nodes.vx[k] = rate * t.nodes.x[k];  // d_xx = rate, everything else 0
  const auto r = shell3_forces(t.model.elements[1], t.model.element_groups[0], t.p, t.nodes, t.state, dt);
  const double c = 2.0e11 / (1.0 - 0.25 * 0.25);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(t.state.sxx[k], c * rate * dt, 1e-9 * c * rate * dt);
    EXPECT_NEAR(t.state.syy[k], 0.25 * c * rate * dt, 1e-9 * c * rate * dt);
    EXPECT_NEAR(t.state.sxy[k], 0.0, 1e-9 * c * rate * dt);
  }
  double fx = 0, fy = 0, fz = 0;
  for (std::size_t k = 0; k < 3; ++k) fx += t.nodes.fx[k], fy += t.nodes.fy[k], fz += t.nodes.fz[k];
  const double scale = c * rate * dt * 0.01 * 2.0;
  EXPECT_NEAR(fx, 0.0, 1e-12 * scale);
  EXPECT_NEAR(fy, 0.0, 1e-12 * scale);
  EXPECT_NEAR(fz, 0.0, 1e-12 * scale);
  // Critical step: twice the area over the longest side, over the bar speed sqrt(E / rho) (eq. T-1a).
  const double area = 0.5 * 2.0 * 1.5, longest = std::sqrt(1.5 * 1.5 + 1.5 * 1.5);
  EXPECT_NEAR(r.min_dt, 2.0 * area / longest / std::sqrt(2.0e11 / 7800.0), 1e-12);
}

TEST(Shell3, RigidRotationGivesNoStress) {
  Triangle t;
  make_triangle(t);
  // v = w x r with w = (0.3, -0.2, 0.5); nodal angular velocities equal w.
  const double w[3] = {0.3, -0.2, 0.5};
  for (std::size_t k = 0; k < 3; ++k) {
    const double r[3] = {t.nodes.x[k], t.nodes.y[k], t.nodes.z[k]};
    t.nodes.vx[k] = w[1] * r[2] - w[2] * r[1];
    t.nodes.vy[k] = w[2] * r[0] - w[0] * r[2];
    t.nodes.vz[k] = w[0] * r[1] - w[1] * r[0];
    t.nodes.wx[k] = w[0], t.nodes.wy[k] = w[1], t.nodes.wz[k] = w[2];
  }
  shell3_forces(t.model.elements[1], t.model.element_groups[0], t.p, t.nodes, t.state, 1e-6);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(t.state.sxx[k], 0.0, 1e-3);
    EXPECT_NEAR(t.state.syy[k], 0.0, 1e-3);
    EXPECT_NEAR(t.state.sxy[k], 0.0, 1e-3);
  }
  EXPECT_NEAR(t.state.qx[0], 0.0, 1e-6);
  EXPECT_NEAR(t.state.qy[0], 0.0, 1e-6);
}

}  // namespace test_shell3
