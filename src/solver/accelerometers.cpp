// /ACCEL (include/crumple/solver/accelerometers.hpp): the accelerometers' filter and their update in the cycle.
// Equations: docs/output-format.md, "ACCEL".
#include "crumple/solver/accelerometers.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMemory = 6;  // per component: x1 x2 y1 y2 z1 z2

// One section 1 / (s^2 + 2 zeta s + 1) of the analog low-pass (s in units of the corner frequency) through the
// bilinear transform s = (1 - 1/z) / (K (1 + 1/z)) (eq. ACC-2).
FilterSection bilinear_section(double zeta, double k) {
  const double k2 = k * k, d = 1.0 + 2.0 * zeta * k + k2;
  return {k2 / d, 2.0 * k2 / d, k2 / d, 2.0 * (k2 - 1.0) / d, (1.0 - 2.0 * zeta * k + k2) / d};
}

double section_sample(const FilterSection& c, double x0, double x1, double x2, double y1, double y2) {
  return c.b0 * x0 + c.b1 * x1 + c.b2 * x2 - c.a1 * y1 - c.a2 * y2;
}

}  // namespace

std::array<FilterSection, 2> butterworth4(double cutoff, double h) {
  // Poles of the 4-pole Butterworth: damping ratios sin(pi/8) and sin(3 pi/8) (eq. ACC-1); the corner frequency
  // prewarped, K = tan(pi fc h), so that the digital filter has the analog gain 1/sqrt(2) at fc exactly.
  const double fc = std::min(cutoff, 0.4 / h);
  const double k = std::tan(kPi * fc * h);
  return {bilinear_section(std::sin(kPi / 8.0), k), bilinear_section(std::sin(3.0 * kPi / 8.0), k)};
}

double filter_sample(const std::array<FilterSection, 2>& filter, double input, double* memory) {
  double& x1 = memory[0];
  double& x2 = memory[1];
  double& y1 = memory[2];
  double& y2 = memory[3];
  double& z1 = memory[4];
  double& z2 = memory[5];
  const double y0 = section_sample(filter[0], input, x1, x2, y1, y2);
  const double z0 = section_sample(filter[1], y0, y1, y2, z1, z2);
  x2 = x1, x1 = input, y2 = y1, y1 = y0, z2 = z1, z1 = z0;
  return z0;
}

void setup_accelerometers(std::size_t count, HistoryIntegrals& h) {
  h.accel_filtered.assign(3 * count, 0.0);
  h.accel_velocity.assign(3 * count, 0.0);
  h.accel_memory.assign(3 * kMemory * count, 0.0);
}

void update_accelerometers(const std::vector<Accelerometer>& accelerometers, const NodalState& n,
                           const std::array<const std::vector<double>*, 3>& before, double dt,
                           const std::vector<SkewAxes>& skews, HistoryIntegrals& h) {
  if (accelerometers.empty() || !(dt > 0.0)) return;
  const std::array<const std::vector<double>*, 3> now{&n.vx, &n.vy, &n.vz};
  for (std::size_t a = 0; a < accelerometers.size(); ++a) {
    const Accelerometer& meter = accelerometers[a];
    const auto k = static_cast<std::size_t>(meter.node);
    const bool filtered = meter.cutoff > 0.0;
    const auto filter = filtered ? butterworth4(meter.cutoff, dt) : std::array<FilterSection, 2>{};
    Vec3 changes{};  // a^n dt^n [L/T], in the meter's axes
    for (std::size_t c = 0; c < 3; ++c) changes[c] = (*now[c])[k] - (*before[c])[k];
    if (meter.skew >= 0) changes = to_skew(skews[static_cast<std::size_t>(meter.skew)], changes);
    for (std::size_t c = 0; c < 3; ++c) {
      const double change = changes[c];
      const double raw = change / dt;  // a^n [L/T^2]
      const std::size_t at = 3 * a + c;
      h.accel_velocity[at] += change;  // eq. ACC-3
      h.accel_filtered[at] = filtered ? filter_sample(filter, raw, &h.accel_memory[kMemory * at]) : raw;
    }
  }
}

}  // namespace crumple
