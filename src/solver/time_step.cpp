// Nodal time step and mass scaling (/DT/NODA/CST) (docs/theory/time-step.md, "Nodal step").
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "crumple/core/geometry.hpp"
#include "crumple/elements/critical_step.hpp"
#include "solver/cycle.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

// The element's current volume: a shell's current area times its current thickness, a truss's or a beam's its
// cross-section times its length, a brick's exact volume.
template <class State>
double current_volume(ElementKind kind, const State& st, std::size_t e, const std::int32_t* c, const NodalState& x) {
  if constexpr (requires { st.area; }) {
    return st.area[e] * st.length[e];
  } else if constexpr (requires { st.thickness; }) {
    const double area = kind == ElementKind::Shell3
                            ? geometry::triangle_area(node_position(x, c[0]), node_position(x, c[1]),
                                                      node_position(x, c[2]))
                            : geometry::quad_area(node_position(x, c[0]), node_position(x, c[1]),
                                                  node_position(x, c[2]), node_position(x, c[3]));
    return area * st.thickness[e];
  } else {
    return geometry::brick_volume(x.x, x.y, x.z, c);
  }
}

// Each element of this domain: the stiffness it gives each of its nodes (eqs. T-4, T-2a), 0 when it is not active.
template <class State>
void element_stiffness(const Model& m, ElementKind kind, const State& st, SolverState& s) {
  const bool mass_scaling = m.run.dt_nodal_cst.given;
  const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
  std::vector<double>& k = s.interface_stiffness[static_cast<std::size_t>(kind)];
  k.resize(table.size());
  for (std::size_t e = 0; e < table.size(); ++e) {
    if (s.domain.several() && !s.domain.mine(kind, e)) continue;
    k[e] = 0.0;
    if (element_condition(st.deleted[e]) != kElementActive || !(st.critical_dt[e] > 0.0)) continue;
    const Part& part = m.parts[static_cast<std::size_t>(table.part[e])];
    if constexpr (requires { st.step_stiffness; }) {  // a spring gives each node its step's stiffness (eq. SP-4a)
      k[e] = st.step_stiffness[e];
      continue;
    }
    const Material& mat = m.materials[static_cast<std::size_t>(part.material)];
    const NodalStiffnessFactor beta =
        nodal_stiffness_factor(kind, m.formulations[static_cast<std::size_t>(part.property)].ishell, mat.poisson);
    const std::int32_t* c = table.nodes_of(e);
    const double volume = current_volume(kind, st, e, c, s.nodes);
    if (mass_scaling && beta.mass_scaling_length != NodalLength::CriticalStep) {  // eqs. T-2a, T-2b, current geometry
      const double length = mass_scaling_nodal_length(
          beta.mass_scaling_length, m.properties[static_cast<std::size_t>(part.property)].shell,
          node_position(s.nodes, c[0]), node_position(s.nodes, c[1]), node_position(s.nodes, c[2]),
          node_position(s.nodes, c[3]));
      k[e] = 0.5 * volume * mat.young / (1.0 - mat.poisson * mat.poisson) / (length * length);
      continue;
    }
    k[e] = (mass_scaling ? beta.mass_scaling : beta.interface) * mat.density * volume /
           (st.critical_dt[e] * st.critical_dt[e]);
  }
}

}  // namespace

// Off under mass scaling: /DT/NODA/CST has its own nodal step (T-2, T-3), /DT/INTER/CST sizes the contacts' masses on
// their own step (C-11c).
// Off under selective mass scaling too: its mass holds the nodes at dt_min (SM-0).
bool interface_nodal_step_on(const Model& m) {
  // An /RBE3 puts the reference on its nodal step too (docs/theory/rigid-bodies.md, RI-6, measured).
  return (!m.type7_interfaces.empty() || !m.interpolation_constraints.empty()) && !m.run.dt_nodal_cst.given && !m.run.dt_inter_cst.given &&
         !selective_mass_on(m);
}

void element_interface_stiffness(const Model& m, SolverState& s) {
  element_stiffness(m, ElementKind::Shell4, s.shells, s);
  element_stiffness(m, ElementKind::Shell3, s.shells3, s);
  element_stiffness(m, ElementKind::Brick8, s.bricks, s);
  element_stiffness(m, ElementKind::Spring, s.springs, s);
  element_stiffness(m, ElementKind::Truss, s.trusses, s);
  element_stiffness(m, ElementKind::Beam, s.beams, s);
}

void nodal_interface_stiffness(const Model& m, SolverState& s) {
  std::vector<double>& k = s.nodal_stiffness;
  k.assign(s.nodes.size(), 0.0);
  s.contact.nodal_contact_stiffness.resize(s.nodes.size(), 0.0);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    const std::vector<double>& ke = s.interface_stiffness[static_cast<std::size_t>(kind)];
    const int n = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < n; ++a) k[static_cast<std::size_t>(table.nodes_of(e)[a])] += ke[e];
  }
}

NodalStep interface_nodal_step(const Model& m, SolverState& s) {
  const std::vector<double>& element = s.nodal_stiffness;
  const std::vector<double>& contact = s.contact.nodal_contact_stiffness;
  const double scale = step_scale(m.run);
  NodalStep step{std::numeric_limits<double>::infinity(), -1};
  for_each_owned_node(s.domain, s.nodes.size(), [&](std::size_t node) {
    const double k = element[node] + contact[node];
    // A node moving with a rigid body: its springs push the body (C-11 takes its step), its elements are carried.
    if (!(k > 0.0) || !(s.nodes.mass[node] > 0.0) || s.rigid_owner[node] >= 0) return;
    const double dt = scale * std::sqrt(2.0 * s.nodes.mass[node] / k);
    if (dt < step.dt) step = {dt, static_cast<std::int32_t>(node)};
  });
  Reducer& r = s.reducer;
  r.values.assign(1, step.dt), r.indices.assign(1, step.node);
  r.min_with_index(r.values, r.indices);  // one domain: as it is
  return {r.values[0], r.indices[0]};
}


// With /DT/NODA/CST the nodal step and its mass take the same stiffness as T-4 (docs/theory/time-step.md, T-2):
// the elements' and, with a TYPE7, the contacts'; /DT/INTER/CST alone sizes the contacts' masses on their own step
// (C-11c).
bool nodal_stiffness_on(const Model& m) { return interface_nodal_step_on(m) || m.run.dt_nodal_cst.given; }

// The smallest nodal mass that keeps scale sqrt(2 m / k) >= dt_min at every node this domain advances (eq. T-3),
// with k the node's elements' and contacts' stiffness (T-2); the added mass summed over the owned nodes and the
// smallest step over them, reduced, so that both are the same at any number of domains.
NodalStep nodal_time_step(const Model& m, SolverState& s) {
  const TimeStepControl& cst = m.run.dt_nodal_cst;
  const double scale = cst.scale > 0.0 ? cst.scale : 0.9;
  const std::vector<double>& element = s.nodal_stiffness;
  const std::vector<double>& contact = s.contact.nodal_contact_stiffness;
  const double target = cst.minimum / scale;
  Reducer& r = s.reducer;
  r.sums.assign(1, ExactSum{});
  NodalStep step{std::numeric_limits<double>::infinity(), -1};
  for_each_local_node(s.domain, s.nodes.size(), [&](std::size_t node) {
    const double k = element[node] + (contact.empty() ? 0.0 : contact[node]);
    // A node moving with a rigid body: its mass is the body's (C-11 takes the step of its springs).
    if (!(k > 0.0) || s.rigid_owner[node] >= 0) return;
    double& mass = s.nodes.mass[node];
    const double needed = 0.5 * k * target * target;
    const bool owned = !s.domain.several() || s.domain.owns(node);
    if (mass < needed) {
      // A shell node's rotational inertia grows in the same ratio (eq. T-3a): its element's rotation modes keep
      // their frequency ratio to the translational ones and stay stable at the step the mass now gives.
      if (mass > 0.0) s.nodes.inertia[node] *= needed / mass;
      if (owned) r.sums[0].add(needed - mass);
      mass = needed;
    }
    const double dt = scale * std::sqrt(2.0 * mass / k);
    if (owned && dt < step.dt) step = {dt, static_cast<std::int32_t>(node)};
  });
  r.sum(r.sums);
  s.mass_added += r.sums[0].value();
  r.values.assign(1, step.dt), r.indices.assign(1, step.node);
  r.min_with_index(r.values, r.indices);
  return {r.values[0], r.indices[0]};
}

double next_output_time(double t, double start, double interval) {
  const double reached = t * (1.0 + 1e-12);  // an output is due once t >= next (1 - 1e-12)
  double next = start + (std::floor((reached - start) / interval) + 1.0) * interval;
  if (next <= reached) next += interval;  // rounding of the quotient
  return std::max(next, start);
}

}  // namespace crumple::solver
