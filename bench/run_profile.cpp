// Time profile of whole runs (docs/performance.md, "Where a cycle goes"): the example tube without contact and the
// same tube with a TYPE7 self contact, each run once through the reader and the solver, with the solver's own
// per-stage wall times (RunSummary::phases, the listing's TIME PROFILE) reported as counters.
// Run: build/release/bench/crumple_bench --benchmark_filter=run_profile
#include <benchmark/benchmark.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "crumple/deck/reader.hpp"
#include "crumple/output/run.hpp"

namespace {

using namespace crumple;

void run_profile(benchmark::State& state, const std::string& deck) {
  const std::filesystem::path path = std::filesystem::path(CRUMPLE_SOURCE_DIR) / "decks" / deck / "TUBE_0000.rad";
  const std::filesystem::path out = std::filesystem::temp_directory_path() / ("crumple_bench_" + deck);
  std::filesystem::create_directories(out);
  RunSummary summary;
  for (auto _ : state) {
    const Model model = read_deck(path).model;
    SimulationOptions options;
    options.name = "TUBE";
    options.output_directory = out;
    options.write_results = false;
    std::ostringstream console;
    summary = run_simulation(model, options, console);
  }
  const PhaseTimes& p = summary.phases;
  const double cycle = p.elements + p.contact + p.loads + p.update + p.output;
  state.counters["cycles"] = static_cast<double>(summary.cycles);
  state.counters["elements_%"] = 100.0 * p.elements / cycle;
  state.counters["contact_%"] = 100.0 * p.contact / cycle;
  state.counters["contact_passes"] = static_cast<double>(p.contact_passes);
  state.counters["update_%"] = 100.0 * p.update / cycle;
  state.counters["other_%"] = 100.0 * (p.loads + p.output) / cycle;
  state.counters["us_per_cycle"] = 1e6 * cycle / static_cast<double>(summary.cycles);
  std::filesystem::remove_all(out);
}

BENCHMARK_CAPTURE(run_profile, tube_without_contact, std::string("tube_impact"))->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(run_profile, tube_self_contact, std::string("tube_self_contact"))->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
