// Time histories of NAME.h5 against the solver state they were written from (docs/output-format.md "/history/th",
// docs/verification.md "Time histories"): a shell strip stretched by an imposed velocity and a brick set ringing by
// an initial velocity, run with /TH/NODE, /TH/PART, /TH/SUBS, /TH/SHEL and /TH/BRIC; at every history row the file
// holds what the state says, and the parts sum to the model.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

#include "crumple/elements/shell4.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/output/history_reader.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_time_histories {
namespace {

constexpr double kRho = 7800.0, kE = 2.1e11, kNu = 0.3, kT = 0.001, kH = 0.01;
constexpr double kPull = 0.5;  // imposed velocity [m/s]: a power of two, so that x = 0.5 sum dt is 0.5 t exactly

std::string var(const std::string& name) { return name + std::string(10 - name.size(), ' '); }

// Strip of 2 x 1 shells on [-0.02, 0] x [0, 0.01] (part 1, nodes 1-6): its left edge clamped, its right edge (nodes
// 3 and 6, at x = 0) pulled at kPull. Brick 1 (part 2, nodes 101-108, the cube [0.1, 0.11] x [0, 0.01]^2): face
// x = 0.1 held, face x = 0.11 launched at 1 m/s, 5 g added at each of its nodes. Both parts in subset 5.
std::string starter() {
  Strip strip;
  strip.nx = 2, strip.length = 0.02, strip.width = kH;
  std::vector<NodeRow> bricks;
  long long id = 101;
  for (double z : {0.0, kH})
    for (auto [x, y] : {std::pair{0.0, 0.0}, std::pair{kH, 0.0}, std::pair{kH, kH}, std::pair{0.0, kH}})
      bricks.push_back({id++, 0.1 + x, y, z});
  std::string s = node_cards(strip.nodes(-0.02)) + node_cards(bricks) + shell_cards(1, strip.shells());
  s += "/BRICK/2\n" + I(1);
  for (long long n = 101; n <= 108; ++n) s += I(n);
  s += "\n/PART/1\nstrip\n" + I(1) + I(1) + I(5) + "\n/PART/2\nblock\n" + I(2) + I(1) + I(5) + "\n/SUBSET/5\nboth\n";
  s += shell_property(kT, 3, 0.0, 24) + "/PROP/SOLID/2\nsolid\n" + I(1) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  s += elastic_material(kRho, kE, kNu) + unit_function(1);
  s += node_group(1, strip.column(0)) + boundary_condition(1, "111 111", 1);
  s += node_group(2, strip.column(2)) + imposed_velocity(1, 1, "X", 2, kPull);
  s += node_group(3, {101, 104, 105, 108}) + boundary_condition(2, "111 000", 3);
  s += node_group(4, {102, 103, 106, 107}) + initial_velocity(1, 1.0, 0.0, 0.0, 4);
  // A lone brick launched at one face outruns its element step (its dilatational mode, whose frequency the element
  // step does not bound, rings on nodes of 1/8 of its mass; measured: it diverges within 10 cycles): its nodes
  // carry added mass, which also puts /ADMAS into the parts' masses.
  s += node_group(6, {101, 102, 103, 104, 105, 106, 107, 108}) + added_mass(1, 0.005, 6);
  auto th = [](const std::string& keyword, const std::string& variables, const std::string& objects) {
    return keyword + "\nhistory\n" + variables + "\n" + objects;
  };
  s += th("/TH/NODE/1", var("DEF") + var("A") + var("REACX") + var("REACY") + var("REACZ") + var("XYZ"),
          I(3) + I(0) + "\n" + I(1) + I(0) + "\n" + I(102) + I(0) + "\n");
  s += th("/TH/PART/2", var("DEF") + var("RKE"), I(1) + I(2) + "\n");
  s += th("/TH/SUBS/3", var("DEF"), I(5) + "\n");
  s += th("/TH/SHEL/4", var("DEF") + var("STRESS") + var("THIC"), I(1) + I(0) + "\n" + I(2) + I(0) + "\n");
  s += th("/TH/BRIC/5", var("DEF") + var("VOL"), I(1) + std::string(10, ' ') + "cube\n");
  return s;
}

// What the state held at one history row.
struct Snapshot {
  double time, internal, hourglass, kinetic;
  std::vector<double> x, y, z, vx, fx, mass;
  std::vector<point_real> sxx, syy, sxy;  // shells
  std::vector<double> thickness;
  std::array<double, 6> brick_stress;
  std::array<Vec3, 8> brick_nodes;
  double brick_volume0;
};

Snapshot snapshot(const Model& m, const SolverState& s) {
  const NodalState& n = s.nodes;
  Snapshot r{s.time, s.energy.internal, s.energy.hourglass, s.energy.kinetic_translational,
             n.x, n.y, n.z, n.vx, n.fx, n.mass, s.shells.sxx, s.shells.syy, s.shells.sxy, s.shells.thickness,
             {s.bricks.sxx[0], s.bricks.syy[0], s.bricks.szz[0], s.bricks.sxy[0], s.bricks.syz[0], s.bricks.szx[0]},
             {}, s.bricks.volume0[0]};
  const std::int32_t* nodes = m.elements[static_cast<int>(ElementKind::Brick8)].nodes_of(0);
  for (std::size_t a = 0; a < 8; ++a) {
    const auto k = static_cast<std::size_t>(nodes[a]);
    r.brick_nodes[a] = {n.x[k], n.y[k], n.z[k]};
  }
  return r;
}

// The columns of a results file by label.
struct Columns {
  std::vector<std::vector<double>> values;
  std::map<std::string, std::pair<std::size_t, std::size_t>> where;  // label -> series, column
  const HistoryFile& file;
  explicit Columns(const HistoryFile& f) : file(f) {
    for (std::size_t s = 0; s < f.series().size(); ++s) {
      values.push_back(f.values(s));
      for (std::size_t c = 0; c < f.series()[s].columns.size(); ++c) where[f.series()[s].columns[c].label] = {s, c};
    }
  }
  double operator()(const std::string& label, std::size_t row) const {
    const auto at = where.find(label);
    if (at == where.end()) {
      ADD_FAILURE() << "no column " << label;
      return 0.0;
    }
    const auto [s, c] = at->second;
    return values[s][row * file.series()[s].columns.size() + c];
  }
};

double relative(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

}  // namespace

TEST(TimeHistories, TheFileHoldsTheStateAtEveryRowAndThePartsSumToTheModel) {
  test::TempDir dir;
  dir.write("VERIF_0001.rad", "/RUN/VERIF/1\n1e-4\n/TFILE\n1e-5\n/PRINT/-100000\n");
  const auto path = dir.write("VERIF_0000.rad", test::begin_card("VERIF") + starter() + "/END\n");
  Model model = read_deck(path).model;
  std::vector<Snapshot> rows;
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  options.on_history_row = [&](const SolverState& s) { rows.push_back(snapshot(model, s)); };
  std::ostringstream console;
  ASSERT_EQ(run_simulation(model, options, console).status, RunStatus::Normal);

  const HistoryFile file(dir.path() / "VERIF.h5");
  ASSERT_EQ(file.rows(), rows.size());
  ASSERT_GE(rows.size(), 10u);
  const Columns h(file);
  const std::size_t clamped = node_index(model, 1), free = node_index(model, 102);
  double zeta[3], membrane[3], bending[3];
  through_thickness_rule(3, zeta, membrane, bending);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Snapshot& s = rows[r];
    SCOPED_TRACE("row " + std::to_string(r) + ", time " + std::to_string(s.time));
    EXPECT_EQ(h("time", r), s.time);
    // The pulled node: x = 0.5 t exactly (its x starts at 0 and grows by 0.5 dt a cycle, like the time by dt).
    EXPECT_EQ(h("NODE_1/3/DX", r), kPull * s.time);
    EXPECT_EQ(h("NODE_1/3/VX", r), kPull);
    if (r > 0) {
      EXPECT_EQ(h("NODE_1/3/AX", r), 0.0);  // after the first step, from rest
    }
    EXPECT_EQ(h("NODE_1/102/X", r), s.x[free]);
    EXPECT_EQ(h("NODE_1/102/DX", r), s.x[free] - model.nodes.x[free]);
    // The clamped node: the support takes the whole nodal force.
    EXPECT_EQ(h("NODE_1/1/DX", r), 0.0);
    EXPECT_LE(std::abs(h("NODE_1/1/REACX", r) + s.fx[clamped]), 1e-12 * std::abs(s.fx[clamped]) + 1e-300);
    // Shell 1: the membrane force of the state's three points.
    const double t = s.thickness[0];
    double n1 = 0.0, m1 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) n1 += membrane[k] * t * s.sxx[k], m1 += bending[k] * t * t * s.sxx[k];
    EXPECT_LE(relative(h("SHEL_4/1/F1", r), n1), 1e-12) << h("SHEL_4/1/F1", r) << " " << n1;
    EXPECT_NEAR(h("SHEL_4/1/M1", r), m1, 1e-12 * std::abs(n1) * t);
    EXPECT_EQ(h("SHEL_4/1/THIC", r), t);
    EXPECT_EQ(h("SHEL_4/2/OFF", r), 1.0);
    // The brick: its one point's stress, its current volume and density.
    EXPECT_EQ(h("BRIC_5/1/SX", r), s.brick_stress[0]);
    EXPECT_EQ(h("BRIC_5/1/SYZ", r), s.brick_stress[4]);
    const double volume = geometry::brick_volume(s.brick_nodes);
    EXPECT_EQ(h("BRIC_5/1/VOL", r), volume);
    EXPECT_EQ(h("BRIC_5/1/DENS", r), kRho * s.brick_volume0 / volume);
    // Parts: energies and mass sum to the model's; the subset of both parts is their sum.
    const double ie = h("PART_2/1/IE", r) + h("PART_2/2/IE", r), he = h("PART_2/1/HE", r) + h("PART_2/2/HE", r);
    const double ke = h("PART_2/1/KE", r) + h("PART_2/2/KE", r), mass = h("PART_2/1/MASS", r) + h("PART_2/2/MASS", r);
    double nodal_mass = 0.0;
    for (double m : s.mass) nodal_mass += m;
    EXPECT_LE(relative(ie, s.internal), 1e-12) << ie << " " << s.internal;
    EXPECT_LE(std::abs(he - s.hourglass), 1e-12 * std::abs(s.internal) + 1e-300) << he << " " << s.hourglass;
    EXPECT_LE(relative(ke, s.kinetic), 1e-12) << ke << " " << s.kinetic;
    EXPECT_LE(relative(mass, nodal_mass), 1e-14);
    EXPECT_LE(relative(h("SUBS_3/5/IE", r), ie), 1e-14);
    EXPECT_LE(relative(h("SUBS_3/5/KE", r), ke), 1e-14);
  }
  // Something happened, and stably: the strip carries tension and the brick rings.
  EXPECT_LT(std::abs(h("total", rows.size() - 1) - h("external_work", rows.size() - 1) - h("total", 0) +
                     h("external_work", 0)),
            0.01 * h("total", rows.size() - 1));
  EXPECT_GT(h("SHEL_4/1/F1", rows.size() - 1), 0.0);
  EXPECT_GT(h("PART_2/1/IE", rows.size() - 1), 0.0);
  EXPECT_NE(h("BRIC_5/1/SX", rows.size() - 1), 0.0);
}

}  // namespace crumple::verification::test_time_histories

namespace crumple::verification::test_time_histories {

// /TH/NODE DRX DRY DRZ (docs/output-format.md, "NODE", eq. TH-1): a node of a free strip turned about z by /IMPVEL ZZ
// at w = 2 rad/s (a drilling rotation, which no shell resists) has DRZ = w t at every row (the sum of w dt, the
// positions' steps); its other integrals and those of a node left alone stay 0.
TEST(TimeHistories, NodeRotationIsTheAngleOfAnImposedSpin) {
  constexpr double kSpin = 2.0;
  Strip strip;
  strip.nx = 2, strip.ny = 1, strip.length = 0.2, strip.width = 0.1;
  std::string s = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                  shell_property(0.002, 3, 0.0, 24) + elastic_material(kRho, kE, kNu) + unit_function(1);
  s += node_group(1, {3}) + imposed_velocity(1, 1, "ZZ", 1, kSpin);
  s += "/TH/NODE/1\nrotations\n" + var("DRX") + var("DRY") + var("DRZ") + var("VRZ") + "\n" + I(3) + I(0) + "\n" + I(1) +
       I(0) + "\n";
  test::TempDir dir;
  dir.write("VERIF_0001.rad", "/RUN/VERIF/1\n1e-3\n/TFILE\n1e-4\n/PRINT/-100000\n");
  const auto path = dir.write("VERIF_0000.rad", test::begin_card("VERIF") + s + "/END\n");
  Model model = read_deck(path).model;
  std::vector<double> times;
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  options.on_history_row = [&](const SolverState& state) { times.push_back(state.time); };
  std::ostringstream console;
  ASSERT_EQ(run_simulation(model, options, console).status, RunStatus::Normal);
  const HistoryFile file(dir.path() / "VERIF.h5");
  ASSERT_EQ(file.rows(), times.size());
  ASSERT_GE(times.size(), 10u);
  const Columns h(file);
  for (std::size_t r = 0; r < times.size(); ++r) {
    SCOPED_TRACE("row " + std::to_string(r));
    EXPECT_EQ(h("NODE_1/3/VRZ", r), kSpin);
    EXPECT_NEAR(h("NODE_1/3/DRZ", r), kSpin * times[r], 1e-12 * kSpin * times[r]);
    EXPECT_NEAR(h("NODE_1/3/DRX", r), 0.0, 1e-12 * kSpin * times[r]);
    EXPECT_NEAR(h("NODE_1/3/DRY", r), 0.0, 1e-12 * kSpin * times[r]);
    EXPECT_NEAR(h("NODE_1/1/DRZ", r), 0.0, 1e-12 * kSpin * times[r]);
  }
}

}  // namespace crumple::verification::test_time_histories
