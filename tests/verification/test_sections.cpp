// Cut sections (/SECT, /TH/SECTIO; docs/output-format.md "SECTIO", docs/verification.md "Cut sections").
//
// A section's force is the sum of the loads its elements take from the nodes of its cut (eq. SEC-1). Two checks
// with answers known without Crumple:
// - Free body. The nodes beyond the cut (set B) feel only their elements, all of them the section's, and the
//   external loads; each element's nodal loads sum to zero. So at every cycle, exactly (round-off),
//       F = sum_B m_j a_j^n - F_ext,B(t^n)                                                      (V-SEC-1)
//   with a^n = (v^(n+1/2) - v^(n-1/2)) / dt^n. A section that forgot a term, took the other sign, or read a
//   stale record fails it by the size of a nodal force. Tolerance 1e-9 of the load: the two sides differ by
//   round-off of sums of some 30 terms of the load's size, ~1e-15 relative.
// - Statics. A bar pulled by an end force F that rises slowly (a raised cosine over 5 periods of its first axial
//   mode: residual oscillation below 1 %) and then holds: averaged over the hold (5 periods, which averages the
//   residual down by another order or more), the section force is -F along the bar (the cut holds the far part
//   back) to 0.1 %, and the section's work is minus the strain energy of the near part, -F^2 a / (2 E A), to 0.5 %
//   (the energy is quadratic in the displacement, so its residual is larger). Measured: 1e-5 and 1.5e-4. A
//   cantilever strip with a tip force F: about the centre of a cut at x = a the moment is (L - a) F, about the
//   origin L F (its y component), to 1 % (ramp over 4 bending periods, average over 3; measured 5e-5); the other
//   side's section carries the opposite force and moment.
// The statics hold for any element (they are equilibrium of the free body), so the tolerances measure only the
// dynamics left by the ramps; the free body (V-SEC-1) runs with 4-node shells, 3-node shells and bricks.
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include "crumple/model/cut_sections.hpp"
#include "crumple/output/history_channels.hpp"
#include "crumple/output/history_reader.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_sections {
namespace {

constexpr double kE = 2.1e11, kRho = 7800.0, kNu = 0.3;

std::string var(const std::string& name) { return name + std::string(10 - name.size(), ' '); }

// /SECT: frame nodes, cut nodes (grnod), element groups (0: none), Iframe; blank file-name line.
std::string section_card(long long id, std::array<long long, 3> frame, long long cut, long long bricks,
                         long long shells, long long triangles, int iframe) {
  return "/SECT/" + std::to_string(id) + "\ncut " + std::to_string(id) + "\n" + I(frame[0]) + I(frame[1]) +
         I(frame[2]) + I(cut) + I(0) + I(0) + R(0.0) + R(0.0) + "\n" + std::string(100, ' ') + "\n" + I(bricks) +
         I(0) + I(shells) + I(0) + I(0) + I(0) + I(triangles) + I(0) + I(0) + I(iframe) + "\n";
}

std::string element_group(const std::string& keyword, long long id, const std::vector<long long>& elements) {
  std::string s = keyword + std::to_string(id) + "\nsection elements\n";
  for (std::size_t k = 0; k < elements.size(); ++k) {
    s += I(elements[k]);
    if (k % 10 == 9 || k + 1 == elements.size()) s += "\n";
  }
  return s;
}

std::string cload(long long id, long long function, const std::string& dir, long long group, double scale) {
  return "/CLOAD/" + std::to_string(id) + "\nload\n" + I(function) + std::string(10 - dir.size(), ' ') + dir + I(0) +
         I(0) + I(group) + std::string(10, ' ') + R(0.0) + R(scale) + "\n";
}

// f(t): a raised cosine from 0 to 1 over [0, rise], in 40 linear pieces, then 1. `at` is the same piecewise-linear
// function, for the load at t^n.
struct Ramp {
  double rise;
  std::vector<std::pair<double, double>> points() const {
    std::vector<std::pair<double, double>> p;
    for (int k = 0; k <= 40; ++k) p.push_back({rise * k / 40.0, 0.5 * (1.0 - std::cos(kPi * k / 40.0))});
    p.push_back({1e3, 1.0});
    return p;
  }
  double at(double t) const {
    const auto p = points();
    for (std::size_t k = 1; k < p.size(); ++k)
      if (t <= p[k].first)
        return p[k - 1].second + (t - p[k - 1].first) / (p[k].first - p[k - 1].first) * (p[k].second - p[k - 1].second);
    return 1.0;
  }
};

// One row's values of one section, by variable (FNX ... CZ, WORK).
using SectionRow = std::map<std::string, double>;

// The /TH/SECTIO values of every written section at a history row, computed as NAME.h5 gets them.
struct SectionProbe {
  std::optional<HistoryChannels> channels;
  std::map<long long, SectionRow> read(const Model& m, const SolverState& s) {
    if (!channels) channels.emplace(m);
    std::vector<std::vector<double>> values;
    channels->evaluate(s, VelocityChange{}, values);
    std::map<long long, SectionRow> out;
    for (std::size_t d = 0; d < channels->datasets().size(); ++d) {
      const HistoryDataset& set = channels->datasets()[d];
      if (set.kind != "SECTIO") continue;
      for (std::size_t c = 0; c < set.columns.size(); ++c)
        out[set.columns[c].object_id][set.columns[c].variable] = values[d][c];
    }
    return out;
  }
};

Vec3 force_of(const SectionRow& r) {  // the resultant: normal plus tangential part
  return {r.at("FNX") + r.at("FTX"), r.at("FNY") + r.at("FTY"), r.at("FNZ") + r.at("FTZ")};
}

// ---------------------------------------------------------------------------------------------------------------
// A bar of nx elements along x on [0, L], cross-section w x w (bricks) or width w (shells, two rows), held at
// x = 0 as a statically determinate support (no lateral restraint) and pulled along x at x = L by F f(t) shared by
// the end nodes. Section 1: the cut at x = a (node column ic), the elements beyond it, Iframe 1; section 2 the same
// about the origin (Iframe 3).
enum class Mesh { Shell4, Shell3, Brick8 };

struct Bar {
  Mesh mesh = Mesh::Shell4;
  int nx = 10, ic = 5;
  double length = 1.0, width = 0.1, thickness = 0.01;
  bool brick() const { return mesh == Mesh::Brick8; }
  int rows() const { return brick() ? 1 : 2; }  // elements across the width
  // Node (i, j, k): j across the width (0 .. rows), k through the height (bricks: 0, 1).
  long long node(int i, int j, int k = 0) const { return 1 + i + (nx + 1) * (j + (rows() + 1) * k); }
  double x(int i) const { return length * i / nx; }
  std::vector<long long> column(int i) const {
    std::vector<long long> v;
    for (int k = 0; k <= (brick() ? 1 : 0); ++k)
      for (int j = 0; j <= rows(); ++j) v.push_back(node(i, j, k));
    return v;
  }
  double area() const { return brick() ? width * width : width * thickness; }
  long long frame_node() const { return 1000; }  // shells: a free node off the strip's plane, in the cut's plane

  std::string cards(double force, const Ramp& ramp) const {
    std::vector<NodeRow> nodes;
    for (int k = 0; k <= (brick() ? 1 : 0); ++k)
      for (int j = 0; j <= rows(); ++j)
        for (int i = 0; i <= nx; ++i) nodes.push_back({node(i, j, k), x(i), width * j / rows(), width * k});
    if (!brick()) nodes.push_back({frame_node(), x(ic), 0.0, width});
    std::string s = node_cards(nodes);
    std::vector<long long> beyond;  // the section's elements: those of columns ic .. nx - 1
    long long id = 1;
    if (mesh == Mesh::Shell4) {
      s += "/SHELL/1\n";
      for (int j = 0; j < rows(); ++j)
        for (int i = 0; i < nx; ++i, ++id) {
          s += I(id) + I(node(i, j)) + I(node(i + 1, j)) + I(node(i + 1, j + 1)) + I(node(i, j + 1)) + "\n";
          if (i >= ic) beyond.push_back(id);
        }
    } else if (mesh == Mesh::Shell3) {
      s += "/SH3N/1\n";
      for (int j = 0; j < rows(); ++j)
        for (int i = 0; i < nx; ++i) {
          s += I(id) + I(node(i, j)) + I(node(i + 1, j)) + I(node(i + 1, j + 1)) + "\n";
          if (i >= ic) beyond.push_back(id);
          ++id;
          s += I(id) + I(node(i, j)) + I(node(i + 1, j + 1)) + I(node(i, j + 1)) + "\n";
          if (i >= ic) beyond.push_back(id);
          ++id;
        }
    } else {
      s += "/BRICK/1\n";
      for (int i = 0; i < nx; ++i, ++id) {
        s += I(id);
        for (int k : {0, 1})
          for (auto [ii, jj] : {std::pair{i, 0}, std::pair{i + 1, 0}, std::pair{i + 1, 1}, std::pair{i, 1}})
            s += I(node(ii, jj, k));
        s += "\n";
        if (i >= ic) beyond.push_back(id);
      }
    }
    s += part_card();
    s += brick() ? "/PROP/SOLID/1\nsolid\n" + I(1) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n"
                 : shell_property(thickness, 3, 0.0, 24);
    s += elastic_material(kRho, kE, kNu);
    // Support: x held on the face x = 0; y at its first node, z at its first node and one more (bricks) or on
    // every node (shells: a membrane problem).
    s += node_group(1, column(0)) + boundary_condition(1, "100 000", 1);
    s += node_group(2, {node(0, 0)}) + boundary_condition(2, "011 000", 2);
    if (brick()) s += node_group(3, {node(0, 1, 0)}) + boundary_condition(3, "001 000", 3);
    if (brick()) s += node_group(4, {node(0, 0, 1)}) + boundary_condition(4, "010 000", 4);
    if (!brick()) {
      std::vector<long long> all;
      for (const NodeRow& n : nodes) all.push_back(n.id);
      s += node_group(5, all) + boundary_condition(5, "001 000", 5);
    }
    const std::vector<long long> end = column(nx);
    s += function_card(1, ramp.points()) + node_group(6, end) +
         cload(1, 1, "X", 6, force / static_cast<double>(end.size()));
    s += node_group(10, column(ic));
    const std::string keyword = mesh == Mesh::Shell4   ? "/GRSHEL/SHEL/"
                                : mesh == Mesh::Shell3 ? "/GRSH3N/SH3N/"
                                                       : "/GRBRIC/BRIC/";
    s += element_group(keyword, 20, beyond);
    const std::array<long long, 3> frame{node(ic, 0), node(ic, rows()), brick() ? node(ic, 0, 1) : frame_node()};
    const long long b = brick() ? 20 : 0, sh = mesh == Mesh::Shell4 ? 20 : 0, tr = mesh == Mesh::Shell3 ? 20 : 0;
    s += section_card(1, frame, 10, b, sh, tr, 1) + section_card(2, frame, 10, b, sh, tr, 3);
    s += "/TH/SECTIO/9\nsections\n" + var("DEF") + var("CENTER") + var("GLOBAL") + var("LOCAL") + var("WORK") + "\n" +
         I(1) + I(2) + "\n";
    return s;
  }
};

struct PullResult {
  double worst_free_body = 0.0;  // largest |V-SEC-1 residual| / F over the rows
  double worst_moment_transfer = 0.0;
  double mean_fx = 0.0, mean_fn = 0.0, mean_work = 0.0;
  std::size_t rows = 0, hold_rows = 0;
};

PullResult pull(const Bar& bar, double force, double sample) {
  const double c = std::sqrt(kE / kRho);
  const double period = 4.0 * bar.length / c;  // first axial mode, fixed-free
  const Ramp ramp{5.0 * period};
  const double end_time = 10.0 * period;
  PullResult out;
  SectionProbe probe;
  std::vector<double> vx, vy, vz;  // v^(n-1/2) of the previous row
  double dt_before = 0.0;
  std::vector<std::size_t> beyond;
  test::TempDir dir;
  // A chain of cubic one-point bricks, one across, is unstable at the default /DT scale 0.9 (it inverts within 200
  // cycles at 0.8, with or without sections; 0.7 runs): the brick bar runs at 0.5.
  const std::string engine = bar.brick() ? "/DT\n0.5 0\n" : "";
  auto observe = [&](const Model& m, const SolverState& s) {
    const auto rows = probe.read(m, s);
    const SectionRow& r = rows.at(1);
    const NodalState& n = s.nodes;
    if (beyond.empty())
      for (std::size_t k = 0; k < m.nodes.size(); ++k)
        if (m.nodes.x[k] > bar.x(bar.ic) + 1e-9) beyond.push_back(k);
    if (!vx.empty()) {  // V-SEC-1 (the first cycle is a half step: skipped)
      const double dt = 0.5 * (dt_before + s.dt), t_n = s.time - s.dt;
      Vec3 inertia{0.0, 0.0, 0.0};
      for (std::size_t k : beyond)
        inertia = inertia + scaled(Vec3{n.vx[k] - vx[k], n.vy[k] - vy[k], n.vz[k] - vz[k]}, n.mass[k] / dt);
      const Vec3 expected = inertia - Vec3{force * ramp.at(t_n), 0.0, 0.0};
      out.worst_free_body = std::max(out.worst_free_body, norm(force_of(r) - expected) / force);
      // The moment about the origin is the moment about the centre plus C x F (eq. SEC-5).
      const SectionRow& o = rows.at(2);
      const Vec3 centre{r.at("CX"), r.at("CY"), r.at("CZ")}, f = force_of(r);
      const Vec3 transfer = Vec3{r.at("MX"), r.at("MY"), r.at("MZ")} + cross(centre, f) -
                            Vec3{o.at("MX"), o.at("MY"), o.at("MZ")};
      out.worst_moment_transfer = std::max(out.worst_moment_transfer, norm(transfer) / (force * bar.length));
    }
    vx = n.vx, vy = n.vy, vz = n.vz, dt_before = s.dt;
    ++out.rows;
    if (s.time > ramp.rise) {
      out.mean_fx += force_of(r).x, out.mean_fn += r.at("FNX"), out.mean_work += r.at("WORK");
      ++out.hold_rows;
    }
  };
  const RunResult run = run_deck(dir, bar.cards(force, ramp), end_time, sample, observe, engine);
  EXPECT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  if (out.hold_rows > 0) {
    const double k = static_cast<double>(out.hold_rows);
    out.mean_fx /= k, out.mean_fn /= k, out.mean_work /= k;
  }
  return out;
}

class PulledBar : public ::testing::TestWithParam<Mesh> {};
INSTANTIATE_TEST_SUITE_P(Kinds, PulledBar, ::testing::Values(Mesh::Shell4, Mesh::Shell3, Mesh::Brick8),
                         [](const testing::TestParamInfo<Mesh>& m) {
                           return std::string(m.param == Mesh::Shell4   ? "Shell4"
                                              : m.param == Mesh::Shell3 ? "Shell3"
                                                                        : "Brick8");
                         });

TEST_P(PulledBar, FreeBodyAtEveryCycleAndEndForceAtRest) {
  Bar bar;
  bar.mesh = GetParam();
  constexpr double kForce = 1000.0;
  // Rows at every cycle (the sample interval is below the step): V-SEC-1 cycle by cycle.
  const PullResult r = pull(bar, kForce, 1e-9);
  ASSERT_GT(r.rows, 100u);
  ASSERT_GT(r.hold_rows, 20u);
  EXPECT_LT(r.worst_free_body, 1e-9);
  EXPECT_LT(r.worst_moment_transfer, 1e-9);
  // At rest the cut holds the far part back with the whole end force.
  EXPECT_NEAR(r.mean_fx / -kForce, 1.0, 1e-3) << r.mean_fx;
  EXPECT_NEAR(r.mean_fn / -kForce, 1.0, 1e-3) << r.mean_fn;
  // The cut's work on the far part: minus the strain energy of the near part, -F^2 a / (2 E A) (uniaxial stress).
  const double strain_energy = kForce * kForce * bar.x(bar.ic) / (2.0 * kE * bar.area());
  EXPECT_NEAR(r.mean_work / -strain_energy, 1.0, 5e-3) << r.mean_work << " " << -strain_energy;
  std::printf("[section pull %d] rows %zu  free body %.2e  moment transfer %.2e  mean FX/F %.5f  FNX/F %.5f  "
              "WORK/(-U) %.5f\n",
              static_cast<int>(GetParam()), r.rows, r.worst_free_body, r.worst_moment_transfer, r.mean_fx / -kForce,
              r.mean_fn / -kForce, r.mean_work / -strain_energy);
}

// ---------------------------------------------------------------------------------------------------------------
// Cantilever strip (10 x 2 four-node shells, L = 1, b = 0.1, t = 0.01) clamped at x = 0, tip force F along z.
// Sections at the cut x = a = 0.4: 1 the tip side about the cut's centre (Iframe 1, the local frame: e1 = y,
// e2 = z, e3 = x), 2 the same in the global frame (Iframe 11), 3 about the origin (Iframe 13), 4 the clamped side
// about the centre (Iframe 11). The cut's nodes are on one line across the strip: the bending moment crosses it as
// the shells' nodal moments, so this also checks that they are in the sums. (One row of square elements, 10 x 1,
// with nu = 0 was unstable at the default /DT scale until the rotational inertia took the transverse-shear mode's
// bound, docs/theory/shell4.md eq. S-8a; the nu = 0 cases of tests/stability/test_thin_shells.cpp hold it.)
TEST(Sections, CantileverMomentIsForceTimesLeverArm) {
  constexpr double L = 1.0, b = 0.1, t = 0.01, a = 0.4;
  const double inertia = b * t * t * t / 12.0;
  const double tip = 1e-3;                                   // static tip deflection [m], 1e-3 of the length
  const double force = 3.0 * kE * inertia * tip / (L * L * L);  // F = 3 E I d / L^3
  const double f1 = 1.875104 * 1.875104 / (2.0 * kPi * L * L) * std::sqrt(kE * inertia / (kRho * b * t));
  const Ramp ramp{4.0 / f1};
  const double end_time = ramp.rise + 3.0 / f1;
  Strip strip;
  strip.nx = 10, strip.ny = 2, strip.length = L, strip.width = b;
  std::vector<NodeRow> nodes = strip.nodes();
  nodes.push_back({1000, a, 0.0, 0.1});
  std::vector<long long> tip_side, clamp_side;
  for (long long e = 1; e <= 20; ++e) ((e - 1) % 10 >= 4 ? tip_side : clamp_side).push_back(e);
  std::string s = node_cards(nodes) + shell_cards(1, strip.shells()) + part_card() + shell_property(t, 5, 0.0, 24) +
                  elastic_material(kRho, kE, 0.0) + node_group(1, strip.column(0)) +
                  boundary_condition(1, "111 111", 1);
  s += function_card(1, ramp.points()) + node_group(2, strip.column(10)) + cload(1, 1, "Z", 2, force / 3.0);
  s += node_group(10, strip.column(4)) + element_group("/GRSHEL/SHEL/", 20, tip_side) +
       element_group("/GRSHEL/SHEL/", 21, clamp_side);
  const std::array<long long, 3> frame{strip.node(4, 0), strip.node(4, 2), 1000};
  s += section_card(1, frame, 10, 0, 20, 0, 1) + section_card(2, frame, 10, 0, 20, 0, 11) +
       section_card(3, frame, 10, 0, 20, 0, 13) + section_card(4, frame, 10, 0, 21, 0, 11);
  s += "/TH/SECTIO/9\nsections\n" + var("DEF") + var("CENTER") + var("GLOBAL") + var("LOCAL") + "\n" + I(1) + I(2) +
       I(3) + I(4) + "\n";
  SectionProbe probe;
  std::map<long long, SectionRow> mean;
  std::size_t hold = 0;
  test::TempDir dir;
  const RunResult run = run_deck(dir, s, end_time, 1e-3, [&](const Model& m, const SolverState& st) {
    if (st.time <= ramp.rise) return;
    for (const auto& [id, row] : probe.read(m, st))
      for (const auto& [name, value] : row) mean[id][name] += value;
    ++hold;
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;
  ASSERT_GT(hold, 100u);
  for (auto& [id, row] : mean)
    for (auto& [name, value] : row) value /= static_cast<double>(hold);
  const double lever = (L - a) * force;
  // Tip side about the cut's centre: M = (L - a) F along y, the force -F along z.
  EXPECT_NEAR(mean[1]["M1"] / lever, 1.0, 0.01) << mean[1]["M1"];  // e1 = y
  EXPECT_NEAR(mean[2]["MY"] / lever, 1.0, 0.01) << mean[2]["MY"];
  EXPECT_NEAR(mean[2]["M2"] / lever, 1.0, 0.01);  // Iframe 11: the local components are the global ones
  EXPECT_NEAR(mean[2]["FNZ"] + mean[2]["FTZ"], -force, 0.01 * force);
  EXPECT_NEAR(mean[1]["F2"], -force, 0.01 * force);  // e2 = z
  EXPECT_LT(std::abs(mean[2]["MX"]), 0.01 * lever);
  // About the origin: M = L F along y and -(b / 2) F along x (the cut's centre is at y = b / 2).
  EXPECT_NEAR(mean[3]["MY"] / (L * force), 1.0, 0.01) << mean[3]["MY"];
  EXPECT_NEAR(mean[3]["MX"] / (-0.5 * b * force), 1.0, 0.01) << mean[3]["MX"];
  EXPECT_EQ(mean[3]["CX"], 0.0);
  EXPECT_NEAR(mean[2]["CX"], a, 1e-5);
  EXPECT_NEAR(mean[2]["CY"], 0.5 * b, 1e-9);
  // The clamped side: the opposite force and moment.
  EXPECT_NEAR(mean[4]["MY"] / -lever, 1.0, 0.01) << mean[4]["MY"];
  EXPECT_NEAR(mean[4]["FNZ"] + mean[4]["FTZ"], force, 0.01 * force);
  std::printf("[section cantilever] hold rows %zu  M/((L-a)F) %.5f  origin MY/(LF) %.5f  other side %.5f\n", hold,
              mean[2]["MY"] / lever, mean[3]["MY"] / (L * force), mean[4]["MY"] / -lever);
}

// ---------------------------------------------------------------------------------------------------------------
// The QA deck box_crush (read from the shared QA folder): a square tube of 4-node shells driven into a rigid wall by
// a rigid body. Its 8 sections cut the tube at x = 10 (all the same nodes and elements, Iframe 0-3 and 10-13). The
// histories must be in NAME.h5, labelled, finite; every section carries the same force, mostly normal to the cut;
// and the normal force follows the wall's: the same direction, and between 70 % and 100 % of it once the first
// impact has passed (the wall also stops the tube's front 10 mm and decelerates the added mass at the cut, which
// the section does not carry; measured: 0.87 to 0.90 after t = 0.02).
TEST(Sections, BoxCrushHistoriesFollowTheWallForce) {
  const std::filesystem::path deck = std::filesystem::path(CRUMPLE_QA_DIR) / "box_crush" / "BOX1BL_0000.rad";
  Model model = read_deck(deck).model;
  test::TempDir dir;
  SimulationOptions options;
  options.name = "BOX1BL";
  options.output_directory = dir.path();
  std::ostringstream console;
  ASSERT_EQ(run_simulation(model, options, console).status, RunStatus::Normal);
  const HistoryFile file(dir.path() / "BOX1BL.h5");
  const HistorySeries* sections = nullptr;
  const HistorySeries* wall = nullptr;
  std::size_t si = 0, wi = 0;
  for (std::size_t k = 0; k < file.series().size(); ++k) {
    if (file.series()[k].path == "/history/th/SECTIO_6") sections = &file.series()[k], si = k;
    if (file.series()[k].path == "/history/th/RWALL_4") wall = &file.series()[k], wi = k;
  }
  ASSERT_NE(sections, nullptr);
  ASSERT_NE(wall, nullptr);
  EXPECT_EQ(sections->kind, "SECTIO");
  EXPECT_EQ(sections->keyword, "/TH/SECTIO/6");
  ASSERT_EQ(sections->columns.size(), 8u * 9u);  // DEF: FNX FNY FNZ FTX FTY FTZ M1 M2 M3 of sections 1-8
  const char* def[] = {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "M1", "M2", "M3"};
  const char* titles[] = {"section_0", "section_1", "section_2", "section_3",
                          "section_10", "section_11", "section_12", "section_13"};
  for (std::size_t k = 0; k < sections->columns.size(); ++k) {
    const HistoryColumn& c = sections->columns[k];
    EXPECT_EQ(c.label, "SECTIO_6/" + std::to_string(k / 9 + 1) + "/" + def[k % 9]);
    EXPECT_EQ(c.object_title, titles[k / 9]);
    EXPECT_EQ(c.unit, k % 9 < 6 ? "F" : "F L");
  }
  const std::vector<double> v = file.values(si), w = file.values(wi), time = file.values(0);
  const std::size_t rows = file.rows(), nc = sections->columns.size(), nw = wall->columns.size();
  ASSERT_GT(rows, 50u);
  for (double x : v) ASSERT_TRUE(std::isfinite(x));
  double lowest = 1e300, highest = -1e300;
  for (std::size_t r = 0; r < rows; ++r) {
    const double* row = &v[r * nc];
    for (std::size_t s = 1; s < 8; ++s)  // the force does not depend on Iframe
      for (std::size_t c = 0; c < 6; ++c) EXPECT_EQ(row[9 * s + c], row[c]) << "row " << r << " section " << s + 1;
    // |M| about N1 is the same in the local (section 1) and the global frame (section 5).
    EXPECT_NEAR(std::hypot(row[6], row[7], row[8]), std::hypot(row[36 + 6], row[36 + 7], row[36 + 8]),
                1e-9 * (1.0 + std::hypot(row[6], row[7], row[8])));
    if (time[r] < 0.02) continue;
    const double wall_fn = w[r * nw];  // RWALL_4/1/FNX: the wall's normal is x
    const double fn = row[0];
    EXPECT_LT(std::hypot(row[3], row[4], row[5]), 0.1 * std::abs(fn)) << "row " << r;
    const double ratio = fn / wall_fn;
    lowest = std::min(lowest, ratio), highest = std::max(highest, ratio);
  }
  EXPECT_GT(lowest, 0.7);
  EXPECT_LT(highest, 1.0);
  std::printf("[section box_crush] rows %zu  FNX / wall FNX after t = 0.02: %.3f .. %.3f\n", rows, lowest, highest);
}

}  // namespace
}  // namespace crumple::verification::test_sections
