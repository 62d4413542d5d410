// Throughput of the 4-node shell kernel (element-cycles per second) on a flat plate group of 128 elements,
// elastic and plastic, 3 and 5 through-thickness points. Run: build/release/bench/crumple_bench
#include <benchmark/benchmark.h>

#include <algorithm>

#include <cmath>

#include "crumple/elements/shell4.hpp"

namespace {

using namespace crumple;

struct Plate {
  ElementTable table = empty_element_tables()[static_cast<std::size_t>(ElementKind::Shell4)];
  ElementGroup group{ElementKind::Shell4, 0, 0, 0, 0, 0};
  NodalState nodes;
  ShellState state;
  ShellGroupParameters p;
  Material material;
  std::vector<Function> functions;
  double zeta[10], wn[10], wb[10];

  Plate(int points, bool plastic, int ishell = 1) {
    constexpr int nx = 16, ny = 8;  // 128 elements, 5 mm, a bending and stretching velocity field
    nodes.resize((nx + 1) * (ny + 1));
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const auto k = static_cast<std::size_t>(j * (nx + 1) + i);
        nodes.x[k] = 5.0 * i, nodes.y[k] = 5.0 * j;
        nodes.vx[k] = 0.01 * nodes.x[k];
        nodes.vz[k] = 0.001 * nodes.x[k] * nodes.x[k];
        nodes.wy[k] = -0.002 * nodes.x[k];
      }
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int n1 = j * (nx + 1) + i;
        table.user_id.push_back(static_cast<std::int64_t>(table.user_id.size() + 1));
        table.part.push_back(0);
        for (int n : {n1, n1 + 1, n1 + nx + 2, n1 + nx + 1}) table.connectivity.push_back(n);
      }
    group.end = static_cast<std::int32_t>(table.size());
    const std::size_t n = table.size();
    state.resize_points(n * static_cast<std::size_t>(std::max(points, 1)));
    state.resize_elements(n, 1.5);
    material.law = plastic ? MaterialLaw::JohnsonCook : MaterialLaw::Elastic;
    material.young = 205.0, material.poisson = 0.3, material.density = 7.8e-6;
    material.johnson_cook.a = 0.0002, material.johnson_cook.b = 0.35, material.johnson_cook.n = 0.52;
    through_thickness_rule(points > 0 ? points : 1, zeta, wn, wb);
    p.hardening = materials::Hardening::of(material, functions);
    p.young = 205.0, p.poisson = 0.3, p.density = 7.8e-6, p.points = points;
    p.zeta = zeta, p.membrane_weight = wn, p.bending_weight = wb;
    p.physical_hourglass = ishell == 24;
    p.resultant_plasticity = points == 0;
    if (p.resultant_plasticity) {  // N = 0: one membrane point plus the bending stress per element
      p.points = 1;
      state.resize_points(n);
      state.bending_stress.assign(3 * n, 0.0);
    }
  }
};

void shell4(benchmark::State& bench, int points, bool plastic, int ishell) {
  Plate plate(points, plastic, ishell);
  for (auto _ : bench) {
    plate.nodes.clear_forces();
    auto r = shell4_forces(plate.table, plate.group, plate.p, plate.nodes, plate.state, 1e-4);
    benchmark::DoNotOptimize(r);
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(bench.iterations() * static_cast<std::int64_t>(plate.table.size()));
  bench.counters["element_cycles_per_s"] =
      benchmark::Counter(static_cast<double>(bench.iterations()) * static_cast<double>(plate.table.size()),
                         benchmark::Counter::kIsRate);
}

// Ishell 1 (Belytschko-Tsay) against Ishell 24 (physical stabilisation) in one run; N = 0 is resultant plasticity.
BENCHMARK_CAPTURE(shell4, elastic_3_points_ishell1, 3, false, 1);
BENCHMARK_CAPTURE(shell4, elastic_3_points_ishell24, 3, false, 24);
BENCHMARK_CAPTURE(shell4, plastic_3_points_ishell1, 3, true, 1);
BENCHMARK_CAPTURE(shell4, plastic_3_points_ishell24, 3, true, 24);
BENCHMARK_CAPTURE(shell4, plastic_5_points_ishell24, 5, true, 24);
BENCHMARK_CAPTURE(shell4, plastic_resultant_n0_ishell24, 0, true, 24);

}  // namespace

BENCHMARK_MAIN();
