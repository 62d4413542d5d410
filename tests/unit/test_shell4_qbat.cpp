// Fully integrated Batoz shell, Ishell 12 (docs/theory/shell4.md, "QBAT", eqs. ): one element driven
// by prescribed nodal velocities over one step from a stress-free state, so that the nodal forces are the
// element's tangent stiffness times the increment. The tests measure what the formulation claims: no force in
// rigid motion (flat and warped), no zero-energy mode besides rigid motion and the drilling rotations, a
// symmetric stiffness, and exact bending and twisting energies of a rectangle.
#include "shell4_element.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell4_qbat {

using namespace crumple;
using namespace crumple::test;

namespace {

TEST(Shell4Qbat, RigidMotionGivesNoForce) {
  for (const auto& shape : {kDistorted, kWarped}) {
    Element el(shape, 0.01, 0);
    const std::vector<double> k = el.stiffness();
    double scale = 0.0;
    for (double v : k) scale = std::max(scale, std::abs(v));
    const auto u = rigid_motion(el, {1.0, -2.0, 0.5}, {0.3, -0.7, 1.1});
    double worst = 0.0;
    for (std::size_t i = 0; i < 24; ++i) {
      double f = 0.0;
      for (std::size_t j = 0; j < 24; ++j) f += k[24 * i + j] * u[j];
      worst = std::max(worst, std::abs(f));
    }
    EXPECT_LT(worst, 1e-9 * scale);
  }
}

TEST(Shell4Qbat, OnlyRigidAndDrillingModesHaveNoStiffness) {
  for (const auto& shape : {kDistorted, kWarped}) {
    Element el(shape, 0.01, 0);
    std::vector<double> k = el.stiffness();
    double asymmetry = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < 24; ++i)
      for (std::size_t j = 0; j < 24; ++j) {
        asymmetry = std::max(asymmetry, std::abs(k[24 * i + j] - k[24 * j + i]));
        scale = std::max(scale, std::abs(k[24 * i + j]));
      }
    for (std::size_t i = 0; i < 24; ++i)
      for (std::size_t j = 0; j < 24; ++j) k[24 * i + j] = 0.5 * (k[24 * i + j] + k[24 * j + i]);
    const std::vector<double> d = eigenvalues(k, 24);
    int zero = 0;
    for (double v : d) zero += std::abs(v) < 1e-8 * d.back() ? 1 : 0;
    std::printf("[qbat modes] asymmetry %.2e  zero modes %d  smallest non-zero %.3e of largest\n", asymmetry / scale, zero,
                d[static_cast<std::size_t>(zero)] / d.back());
    EXPECT_LT(asymmetry, 1e-9 * scale) << "the tangent stiffness is not symmetric";
    // 6 rigid-body modes and the 4 drilling rotations about the nodal directors (no drilling stiffness, Idrill 0):
    // the free axis of each node is its director, so a warped element has exactly the same count.
    EXPECT_EQ(zero, 10);
  }
}

}  // namespace

namespace {
// Highest natural frequency of the free element with the lumped masses of setup_shells: m/4 per node and the
// rotational inertia (m/4) (t^2 + A) / 12 (eq. S-8), from the symmetric stiffness (largest eigenvalue of
// M^-1/2 K M^-1/2).
double highest_frequency(Element& el, double thickness, double area) {
  const std::vector<double> stiffness = el.stiffness();
  const double mass = kRho * thickness * area / 4.0, inertia = mass * (thickness * thickness + area) / 12.0;
  std::vector<double> k(24 * 24);
  for (std::size_t i = 0; i < 24; ++i)
    for (std::size_t j = 0; j < 24; ++j) {
      const double mi = i % 6 < 3 ? mass : inertia, mj = j % 6 < 3 ? mass : inertia;
      k[24 * i + j] = 0.5 * (stiffness[24 * i + j] + stiffness[24 * j + i]) / std::sqrt(mi * mj);
    }
  // Power iteration: the largest eigenvalue of the positive semi-definite matrix.
  std::vector<double> x(24, 1.0), y(24);
  double lambda = 0.0;
  for (int it = 0; it < 2000; ++it) {
    double norm = 0.0;
    for (std::size_t i = 0; i < 24; ++i) {
      y[i] = 0.0;
      for (std::size_t j = 0; j < 24; ++j) y[i] += k[24 * i + j] * x[j];
      norm += y[i] * y[i];
    }
    norm = std::sqrt(norm);
    double rayleigh = 0.0;
    for (std::size_t i = 0; i < 24; ++i) rayleigh += x[i] * y[i], x[i] = y[i] / norm;
    lambda = rayleigh;
  }
  return std::sqrt(lambda);
}
}  // namespace

// The critical step of Ishell 12 is the one of eq. T-1 because full integration adds no faster mode: the highest
// frequency of the free element (lumped masses of setup_shells) is that of the one-point element, the membrane
// dilatation, for a square exactly omega = 2 c sqrt(1 + nu) / h (c the plate wave speed): its energy is
// 4 t E u^2 / (1 - nu) for corner displacements (+-u, +-u), its kinetic energy rho t h^2 u_dot^2. Transverse shear
// and bending modes stay below it at every thickness (the rotational inertia of eq. S-8 sees to that). The
// printed ratio omega_max dt / 2 of the unscaled step of T-1 is sqrt(1 + nu) = 1.14 for the square (docs/theory/
// shell4.md, "Critical step"): the same for Ishell 1, 24 and 12.
TEST(Shell4Qbat, HighestFrequencyIsTheMembraneDilatation) {
  const double c = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  const std::array<std::array<std::array<double, 3>, 4>, 3> shapes{
      {{{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {0, 0.1, 0}}}, {{{0, 0, 0}, {0.5, 0, 0}, {0.5, 0.275, 0}, {0, 0.275, 0}}},
       kDistorted}};
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const auto& x = shapes[k];
    const double area = 0.5 * std::abs((x[2][0] - x[0][0]) * (x[3][1] - x[1][1]) - (x[3][0] - x[1][0]) * (x[2][1] - x[0][1]));
    for (double t : {0.001, 0.01, 0.1}) {
      Element qbat(x, t, 0);
      const double w = highest_frequency(qbat, t, area);
      qbat.response({}, 1.0);
      Element bt(x, t, 0);
      bt.p.fully_integrated = false;
      bt.state.resize_points(1);
      bt.state.bending_stress.assign(3, 0.0);
      const double w_bt = highest_frequency(bt, t, area);
      // Parallelograms: equal to round-off; the distorted shape: +0.16 % (its fully integrated membrane is a little
      // stiffer in the dilatation), well inside the 0.9 scale of the step.
      EXPECT_NEAR(w, w_bt, 5e-3 * w_bt) << "shape " << k << " t " << t;
      if (k == 0) {
        EXPECT_NEAR(w, 2.0 * c * std::sqrt(1.0 + kNu) / 0.1, 1e-9 * w);
      }
      std::printf("[qbat step] shape %zu t %.3f: step (T-1) %.4e  2 / omega_max %.4e  omega_max step / 2 = %.4f\n", k, t,
                  qbat.last.min_dt, 2.0 / w, w * qbat.last.min_dt / 2.0);
    }
  }
}

// In-plane bending u = kappa x y of a rectangle 2a x 2b: the normal strains at the Gauss points are exact and the
// in-plane shear taken at the centre is zero, so the energy is that of the field itself, (2/3) E t a b^3 kappa^2 /
// (1 - nu^2) (v = 0 holds the lateral strain), at every aspect ratio: no in-plane shear locking.
TEST(Shell4Qbat, InPlaneBendingWithoutShearLocking) {
  const double kappa = 1e-4, t = 0.01;
  for (const double aspect : {1.0, 4.0, 0.25}) {
    const double b = 0.05, a = aspect * b;
    Element el({{{0, 0, 0}, {2 * a, 0, 0}, {2 * a, 2 * b, 0}, {0, 2 * b, 0}}}, t, 5);
    std::array<double, 24> u{};
    for (std::size_t k = 0; k < 4; ++k) u[6 * k] = kappa * (el.nodes.x[k] - a) * (el.nodes.y[k] - b);
    el.response(u, 1.0);
    const double exact = 2.0 / 3.0 * kE * t * a * b * b * b * kappa * kappa / (1.0 - kNu * kNu);
    EXPECT_NEAR(el.last.internal_energy, exact, 1e-10 * exact) << "aspect " << aspect;
  }
}

// Kirchhoff twist of a thin plate, w = c x y with theta_x = c x, theta_y = -c y: the tying-point shear strains of
// Q4gamma vanish (the rotations match the side slopes), so the energy is the twisting energy alone,
// (1/2) D (1 - nu) (2 c)^2 / 2 x area with D = E t^3 / (12 (1 - nu^2)): no transverse shear locking.
TEST(Shell4Qbat, KirchhoffTwistWithoutShearLocking) {
  const double c = 1e-3, t = 0.001;
  for (const double aspect : {1.0, 3.0}) {
    const double b = 0.05, a = aspect * b;
    Element el({{{0, 0, 0}, {2 * a, 0, 0}, {2 * a, 2 * b, 0}, {0, 2 * b, 0}}}, t, 0);
    std::array<double, 24> u{};
    for (std::size_t k = 0; k < 4; ++k) {
      const double x = el.nodes.x[k] - a, y = el.nodes.y[k] - b;
      u[6 * k + 2] = c * x * y, u[6 * k + 3] = c * x, u[6 * k + 4] = -c * y;
    }
    el.response(u, 1.0);
    const double D = kE * t * t * t / (12.0 * (1.0 - kNu * kNu));
    const double exact = 0.5 * D * (1.0 - kNu) / 2.0 * (2.0 * c) * (2.0 * c) * 4.0 * a * b;
    EXPECT_NEAR(el.last.internal_energy, exact, 1e-10 * exact) << "aspect " << aspect;
  }
}

}  // namespace test_shell4_qbat
