// Sliding block with Coulomb friction through TYPE7 (docs/verification.md, "Contact").
//
// A one-shell block (0.05 m square, 2 mm steel) rests on a fixed plate under gravity g, its four nodes the
// secondary nodes, the plate's surface the main surface, Fric = 0.3. Launched along x at v0 = 1 m/s, it slides
// under the kinetic friction force mu N = mu m g: a constant deceleration mu g until it stops after
// v0^2 / (2 mu g). With Iform 1 the trial force is viscous (C_t V_t) and with Iform 2 incremental (K_t dx_t);
// both are capped by the cone, so while sliding both give mu N.
//
// Time step: the block is a single free element, whose breathing (in-plane dilatation) mode has the critical step
// L sqrt(1 - nu) / c0 = 0.877 of the plate-wave step L / c of docs/theory/time-step.md (T-1) at nu = 0.3: at the
// default scale 0.9 it is unstable and grows from round-off (docs/theory/time-step.md, "Isolated elements"). In
// a mesh the neighbours keep the highest mode below T-1; here /DT 0.7 keeps the lone element stable.
#include <array>
#include <cmath>
#include <string>

#include "contact_cards.hpp"
#include "crumple/contact/kernels.hpp"

namespace crumple::verification::test_contact_friction {
namespace {

constexpr double kMu = 0.3, kG = 9.81, kV0 = 1.0;

struct Sliding {
  double deceleration = 0.0, distance = 0.0, stop_time = -1.0;
  RunResult run;
};

constexpr double kThickness = 0.002, kBlock = 0.05, kRho = 7800.0;

Sliding slide(const Type7Options& o, double end_time) {
  constexpr double t = kThickness, gap = 0.001, block = kBlock;
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> plate, blocks;
  // Plate: 10 x 2 shells of 0.1 m, nodes 1..33, fixed.
  plate = shell_grid(10, 2, 0.1, 0.1, 0.0, 0.0, 0.0, 1, 1, nodes);
  // Block resting at its static penetration: a node's weight m g / 4 = 0.0957 N on K0 = E t / 2 = 2.1e8 N/m is
  // p = 4.6e-10 m (the penalty is linear at p << g); away from the plate's nodes.
  const double weight = 7800.0 * t * block * block / 4.0 * kG, k0 = 0.5 * 2.1e11 * t;
  const double z0 = gap - weight / k0, x0 = 0.125, y0 = 0.02;
  nodes.push_back({101, x0, y0, z0});
  nodes.push_back({102, x0 + block, y0, z0});
  nodes.push_back({103, x0 + block, y0 + block, z0});
  nodes.push_back({104, x0, y0 + block, z0});
  blocks.push_back({100, 101, 102, 103, 104});
  std::vector<long long> plate_nodes;
  for (int k = 1; k <= 33; ++k) plate_nodes.push_back(k);
  const std::string starter =
      node_cards(nodes) + shell_cards(1, blocks) + shell_cards(2, plate) + part_card(1) + part_card(2) +
      shell_property(t, 3, 0.0, 24) + elastic_material(7800.0, 2.1e11, 0.3) + node_group(1, {101, 102, 103, 104}) +
      node_group(2, plate_nodes) + boundary_condition(1, "111 111", 2) + initial_velocity(1, kV0, 0.0, 0.0, 1) +
      unit_function(1) + "/GRAV/1\ngravity\n" + I(1) + "         Z" + I(0) + I(0) + I(1) + I(0) + R(0.0) +
      R(-kG) + "\n" + surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  Sliding out;
  std::vector<double> time, velocity, position;
  test::TempDir dir;
  out.run = run_deck(dir, starter, end_time, 1e-3, [&](const Model& m, const SolverState& s) {
    double v = 0.0, x = 0.0;
    for (long long n : {101, 102, 103, 104}) v += 0.25 * s.nodes.vx[node_index(m, n)], x += 0.25 * s.nodes.x[node_index(m, n)];
    time.push_back(s.time), velocity.push_back(v), position.push_back(x);
  }, "/DT\n0.7 0\n");
  // Deceleration: the slope of v between 0.8 v0 and 0.2 v0; distance: where v first reaches 0.
  const double t1 = first_crossing(time, velocity, 0.8 * kV0), t2 = first_crossing(time, velocity, 0.2 * kV0);
  out.deceleration = 0.6 * kV0 / (t2 - t1);
  for (std::size_t k = 1; k < time.size(); ++k)
    if (velocity[k] <= 1e-3 * kV0) {
      out.distance = position[k] - (x0 + 0.5 * block);
      out.stop_time = first_crossing(time, velocity, 1e-3 * kV0);
      break;
    }
  return out;
}

Type7Options coulomb(int iform) {
  Type7Options o;
  o.gapmin = 0.001, o.fric = kMu, o.iform = iform;
  return o;
}

class SlidingBlock : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Iform, SlidingBlock, ::testing::Values(1, 2));

TEST_P(SlidingBlock, DeceleratesAtMuGAndStopsAtTheCoulombDistance) {
  const Sliding s = slide(coulomb(GetParam()), 1.3 * kV0 / (kMu * kG));
  ASSERT_EQ(s.run.summary.status, RunStatus::Normal) << s.run.summary.message;
  const double a = kMu * kG, d = kV0 * kV0 / (2.0 * a);
  EXPECT_NEAR(s.deceleration, a, 0.02 * a);
  EXPECT_NEAR(s.distance, d, 0.03 * d);
  std::printf("[sliding block Iform %d] cycles %lld  deceleration %.4f (mu g %.4f, %+.2f %%)  distance %.4f (%.4f, "
              "%+.2f %%)  friction work %.4g  energy error %.3f %%\n",
              GetParam(), s.run.summary.cycles, s.deceleration, a, 100 * (s.deceleration / a - 1), s.distance, d,
              100 * (s.distance / d - 1), s.run.summary.energy.contact, s.run.summary.energy.error_percent);
}

}  // namespace
}  // namespace crumple::verification::test_contact_friction

namespace crumple::verification::test_contact_friction {
namespace {

using contact::FrictionLaw;
using contact::friction_coefficient;

// Friction laws (eq. C-9a..c) and the filter (eq. C-9d) on the same block: the contact pressure is the block's
// weight over its area, p = rho t g = 153 Pa, and the law's coefficient follows the sliding speed. Reference: the
// block's equation of motion dv/dt = -g mu_f, with the filtered coefficient dmu_f/dt = omega (mu(p, v) - mu_f)
// (Ifiltr 2 and 3 are this first-order low-pass with omega = 2 pi / Xfreq and 2 pi Xfreq; without a filter
// mu_f = mu), integrated by RK4 with 1e5 steps.
struct LawCase {
  const char* name;
  Type7Options options;
  double omega;  // filter's angular frequency [1/s]; 0: no filter
};

struct Reference {
  double stop_time = -1.0, distance = 0.0;
};

Reference integrate(const LawCase& c) {
  FrictionLaw law{c.options.ifric, c.options.fric, {}};
  for (int k = 0; k < 6; ++k) law.c[k] = c.options.c[static_cast<std::size_t>(k)];
  const double p = kRho * kThickness * kG;
  auto rate = [&](const std::array<double, 3>& y) {  // y = (v, x, mu_f)
    const double mu = friction_coefficient(law, p, std::max(y[0], 0.0));
    return std::array<double, 3>{-kG * (c.omega > 0.0 ? y[2] : mu), y[0], c.omega > 0.0 ? c.omega * (mu - y[2]) : 0.0};
  };
  std::array<double, 3> y{kV0, 0.0, friction_coefficient(law, p, kV0)};
  const double h = 1e-5;
  Reference r;
  for (int step = 0; step < 200000; ++step) {
    auto add = [&](const std::array<double, 3>& a, const std::array<double, 3>& b, double f) {
      return std::array<double, 3>{a[0] + f * b[0], a[1] + f * b[1], a[2] + f * b[2]};
    };
    const auto k1 = rate(y), k2 = rate(add(y, k1, h / 2)), k3 = rate(add(y, k2, h / 2)), k4 = rate(add(y, k3, h));
    const auto next = add(y, {k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0], k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1],
                              k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]}, h / 6);
    if (next[0] <= 1e-3 * kV0) {  // the measured stop: v = 1e-3 v0, by linear interpolation
      const double f = (y[0] - 1e-3 * kV0) / (y[0] - next[0]);
      r.stop_time = h * (step + f), r.distance = y[1] + f * (next[1] - y[1]);
      return r;
    }
    y = next;
  }
  return r;
}

LawCase law_case(const char* name, int ifric, double fric, std::array<double, 6> c, int ifiltr = 0, double xfreq = 0.0) {
  LawCase l{name, coulomb(1), 0.0};
  l.options.ifric = ifric, l.options.fric = fric, l.options.c = c;
  l.options.ifiltr = ifiltr, l.options.xfreq = xfreq;
  l.omega = ifiltr == 2 ? 2.0 * kPi / xfreq : ifiltr == 3 ? 2.0 * kPi * xfreq : 0.0;
  return l;
}

class FrictionLaws : public ::testing::TestWithParam<LawCase> {};
INSTANTIATE_TEST_SUITE_P(
    Ifric, FrictionLaws,
    ::testing::Values(
        // 1: mu = 0.1 + 1e-3 p + 0.1 v = 0.253 + 0.1 v
        law_case("generalized_viscous", 1, 0.1, {1e-3, 0.1, 0.0, 0.0, 0.0, 0.0}),
        // 2: mu = 1e-3 p + 0.3 e^(-0.5 v) = 0.153 + 0.3 e^(-0.5 v)
        law_case("darmstad", 2, 0.0, {0.0, 0.0, 1e-3, 0.0, 0.3, -0.5}),
        // 3: mu_s 0.3, mu_d 0.2, mu_max 0.4, mu_min 0.1, Vcr1 0.2, Vcr2 0.6 m/s: every branch on the way to rest
        law_case("renard", 3, 0.0, {0.3, 0.2, 0.4, 0.1, 0.2, 0.6}),
        // the generalized viscous law through a low-pass filter of 1 Hz (Ifiltr 3) and of period 1 s (Ifiltr 2)
        law_case("viscous_filtered_frequency", 1, 0.1, {1e-3, 0.1, 0.0, 0.0, 0.0, 0.0}, 3, 1.0),
        law_case("viscous_filtered_period", 1, 0.1, {1e-3, 0.1, 0.0, 0.0, 0.0, 0.0}, 2, 1.0)),
    [](const ::testing::TestParamInfo<LawCase>& param) { return std::string(param.param.name); });

TEST_P(FrictionLaws, BlockStopsWhereItsEquationOfMotionSays) {
  const LawCase& c = GetParam();
  const Reference ref = integrate(c);
  ASSERT_GT(ref.stop_time, 0.0);
  const Sliding s = slide(c.options, 1.3 * ref.stop_time);
  ASSERT_EQ(s.run.summary.status, RunStatus::Normal) << s.run.summary.message;
  LawCase unfiltered = c;
  unfiltered.omega = 0.0;
  const Reference plain = integrate(unfiltered);
  std::printf("[friction law %s] cycles %lld  stop %.4f s (ref %.4f, %+.2f %%)  distance %.4f m (ref %.4f, %+.2f %%)"
              "  unfiltered ref %.4f m  energy error %.3f %%\n",
              c.name, s.run.summary.cycles, s.stop_time, ref.stop_time, 100 * (s.stop_time / ref.stop_time - 1),
              s.distance, ref.distance, 100 * (s.distance / ref.distance - 1), plain.distance,
              s.run.summary.energy.error_percent);
  EXPECT_NEAR(s.stop_time, ref.stop_time, 0.02 * ref.stop_time);
  EXPECT_NEAR(s.distance, ref.distance, 0.03 * ref.distance);
}

}  // namespace
}  // namespace crumple::verification::test_contact_friction
