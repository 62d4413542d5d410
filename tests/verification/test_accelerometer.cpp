// /ACCEL end to end (docs/output-format.md, "ACCEL"): a free strip pushed along x by /GRAV with the ramp
// a(t) = c t moves rigidly, every node with the acceleration a^n = c t^n of cycle n. NAME.h5's /TH/ACCEL dataset
// must hold, at every row (the end of cycle n, t = t^(n+1), step dt):
//   - the unfiltered accelerometer (Fcut 0): AX = c t^n, and WX = sum a^k dt^k = c dt^2 (1 + ... + n) =
//     c t^n t^(n+1) / 2 exactly (the first cycle is a half step from rest at t = 0, where a = 0);
//   - the filtered one (Fcut = fc): once the transient is gone (time constant 0.416 / fc), the ramp delayed by the
//     digital filter's group delay at zero frequency, AX = c (t^n - tau), tau = (2 sin(pi/8) + 2 sin(3 pi/8)) /
//     (2 pi fc) x / tan(x), x = pi fc dt (eq. ACC-2: the analog delay times the bilinear map's x / tan(x)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "crumple/output/history_reader.hpp"
#include "verification_support.hpp"

namespace crumple::verification::test_accelerometer {
namespace {

constexpr double kRamp = 1000.0;    // c [m/s^3]
constexpr double kCutoff = 1000.0;  // fc [Hz]

std::string var(const std::string& name) { return name + std::string(10 - name.size(), ' '); }

std::string starter() {
  Strip strip;
  strip.nx = 2, strip.ny = 1, strip.length = 0.2, strip.width = 0.1;
  std::string s = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                  shell_property(0.002, 3) + elastic_material(7800.0, 2.1e11, 0.3);
  s += function_card(1, {{0.0, 0.0}, {1.0, 1.0}}) + "/GRAV/1\nramp\n" + I(1) + "         X" + I(0) + I(0) + I(0) +
       I(0) + R(0.0) + R(kRamp) + "\n";
  s += "/ACCEL/1\nraw\n" + I(1) + I(0) + std::string(10, ' ') + R(0.0) + "\n";
  s += "/ACCEL/2\nfiltered\n" + I(3) + I(0) + std::string(10, ' ') + R(kCutoff) + "\n";
  s += "/TH/ACCEL/5\nsensors\n" + var("DEF") + var("W") + "\n" + I(1) + I(2) + "\n";
  s += "/TH/NODE/6\nnode\n" + var("VX") + var("AX") + "\n" + I(1) + I(0) + "\n";
  return s;
}

struct Columns {
  std::vector<std::vector<double>> values;
  std::map<std::string, std::pair<std::size_t, std::size_t>> where;
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

}  // namespace

TEST(Accelerometer, RawAndFilteredAccelerationOfARampAndItsIntegral) {
  test::TempDir dir;
  dir.write("VERIF_0001.rad", "/RUN/VERIF/1\n0.02\n/TFILE\n1e-3\n/PRINT/-100000\n");
  const auto path = dir.write("VERIF_0000.rad", test::begin_card("VERIF") + starter() + "/END\n");
  Deck deck = read_deck(path);
  for (const auto& w : deck.report.warnings) EXPECT_EQ(w.text().find("ACCEL"), std::string::npos) << w.text();
  struct Row {
    double time, dt;
  };
  std::vector<Row> rows;
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  options.on_history_row = [&](const SolverState& s) { rows.push_back({s.time, s.dt}); };
  std::ostringstream console;
  ASSERT_EQ(run_simulation(deck.model, options, console).status, RunStatus::Normal);

  const HistoryFile file(dir.path() / "VERIF.h5");
  ASSERT_EQ(file.rows(), rows.size());
  ASSERT_GE(rows.size(), 20u);
  const Columns h(file);
  const double dt = rows.front().dt;
  const double x = kPi * kCutoff * dt;
  const double analog_delay = (2.0 * std::sin(kPi / 8.0) + 2.0 * std::sin(3.0 * kPi / 8.0)) / (2.0 * kPi * kCutoff);
  const double tau = analog_delay * x / std::tan(x);
  std::size_t settled = 0;
  double worst_raw = 0.0, worst_filtered = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    // The step is that of the undeformed strip, to round-off; the last one is cut to land on the end time.
    if (std::abs(rows[r].dt - dt) > 1e-12 * dt) continue;
    const double t = rows[r].time, tn = t - dt;
    SCOPED_TRACE("row " + std::to_string(r) + ", time " + std::to_string(t));
    EXPECT_NEAR(h("ACCEL_5/1/AX", r), kRamp * tn, 1e-9 * kRamp * t);
    worst_raw = std::max(worst_raw, std::abs(h("ACCEL_5/1/AX", r) - kRamp * tn) / (kRamp * t));
    EXPECT_NEAR(h("ACCEL_5/1/AY", r), 0.0, 1e-9 * kRamp * t);
    EXPECT_NEAR(h("ACCEL_5/1/WX", r), 0.5 * kRamp * tn * t, 1e-9 * kRamp * t * t);
    EXPECT_NEAR(h("ACCEL_5/1/WX", r), h("NODE_6/1/VX", r), 1e-12 * kRamp * t * t);
    EXPECT_NEAR(h("ACCEL_5/1/AX", r), h("NODE_6/1/AX", r), 1e-12 * kRamp * t);
    EXPECT_NEAR(h("ACCEL_5/2/WX", r), h("ACCEL_5/1/WX", r), 1e-9 * kRamp * t * t);  // the strip moves rigidly
    if (tn < 12.0 / kCutoff) continue;
    ++settled;
    EXPECT_NEAR(h("ACCEL_5/2/AX", r), kRamp * (tn - tau), 1e-5 * kRamp * tau);
    worst_filtered = std::max(worst_filtered, std::abs(h("ACCEL_5/2/AX", r) - kRamp * (tn - tau)) / (kRamp * tau));
  }
  EXPECT_GE(settled, 5u);
  std::printf("[accelerometer] dt %.4g s, fc dt %.3g, delay %.6g s; raw AX %.2g (of c t), filtered AX %.2g (of c "
              "tau)\n", dt, kCutoff * dt, tau, worst_raw, worst_filtered);
}

}  // namespace crumple::verification::test_accelerometer
