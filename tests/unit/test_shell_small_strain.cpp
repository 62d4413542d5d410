// The small-strain switch of Ismstr 2 (docs/theory/shell4.md, eq. S-16): shell_switch_to_small_strain freezes the
// element's current shape as its reference; from then on its strain rates, forces and critical step are those of
// that shape, whatever it becomes. Ismstr 1 (small strain from the start) and 4 (never switched) refuse it.
#include "crumple/core/geometry.hpp"
#include "shell4_element.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_shell_small_strain {

using namespace crumple;
using namespace crumple::test;

namespace {

constexpr double kPlateModulus = kE / (1.0 - kNu * kNu);

// Moves the nodes of a unit square to the height h (y scaled), keeping x.
void squash(Element& el, double h) {
  const double y[4] = {0.0, 0.0, h, h};
  for (std::size_t k = 0; k < 4; ++k) el.nodes.y[k] = y[k];
}

// One step of a uniform compression rate c along y on the current shape: v_y = c (y - y_centre).
GroupStepResult compress(Element& el, double c, double dt) {
  el.p.zeta = el.zeta, el.p.membrane_weight = el.wn, el.p.bending_weight = el.wb;
  const double centre = 0.25 * (el.nodes.y[0] + el.nodes.y[1] + el.nodes.y[2] + el.nodes.y[3]);
  for (std::size_t k = 0; k < 4; ++k) el.nodes.vy[k] = c * (el.nodes.y[k] - centre);
  return shell4_forces(el.table, el.group, el.p, el.nodes, el.state, dt);
}

// The switched element computes on the shape it had at the switch: squashed to height 0.5, switched, squashed
// further to 0.25, its strain rate is the nodal velocity difference over 0.5 (half the current rate) and its step
// that of the 1 x 0.5 shape (area / longest side = 0.5, against 0.25 for the current shape).
TEST(ShellSmallStrain, SwitchFreezesTheShapeOfTheSwitch) {
  const double c = -1.0, dt = 1e-6, wave_speed = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  for (const int ishell : {24, 12}) {
    Element el({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, 0.01, 1);
    if (ishell == 24) el.one_point(1), el.p.physical_hourglass = true;
    el.p.small_strain_switchable = true;  // Ismstr 2
    squash(el, 0.5);
    ASSERT_TRUE(shell_switch_to_small_strain(el.table, el.p, el.nodes, el.state, 0));
    EXPECT_EQ(el.state.small_strain[0], 1);
    EXPECT_FALSE(shell_switch_to_small_strain(el.table, el.p, el.nodes, el.state, 0)) << "switched twice";
    squash(el, 0.25);
    const GroupStepResult r = compress(el, c, dt);
    // Plane stress with e_xx = 0: sigma_yy = E / (1 - nu^2) e_yy, e_yy = c (0.25 / 0.5) dt.
    const double expected = kPlateModulus * c * 0.5 * dt;
    EXPECT_NEAR(el.state.syy[0], expected, 1e-9 * std::abs(expected)) << "Ishell " << ishell;
    // Ishell 24: the reference's QEPH length of the 1 x 0.5 shape (eq. T-1d) times dn's factor (T-1c) over the
    // bar speed; Ishell 12: area over the longest side over the plate speed.
    const double dn = el.p.numerical_damping, damping = std::sqrt(1.0 + dn * dn) - dn;
    const double step = ishell == 24 ? geometry::qeph_length({0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}) * damping /
                                           std::sqrt(kE / kRho)
                                     : 0.5 / wave_speed;
    EXPECT_NEAR(r.min_dt, step, 1e-12 * r.min_dt) << "Ishell " << ishell;
  }
}

// Without the switch the same element sees the current shape: rate c, step 0.25 / c_plate.
TEST(ShellSmallStrain, UnswitchedElementFollowsItsShape) {
  const double c = -1.0, dt = 1e-6, wave_speed = std::sqrt(kE / (kRho * (1.0 - kNu * kNu)));
  Element el({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, 0.01, 1);
  el.p.small_strain_switchable = true;
  squash(el, 0.25);
  const GroupStepResult r = compress(el, c, dt);
  EXPECT_NEAR(el.state.syy[0], kPlateModulus * c * dt, 1e-9 * kPlateModulus * dt);
  EXPECT_NEAR(r.min_dt, 0.25 / wave_speed, 1e-12 * r.min_dt);
}

// Ismstr 1 and 3 run on the initial shape already, Ismstr 4 never switches, a deleted element stays deleted.
TEST(ShellSmallStrain, OnlyIsmstr2ElementsSwitch) {
  Element el({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, 0.01, 1);
  el.p.small_strain_switchable = false;  // Ismstr 1, 3 or 4
  EXPECT_FALSE(shell_switch_to_small_strain(el.table, el.p, el.nodes, el.state, 0));
  EXPECT_EQ(el.state.small_strain[0], 0);
  el.p.small_strain_switchable = true;
  el.state.deleted[0] = 1;
  EXPECT_FALSE(shell_switch_to_small_strain(el.table, el.p, el.nodes, el.state, 0));
}

// The 3-node shell switches the same way (/DT/SH_3N/CST): a triangle squashed to half its height, switched, then
// squashed to a quarter, keeps the step and the gradients of the half-height shape.
TEST(ShellSmallStrain, TriangleSwitchFreezesItsShape) {
  ElementTable table;
  table.kind = ElementKind::Shell3, table.user_id = {1}, table.part = {0}, table.connectivity = {0, 1, 2};
  NodalState nodes;
  nodes.resize(3);
  nodes.x = {0.0, 1.0, 0.0}, nodes.y = {0.0, 0.0, 0.5};
  Element quad({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, 0.01, 1);  // parameters and state sizes
  ShellGroupParameters p = quad.p;
  p.fully_integrated = false, p.small_strain_switchable = true;
  p.zeta = quad.zeta, p.membrane_weight = quad.wn, p.bending_weight = quad.wb;
  ShellState state;
  state.resize_elements(1, 0.01);
  state.resize_points(1);
  state.initial_shape.assign(6, 0.0);
  ASSERT_TRUE(shell_switch_to_small_strain(table, p, nodes, state, 0));
  nodes.y[2] = 0.25;
  nodes.vy = {0.0, 0.0, -0.25};  // the apex moves down at 0.25: rate -0.5 on the frozen height 0.5, not -1
  const ElementGroup group{ElementKind::Shell3, 0, 0, 0, 0, 1};
  const GroupStepResult r = shell3_forces(table, group, p, nodes, state, 1e-6);
  const double wave_speed = std::sqrt(kE / kRho);  // the triangle's bar speed (eq. T-1a)
  EXPECT_NEAR(state.syy[0], kPlateModulus * -0.5 * 1e-6, 1e-9 * kPlateModulus * 0.5e-6);
  // Twice the frozen area over its longest side: 0.5 / sqrt(1.25).
  EXPECT_NEAR(r.min_dt, 0.5 / std::sqrt(1.25) / wave_speed, 1e-12 * r.min_dt);
}

}  // namespace

}  // namespace test_shell_small_strain
