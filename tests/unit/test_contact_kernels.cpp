// TYPE7 contact kernels and pass against hand calculations (docs/theory/contact.md, eqs. C-1 to C-12).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "crumple/contact/contact.hpp"
#include "crumple/contact/kernels.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_contact_kernels {

using namespace crumple;
using namespace crumple::contact;

TEST(ContactKernels, PenaltyForceStiffnessAndEnergyByHand) {
  const double k0 = 1000.0, g = 0.1, p = 0.05;
  EXPECT_DOUBLE_EQ(penalty_force(k0, g, p), 100.0);      // 1000 * 0.1 * 0.05 / 0.05
  EXPECT_DOUBLE_EQ(secant_stiffness(k0, g, p), 2000.0);  // 1000 * 0.1 / 0.05
  EXPECT_DOUBLE_EQ(tangent_stiffness(k0, g, p), 4000.0); // 1000 * (0.1 / 0.05)^2
  // 1000 * 0.1 * (-0.05 - 0.1 ln 0.5) = 1.9314718...
  EXPECT_NEAR(elastic_energy(k0, g, p), 100.0 * (-0.05 + 0.1 * std::log(2.0)), 1e-12);
  // The energy is the integral of the force (Simpson, 2000 intervals) and the tangent its derivative.
  const int n = 2000;
  double integral = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    integral += w * penalty_force(k0, g, p * k / n);
  }
  integral *= p / n / 3.0;
  EXPECT_NEAR(elastic_energy(k0, g, p), integral, 1e-9);
  const double h = 1e-7;
  EXPECT_NEAR(tangent_stiffness(k0, g, p), (penalty_force(k0, g, p + h) - penalty_force(k0, g, p - h)) / (2 * h), 1e-3);
  // At release, (1 - 1e-10) g, a node has stored about 23 K0 g^2 (ln 1e10 = 23.03): the most one node can absorb.
  EXPECT_NEAR(elastic_energy(k0, g, (1.0 - 1e-10) * g) / (k0 * g * g), std::log(1e10) - 1.0, 1e-6);
}

TEST(ContactKernels, DampingActsBothWaysButNeverPulls) {
  const double kt = 4000.0, mass = 2.0, viss = 0.05, c = 0.05 * std::sqrt(2.0 * 4000.0 * 2.0);  // C = 8
  EXPECT_NEAR(damping_force(viss, kt, mass, 3.0, 100.0), c * 3.0, 1e-12);  // closing: adds to the push
  // Separating: it takes off the push (C dp/dt = -24 of 100), the manual's F = Ks p + C dp/dt ...
  EXPECT_NEAR(damping_force(viss, kt, mass, -3.0, 100.0), -c * 3.0, 1e-12);
  // ... but never more than the elastic push: the total normal force stays >= 0 (10 - 24 -> 0).
  EXPECT_EQ(damping_force(viss, kt, mass, -3.0, 10.0), -10.0);
  EXPECT_EQ(10.0 + damping_force(viss, kt, mass, -3.0, 10.0), 0.0);
  EXPECT_EQ(damping_force(viss, kt, mass, 0.0, 10.0), 0.0);
}

TEST(ContactKernels, FrictionViscosityIsVisFOfTheCriticalDashpot) {
  EXPECT_DOUBLE_EQ(friction_viscosity(1.0, 4000.0, 2.0), std::sqrt(2.0 * 4000.0 * 2.0));  // 126.49 N s/m
  EXPECT_DOUBLE_EQ(friction_viscosity(3.0, 4000.0, 2.0), 3.0 * std::sqrt(16000.0));
}

TEST(ContactKernels, FrictionCone) {
  double trial[3] = {3.0, 4.0, 0.0};
  EXPECT_TRUE(friction_cone(trial, 2.0));  // |trial| = 5 > mu Fn = 2: slides, scaled to 2 along (0.6, 0.8)
  EXPECT_NEAR(trial[0], 1.2, 1e-15);
  EXPECT_NEAR(trial[1], 1.6, 1e-15);
  double inside[3] = {0.3, -0.4, 0.0};
  EXPECT_FALSE(friction_cone(inside, 2.0));  // sticks: unchanged
  EXPECT_EQ(inside[0], 0.3);
  EXPECT_EQ(inside[1], -0.4);
}

TEST(ContactKernels, FrictionLawsByHand) {
  // Ifric 0: Coulomb, whatever p and v.
  FrictionLaw coulomb;
  coulomb.fric = 0.3;
  EXPECT_DOUBLE_EQ(friction_coefficient(coulomb, 1e6, 5.0), 0.3);
  // Ifric 1 (eq. C-9a): 0.1 + 1e-6 1e5 + 0.01 2 + 1e-8 1e5 2 + 1e-12 1e10 + 1e-3 4 = 0.236.
  FrictionLaw viscous{1, 0.1, {1e-6, 0.01, 1e-8, 1e-12, 1e-3, 0.0}};
  EXPECT_NEAR(friction_coefficient(viscous, 1e5, 2.0), 0.236, 1e-15);
  // Ifric 2 (eq. C-9b): 1e-12 e^-0.2 1e10 + 1e-6 e^-0.4 1e5 + 0.2 e^-0.1; Fric plays no part.
  FrictionLaw darmstad{2, 0.7, {1e-12, -0.1, 1e-6, -0.2, 0.2, -0.05}};
  EXPECT_NEAR(friction_coefficient(darmstad, 1e5, 2.0),
              0.01 * std::exp(-0.2) + 0.1 * std::exp(-0.4) + 0.2 * std::exp(-0.1), 1e-15);
  // Ifric 3 (eq. C-9c): mu_s 0.3, mu_d 0.2, mu_max 0.4, mu_min 0.1, Vcr1 1, Vcr2 3.
  FrictionLaw renard{3, 0.0, {0.3, 0.2, 0.4, 0.1, 1.0, 3.0}};
  EXPECT_DOUBLE_EQ(friction_coefficient(renard, 0.0, 0.0), 0.3);    // static
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 0.5), 0.375, 1e-15); // 0.3 + 0.1 0.5 1.5
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 1.0), 0.4, 1e-15);   // maximum at Vcr1
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 2.0), 0.25, 1e-15);  // 0.4 - 0.3 0.25 2
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 3.0), 0.1, 1e-15);   // minimum at Vcr2
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 4.0), 0.2 - 1.0 / 11.0, 1e-15);
  EXPECT_NEAR(friction_coefficient(renard, 0.0, 1e4), 0.2 - 1.0 / (10.0 + 9997.0 * 9997.0), 1e-15);  // -> mu_d
  // Continuous across the critical speeds.
  for (double v : {1.0, 3.0})
    EXPECT_NEAR(friction_coefficient(renard, 0.0, v * (1 - 1e-9)), friction_coefficient(renard, 0.0, v * (1 + 1e-9)), 1e-8);
  // A law that turns negative gives no friction rather than a driving force.
  FrictionLaw falling{1, 0.1, {0.0, -1.0, 0.0, 0.0, 0.0, 0.0}};
  EXPECT_EQ(friction_coefficient(falling, 0.0, 1.0), 0.0);
}

TEST(ContactKernels, FrictionFilterWeights) {
  // eq. C-9d: Ifiltr 1 the factor itself; 2 2 pi dt / T; 3 2 pi f dt; never above 1.
  EXPECT_DOUBLE_EQ(friction_filter_weight(1, 0.25, 1e-6), 0.25);
  EXPECT_NEAR(friction_filter_weight(2, 1e-3, 1e-6), 2.0 * M_PI * 1e-3, 1e-15);
  EXPECT_NEAR(friction_filter_weight(3, 100.0, 1e-6), 2.0 * M_PI * 1e-4, 1e-15);
  EXPECT_DOUBLE_EQ(friction_filter_weight(3, 1e9, 1e-6), 1.0);
  EXPECT_DOUBLE_EQ(friction_filter_weight(0, 0.0, 1e-6), 1.0);
}

TEST(ContactKernels, KinematicAndStiffnessSteps) {
  EXPECT_DOUBLE_EQ(kinematic_step(0.1, 0.05, 10.0), 0.5 * 0.05 / 10.0);
  EXPECT_TRUE(std::isinf(kinematic_step(0.1, 0.05, -1.0)));  // separating: no kinematic limit
  EXPECT_DOUBLE_EQ(stiffness_step(2.0, 4000.0, 0.0), std::sqrt(2.0 * 2.0 / 4000.0));
  const double xi = 0.05;
  EXPECT_DOUBLE_EQ(stiffness_step(2.0, 4000.0, xi), std::sqrt(2.0 * 2.0 / 4000.0) * (std::sqrt(1.0 + xi * xi) - xi));
}

// eq. C-11b: the step with a friction dashpot C solves dt = a sqrt(2 M / (K + C / dt)), a = scale (sqrt(1 + xi^2)
// - xi); without the dashpot it is the stiffness step, without the spring the dashpot's 2 M a^2 / C.
TEST(ContactKernels, StepWithTheFrictionDashpot) {
  const double m = 2.0, k = 4000.0, xi = 0.05, scale = 0.9, a = scale * (std::sqrt(1.0 + xi * xi) - xi);
  EXPECT_NEAR(scaled_stiffness_step(m, k, 0.0, xi, scale), scale * stiffness_step(m, k, xi), 1e-15);
  EXPECT_NEAR(scaled_stiffness_step(m, 0.0, 126.0, xi, scale), 2.0 * m * a * a / 126.0, 1e-15);
  for (double c : {1.0, 126.0, 1e4}) {
    const double dt = scaled_stiffness_step(m, k, c, xi, scale);
    EXPECT_NEAR(dt, a * std::sqrt(2.0 * m / (k + c / dt)), 1e-13 * dt) << c;  // the root of its own equation
  }
  EXPECT_TRUE(std::isinf(scaled_stiffness_step(m, 0.0, 0.0, xi, scale)));
  // The QA deck `friction` (plate node 0.0225 kg on K0 = E t / 2 = 4.725e8 N/m, VisF 1, /DT 0.1, no VisS factor):
  // the reference's listing settles at 9.66e-8 s once the node is in contact (cycles 165 to 167, p << g so that
  // Kt = K0), a tenth of the 9.76e-7 s of the spring alone.
  const double node = 0.0225, k0 = 0.5 * 2.1e11 * 0.0045;
  EXPECT_NEAR(scaled_stiffness_step(node, k0, friction_viscosity(1.0, k0, node), 0.0, 0.1), 9.66e-8, 0.005e-8);
  EXPECT_NEAR(scaled_stiffness_step(node, k0, 0.0, 0.0, 0.1), 9.759e-7, 0.001e-7);
  // /DT/INTER/CST: the mass that brings the step up to dt (the dashpot grows with sqrt(M)).
  const double c_unit = friction_viscosity(1.0, k, 1.0), target = 0.05;
  const double added = mass_for_step(k, c_unit, xi, scale, target);
  EXPECT_NEAR(scaled_stiffness_step(added, k, c_unit * std::sqrt(added), xi, scale), target, 1e-12);
  EXPECT_NEAR(mass_for_step(k, 0.0, xi, scale, target), 0.5 * k * std::pow(target / a, 2), 1e-12);
}

// The interface nodal step's pair stiffness (time-step.md, T-4c), on the figures measured on the reference solver: a
// corner node of 4.906e-5 kg of a 5 mm steel square resting in the gap of a 1 mm plate (Kt = 105.2 kN/mm, the
// element's 85.05): k = 2 m (0.9 / dt)^2 is 198.3 at dt 6.331e-4 ms with VisS 0.05 (K_t + 8.1), 190.3 with VisS
// 1e-5; with Fric 0.1 and VisF 1 the friction's dashpot, 188.4 at dt 5.392e-4, is the larger and the normal one no part.
TEST(ContactKernels, NodalPairStiffnessHoldsTheNormalDashpot) {
  const double kt = 105.2, m = 4.906e-5, element = 85.05;
  const auto step = [&](double k) { return 0.9 * std::sqrt(2.0 * m / (element + k)); };
  EXPECT_NEAR(step(nodal_pair_stiffness(kt, kt, kt, 0.05, 0.0, m, 6.331e-4)), 6.331e-4, 0.002e-4);
  EXPECT_NEAR(step(nodal_pair_stiffness(kt, kt, kt, 1e-5, 0.0, m, 6.466e-4)), 6.466e-4, 0.003e-4);
  EXPECT_NEAR(step(nodal_pair_stiffness(kt, kt, kt, 0.05, 1.0, m, 5.392e-4)), 5.392e-4, 0.002e-4);
  // the first cycle (no last step): the tangent stiffness alone
  EXPECT_EQ(nodal_pair_stiffness(kt, kt, kt, 0.05, 1.0, m, 0.0), kt);
}

namespace {
const double kSquare[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
void expect_reproduces(const SegmentPoint& c) {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    double q = 0.0;
    for (int a = 0; a < 4; ++a) q += c.weight[a] * kSquare[a][k];
    EXPECT_NEAR(q, c.point[k], 1e-15);
  }
  for (double w : c.weight) {
    sum += w;
    EXPECT_GE(w, -1e-15);
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
}
}  // namespace

TEST(ContactKernels, ClosestPointOnFaceEdgeAndCorner) {
  // Above the face: along the normal.
  const double above[3] = {0.3, 0.6, 0.2};
  const SegmentPoint f = closest_point_on_segment(above, kSquare);
  EXPECT_NEAR(f.distance, 0.2, 1e-15);
  EXPECT_NEAR(f.point[0], 0.3, 1e-15);
  EXPECT_NEAR(f.point[1], 0.6, 1e-15);
  expect_reproduces(f);
  // Beside an edge: radially from the edge, shared by its two nodes.
  const double beside[3] = {1.2, 0.5, 0.1};
  const SegmentPoint e = closest_point_on_segment(beside, kSquare);
  EXPECT_NEAR(e.distance, std::hypot(0.2, 0.1), 1e-15);
  EXPECT_NEAR(e.weight[1], 0.5, 1e-15);
  EXPECT_NEAR(e.weight[2], 0.5, 1e-15);
  expect_reproduces(e);
  // Beyond a corner: from the corner node alone.
  const double corner[3] = {-0.1, -0.2, 0.3};
  const SegmentPoint c = closest_point_on_segment(corner, kSquare);
  EXPECT_NEAR(c.distance, std::sqrt(0.01 + 0.04 + 0.09), 1e-15);
  EXPECT_NEAR(c.weight[0], 1.0, 1e-15);
  // Triangle segment (third node repeated).
  const double tri[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  const double over[3] = {0.7, 0.7, 0.1};  // beyond the hypotenuse: its midpoint
  const SegmentPoint t = closest_point_on_segment(over, tri);
  EXPECT_NEAR(t.point[0], 0.5, 1e-15);
  EXPECT_NEAR(t.point[1], 0.5, 1e-15);
  EXPECT_NEAR(t.distance, std::sqrt(0.04 + 0.04 + 0.01), 1e-15);
}

namespace {

// Two unit squares side by side in z = 0 (nodes 0..5) and secondary node 6; gap 0.1, K0 = 1000.
struct TwoSegments {
  Model model;
  NodalState nodes;
  ContactState contact;
  TwoSegments(double x, double y, double z) {
    nodes.resize(7);
    const double xy[6][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
    for (std::size_t k = 0; k < 6; ++k) nodes.x[k] = xy[k][0], nodes.y[k] = xy[k][1], nodes.mass[k] = 1.0;
    nodes.x[6] = x, nodes.y[6] = y, nodes.z[6] = z, nodes.mass[6] = 0.5;
    ContactInterface in;
    in.secondary_nodes = {6};
    in.node_gap = {0.0}, in.gap_reduction = {0.0}, in.gap_clearance = {0.0}, in.node_active = {1}, in.node_touched = {0}, in.node_impacted = {0};
    in.node_tangent_sum = {0.0}, in.node_reach_stiffness = {0.0}, in.node_entry_stiffness = {0.0};
    in.node_friction_viscosity = {0.0}, in.node_element_stiffness = {0.0};
    in.segments = {{0, 1, 4, 3}, {1, 2, 5, 4}};
    in.segment_gap = {0.1, 0.1}, in.segment_stiffness = {1000.0, 1000.0};
    in.segment_active = {1, 1}, in.segment_owner = {-1, -1}, in.segment_owner_kind = {0, 0};
    in.main_nodes = {0, 1, 2, 3, 4, 5};
    in.largest_gap = 0.1, in.margin = 0.1, in.damping = 0.0;
    contact.interfaces.push_back(in);
    contact.results.resize(1);
    contact.fx.assign(7, 0.0), contact.fy.assign(7, 0.0), contact.fz.assign(7, 0.0);
  }
  ContactStep run() {
    double added = 0.0;
    return contact_forces(model, contact, nodes, 0.0, 1e-6, 1e-6, 0.9, added);
  }
};

}  // namespace

TEST(ContactPass, ForceAlongTheNormalEqualAndOpposite) {
  TwoSegments s(0.5, 0.25, 0.04);  // above the first square: p = 0.06
  s.run();
  EXPECT_NEAR(s.nodes.fz[6], penalty_force(1000.0, 0.1, 0.06), 1e-12);
  EXPECT_NEAR(s.nodes.fx[6], 0.0, 1e-15);
  double total[3] = {0, 0, 0};
  for (std::size_t k = 0; k < 7; ++k) total[0] += s.nodes.fx[k], total[1] += s.nodes.fy[k], total[2] += s.nodes.fz[k];
  for (double t : total) EXPECT_NEAR(t, 0.0, 1e-12);  // momentum: the segment takes the opposite force
  EXPECT_EQ(s.contact.results[0].active_nodes, 1);
  EXPECT_NEAR(s.contact.results[0].elastic_energy, elastic_energy(1000.0, 0.1, 0.06), 1e-12);
}

TEST(ContactPass, OverlappingGapsAtASharedEdgeDoubleTheForce) {
  TwoSegments s(1.0, 0.5, 0.04);  // above the shared edge x = 1: each segment pushes along z
  s.run();
  EXPECT_NEAR(s.nodes.fz[6], 2.0 * penalty_force(1000.0, 0.1, 0.06), 1e-12);
}

TEST(ContactPass, NoForceOutsideTheGapNorBesideTheEdgeBeyondIt) {
  TwoSegments above(0.5, 0.5, 0.1 * (1.0 + 1e-9));
  above.run();
  EXPECT_EQ(above.nodes.fz[6], 0.0);
  // Beside the free edge x = 2 at distance 0.08 radially (0.06 out, 0.0529 up): pushed radially away from the edge.
  TwoSegments beside(2.06, 0.5, std::sqrt(0.08 * 0.08 - 0.06 * 0.06));
  beside.run();
  const double f = penalty_force(1000.0, 0.1, 0.02);
  EXPECT_NEAR(beside.nodes.fx[6], f * 0.06 / 0.08, 1e-9);
  EXPECT_NEAR(beside.nodes.fz[6], f * std::sqrt(0.08 * 0.08 - 0.06 * 0.06) / 0.08, 1e-9);
}

TEST(ContactPass, StepOfAClosingNodeIsTheSmallerOfKinematicAndStiffness) {
  TwoSegments s(0.5, 0.25, 0.04);
  s.nodes.vz[6] = -100.0;  // closing at 100
  const ContactStep step = s.run();
  const double kt = tangent_stiffness(1000.0, 0.1, 0.06);
  const double expected = 0.9 * std::min(kinematic_step(0.1, 0.06, 100.0), stiffness_step(0.5, kt, 0.0));
  EXPECT_NEAR(step.dt, expected, 1e-15);
  EXPECT_EQ(step.node, 6);
}

// With viscous friction (Iform 1) the node's step also holds the pair's dashpot C_t = VisF sqrt(2 Kt M) (eq.
// C-11b); the stiffness form (Iform 2) has no dashpot and keeps the stiffness step.
TEST(ContactPass, ViscousFrictionDashpotShortensTheNodeStep) {
  const double kt = tangent_stiffness(1000.0, 0.1, 0.06), ct = friction_viscosity(3.0, kt, 0.5);
  for (int form : {1, 2}) {
    TwoSegments s(0.5, 0.25, 0.04);
    s.nodes.vx[6] = 1.0;  // sliding, separating so slowly that the kinematic step does not bound it
    s.nodes.vz[6] = 1e-3;
    ContactInterface& in = s.contact.interfaces[0];
    in.friction = true, in.friction_law.fric = 0.2, in.friction_damping = 3.0, in.friction_form = form;
    const ContactStep step = s.run();
    const double expected = form == 1 ? scaled_stiffness_step(0.5, kt, ct, 0.0, 0.9) : 0.9 * stiffness_step(0.5, kt, 0.0);
    EXPECT_NEAR(step.dt, expected, 1e-15) << form;
    if (form == 1) {
      EXPECT_LT(step.dt, 0.5 * 0.9 * stiffness_step(0.5, kt, 0.0));  // C_t / dt dominates K
    }
  }
}

// /TH/INTER |FNX| .. ||F|| (docs/output-format.md, "INTER"): per pair the absolute components and the magnitude of
// its normal force and of its whole force, summed over the pairs in contact, only when a request asks them.
// Beside the free edge x = 2 (as above): the normal (0.06, 0, 0.0529) / 0.08 carries f = K0 penalty at p = 0.02.
TEST(ContactPass, PairSumsOfAbsoluteForcesOnlyWhenAsked) {
  TwoSegments unasked(2.06, 0.5, std::sqrt(0.08 * 0.08 - 0.06 * 0.06));
  unasked.run();
  EXPECT_EQ(unasked.contact.results[0].pair_normal_norm, 0.0);
  EXPECT_EQ(unasked.contact.results[0].pair_normal_abs[0], 0.0);
  TwoSegments s(2.06, 0.5, std::sqrt(0.08 * 0.08 - 0.06 * 0.06));
  s.contact.interfaces[0].sum_pair_forces = true;
  s.run();
  const InterfaceResult& r = s.contact.results[0];
  const double f = penalty_force(1000.0, 0.1, 0.02), nz = std::sqrt(0.08 * 0.08 - 0.06 * 0.06) / 0.08;
  EXPECT_NEAR(r.pair_normal_abs[0], 0.75 * f, 1e-9);
  EXPECT_NEAR(r.pair_normal_abs[1], 0.0, 1e-12);
  EXPECT_NEAR(r.pair_normal_abs[2], nz * f, 1e-9);
  EXPECT_NEAR(r.pair_normal_norm, f, 1e-9);
  EXPECT_NEAR(r.pair_force_norm, f, 1e-9);  // no friction: the whole force is the normal one
  EXPECT_NEAR(r.pair_force_abs[0], 0.75 * f, 1e-9);
}

// Two secondary nodes pushed opposite ways through the plate (z = +0.04 over the first square, z = -0.04 under the
// second): the net normal force cancels, the sum of absolute values is 2 f. Sliding along x at 1 m/s with
// Coulomb friction mu = 0.2 (a dashpot far above the cone): each pair's friction is mu f along -x, so |FX| = 2 mu f
// while the net friction force is -2 mu f, and ||F|| = 2 f sqrt(1 + mu^2).
TEST(ContactPass, PairSumsDoNotCancelWhereTheForcesDo) {
  TwoSegments s(0.5, 0.25, 0.04);
  s.nodes.resize(8);
  const double xy[6][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  for (std::size_t k = 0; k < 6; ++k) s.nodes.x[k] = xy[k][0], s.nodes.y[k] = xy[k][1], s.nodes.mass[k] = 1.0;
  s.nodes.x[6] = 0.5, s.nodes.y[6] = 0.25, s.nodes.z[6] = 0.04, s.nodes.mass[6] = 0.5;
  s.nodes.x[7] = 1.5, s.nodes.y[7] = 0.75, s.nodes.z[7] = -0.04, s.nodes.mass[7] = 0.5;
  s.nodes.vx[6] = s.nodes.vx[7] = 1.0;
  ContactInterface& in = s.contact.interfaces[0];
  in.secondary_nodes = {6, 7};
  for (auto* v : {&in.node_gap, &in.gap_reduction, &in.gap_clearance, &in.node_tangent_sum, &in.node_reach_stiffness,
                  &in.node_entry_stiffness, &in.node_friction_viscosity, &in.node_element_stiffness})
    v->assign(2, 0.0);
  in.node_active = {1, 1}, in.node_touched = {0, 0}, in.node_impacted = {0, 0};
  in.friction = true, in.friction_law.fric = 0.2, in.friction_damping = 1e3, in.friction_form = 1;
  in.sum_pair_forces = true;
  s.contact.fx.assign(8, 0.0), s.contact.fy.assign(8, 0.0), s.contact.fz.assign(8, 0.0);
  s.run();
  const InterfaceResult& r = s.contact.results[0];
  const double f = penalty_force(1000.0, 0.1, 0.06), mu = 0.2;
  EXPECT_EQ(r.active_nodes, 2);
  EXPECT_NEAR(r.normal_force[2], 0.0, 1e-9 * f);
  EXPECT_NEAR(r.pair_normal_abs[2], 2.0 * f, 1e-9 * f);
  EXPECT_NEAR(r.pair_normal_norm, 2.0 * f, 1e-9 * f);
  EXPECT_NEAR(r.tangential_force[0], -2.0 * mu * f, 1e-9 * f);
  EXPECT_NEAR(r.pair_force_abs[0], 2.0 * mu * f, 1e-9 * f);
  EXPECT_NEAR(r.pair_force_abs[2], 2.0 * f, 1e-9 * f);
  EXPECT_NEAR(r.pair_force_norm, 2.0 * f * std::sqrt(1.0 + mu * mu), 1e-9 * f);
}

// The bucket sort finds exactly the pairs a brute-force test of every node against every grown segment box finds.
TEST(ContactSearch, BucketSortMatchesBruteForceOnRandomClouds) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 10.0), small(-0.5, 0.5);
  for (int trial = 0; trial < 5; ++trial) {
    NodalState nodes;
    const std::size_t secondary = 300, segments = 200;
    nodes.resize(secondary + 4 * segments);
    ContactInterface in;
    for (std::size_t k = 0; k < secondary; ++k) {
      nodes.x[k] = u(rng), nodes.y[k] = u(rng), nodes.z[k] = u(rng);
      in.secondary_nodes.push_back(static_cast<std::int32_t>(k));
    }
    for (std::size_t s = 0; s < segments; ++s) {
      const double cx = u(rng), cy = u(rng), cz = u(rng);
      std::array<std::int32_t, 4> seg{};
      for (int a = 0; a < 4; ++a) {
        const std::size_t k = secondary + 4 * s + static_cast<std::size_t>(a);
        nodes.x[k] = cx + small(rng), nodes.y[k] = cy + small(rng), nodes.z[k] = cz + small(rng);
        seg[static_cast<std::size_t>(a)] = static_cast<std::int32_t>(k);
      }
      in.segments.push_back(seg);
    }
    in.segment_active.assign(segments, 1), in.node_active.assign(secondary, 1);
    in.largest_gap = 0.2, in.margin = 0.3;
    sort_candidates(in, nodes);
    std::set<std::pair<int, int>> found, expected;
    for (std::size_t q = 0; q < in.candidate_node.size(); ++q) found.emplace(in.candidate_node[q], in.candidate_segment[q]);
    EXPECT_EQ(found.size(), in.candidate_node.size()) << "a pair was listed twice";
    const double reach = 0.5;
    for (std::size_t i = 0; i < secondary; ++i)
      for (std::size_t s = 0; s < segments; ++s) {
        bool inside = true;
        const double p[3] = {nodes.x[i], nodes.y[i], nodes.z[i]};
        const std::vector<double>* c[3] = {&nodes.x, &nodes.y, &nodes.z};
        for (int d = 0; d < 3; ++d) {
          double lo = 1e300, hi = -1e300;
          for (std::int32_t n : in.segments[s]) lo = std::min(lo, (*c[d])[static_cast<std::size_t>(n)]), hi = std::max(hi, (*c[d])[static_cast<std::size_t>(n)]);
          inside = inside && p[d] >= lo - reach && p[d] <= hi + reach;
        }
        if (inside) expected.emplace(static_cast<int>(i), static_cast<int>(s));
      }
    EXPECT_EQ(found, expected);
    EXPECT_GT(expected.size(), 10u);
  }
}

namespace {
// Independent reference: the Voronoi-region walk of Ericson ("Real-Time Collision Detection", 5.1.5) over the same
// four-triangle fan, with branches, one pair at a time.
void reference_on_triangle(const double p[3], const double a[3], const double b[3], const double c[3], double w[3]) {
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  for (int k = 0; k < 3; ++k) ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = p[k] - a[k], bp[k] = p[k] - b[k], cp[k] = p[k] - c[k];
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (d1 <= 0 && d2 <= 0) w[0] = 1, w[1] = 0, w[2] = 0;
  else if (d3 >= 0 && d4 <= d3) w[0] = 0, w[1] = 1, w[2] = 0;
  else if (vc <= 0 && d1 >= 0 && d3 <= 0) w[1] = d1 / (d1 - d3), w[0] = 1 - w[1], w[2] = 0;
  else if (d6 >= 0 && d5 <= d6) w[0] = 0, w[1] = 0, w[2] = 1;
  else if (vb <= 0 && d2 >= 0 && d6 <= 0) w[2] = d2 / (d2 - d6), w[0] = 1 - w[2], w[1] = 0;
  else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) w[2] = (d4 - d3) / ((d4 - d3) + (d5 - d6)), w[1] = 1 - w[2], w[0] = 0;
  else w[1] = vb / (va + vb + vc), w[2] = vc / (va + vb + vc), w[0] = 1 - w[1] - w[2];
}
double reference_distance(const double p[3], const double x[4][3]) {
  double centre[3], best = 1e300;
  for (int k = 0; k < 3; ++k) centre[k] = 0.25 * (x[0][k] + x[1][k] + x[2][k] + x[3][k]);
  for (int t = 0; t < 4; ++t) {
    double w[3], d2 = 0.0;
    reference_on_triangle(p, x[t], x[(t + 1) % 4], centre, w);
    for (int k = 0; k < 3; ++k) {
      const double e = p[k] - (w[0] * x[t][k] + w[1] * x[(t + 1) % 4][k] + w[2] * centre[k]);
      d2 += e * e;
    }
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}
}  // namespace

TEST(ContactKernels, VectorisedBatchMatchesTheRegionWalk) {
  // Random warped quadrilaterals and triangles (third node repeated), nodes above, beside and far from them: the
  // batch's distance equals the reference's, and its point is the weighted corners at that distance.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairBatch batch;
  double nodes[PairBatch::kSize][3], corners[PairBatch::kSize][4][3];
  for (int round = 0; round < 50; ++round) {
    for (int i = 0; i < PairBatch::kSize; ++i) {
      const double base[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int a = 0; a < 4; ++a) {
        corners[i][a][0] = base[a][0] + 0.2 * u(rng), corners[i][a][1] = base[a][1] + 0.2 * u(rng);
        corners[i][a][2] = 0.3 * u(rng);  // warped
      }
      if (i % 4 == 3)
        for (int k = 0; k < 3; ++k) corners[i][3][k] = corners[i][2][k];  // a triangle
      const double reach = i % 3 == 0 ? 0.2 : i % 3 == 1 ? 1.0 : 3.0;
      for (int k = 0; k < 3; ++k) nodes[i][k] = 0.5 + reach * u(rng);
      for (int k = 0; k < 3; ++k) {
        batch.node[k][i] = nodes[i][k];
        for (int a = 0; a < 4; ++a) batch.corner[a][k][i] = corners[i][a][k];
      }
    }
    closest_points(batch, PairBatch::kSize);
    for (int i = 0; i < PairBatch::kSize; ++i) {
      const double expected = reference_distance(nodes[i], corners[i]);
      EXPECT_NEAR(batch.distance[i], expected, 1e-12 * (1.0 + expected)) << round << " " << i;
      double d2 = 0.0, sum = 0.0;
      for (int k = 0; k < 3; ++k) {
        double q = 0.0;
        for (int a = 0; a < 4; ++a) q += batch.weight[a][i] * corners[i][a][k];
        EXPECT_NEAR(q, batch.point[k][i], 1e-12);
        d2 += (nodes[i][k] - q) * (nodes[i][k] - q);
      }
      for (int a = 0; a < 4; ++a) {
        sum += batch.weight[a][i];
        EXPECT_GE(batch.weight[a][i], -1e-12);
      }
      EXPECT_NEAR(std::sqrt(d2), batch.distance[i], 1e-12 * (1.0 + expected));
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
  }
}

}  // namespace test_contact_kernels
