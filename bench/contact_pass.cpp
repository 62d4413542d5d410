// Cost of the TYPE7 contact pass against the shell kernel on the same mesh (docs/performance.md, "Contact").
// Scene: a plate of n x n 4-node shells (the main surface) and a second plate of (n+1)^2 secondary nodes offset by
// half an element, at half the gap above it: every node is in contact with one segment (two or four at edges).
// Run: build/release/bench/crumple_bench --benchmark_filter=contact
#include <benchmark/benchmark.h>

#include "crumple/contact/contact.hpp"
#include "crumple/elements/shell4.hpp"

namespace {

using namespace crumple;

struct Scene {
  Model model;
  NodalState nodes;
  ContactState contact;
  ElementTable table = empty_element_tables()[static_cast<std::size_t>(ElementKind::Shell4)];
  ElementGroup group{ElementKind::Shell4, 0, 0, 0, 0, 0};
  ShellState state;
  ShellGroupParameters p;
  Material material;
  std::vector<Function> functions;
  double zeta[3], wn[3], wb[3];

  explicit Scene(int n, double height = 0.5) {
    const double e = 5.0, gap = 0.5;
    const auto plate_nodes = static_cast<std::size_t>((n + 1) * (n + 1));
    nodes.resize(2 * plate_nodes);
    ContactInterface in;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const auto k = static_cast<std::size_t>(j * (n + 1) + i);
        nodes.x[k] = e * i, nodes.y[k] = e * j, nodes.mass[k] = 1e-4;
        const std::size_t s = plate_nodes + k;
        nodes.x[s] = e * i + 0.5 * e, nodes.y[s] = e * j + 0.5 * e, nodes.z[s] = height * gap, nodes.mass[s] = 1e-4;
        nodes.vz[s] = -1.0;
        in.secondary_nodes.push_back(static_cast<std::int32_t>(s));
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i;
        const std::array<std::int32_t, 4> seg{a, a + 1, a + n + 2, a + n + 1};
        in.segments.push_back(seg);
        table.user_id.push_back(static_cast<std::int64_t>(table.user_id.size() + 1));
        table.part.push_back(0);
        for (std::int32_t v : seg) table.connectivity.push_back(v);
      }
    const std::size_t segments = in.segments.size(), secondary = in.secondary_nodes.size();
    in.segment_gap.assign(segments, gap);
    in.segment_stiffness.assign(segments, 100.0), in.segment_active.assign(segments, 1);
    in.segment_owner.assign(segments, -1), in.segment_owner_kind.assign(segments, 0);
    for (std::size_t k = 0; k < plate_nodes; ++k) in.main_nodes.push_back(static_cast<std::int32_t>(k));
    in.node_gap.assign(secondary, 0.0), in.node_element_stiffness.assign(secondary, 0.0);
    in.size_node_arrays();
    in.largest_gap = gap, in.margin = gap;
    contact.interfaces.push_back(in);
    contact.results.resize(1);
    contact.fx.assign(nodes.size(), 0.0), contact.fy = contact.fx, contact.fz = contact.fx;
    // The plate as one shell group (the bench compares the two passes on the same segments).
    group.end = static_cast<std::int32_t>(table.size());
    state.resize_points(3 * table.size());
    state.resize_elements(table.size(), 1.5);
    material.law = MaterialLaw::Elastic, material.young = 205.0, material.poisson = 0.3, material.density = 7.8e-6;
    through_thickness_rule(3, zeta, wn, wb);
    p.hardening = materials::Hardening::of(material, functions);
    p.young = 205.0, p.poisson = 0.3, p.density = 7.8e-6, p.points = 3, p.physical_hourglass = true;
    p.zeta = zeta, p.membrane_weight = wn, p.bending_weight = wb;
  }
};

void contact_pass(benchmark::State& bench, int n, double height = 0.5) {
  Scene scene(n, height);
  double added = 0.0;
  contact::contact_forces(scene.model, scene.contact, scene.nodes, 0.0, 1e-6, 1e-6, 0.9, added);  // first sort
  for (auto _ : bench) {
    auto step = contact::contact_forces(scene.model, scene.contact, scene.nodes, 0.0, 1e-6, 1e-6, 0.9, added);
    benchmark::DoNotOptimize(step);
    benchmark::ClobberMemory();
  }
  const auto pairs = static_cast<double>(scene.contact.interfaces[0].candidate_node.size());
  bench.counters["pairs"] = pairs;
  bench.counters["active_nodes"] = scene.contact.results[0].active_nodes;
  bench.counters["pairs_per_s"] = benchmark::Counter(pairs * static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
}

void contact_sort(benchmark::State& bench, int n) {
  Scene scene(n);
  for (auto _ : bench) {
    contact::sort_candidates(scene.contact.interfaces[0], scene.nodes);
    benchmark::ClobberMemory();
  }
  bench.counters["nodes_and_segments_per_s"] = benchmark::Counter(
      static_cast<double>(scene.contact.interfaces[0].secondary_nodes.size() + scene.contact.interfaces[0].segments.size()) *
          static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
}

void contact_shell_kernel(benchmark::State& bench, int n) {
  Scene scene(n);
  for (auto _ : bench) {
    scene.nodes.clear_forces();
    auto r = shell4_forces(scene.table, scene.group, scene.p, scene.nodes, scene.state, 1e-4);
    benchmark::DoNotOptimize(r);
    benchmark::ClobberMemory();
  }
}

BENCHMARK_CAPTURE(contact_pass, contact_pass_32x32, 32);
BENCHMARK_CAPTURE(contact_pass, contact_pass_64x64, 64);
// The same nodes at 1.5 gaps: candidates of the search, outside their gap (closest point and kinematic step only).
BENCHMARK_CAPTURE(contact_pass, contact_pass_64x64_outside_gap, 64, 1.5);
BENCHMARK_CAPTURE(contact_sort, contact_sort_32x32, 32);
BENCHMARK_CAPTURE(contact_sort, contact_sort_64x64, 64);
BENCHMARK_CAPTURE(contact_shell_kernel, contact_scene_shells_32x32, 32);
BENCHMARK_CAPTURE(contact_shell_kernel, contact_scene_shells_64x64, 64);

}  // namespace
