// The /TH datasets and their values (include/crumple/output/history_channels.hpp, docs/output-format.md
// "/history/th") on a small model read from a deck, with a hand-made solver state of known values.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <sstream>

#include "crumple/core/geometry.hpp"
#include "crumple/model/history_variables.hpp"
#include "crumple/output/history_channels.hpp"
#include "crumple/solver/accelerometers.hpp"
#include "crumple/solver/node_rotations.hpp"
#include "crumple/state/element_status.hpp"
#include "crumple/solver/solver.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_history_channels {

using namespace crumple;
using test::blank;
using test::I;
using test::R;

namespace {

std::string vec(double x, double y, double z) { return R(x) + R(y) + R(z) + "\n"; }
std::string var(const std::string& name) { return name + blank(10 - static_cast<int>(name.size())); }
std::string th(const std::string& keyword, const std::string& variables, const std::string& objects) {
  return keyword + "\ngroup title\n" + variables + "\n" + objects;
}

// Two shells of the plate in parts 1 and 2 (nodes 2 and 5 shared), subset 9 of both; a brick (part 3, nodes 7-14) of
// side 0.01; a rigid body 7 (main node 15, node 16) of mass 3; a rigid wall under the plate; an interface on it;
// accelerometers 4 (node 5, unfiltered) and 6 (node 7, Fcut 100).
std::string model_cards() {
  std::string s = "/NODE\n";
  const double xs[3] = {0.0, 0.01, 0.02};
  long long id = 1;
  for (double y : {0.0, 0.01})
    for (double x : xs) s += I(id++) + vec(x, y, 0.0);
  for (int k = 0; k < 2; ++k)
    for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{0.01, 0.0}, std::pair{0.01, 0.01}, std::pair{0.0, 0.01}})
      s += I(id++) + R(0.1 + x) + R(y) + R(0.01 * k) + "\n";
  s += I(15) + vec(0.3, 0.0, 0.0) + I(16) + vec(0.3, 0.01, 0.0);
  s += "/SHELL/1\n" + I(1) + I(1) + I(2) + I(5) + I(4) + "\n/SHELL/2\n" + I(2) + I(2) + I(3) + I(6) + I(5) + "\n";
  s += "/BRICK/3\n" + I(1);
  for (long long n = 7; n <= 14; ++n) s += I(n);
  s += "\n/PART/1\nleft\n" + I(1) + I(1) + I(9) + "\n/PART/2\nright\n" + I(1) + I(1) + I(9) + "\n";
  s += "/PART/3\nblock\n" + I(2) + I(1) + "\n/SUBSET/9\nplate\n";
  s += "/PROP/SHELL/1\nshell\n" + I(24) + I(0) + I(0) + "\n" + R(0.0) + "\n" + I(3) + I(0) + R(0.001) + "\n";
  s += "/PROP/SOLID/2\nsolid\n" + I(1) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  s += "/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n";
  s += "/GRNOD/NODE/10\nplate\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + "\n";
  s += "/GRNOD/NODE/14\nbody\n" + I(16) + "\n/SURF/PART/20\nsurface\n" + I(1) + "\n";
  s += "/RWALL/PLANE/1\nfloor\n" + I(0) + I(0) + I(10) + I(0) + "\n" + vec(0, 0, 0) + vec(0, 0, -1) + vec(0, 0, 0);
  s += "/RBODY/7\nsled\n" + I(15) + I(0) + I(0) + I(0) + R(3.0) + I(14) + I(0) + I(0) + I(0) + "\n" + vec(0, 0, 0) +
       vec(0, 0, 0) + I(0) + I(0) + "\n";
  s += "/INTER/TYPE7/5\ncontact\n" + I(10) + I(20) + "\n\n\n\n" + "       000\n\n";
  s += "/ACCEL/4\nsensor\n" + I(5) + "\n/ACCEL/6\nblock sensor\n" + I(7) + I(0) + blank(10) + R(100.0) + "\n";
  return s;
}

std::string requests() {
  return th("/TH/NODE/1", var("DEF") + var("A") + var("VR") + var("AR") + var("REACX") + var("REACXX") + var("XYZ"),
            I(2) + I(0) + blank(20) + "shared\n" + I(7) + I(0) + "\n" + I(15) + I(0) + "\n") +
         th("/TH/PART/2", var("DEF") + var("XCG") + var("YCG") + var("ZCG") + var("RKE"), I(1) + I(2) + I(3) + "\n") +
         th("/TH/SUBS/3", var("DEF"), I(9) + "\n") +
         th("/TH/SHEL/4", var("STRESS") + var("PLAS") + var("THIC") + var("OFF") + var("EPSD"),
            I(1) + I(0) + "\n" + I(2) + I(0) + "\n") +
         th("/TH/BRIC/5", var("DEF") + var("VOL"), I(1) + blank(10) + "cube\n") +
         th("/TH/RWALL/6", var("DEF"), I(1) + "\n") + th("/TH/RBODY/7", var("DEF"), I(7) + "\n") +
         th("/TH/INTER/8", var("DEF") + var("CE_ELAST") + var("CE_FRIC") + var("CE_DAMP") + var("|FN|") + var("|F|"),
            I(5) + "\n");
}

struct Fixture {
  test::TempDir dir;
  Deck deck;
  SolverState state;
  explicit Fixture(const std::string& cards = requests())
      : deck(read_deck(dir.write("T_0000.rad", test::begin_card() + model_cards() + cards + "/END\n"))) {
    std::vector<std::string> notes;
    state = initial_state(deck.model, notes);
  }
  const Model& model() const { return deck.model; }
  std::size_t node(long long id) const { return static_cast<std::size_t>(model().index.nodes.at(id)); }
};

// The values of dataset `name`, by column label.
struct Row {
  const std::vector<HistoryDataset>* datasets;
  std::vector<std::vector<double>> values;
  double operator()(const std::string& label) const {
    for (std::size_t d = 0; d < datasets->size(); ++d)
      for (std::size_t c = 0; c < (*datasets)[d].columns.size(); ++c)
        if ((*datasets)[d].columns[c].label == label) return values[d].at(c);
    ADD_FAILURE() << "no column " << label;
    return 0.0;
  }
};

Row evaluate(const HistoryChannels& channels, const SolverState& s, const VelocityChange& change = {}) {
  Row row{&channels.datasets(), {}};
  channels.evaluate(s, change, row.values);
  return row;
}

std::array<double, 9> rotation(const std::array<double, 3>& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
          t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}

}  // namespace

TEST(HistoryChannels, OneDatasetPerRequestWithLabelledColumnsObjectByObject) {
  Fixture f;
  const HistoryChannels channels(f.model());
  const auto& d = channels.datasets();
  ASSERT_EQ(d.size(), 8u);
  EXPECT_EQ(d[0].name, "NODE_1");
  EXPECT_EQ(d[0].kind, "NODE");
  EXPECT_EQ(d[0].keyword, "/TH/NODE/1");
  EXPECT_EQ(d[0].title, "group title");
  // DEF A VR AR REACX REACXX XYZ: 6 + 3 + 3 + 3 + 1 + 1 + 3 variables for each of 3 nodes.
  ASSERT_EQ(d[0].columns.size(), 3u * 20u);
  const HistoryColumn& first = d[0].columns[0];
  EXPECT_EQ(first.object_id, 2);
  EXPECT_EQ(first.object_title, "shared");
  EXPECT_EQ(first.variable, "DX");
  EXPECT_EQ(first.unit, "L");
  EXPECT_EQ(first.label, "NODE_1/2/DX");
  EXPECT_EQ(d[0].columns[20].label, "NODE_1/7/DX");
  EXPECT_EQ(d[0].columns[19].label, "NODE_1/2/Z");
  EXPECT_EQ(d[1].columns[0].object_title, "left");
  EXPECT_EQ(d[1].columns[5].variable, "MASS");
  EXPECT_EQ(d[1].columns[5].unit, "M");
  EXPECT_EQ(d[3].name, "SHEL_4");
  EXPECT_EQ(d[3].columns.size(), 2u * 13u);  // STRESS 8, PLAS 2, THIC, OFF, EPSD
  EXPECT_EQ(d[3].columns[3].unit, "F/L");
  EXPECT_EQ(d[3].columns[5].unit, "F");
  EXPECT_EQ(d[4].columns[0].object_title, "cube");
  EXPECT_EQ(d[6].columns[0].object_title, "sled");
  for (const HistoryDataset& set : d)
    for (const HistoryColumn& c : set.columns) EXPECT_EQ(c.si_scale, 1.0) << c.label;  // kg, m, s
}

// Every variable the tables mark as written has a value: a request for all the names of every kind builds.
TEST(HistoryChannels, EveryWrittenVariableIsEvaluated) {
  std::string cards;
  const std::pair<const char*, std::string> kinds[] = {
      {"/TH/NODE/1", I(1) + I(0) + "\n"},       {"/TH/PART/2", I(1) + "\n"}, {"/TH/SUBS/3", I(9) + "\n"},
      {"/TH/SHEL/4", I(1) + I(0) + "\n"},       {"/TH/BRIC/5", I(1) + "\n"}, {"/TH/RWALL/6", I(1) + "\n"},
      {"/TH/RBODY/7", I(7) + "\n"},             {"/TH/INTER/8", I(5) + "\n"}, {"/TH/ACCEL/9", I(4) + "\n"}};
  const HistoryObject objects[] = {HistoryObject::Node,  HistoryObject::Part,      HistoryObject::Subset,
                                   HistoryObject::Shell, HistoryObject::Brick,     HistoryObject::RigidWall,
                                   HistoryObject::RigidBody, HistoryObject::Interface, HistoryObject::Accelerometer};
  constexpr std::size_t kKinds = std::size(objects);
  std::vector<std::size_t> expected;
  for (std::size_t k = 0; k < kKinds; ++k) {
    std::string variables;
    std::size_t written = 0, on_line = 0;
    for (const HistoryVariable& v : history_kind(objects[k]).variables) {
      variables += var(std::string(v.name)) + (++on_line % 10 == 0 ? "\n" : "");
      written += v.written ? 1 : 0;
    }
    cards += kinds[k].first + std::string("\nall\n") + variables + (on_line % 10 == 0 ? "" : "\n") + kinds[k].second;
    expected.push_back(written);
  }
  Fixture f(cards);
  const HistoryChannels channels(f.model());
  ASSERT_EQ(channels.datasets().size(), kKinds);
  for (std::size_t k = 0; k < kKinds; ++k)
    EXPECT_EQ(channels.datasets()[k].columns.size(), expected[k]) << kinds[k].first;
  const Row row = evaluate(channels, f.state);
  for (std::size_t k = 0; k < kKinds; ++k) EXPECT_EQ(row.values[k].size(), expected[k]);
}

// Displacement from the deck's position, velocity, the acceleration and the kinematic conditions' reaction from
// the cycle's velocity update.
TEST(HistoryChannels, NodeValuesFromTheStateAndTheVelocityUpdate) {
  Fixture f;
  SolverState& s = f.state;
  NodalState& n = s.nodes;
  const std::size_t k = f.node(2), b = f.node(7);
  n.x[k] += 1e-3, n.y[k] -= 2e-3, n.z[k] += 3e-3;
  n.vx[k] = 1.0, n.vy[k] = 2.0, n.vz[k] = 3.0, n.wx[k] = 0.1, n.wy[k] = 0.2, n.wz[k] = 0.3;
  std::array<std::vector<double>, 6> before, free;
  for (std::size_t d = 0; d < 6; ++d) before[d].assign(n.size(), 0.25 * static_cast<double>(d)), free[d].assign(n.size(), 0.5);
  VelocityChange change;
  for (std::size_t d = 0; d < 6; ++d) change.before[d] = &before[d], change.free[d] = &free[d];
  change.dt = 1e-6;
  const HistoryChannels channels(f.model());
  const Row row = evaluate(channels, s, change);
  const Model& m = f.model();
  EXPECT_EQ(row("NODE_1/2/DX"), n.x[k] - m.nodes.x[k]);
  EXPECT_EQ(row("NODE_1/2/DY"), n.y[k] - m.nodes.y[k]);
  EXPECT_NEAR(row("NODE_1/2/DZ"), 3e-3, 1e-15);
  EXPECT_EQ(row("NODE_1/2/X"), n.x[k]);
  EXPECT_EQ(row("NODE_1/2/VY"), 2.0);
  EXPECT_EQ(row("NODE_1/2/VRZ"), 0.3);
  EXPECT_DOUBLE_EQ(row("NODE_1/2/AX"), (1.0 - 0.0) / 1e-6);
  EXPECT_DOUBLE_EQ(row("NODE_1/2/AZ"), (3.0 - 0.5) / 1e-6);
  EXPECT_DOUBLE_EQ(row("NODE_1/2/ARY"), (0.2 - 1.0) / 1e-6);
  ASSERT_GT(n.mass[k], 0.0);
  ASSERT_GT(n.inertia[k], 0.0);
  EXPECT_DOUBLE_EQ(row("NODE_1/2/REACX"), n.mass[k] * (1.0 - 0.5) / 1e-6);
  EXPECT_DOUBLE_EQ(row("NODE_1/2/REACXX"), n.inertia[k] * (0.1 - 0.5) / 1e-6);
  EXPECT_EQ(row("NODE_1/7/REACXX"), 0.0);  // a brick node has no rotational inertia
  EXPECT_DOUBLE_EQ(row("NODE_1/7/REACX"), n.mass[b] * (n.vx[b] - 0.5) / 1e-6);
  // A rigid body's node moves with its body: no nodal reaction.
  EXPECT_TRUE(std::isnan(row("NODE_1/15/REACX")));
  // Without the velocity update there is no acceleration.
  EXPECT_TRUE(std::isnan(evaluate(channels, s)("NODE_1/2/AX")));
}

// Element energies by the element's part; the nodes' mass, momentum and kinetic energy by the elements' lumped-mass
// shares: the sums over all parts are the model's.
TEST(HistoryChannels, PartValuesSplitSharedNodesAndSumToTheModel) {
  Fixture f;
  SolverState& s = f.state;
  NodalState& n = s.nodes;
  s.shells.internal_energy = {1.5, 2.5}, s.shells.hourglass_energy = {0.25, 0.5};
  s.bricks.internal_energy = {4.0}, s.bricks.hourglass_energy = {1.0};
  double kinetic = 0.0, rotational = 0.0, mass = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    n.vx[k] = 1.0 + 0.1 * static_cast<double>(k), n.vy[k] = -0.5, n.wz[k] = 2.0;
    const long long id = f.model().nodes.user_id[k];
    if (id == 15 || id == 16) continue;  // the rigid body's nodes carry no element
    kinetic += 0.5 * n.mass[k] * (n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k]);
    rotational += 0.5 * n.inertia[k] * 4.0;
    mass += n.mass[k];
  }
  const HistoryChannels channels(f.model());
  const Row row = evaluate(channels, s);
  EXPECT_EQ(row("PART_2/1/IE"), 1.5);
  EXPECT_EQ(row("PART_2/2/HE"), 0.5);
  EXPECT_EQ(row("PART_2/3/IE"), 4.0);
  EXPECT_EQ(row("PART_2/3/HE"), 1.0);
  // The two shells are equal: the shared nodes 2 and 5 are half in each part.
  const auto m = [&](long long id) { return n.mass[f.node(id)]; };
  const auto v = [&](long long id) { return n.vx[f.node(id)]; };
  const double left = m(1) + m(4) + 0.5 * (m(2) + m(5));
  EXPECT_NEAR(row("PART_2/1/MASS"), left, 1e-15 * left);
  EXPECT_NEAR(row("PART_2/1/XMOM"), m(1) * v(1) + m(4) * v(4) + 0.5 * (m(2) * v(2) + m(5) * v(5)), 1e-15);
  EXPECT_NEAR(row("PART_2/1/YMOM"), -0.5 * left, 1e-15);
  EXPECT_NEAR(row("PART_2/1/XCG"), (0.5 * (m(2) + m(5)) * 0.01) / left, 1e-15);
  EXPECT_NEAR(row("PART_2/1/YCG"), (m(4) + 0.5 * m(5)) * 0.01 / left, 1e-15);
  EXPECT_NEAR(row("PART_2/3/XCG"), 0.105, 1e-15);
  EXPECT_NEAR(row("PART_2/3/ZCG"), 0.005, 1e-15);
  double ke = 0.0, rke = 0.0, total_mass = 0.0;
  for (const char* p : {"1", "2", "3"}) {
    ke += row(std::string("PART_2/") + p + "/KE"), rke += row(std::string("PART_2/") + p + "/RKE");
    total_mass += row(std::string("PART_2/") + p + "/MASS");
  }
  EXPECT_NEAR(ke, kinetic, 1e-14 * kinetic);
  EXPECT_NEAR(rke, rotational, 1e-14 * rotational);
  EXPECT_NEAR(total_mass, mass, 1e-14 * mass);
  // Subset 9 is parts 1 and 2.
  EXPECT_EQ(row("SUBS_3/9/IE"), 4.0);
  EXPECT_EQ(row("SUBS_3/9/HE"), 0.75);
  EXPECT_NEAR(row("SUBS_3/9/KE"), row("PART_2/1/KE") + row("PART_2/2/KE"), 1e-15);
  EXPECT_NEAR(row("SUBS_3/9/MASS"), row("PART_2/1/MASS") + row("PART_2/2/MASS"), 1e-18);
}

// Linear stresses through the thickness, s = s0 + s1 zeta at the three points of Ishell 24: N = t s0 and
// M = t^2 s1 / 12 exactly (the rule integrates linear stresses exactly).
TEST(HistoryChannels, ShellResultantsFromKnownStresses) {
  Fixture f;
  SolverState& s = f.state;
  ShellState& sh = s.shells;
  const Model& m = f.model();
  const std::size_t e = static_cast<std::size_t>(m.index.elements[0].at(1));
  const double t = 0.0009, zeta[3] = {-0.5, 0.0, 0.5};
  const double s0[3] = {100e6, -50e6, 10e6}, s1[3] = {60e6, 30e6, -12e6};
  std::size_t first = 0;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g)
    if (m.element_groups[g].kind == ElementKind::Shell4 && m.element_groups[g].begin <= static_cast<int>(e) &&
        static_cast<int>(e) < m.element_groups[g].end)
      first = sh.point_offset[g] + (e - static_cast<std::size_t>(m.element_groups[g].begin)) * 3;
  for (std::size_t k = 0; k < 3; ++k) {
    sh.sxx[first + k] = s0[0] + s1[0] * zeta[k];
    sh.syy[first + k] = s0[1] + s1[1] * zeta[k];
    sh.sxy[first + k] = s0[2] + s1[2] * zeta[k];
    sh.eps_p[first + k] = 0.01 * static_cast<double>(k + 1);
    sh.eps_rate[first + k] = static_cast<double>(k + 1);
  }
  sh.thickness[e] = t, sh.qx[e] = 7.0, sh.qy[e] = -3.0;
  sh.deleted[1 - e] = kElementDeleted;
  const HistoryChannels channels(m);
  const Row row = evaluate(channels, s);
  const char* force[3] = {"F1", "F2", "F12"};
  const char* moment[3] = {"M1", "M2", "M12"};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(row(std::string("SHEL_4/1/") + force[c]), t * s0[c], 1e-12 * std::abs(t * s0[c])) << force[c];
    EXPECT_NEAR(row(std::string("SHEL_4/1/") + moment[c]), t * t * s1[c] / 12.0, 1e-12 * std::abs(t * t * s1[c]))
        << moment[c];
  }
  EXPECT_EQ(row("SHEL_4/1/Q1"), 7.0);
  EXPECT_EQ(row("SHEL_4/1/Q2"), -3.0);
  EXPECT_EQ(row("SHEL_4/1/EMIN"), 0.01);  // lower surface
  EXPECT_EQ(row("SHEL_4/1/EMAX"), 0.03);  // upper surface
  EXPECT_DOUBLE_EQ(row("SHEL_4/1/EPSD"), 2.0);
  EXPECT_EQ(row("SHEL_4/1/THIC"), t);
  EXPECT_EQ(row("SHEL_4/1/OFF"), 1.0);
  EXPECT_EQ(row("SHEL_4/2/OFF"), 0.0);
}

TEST(HistoryChannels, BrickWallBodyAndInterfaceValues) {
  Fixture f;
  SolverState& s = f.state;
  const Model& m = f.model();
  BrickState& b = s.bricks;
  b.sxx = {1.0}, b.syy = {2.0}, b.szz = {3.0}, b.sxy = {4.0}, b.syz = {5.0}, b.szx = {6.0}, b.eps_p = {0.05};
  b.internal_energy = {4.0};
  for (long long id = 7; id <= 14; ++id) {  // stretched by 1.25 along x from x = 0.1
    const std::size_t k = f.node(id);
    s.nodes.x[k] = 0.1 + 1.25 * (s.nodes.x[k] - 0.1);
  }
  s.walls.at(0).force = {1.0, 2.0, 3.0}, s.walls.at(0).normal_force = {0.0, 0.0, 3.0};
  RigidBodyState& body = s.bodies.at(0);
  body.rotation = rotation({0.0, 0.0, 1.0}, 0.3);
  const std::size_t main = static_cast<std::size_t>(body.main_node);
  s.nodes.fx[main] = 5.0, s.nodes.mz[main] = -2.0;
  InterfaceResult& r = s.contact.results.at(0);
  r.normal_force = {0.0, 0.0, 9.0}, r.tangential_force = {1.0, 0.0, 0.0};
  r.elastic_energy = 0.5, r.friction_work = 0.25, r.damping_work = 0.125;
  r.pair_normal_abs = {1.5, 0.0, 11.0}, r.pair_normal_norm = 12.0, r.pair_force_abs = {2.5, 0.5, 11.0}, r.pair_force_norm = 13.0;
  const HistoryChannels channels(m);
  Row row = evaluate(channels, s);
  EXPECT_EQ(row("BRIC_5/1/SX"), 1.0);
  EXPECT_EQ(row("BRIC_5/1/SXZ"), 6.0);
  EXPECT_EQ(row("BRIC_5/1/PLAS"), 0.05);
  EXPECT_EQ(row("BRIC_5/1/IE"), 4.0);
  EXPECT_EQ(row("BRIC_5/1/OFF"), 1.0);
  EXPECT_NEAR(row("BRIC_5/1/VOL"), 1.25e-6, 1e-20);
  EXPECT_NEAR(row("BRIC_5/1/DENS"), 7800.0 / 1.25, 1e-10);
  EXPECT_EQ(row("RWALL_6/1/FNZ"), 3.0);
  EXPECT_EQ(row("RWALL_6/1/FTX"), 1.0);
  EXPECT_EQ(row("RWALL_6/1/FTY"), 2.0);
  EXPECT_EQ(row("RWALL_6/1/FTZ"), 0.0);
  EXPECT_EQ(row("RBODY_7/7/FX"), 5.0);
  EXPECT_EQ(row("RBODY_7/7/MZ"), -2.0);
  EXPECT_NEAR(row("RBODY_7/7/RZ"), 0.3, 1e-15);
  EXPECT_NEAR(row("RBODY_7/7/RX"), 0.0, 1e-15);
  EXPECT_EQ(row("INTER_8/5/FNZ"), 9.0);
  EXPECT_EQ(row("INTER_8/5/FTX"), 1.0);
  EXPECT_EQ(row("INTER_8/5/CE_ELAST"), 0.5);
  EXPECT_EQ(row("INTER_8/5/CE_FRIC"), 0.25);
  EXPECT_EQ(row("INTER_8/5/CE_DAMP"), 0.125);
  EXPECT_EQ(row("INTER_8/5/|FNX|"), 1.5);
  EXPECT_EQ(row("INTER_8/5/|FNZ|"), 11.0);
  EXPECT_EQ(row("INTER_8/5/||FN||"), 12.0);
  EXPECT_EQ(row("INTER_8/5/|FY|"), 0.5);
  EXPECT_EQ(row("INTER_8/5/||F||"), 13.0);
  EXPECT_TRUE(s.contact.interfaces.at(0).sum_pair_forces);  // asked by /TH/INTER/8: the pass sums them
  // The rotation vector of a large turn about a slanted axis, and of a half turn.
  const double a = 1.0 / std::sqrt(2.0);
  body.rotation = rotation({a, a, 0.0}, 3.0);
  row = evaluate(channels, s);
  EXPECT_NEAR(row("RBODY_7/7/RX"), 3.0 * a, 1e-12);
  EXPECT_NEAR(row("RBODY_7/7/RY"), 3.0 * a, 1e-12);
  body.rotation = rotation({0.0, 1.0, 0.0}, 3.14159265358979323846);
  row = evaluate(channels, s);
  EXPECT_NEAR(row("RBODY_7/7/RY"), 3.14159265358979323846, 1e-7);
  EXPECT_NEAR(row("RBODY_7/7/RX"), 0.0, 1e-7);
}

// /TH/ACCEL: after one cycle's velocity update, the raw acceleration (v - before) / dt of an unfiltered accelerometer
// and its integral, and the filter's first sample b0 b0' a (fc h = 1/4: docs/output-format.md, eq. ACC-2) for the
// filtered one, in the card's order of objects, with their units and titles.
TEST(HistoryChannels, AccelerometerValuesAfterAVelocityUpdate) {
  Fixture f(requests() + th("/TH/ACCEL/9", var("DEF") + var("W"), I(6) + I(4) + "\n"));
  SolverState& s = f.state;
  NodalState& n = s.nodes;
  std::vector<double> bx = n.vx, by = n.vy, bz = n.vz;
  const std::size_t k5 = f.node(5), k7 = f.node(7);
  n.vx[k5] = 0.5, n.vy[k5] = -0.25, n.vz[k7] = 2.0;
  const double dt = 2.5e-3;  // 100 Hz x 2.5 ms = 1/4
  update_accelerometers(f.model().accelerometers, n, {&bx, &by, &bz}, dt, s.skew_axes, s.histories);
  const HistoryChannels channels(f.model());
  const HistoryDataset& d = channels.datasets().back();
  EXPECT_EQ(d.name, "ACCEL_9");
  EXPECT_EQ(d.kind, "ACCEL");
  ASSERT_EQ(d.columns.size(), 12u);
  EXPECT_EQ(d.columns[0].label, "ACCEL_9/6/AX");
  EXPECT_EQ(d.columns[0].object_title, "block sensor");
  EXPECT_EQ(d.columns[0].unit, "L/T^2");
  EXPECT_EQ(d.columns[3].label, "ACCEL_9/6/WX");
  EXPECT_EQ(d.columns[3].unit, "L/T");
  EXPECT_EQ(d.columns[6].label, "ACCEL_9/4/AX");
  const Row row = evaluate(channels, s);
  EXPECT_DOUBLE_EQ(row("ACCEL_9/4/AX"), 0.5 / dt);
  EXPECT_DOUBLE_EQ(row("ACCEL_9/4/AY"), -0.25 / dt);
  EXPECT_EQ(row("ACCEL_9/4/AZ"), 0.0);
  EXPECT_DOUBLE_EQ(row("ACCEL_9/4/WX"), 0.5);
  EXPECT_DOUBLE_EQ(row("ACCEL_9/4/WY"), -0.25);
  EXPECT_NEAR(row("ACCEL_9/6/AZ"), 0.09398085143379448 * 2.0 / dt, 1e-12 * 2.0 / dt);
  EXPECT_EQ(row("ACCEL_9/6/AX"), 0.0);
  EXPECT_DOUBLE_EQ(row("ACCEL_9/6/WZ"), 2.0);
}

// /TH/NODE DRX DRY DRZ: the cycle integrates the angular velocity of the nodes a request asks them of, and only
// theirs: two steps with w = (0.1, 0.2, 0.3) for dt = 1e-3 then w = (-0.5, 0, 1) for dt = 2e-3 give
// DRX = 1e-4 - 1e-3 = -9e-4, DRY = 2e-4, DRZ = 3e-4 + 2e-3 = 2.3e-3 (hand values).
TEST(HistoryChannels, NodeRotationIsTheIntegralOfTheAngularVelocity) {
  Fixture f(requests() + th("/TH/NODE/9", var("DRX") + var("DRY") + var("DRZ"), I(5) + I(0) + "\n" + I(2) + I(0) + "\n"));
  SolverState& s = f.state;
  NodalState& n = s.nodes;
  const std::size_t k = f.node(2), other = f.node(5);
  ASSERT_EQ(s.histories.rotation_nodes.size(), 2u);  // nodes 2 and 5, and not the nodes of /TH/NODE/1 without DR
  n.wx[k] = 0.1, n.wy[k] = 0.2, n.wz[k] = 0.3, n.wz[other] = 7.0;
  n.wx[f.node(7)] = 9.0;  // a node no request asks DR of: not integrated
  integrate_node_rotations(n, 1e-3, s.histories);
  n.wx[k] = -0.5, n.wy[k] = 0.0, n.wz[k] = 1.0;
  integrate_node_rotations(n, 2e-3, s.histories);
  const HistoryChannels channels(f.model());
  const Row row = evaluate(channels, s);
  EXPECT_NEAR(row("NODE_9/2/DRX"), -9e-4, 1e-18);
  EXPECT_NEAR(row("NODE_9/2/DRY"), 2e-4, 1e-18);
  EXPECT_NEAR(row("NODE_9/2/DRZ"), 2.3e-3, 1e-18);
  EXPECT_NEAR(row("NODE_9/5/DRZ"), 7.0 * 3e-3, 1e-15);
  EXPECT_EQ(row("NODE_9/5/DRX"), 0.0);
  EXPECT_EQ(channels.datasets().back().columns[0].unit, "-");
  EXPECT_EQ(channels.datasets().back().columns[0].label, "NODE_9/5/DRX");
}

// /TH/SECTIO (docs/output-format.md, "SECTIO", eqs. SEC-1 to SEC-5) from hand-made loads: the cut is nodes 2 and 5
// (x = 0.01), the section's element shell 2 (nodes 2 3 6 5: slots 0 and 3 on the cut); the frame N1 = 2, N2 = 5,
// N3 = 7 has e1 = y, e2 = x, e3 = -z. The run records the loads of shell 2's group only.
TEST(HistoryChannels, SectionValuesFromKnownLoads) {
  auto sect = [](int id, int iframe) {
    return "/SECT/" + std::to_string(id) + "\ncut\n" + I(2) + I(5) + I(7) + I(11) + "\n" + blank(100) + "\n" + I(0) +
           I(0) + I(6) + I(0) + I(0) + I(0) + I(0) + I(0) + I(0) + I(iframe) + "\n";
  };
  const std::string cards = "/GRNOD/NODE/11\ncut\n" + I(2) + I(5) + "\n/GRSHEL/SHEL/6\nright\n" + I(2) + "\n" +
                            sect(1, 0) + sect(2, 2) + sect(3, 12) + sect(4, 3) +
                            th("/TH/SECTIO/9", var("DEF") + var("CENTER") + var("GLOBAL") + var("LOCAL") + var("WORK"),
                               I(1) + I(2) + I(3) + I(4) + "\n");
  Fixture f(cards);
  const Model& m = f.model();
  SolverState& s = f.state;
  const auto shell2 = static_cast<std::size_t>(m.index.elements[0].at(2));
  for (const ElementGroup& g : m.element_groups)  // only shell 2's group records
    EXPECT_EQ(s.shells.records.on(g.begin), g.kind == ElementKind::Shell4 && g.begin <= static_cast<std::int32_t>(shell2) &&
                                                static_cast<std::int32_t>(shell2) < g.end);
  ASSERT_TRUE(s.shells.records.covers(shell2));
  const double first[6] = {1, 2, 3, 0.1, 0.2, 0.3}, last[6] = {4, 5, 6, 0.4, 0.5, 0.6};
  std::copy(first, first + 6, s.shells.records.load_at(shell2, 0));
  std::copy(last, last + 6, s.shells.records.load_at(shell2, 3));
  std::fill(s.shells.records.load_at(shell2, 1), s.shells.records.load_at(shell2, 1) + 6, 1e3);  // not on the cut
  ASSERT_EQ(s.shells.section_work.size(), 4 * m.elements[0].size());
  s.shells.section_work[4 * shell2] = 2.5, s.shells.section_work[4 * shell2 + 3] = 1.5;
  s.shells.section_work[4 * shell2 + 1] = 100.0;
  s.nodes.mass[f.node(2)] = 1.0, s.nodes.mass[f.node(5)] = 3.0;
  const HistoryChannels channels(m);
  const Row r = evaluate(channels, s);
  auto expect = [&](int section, const std::string& names, const std::vector<double>& values) {
    std::istringstream words(names);
    std::string name;
    for (double v : values) {
      words >> name;
      EXPECT_NEAR(r("SECTIO_9/" + std::to_string(section) + "/" + name), v, 1e-12) << section << " " << name;
    }
  };
  for (int k = 1; k <= 4; ++k) {
    expect(k, "FNX FNY FNZ FTX FTY FTZ WORK", {0, 0, 9, 5, 7, 0, 4.0});  // F = (5, 7, 9), e3 = -z
  }
  // About N1 (x2): M = sum m + (x5 - x2) x f5 = (0.56, 0.7, 0.86); local axes e1 = y, e2 = x, e3 = -z.
  expect(1, "MX MY MZ M1 M2 M3 F1 F2 F3 CX CY CZ", {0.56, 0.7, 0.86, 0.7, 0.56, -0.86, 7, 5, -9, 0.01, 0, 0});
  // About the centre of gravity of the cut's nodes (masses 1 and 3): (0.01, 0.0075, 0).
  expect(2, "MX MY MZ M1 M2 M3 CX CY CZ", {0.4925, 0.7, 0.8975, 0.7, 0.4925, -0.8975, 0.01, 0.0075, 0});
  expect(3, "MX MY MZ M1 M2 M3 F1 F2 F3", {0.4925, 0.7, 0.8975, 0.4925, 0.7, 0.8975, 5, 7, 9});  // global axes
  // About the origin: sum m + x2 x f2 + x5 x f5 = (0.56, 0.61, 0.93).
  expect(4, "MX MY MZ CX CY CZ", {0.56, 0.61, 0.93, 0, 0, 0});
}

}  // namespace test_history_channels
