#pragma once
// Deck cards of the contact verification scenes: /INTER/TYPE7, /SURF/PART, second shell parts and properties.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "crumple/contact/kernels.hpp"
#include "verification_support.hpp"

namespace crumple::verification {

struct Type7Options {
  double gapmin = 0.0, stfac = 0.0, fric = 0.0, viss = 0.0, visf = 0.0, dtmin = 0.0;
  int istf = 0, igap = 0, inacti = 0, iform = 0, idel = 0;
  std::string ibc = "000";  // IBC flags x y z
  int ifric = 0, ifiltr = 0;
  double xfreq = 0.0;
  long long sensor = 0;  // sens_ID
  std::array<double, 6> c{};  // C1..C6 of the friction law
};

// /INTER/TYPE7/id: secondary node group, main surface, the fields of Type7Options, everything else default.
inline std::string type7_card(long long id, long long group, long long surface, const Type7Options& o) {
  const std::string blank10(10, ' ');
  std::string s = "/INTER/TYPE7/" + std::to_string(id) + "\ncontact\n";
  s += I(group) + I(surface) + I(o.istf) + I(0) + I(o.igap) + blank10 + I(0) + I(o.idel) + I(0) + I(0) + "\n";
  s += R(0.0) + R(0.0) + R(0.0) + "\n";
  s += R(0.0) + R(0.0) + R(0.0) + R(o.dtmin) + I(0) + I(0) + "\n";
  s += R(o.stfac) + R(o.fric) + R(o.gapmin) + R(0.0) + R(0.0) + "\n";
  s += "       " + o.ibc + std::string(20, ' ') + I(o.inacti) + R(o.viss) + R(o.visf) + R(0.0) + "\n";
  s += I(o.ifric) + I(o.ifiltr) + R(o.xfreq) + I(o.iform) + I(o.sensor) + I(0) + R(0.0) + I(0) + "\n";
  if (o.ifric > 0) s += R(o.c[0]) + R(o.c[1]) + R(o.c[2]) + R(o.c[3]) + R(o.c[4]) + "\n";
  if (o.ifric > 1) s += R(o.c[5]) + "\n";
  return s;
}

// A flat grid of nx x ny shells of sides hx, hy with its corner at (x0, y0, z): nodes first_node + i + (nx+1) j
// appended to `nodes`, shells numbered from first_shell returned.
inline std::vector<ShellRow> shell_grid(int nx, int ny, double hx, double hy, double x0, double y0, double z,
                                        long long first_node, long long first_shell, std::vector<NodeRow>& nodes) {
  auto id = [&](int i, int j) { return first_node + i + (nx + 1LL) * j; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) nodes.push_back({id(i, j), x0 + hx * i, y0 + hy * j, z});
  std::vector<ShellRow> shells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      shells.push_back({first_shell + i + static_cast<long long>(nx) * j, id(i, j), id(i + 1, j), id(i + 1, j + 1),
                        id(i, j + 1)});
  return shells;
}

inline std::string surface_of_part(long long id, long long part) {
  return "/SURF/PART/" + std::to_string(id) + "\nsurface\n" + I(part) + "\n";
}

// /PART/id with property and material 1.
inline std::string part_card(long long id) { return "/PART/" + std::to_string(id) + "\npart\n" + I(1) + I(1) + "\n"; }

constexpr double kPlateThickness = 0.002;

struct ImpactResult {
  RunResult run;
  double worst_momentum = 0.0, max_ratio = 0.0, smallest_dt = 1e300;
  // Largest step taken over the kinematic bound 0.5 (g - p) / (dp/dt) = 0.5 d / (dp/dt) of the closing candidate
  // pairs in the state the pass saw (x^n, v^(n-1/2)): must not exceed the /DT scale.
  double worst_step_over_kinematic = 0.0;
  long long released = 0;  // contacts released below dtmin (/DT/INTER/DEL, card dtmin)
  double added_mass_energy = 0.0;  // kinetic energy the /DT/INTER/CST mass took when it was added [J]
};

// Two 4 x 4 shell plates (0.1 m, t = 2 mm steel) 1 mm apart, free; the upper one (secondary nodes, offset by half an
// element) flies down at `speed` onto the lower one (main surface). `samples` observer calls over the run.
inline ImpactResult plate_impact(double speed, const Type7Options& o, const std::string& extra_engine = "",
                                 double samples = 200) {
  constexpr double t = kPlateThickness, size = 0.1, h0 = 0.001;
  constexpr int n = 4;
  std::vector<NodeRow> nodes;
  std::vector<ShellRow> lower, upper;
  const double e = size / n;
  auto id = [](int plate, int i, int j) { return 1000LL * plate + 10 * j + i + 1; };
  for (int plate = 1; plate <= 2; ++plate)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        nodes.push_back({id(plate, i, j), e * i + (plate == 1 ? 0.5 * e : 0.0), e * j + (plate == 1 ? 0.5 * e : 0.0),
                         plate == 1 ? h0 : 0.0});
  long long shell = 1;
  for (int plate = 1; plate <= 2; ++plate)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        (plate == 1 ? upper : lower)
            .push_back({shell++, id(plate, i, j), id(plate, i + 1, j), id(plate, i + 1, j + 1), id(plate, i, j + 1)});
  std::vector<long long> upper_nodes;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) upper_nodes.push_back(id(1, i, j));
  const std::string starter = node_cards(nodes) + shell_cards(1, upper) + shell_cards(2, lower) + part_card(1) +
                              part_card(2) + shell_property(t, 3, 0.0, 24) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, upper_nodes) + initial_velocity(1, 0.0, 0.0, -speed, 1) +
                              surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  const double plate_mass = 7800.0 * t * size * size;
  const double momentum0 = plate_mass * speed;  // |P| at the start (along -z)
  ImpactResult out;
  test::TempDir dir;
  // Long enough for the upper plate to reach the lower one and bounce: 3 h0 / v.
  const double end_time = 3.0 * h0 / speed;
  double kinematic_bound = std::numeric_limits<double>::infinity();
  out.run = run_deck(dir, starter, end_time, end_time / samples, [&](const Model&, const SolverState& s) {
    // The step just taken against the bound of the state the pass saw at its start (the previous call's state;
    // with `samples` large every cycle is observed).
    if (std::isfinite(kinematic_bound) && s.time < end_time * (1.0 - 1e-9))
      out.worst_step_over_kinematic = std::max(out.worst_step_over_kinematic, s.dt / kinematic_bound);
    kinematic_bound = std::numeric_limits<double>::infinity();
    const ContactInterface& in = s.contact.interfaces.at(0);
    for (std::size_t q = 0; q < in.candidate_node.size(); ++q) {
      const auto m = static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(in.candidate_node[q])]);
      const auto& seg = in.segments[static_cast<std::size_t>(in.candidate_segment[q])];
      double x[4][3], w_v[3] = {0, 0, 0};
      const double node[3] = {s.nodes.x[m], s.nodes.y[m], s.nodes.z[m]};
      for (int a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
        x[a][0] = s.nodes.x[k], x[a][1] = s.nodes.y[k], x[a][2] = s.nodes.z[k];
      }
      const contact::SegmentPoint cp = contact::closest_point_on_segment(node, x);
      for (int a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
        w_v[0] += cp.weight[a] * s.nodes.vx[k], w_v[1] += cp.weight[a] * s.nodes.vy[k], w_v[2] += cp.weight[a] * s.nodes.vz[k];
      }
      const double v_rel[3] = {s.nodes.vx[m] - w_v[0], s.nodes.vy[m] - w_v[1], s.nodes.vz[m] - w_v[2]};
      double rate = 0.0;  // dp/dt = -v_rel . normal
      for (int k = 0; k < 3; ++k) rate -= v_rel[k] * (node[k] - cp.point[k]) / cp.distance;
      // A node at the mid-surface (d < 1e-10 g) is released by the pass (eq. C-4): no bound from it.
      const auto i = static_cast<std::size_t>(in.candidate_node[q]);
      const double g = in.pair_gap(i, static_cast<std::size_t>(in.candidate_segment[q])) - in.gap_reduction[i];
      if (rate > 0.0 && cp.distance >= 1e-10 * g) kinematic_bound = std::min(kinematic_bound, 0.5 * cp.distance / rate);
    }
    double p[3] = {0, 0, 0};
    for (std::size_t k = 0; k < s.nodes.size(); ++k)
      p[0] += s.nodes.mass[k] * s.nodes.vx[k], p[1] += s.nodes.mass[k] * s.nodes.vy[k], p[2] += s.nodes.mass[k] * s.nodes.vz[k];
    p[2] += momentum0;
    out.worst_momentum = std::max(out.worst_momentum, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / momentum0);
    out.max_ratio = std::max(out.max_ratio, s.contact.results.at(0).max_penetration_ratio);
    out.released = s.contact.results.at(0).released;
    out.added_mass_energy = s.contact.results.at(0).added_mass_energy;
    // The last step is cut to land on the end time: not a step the solver chose.
    if (s.time < end_time * (1.0 - 1e-9)) out.smallest_dt = std::min(out.smallest_dt, s.dt);
  }, extra_engine);
  return out;
}

}  // namespace crumple::verification
