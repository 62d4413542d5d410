// /DAMP: Rayleigh damping of node groups (docs/theory/damping.md, eq. D-1 to D-5).
#include <algorithm>
#include <cmath>

#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// The damped update of one velocity component (eq. D-2): the damping force -alpha m v at the mean of the velocities
// before and after the step, solved for the new velocity, v' = ((1 - c) v + dt f / m) / (1 + c) with c = alpha dt / 2.
// Returns the damping force that gives v' through the undamped update v' = v + dt (f + f_d) / m.
// The first cycle's velocity is v^0 itself, at t = 0: the force is -alpha m v^0, explicit (eq. D-2a).
double mass_damping_force(double alpha, double mass, double velocity, double force, double dt, bool first) {
  if (first) return -alpha * mass * velocity;
  const double c = 0.5 * alpha * dt;
  const double after = ((1.0 - c) * velocity + dt * force / mass) / (1.0 + c);
  return mass * (after - velocity) / dt - force;
}

// Calls visit(damping index, node) for every local node of every /DAMP active at the current time.
template <class Visit>
void for_each_damped_node(const Model& m, const SolverState& s, Visit visit) {
  for (std::size_t d = 0; d < m.dampings.size(); ++d) {
    if (!m.dampings[d].active(s.time)) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(m.dampings[d].node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (s.domain.is_local(k)) visit(d, k);
    }
  }
}

bool first_cycle(const SolverState& s) { return s.cycle + s.cycles_done == 0; }

std::array<std::vector<double>*, 6> nodal_forces(NodalState& n) { return {&n.fx, &n.fy, &n.fz, &n.mx, &n.my, &n.mz}; }
std::array<const std::vector<double>*, 6> nodal_velocities(const NodalState& n) {
  return {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
}
double dof_mass(const NodalState& n, std::size_t k, std::size_t d) { return d < 3 ? n.mass[k] : n.inertia[k]; }

}  // namespace

double damping_step_factor(const Model& m, const SolverState& s, double dt) {
  double alpha = 0.0, beta = 0.0;
  for (std::size_t d = 0; d < m.dampings.size(); ++d)
    if (m.dampings[d].active(s.time))
      alpha = std::max(alpha, s.damping.alpha[d]), beta = std::max(beta, s.damping.beta[d]);
  // eq. D-3: the stiffness part from the second cycle, when its force starts (measured on the reference)
  const double fraction = 0.5 * alpha * dt + (first_cycle(s) ? 0.0 : beta / dt);
  return fraction > 0.0 ? damped_step_factor(fraction) : 1.0;
}

void setup_damping(const Model& m, SolverState& s) {
  const bool stiffness = std::any_of(s.damping.beta.begin(), s.damping.beta.end(), [](double b) { return b > 0.0; });
  if (!stiffness || s.damping.stiffness()) return;
  s.damping.element_force_before.assign(6 * m.nodes.size(), 0.0);
  s.damping.stiffness_force.assign(6 * m.nodes.size(), 0.0);
}

void stiffness_damping_forces(const Model& m, SolverState& s) {
  if (!s.damping.stiffness()) return;
  DampingState& st = s.damping;
  std::fill(st.stiffness_force.begin(), st.stiffness_force.end(), 0.0);
  const auto force = nodal_forces(s.nodes);
  // The elements' force on each node of a stiffness-damped group (the nodal sums hold minus it here), its rate over
  // the last step dt^(n-1/2), and the force -beta times that rate (eq. D-5); none on the first cycle.
  for (std::size_t d = 0; d < m.dampings.size(); ++d) {
    if (!(st.beta[d] > 0.0)) continue;
    const bool acts = m.dampings[d].active(s.time) && !first_cycle(s) && s.dt > 0.0;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(m.dampings[d].node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (!s.domain.is_local(k)) continue;
      for (std::size_t c = 0; c < 6; ++c) {
        const double now = -(*force[c])[k];
        if (acts) st.stiffness_force[6 * k + c] -= st.beta[d] * (now - st.element_force_before[6 * k + c]) / s.dt;
      }
    }
  }
  for (std::size_t d = 0; d < m.dampings.size(); ++d) {  // each node's force of this cycle, for the next
    if (!(st.beta[d] > 0.0)) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(m.dampings[d].node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      if (!s.domain.is_local(k)) continue;
      for (std::size_t c = 0; c < 6; ++c) st.element_force_before[6 * k + c] = -(*force[c])[k];
    }
  }
}

void apply_damping(const Model& m, SolverState& s, double dt_average) {
  if (m.dampings.empty() || !(dt_average > 0.0)) return;
  NodalState& n = s.nodes;
  const bool first = first_cycle(s);
  const auto velocity = nodal_velocities(n);
  const auto force = nodal_forces(n);
  if (s.damping.stiffness())  // eq. D-5, before the mass damping solves for the new velocity with it
    for_each_local_node(s.domain, n.size(), [&](std::size_t k) {
      for (std::size_t c = 0; c < 6; ++c) (*force[c])[k] += s.damping.stiffness_force[6 * k + c];
    });
  for_each_damped_node(m, s, [&](std::size_t d, std::size_t k) {
    const double alpha = s.damping.alpha[d];
    if (!(alpha > 0.0)) return;
    for (std::size_t c = 0; c < 6; ++c) {
      const double mass = dof_mass(n, k, c);
      if (mass > 0.0) (*force[c])[k] += mass_damping_force(alpha, mass, (*velocity[c])[k], (*force[c])[k], dt_average, first);
    }
  });
}

void add_damping_work(const Model& m, const SolverState& s, const VelocityScratch& scratch, double dt_average,
                      ExactSum& work) {
  if (m.dampings.empty()) return;
  const NodalState& n = s.nodes;
  const bool first = first_cycle(s);
  const auto after = nodal_velocities(n);
  // The velocity the damping forces act at (D-4): the mean of the step's velocities the constraints left (a fixed
  // degree of freedom does no work), v^0 on the first cycle (D-2a).
  auto mean = [&](std::size_t k, std::size_t c) {
    const double now = (*after[c])[k];
    return first ? (now != 0.0 ? scratch.before[c][k] : 0.0) : 0.5 * (scratch.before[c][k] + now);
  };
  for_each_damped_node(m, s, [&](std::size_t d, std::size_t k) {
    if (!s.domain.owns(k) || !(s.damping.alpha[d] > 0.0)) return;
    for (std::size_t c = 0; c < 6; ++c) {  // eq. D-4: -alpha m v_mean^2 dt
      const double mass = dof_mass(n, k, c), v = mean(k, c);
      if (mass > 0.0) work.add(-s.damping.alpha[d] * mass * v * v * dt_average);
    }
  });
  if (!s.damping.stiffness()) return;
  for_each_owned_node(s.domain, n.size(), [&](std::size_t k) {  // the stiffness part's work, f_d v_mean dt
    for (std::size_t c = 0; c < 6; ++c)
      if (const double f = s.damping.stiffness_force[6 * k + c]; f != 0.0) work.add(f * mean(k, c) * dt_average);
  });
}

}  // namespace crumple::solver
