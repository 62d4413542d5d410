// Elastic wave in a bar made of shells (docs/verification.md, "Elastic wave").
//
// Physics: a membrane strip with nu = 0 is an exact 1-D bar: the plate speed sqrt(E / (rho (1 - nu^2))) equals
// the bar speed c = sqrt(E / rho) and no lateral stress appears. A velocity step v0 imposed at x = 0 sends a
// compression front at speed c; behind it the particle velocity is v0 and the stress -rho c v0 (impedance
// relation). At the free far end the front reflects with the particle velocity doubled (2 v0), so the end
// reaches v0, half its plateau, when the front arrives at t = L / c. The discrete front is dispersed by the
// mesh (Gibbs oscillations behind it), but its mid-level point travels at the long-wave speed c, so the
// half-level crossing time is a sharp measure of the speed; the plateau is averaged over the oscillations.
// Energy: the work of the imposed velocity goes into kinetic and strain energy in equal parts. The balance adds
// kinetic energy at half steps to strain energy at whole steps and counts the work through the half step, so
// while energy flows in it is off by a fraction of order dt / t, and the ringing behind the front adds a
// residual of order 1/nx; with 200 elements both stay below the 0.1 % bound of issue 4.
#include <algorithm>
#include <cmath>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification::test_wave {
namespace {

TEST(ElasticWave, BarOfShellsVelocityStep) {
  constexpr double E = 2.1e11, rho = 7800.0, L = 1.0, v0 = 1.0;
  const double c = std::sqrt(E / rho);
  Strip strip;
  strip.nx = 200, strip.ny = 1, strip.length = L, strip.width = L / 200;
  std::string starter = node_cards(strip.nodes()) + shell_cards(1, strip.shells()) + part_card() +
                        shell_property(0.001, 1) + elastic_material(rho, E, 0.0) + unit_function(1) +
                        node_group(1, strip.column(0)) + imposed_velocity(1, 1, "X", 1, v0);

  const std::size_t mid_element_id = 100;  // element between x = 0.495 and 0.5
  std::vector<double> t, v_end, v_mid, s_mid;
  const double end_time = 1.5 * L / c;
  test::TempDir dir;
  const double step = 0.9 * strip.width / c;  // square elements: dt = 0.9 h / c
  const RunResult run = run_deck(dir, starter, end_time, 0.5 * step, [&](const Model& m, const SolverState& s) {
    auto mean_vx = [&](int column) {
      double sum = 0.0;
      for (long long id : strip.column(column)) sum += s.nodes.vx[node_index(m, id)];
      return sum / static_cast<double>(strip.ny + 1);
    };
    t.push_back(s.time - 0.5 * s.dt);  // velocities live at the half step t^(n+1/2)
    v_end.push_back(mean_vx(strip.nx));
    v_mid.push_back(mean_vx(strip.nx / 2));
    s_mid.push_back(s.shells.sxx[first_point(m, s, shell_index(m, static_cast<long long>(mid_element_id)))]);
  });
  ASSERT_EQ(run.summary.status, RunStatus::Normal) << run.summary.message;

  // Arrival at the free end: the end velocity crosses v0 (half of 2 v0).
  const double arrival = first_crossing(t, v_end, v0);
  ASSERT_GT(arrival, 0.0) << "the front never reached the far end";
  // Plateau at mid-length between the passage of the front (t = 0.5 L/c) and the return of the reflection
  // (t = 1.5 L/c), leaving a quarter transit for the front's oscillations to pass.
  double v_sum = 0.0, s_sum = 0.0;
  int samples = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > 0.75 * L / c && t[k] < 1.4 * L / c) v_sum += v_mid[k], s_sum += s_mid[k], ++samples;
  ASSERT_GT(samples, 50);
  const double plateau = v_sum / samples, stress = s_sum / samples;
  const double arrival_error = arrival / (L / c) - 1.0;
  const double amplitude_error = plateau / v0 - 1.0;
  const double stress_error = stress / (-rho * c * v0) - 1.0;
  // Tolerances of issue 4: arrival 2 %, amplitude 5 %, energy 0.1 %. The stress is the impedance relation,
  // held to the amplitude's 5 %.
  EXPECT_LT(std::abs(arrival_error), 0.02);
  EXPECT_LT(std::abs(amplitude_error), 0.05);
  EXPECT_LT(std::abs(stress_error), 0.05);
  EXPECT_LT(std::abs(run.summary.energy.error_percent), 0.1);
  std::printf("[wave] cycles %lld  arrival %.6e s (L/c %.6e, %+.3f %%)  mid velocity %.5f (%+.3f %%)  "
              "stress %.5e (%+.3f %%)  energy error %.4f %%\n",
              run.summary.cycles, arrival, L / c, 100 * arrival_error, plateau, 100 * amplitude_error, stress,
              100 * stress_error, run.summary.energy.error_percent);
}

}  // namespace
}  // namespace crumple::verification::test_wave
