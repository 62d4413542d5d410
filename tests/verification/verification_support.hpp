#pragma once
// Verification tests (docs/verification.md): decks generated card by card into a TempDir, a run helper that
// reads the deck, runs the solver without result files and hands the solver state to a callback at every
// time-history output time (SolverOptions::on_history_row), and a few numerical helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "crumple/deck/reader.hpp"
#include "crumple/output/run.hpp"
#include "crumple/solver/solver_state.hpp"
#include "deck_files.hpp"

namespace crumple::verification {

using test::I;

// A 20-column real field with as many significant digits as fit (up to 17, the round-trip precision), so that
// the deck carries the test's values exactly (test::R keeps 10 digits).
inline std::string R(double v) {
  char buffer[40];
  for (int digits = 17; digits > 6; --digits) {
    const int n = std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (n <= 20) return std::string(static_cast<std::size_t>(20 - n), ' ') + buffer;
  }
  ADD_FAILURE() << "no 20-column form for " << v;
  return std::string(20, ' ');
}

inline constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------------------------
// Starter cards (layouts: docs/cards/starter-model.md, docs/cards/loads-output-engine.md).

struct NodeRow {
  long long id;
  double x, y, z;
};

inline std::string node_cards(const std::vector<NodeRow>& nodes) {
  std::string s = "/NODE\n";
  for (const NodeRow& n : nodes) s += I(n.id) + R(n.x) + R(n.y) + R(n.z) + "\n";
  return s;
}

struct ShellRow {
  long long id, n1, n2, n3, n4;
};

inline std::string shell_cards(long long part, const std::vector<ShellRow>& shells) {
  std::string s = "/SHELL/" + std::to_string(part) + "\n";
  for (const ShellRow& e : shells) s += I(e.id) + I(e.n1) + I(e.n2) + I(e.n3) + I(e.n4) + "\n";
  return s;
}

// Part 1 with property 1 and material 1.
inline std::string part_card() { return "/PART/1\npart\n" + I(1) + I(1) + "\n"; }

// /PROP/SHELL/1: Belytschko-Tsay (Ishell 1) unless told, hourglass coefficients hm = hf = hr (0: default 0.01),
// N points, numerical damping dn (0: the formulation's default), small-strain flag Ismstr (0: default 2),
// plane-stress return Iplas (0: default 2, the radial return; 1 the iterative projection).
inline std::string shell_property(double thickness, int points, double hourglass = 0.0, int ishell = 1,
                                  double dn = 0.0, int ismstr = 0, int iplas = 0, double dm = 0.0) {
  return "/PROP/SHELL/1\nshell\n" + I(ishell) + I(ismstr) + I(0) + "\n" + R(hourglass) + R(hourglass) + R(hourglass) +
         (dn > 0.0 || dm > 0.0 ? R(dm) + R(dn) : std::string()) + "\n" + I(points) + I(0) + R(thickness) +
         (iplas != 0 ? R(0.0) + I(0) + I(0) + I(iplas) : std::string()) + "\n";
}

inline std::string elastic_material(double rho, double young, double nu) {
  return "/MAT/ELAST/1\nelastic\n" + R(rho) + "\n" + R(young) + R(nu) + "\n";
}

// Johnson-Cook without cap or failure; strain-rate effect c ln(rate / rate0) when c > 0, with the strain-rate
// filter of cut-off frequency f_cut (Fsmooth = 1) when f_cut > 0.
inline std::string johnson_cook_material(double rho, double young, double nu, double a, double b, double n,
                                         double c = 0.0, double rate0 = 0.0, double f_cut = 0.0) {
  std::string s = "/MAT/PLAS_JOHNS/1\njohnson-cook\n" + R(rho) + "\n" + R(young) + R(nu) + I(0) + "\n" + R(a) + R(b) +
                  R(n) + "\n";
  if (c > 0.0) s += R(c) + R(rate0) + I(1) + I(f_cut > 0.0 ? 1 : 0) + R(f_cut) + "\n";
  return s;
}

// /GRNOD/NODE: ten ids per line.
inline std::string node_group(long long id, const std::vector<long long>& nodes) {
  std::string s = "/GRNOD/NODE/" + std::to_string(id) + "\ngroup\n";
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    s += I(nodes[k]);
    if (k % 10 == 9 || k + 1 == nodes.size()) s += "\n";
  }
  return s;
}

inline std::string function_card(long long id, const std::vector<std::pair<double, double>>& points) {
  std::string s = "/FUNCT/" + std::to_string(id) + "\nfunction\n";
  for (const auto& [x, y] : points) s += R(x) + R(y) + "\n";
  return s;
}

// f(t) = 1 for all times of a run (Radioss extrapolates, Crumple too; two points bracket every run here).
inline std::string unit_function(long long id) { return function_card(id, {{0.0, 1.0}, {1e3, 1.0}}); }

// /IMPVEL: v(t) = scale * f(t) along dir ("X", "Y", "Z", or "XX", "YY", "ZZ" for rotations) on a node group,
// from t = 0 to t_stop (0: never stops). Beware: a zero scale means 1.
inline std::string imposed_velocity(long long id, long long function, const std::string& dir, long long group,
                                    double scale, double t_stop = 0.0) {
  return "/IMPVEL/" + std::to_string(id) + "\nimposed velocity\n" + I(function) + std::string(10 - dir.size(), ' ') +
         dir + I(0) + I(0) + I(group) + "\n" + R(0.0) + R(scale) + R(0.0) + R(t_stop) + "\n";
}

inline std::string initial_velocity(long long id, double vx, double vy, double vz, long long group) {
  return "/INIVEL/TRA/" + std::to_string(id) + "\ninitial velocity\n" + R(vx) + R(vy) + R(vz) + I(group) + "\n";
}

// /BCS with the codes written as in decks, e.g. "111 111" (translations, blank, rotations) in columns 4-10.
inline std::string boundary_condition(long long id, const std::string& code, long long group) {
  return "/BCS/" + std::to_string(id) + "\nbcs\n   " + code + I(0) + I(group) + "\n";
}

// /ADMAS type 0: `mass` added to each node of the group.
inline std::string added_mass(long long id, double mass, long long group) {
  return "/ADMAS/0/" + std::to_string(id) + "\nadded mass\n" + R(mass) + I(group) + "\n";
}

// ---------------------------------------------------------------------------------------------------------------
// Structured strip of nx x ny four-node shells on [0, length] x [0, width] at z = 0, nodes numbered row by row
// from 1 (node (i, j) has id 1 + i + j (nx + 1)), shells from 1.

struct Strip {
  int nx = 1, ny = 1;
  double length = 1.0, width = 1.0;
  long long node(int i, int j) const { return 1 + i + j * (nx + 1); }
  std::vector<NodeRow> nodes(double x0 = 0.0) const {
    std::vector<NodeRow> v;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) v.push_back({node(i, j), x0 + length * i / nx, width * j / ny, 0.0});
    return v;
  }
  std::vector<ShellRow> shells() const {
    std::vector<ShellRow> v;
    long long id = 1;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) v.push_back({id++, node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
    return v;
  }
  std::vector<long long> column(int i) const {  // the nodes at x = x0 + length i / nx
    std::vector<long long> v;
    for (int j = 0; j <= ny; ++j) v.push_back(node(i, j));
    return v;
  }
  std::vector<long long> all() const {
    std::vector<long long> v;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) v.push_back(node(i, j));
    return v;
  }
};

// ---------------------------------------------------------------------------------------------------------------
// Running a generated deck.

struct RunResult {
  Model model;
  RunSummary summary;
};

// Writes VERIF_0000.rad (/BEGIN + `starter` + /END) and VERIF_0001.rad (/RUN to end_time, /TFILE every
// `sample`), runs the solver without result files and calls `observer` at every time-history output time.
// A sample interval below the time step gives one call per cycle (the next output time is found in O(1)).
inline RunResult run_deck(const test::TempDir& dir, const std::string& starter, double end_time, double sample,
                          const std::function<void(const Model&, const SolverState&)>& observer = {},
                          const std::string& extra_engine = "", const std::function<void(Model&)>& edit = {},
                          int input_version = 2019) {
  std::ostringstream engine;
  engine.precision(17);
  engine << "/RUN/VERIF/1\n" << end_time << "\n/TFILE\n" << sample << "\n/PRINT/-100000\n" << extra_engine;
  dir.write("VERIF_0001.rad", engine.str());
  const auto path = dir.write("VERIF_0000.rad", test::begin_card("VERIF", input_version) + starter + "/END\n");
  RunResult result{read_deck(path).model, {}};
  if (edit) edit(result.model);
  SimulationOptions options;
  options.name = "VERIF";
  options.output_directory = dir.path();
  options.write_results = false;
  const Model& model = result.model;
  if (observer) options.on_history_row = [&](const SolverState& s) { observer(model, s); };
  std::ostringstream console;
  result.summary = run_simulation(result.model, options, console);
  return result;
}

// Dense index of a node from its deck id.
inline std::size_t node_index(const Model& m, long long id) {
  return static_cast<std::size_t>(m.index.nodes.at(id));
}

// Dense index of a 4-node shell from its deck id.
inline std::size_t shell_index(const Model& m, long long id) {
  return static_cast<std::size_t>(m.index.elements[static_cast<int>(ElementKind::Shell4)].at(id));
}

// Index of the first through-thickness point of a 4-node shell in ShellState.
inline std::size_t first_point(const Model& m, const SolverState& s, std::size_t element) {
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Shell4 || static_cast<std::int32_t>(element) < group.begin ||
        static_cast<std::int32_t>(element) >= group.end)
      continue;
    return s.shells.point_offset[g] +
           (element - static_cast<std::size_t>(group.begin)) * static_cast<std::size_t>(s.shells.points[g]);
  }
  ADD_FAILURE() << "element " << element << " is in no shell group";
  return 0;
}

// Time at which a sampled signal first crosses `level` (rising or falling), by linear interpolation; -1 if never.
inline double first_crossing(const std::vector<double>& t, const std::vector<double>& y, double level,
                             std::size_t from = 0) {
  for (std::size_t k = std::max<std::size_t>(from, 1); k < y.size(); ++k)
    if ((y[k - 1] - level) * (y[k] - level) <= 0.0 && y[k] != y[k - 1])
      return t[k - 1] + (level - y[k - 1]) / (y[k] - y[k - 1]) * (t[k] - t[k - 1]);
  return -1.0;
}

}  // namespace crumple::verification
