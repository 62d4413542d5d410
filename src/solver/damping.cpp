// /DAMP: Rayleigh mass damping of node groups (docs/theory/damping.md, eq. D-1 to D-4).
#include <cmath>

#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// The damped update of one velocity component (eq. D-2): the damping force -alpha m v at the mean of the velocities
// before and after the step, solved for the new velocity, v' = ((1 - c) v + dt f / m) / (1 + c) with c = alpha dt / 2.
// Returns the damping force that gives v' through the undamped update v' = v + dt (f + f_d) / m.
// The first cycle's velocity is v^0 itself, at t = 0: the force is -alpha m v^0, explicit (eq. D-2a).
double damping_force(double alpha, double mass, double velocity, double force, double dt, bool first) {
  if (first) return -alpha * mass * velocity;
  const double c = 0.5 * alpha * dt;
  const double after = ((1.0 - c) * velocity + dt * force / mass) / (1.0 + c);
  return mass * (after - velocity) / dt - force;
}

template <class Visit>
void for_each_damped_node(const Model& m, const SolverState& s, Visit visit) {
  for (std::size_t d = 0; d < m.dampings.size(); ++d) {
    const RayleighDamping& damping = m.dampings[d];
    const double alpha = s.damping_alpha[d];
    if (!(alpha > 0.0) || !damping.active(s.time)) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(damping.node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (!s.domain.is_local(k)) continue;
      visit(alpha, k);
    }
  }
}

}  // namespace

double damping_step_factor(const Model& m, const SolverState& s, double dt) {
  double alpha = 0.0;
  for (std::size_t d = 0; d < m.dampings.size(); ++d)
    if (m.dampings[d].active(s.time)) alpha = std::max(alpha, s.damping_alpha[d]);
  return alpha > 0.0 ? damped_step_factor(0.5 * alpha * dt) : 1.0;  // eq. D-3
}

void apply_damping(const Model& m, SolverState& s, double dt_average) {
  if (m.dampings.empty() || !(dt_average > 0.0)) return;
  NodalState& n = s.nodes;
  const bool first = s.cycle + s.cycles_done == 0;
  std::vector<double>* velocity[6] = {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  std::vector<double>* force[6] = {&n.fx, &n.fy, &n.fz, &n.mx, &n.my, &n.mz};
  for_each_damped_node(m, s, [&](double alpha, std::size_t k) {
    for (std::size_t d = 0; d < 6; ++d) {
      const double mass = d < 3 ? n.mass[k] : n.inertia[k];
      if (!(mass > 0.0)) continue;
      (*force[d])[k] += damping_force(alpha, mass, (*velocity[d])[k], (*force[d])[k], dt_average, first);
    }
  });
}

void add_damping_work(const Model& m, const SolverState& s, const VelocityScratch& scratch, double dt_average,
                      ExactSum& work) {
  if (m.dampings.empty()) return;
  const NodalState& n = s.nodes;
  const bool first = s.cycle + s.cycles_done == 0;
  const std::vector<double>* after[6] = {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  for_each_damped_node(m, s, [&](double alpha, std::size_t k) {
    if (!s.domain.owns(k)) return;
    // eq. D-4: -alpha m v_mean^2 dt with v_mean of eq. D-2 (v^0 on the first cycle, D-2a), on the velocities the
    // constraints left: a fixed degree of freedom does no damping work.
    for (std::size_t d = 0; d < 6; ++d) {
      const double mass = d < 3 ? n.mass[k] : n.inertia[k];
      const double now = (*after[d])[k];
      const double mean = first ? (now != 0.0 ? scratch.before[d][k] : 0.0) : 0.5 * (scratch.before[d][k] + now);
      if (mass > 0.0) work.add(-alpha * mass * mean * mean * dt_average);
    }
  });
}

}  // namespace crumple::solver
