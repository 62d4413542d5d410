// Solver state of the springs (docs/theory/spring.md): per-group parameters from the part's property (/PROP/TYPE4,
// TYPE8, TYPE13), each spring's length at rest, mass, frame and step.
#include <cmath>
#include <algorithm>
#include <vector>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "crumple/core/deck_error.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/core/vec3.hpp"
#include "crumple/elements/spring.hpp"
#include "crumple/model/mass.hpp"
#include "crumple/model/skews.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {

namespace {

// The direction a beam-type spring's Y is taken from at rest: towards its orientation node, else its property's
// skew's Y, else global Y (SP-15; measured: the node wins over the skew).
Vec3 reference_y(const Model& m, const ElementGroup& group, std::size_t e) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  if (!table.orientation_node.empty() && table.orientation_node[e] >= 0)
    return m.nodes.position(table.orientation_node[e]) - m.nodes.position(table.nodes_of(e)[0]);
  const SpringSection& section = m.properties[static_cast<std::size_t>(group.property)].spring;
  if (section.skew < 0) return {0.0, 1.0, 0.0};
  return skew_axes(m.skews[static_cast<std::size_t>(section.skew)], m.nodes.x, m.nodes.y, m.nodes.z).axis[1];
}

// SP-25f: a joint's frame at rest (the reference's starter listing): the global axes; given node_ID3 alone, X from
// node 1 to it, Y = X x e_x where X's largest component is z, else e_z x X, Z = X x Y; given node_ID4 too, a along
// node_ID3, b towards node_ID4 normal to a, and (X, Y, Z) = (a, b, a x b), the universal joint's (a x b, a, b); given
// neither but a Skew_ID1, its axes at rest. Returns the rest offset of node 2 from node 1 in it.
Vec3 joint_frame_at_rest(const Model& m, std::size_t e, const SpringJoint& joint, SpringState& st) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  const std::int32_t* n = table.nodes_of(e);
  const std::int32_t third = table.orientation_node.empty() ? -1 : table.orientation_node[e];
  const std::int32_t fourth = table.plane_node.empty() ? -1 : table.plane_node[e];
  std::array<Vec3, 3> f{Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}, Vec3{0.0, 0.0, 1.0}};
  const auto unit = [](const Vec3& v) { return scaled(v, 1.0 / norm(v)); };
  if (third >= 0) {
    const Vec3 a = unit(m.nodes.position(third) - m.nodes.position(n[0]));
    Vec3 b;
    if (fourth >= 0) {
      const Vec3 towards = m.nodes.position(fourth) - m.nodes.position(n[0]);
      b = unit(towards - scaled(a, dot(a, towards)));
    } else {
      const bool z_largest = std::abs(a.z) >= std::abs(a.x) && std::abs(a.z) >= std::abs(a.y);
      b = unit(z_largest ? cross(a, Vec3{1.0, 0.0, 0.0}) : cross(Vec3{0.0, 0.0, 1.0}, a));
    }
    f = joint.universal() ? std::array<Vec3, 3>{cross(a, b), a, b} : std::array<Vec3, 3>{a, b, cross(a, b)};
  } else if (joint.skew >= 0) {
    const SkewAxes skew = skew_axes(m.skews[static_cast<std::size_t>(joint.skew)], m.nodes.x, m.nodes.y, m.nodes.z);
    f = {skew.axis[0], skew.axis[1], skew.axis[2]};
  }
  double* frame = &st.joint_frame[9 * e];
  for (std::size_t k = 0; k < 3; ++k) frame[3 * k] = f[k].x, frame[3 * k + 1] = f[k].y, frame[3 * k + 2] = f[k].z;
  const Vec3 offset = m.nodes.position(n[1]) - m.nodes.position(n[0]);
  return {dot(f[0], offset), dot(f[1], offset), dot(f[2], offset)};
}

// SP-19: a spring's step is its nodes', each node's whole mass and inertia held by every spring on it, their
// stiffnesses and dampings added (measured: a spring between nodes of 10 kg added mass steps as those nodes, 3.3 times
// its own step; springs of three types on the same nodes step as their nodes' sums).
void setup_spring_steps(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  SpringState& st = s.springs;
  st.node_held.assign(SpringState::kNodeHeldValues * m.nodes.size(), 0.0), st.own_held.assign(4 * table.size(), 0.0);
  for (std::size_t k = 0; k < m.nodes.size(); ++k)  // the nodes' own mass and inertia, before a tie takes them (TI-3)
    st.node_held[SpringState::kNodeHeldValues * k + 4] = s.nodes.mass[k], st.node_held[SpringState::kNodeHeldValues * k + 5] = s.nodes.inertia[k];
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    if (m.element_groups[g].kind != ElementKind::Spring) continue;
    for (std::int32_t e = m.element_groups[g].begin; e < m.element_groups[g].end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const SpringStepStiffness k =
          spring_step_stiffness(spring_of_length(s.spring_groups[g], st.length0[ue]), st.length0[ue]);
      const double own[4] = {k.translation, k.translation_damping, k.rotation, k.rotation_damping};
      for (std::size_t i = 0; i < 4; ++i) st.own_held[4 * ue + i] = own[i];
      for (int a = 0; a < 2; ++a)
        for (std::size_t i = 0; i < 4; ++i)
          st.node_held[SpringState::kNodeHeldValues * static_cast<std::size_t>(table.nodes_of(ue)[a]) + i] += own[i];
    }
  }
  refresh_spring_steps(m, s);
}

// SP-25: what a joint takes of a rigid body: its mass, its smallest principal inertia, and the joint node's distance
// from its centre (the main node, which sits there).
struct JointBody {
  double mass = 0.0, least_inertia = 0.0, mean_inertia = 0.0, arm = 0.0;
};
JointBody joint_body(const SolverState& s, const RigidBodyState& body, std::int32_t node) {
  Eigen::Matrix3d inertia;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inertia(i, j) = body.inertia_body[static_cast<std::size_t>(3 * i + j)];
  const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly).eigenvalues()(0);
  const double arm = norm(node_position(s.nodes, node) - node_position(s.nodes, body.main_node));
  return {body.mass, least, inertia.trace() / 3.0, arm};
}

// SP-25i: a given Kn holds the translations and ScF Kn the rotations (measured: Kn 1e5 N/m, ScF 2, every row of the
// reference's to 4 digits). Above the automatic stiffness at ScF 1 (`translation`, `rotation`) the joint bounds the
// reference's step by a rule not measured (Kn 1e7, ScF 10: its step 2.434e-5 against the /DTIX 1e-4): refused.
void take_given_stiffness(const Property& p, const SpringJoint& joint, double translation, double rotation, double* v) {
  const double given = joint.blocking_stiffness, given_rotation = joint.stiffness_scale * joint.blocking_stiffness;
  if (given > translation || given_rotation > rotation)
    throw DeckError(p.where, fmt::format("/PROP/TYPE45/{}", p.user_id), "Kn",
                    fmt::format("a blocking stiffness at most the automatic one at the first step, {:.4g} (and ScF Kn at "
                                "most {:.4g} for the rotations; a stiffer joint bounds the reference's step by a rule "
                                "Crumple does not have)",
                                translation, rotation),
                    fmt::format("Kn {:g}, ScF Kn {:g}", given, given_rotation));
  v[0] = given, v[1] = given_rotation;
}

}  // namespace

bool has_joints(const Model& m) {
  for (const ElementGroup& group : m.element_groups)
    if (group.kind == ElementKind::Spring && m.properties[static_cast<std::size_t>(group.property)].spring.joint.on)
      return true;
  return false;
}

// SP-25c to SP-25e (measured on the reference's listing of its automatic stiffness and the decay of its joints):
// with m the smaller body mass, I the smallest principal inertia of the two bodies and d the larger distance of a
// joint node from its body's centre, K_t = ScF min(2 m, 0.8 I / d^2) / (4.1 dt^2), K_r = ScF I / (4.1 dt^2); the
// translations damped at Cr sqrt(K_t m1 m2 / (m1 + m2)), the rotations at Cr sqrt(K_r J1 J2 / (J1 + J2)), J a body's
// mean principal inertia. Each body steps on them as a held mass and inertia, eq. SP-4.
void resolve_joints(const Model& m, SolverState& s, double dt) {
  std::vector<std::int32_t> body_of(s.nodes.size(), -1);
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    for (std::int32_t node : s.bodies[b].secondary) body_of[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(b);
    body_of[static_cast<std::size_t>(s.bodies[b].main_node)] = static_cast<std::int32_t>(b);
  }
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Spring || !s.spring_groups[g].joint.on) continue;
    const SpringJoint& joint = s.spring_groups[g].joint;
    for (auto e = static_cast<std::size_t>(group.begin); e < static_cast<std::size_t>(group.end); ++e) {
      const std::int32_t* n = table.nodes_of(e);
      JointBody b[2];
      for (int a = 0; a < 2; ++a)
        b[a] = joint_body(s, s.bodies[static_cast<std::size_t>(body_of[static_cast<std::size_t>(n[a])])], n[a]);
      const double mass = std::min(b[0].mass, b[1].mass), inertia = std::min(b[0].least_inertia, b[1].least_inertia);
      const double arm = std::max(b[0].arm, b[1].arm), per_step = joint.stiffness_scale / (4.1 * dt * dt);
      const double held = arm > 0.0 ? std::min(2.0 * mass, 0.8 * inertia / (arm * arm)) : 2.0 * mass;
      const double translation = per_step * held;
      const double reduced = b[0].mass * b[1].mass / (b[0].mass + b[1].mass);
      const double reduced_inertia = b[0].mean_inertia * b[1].mean_inertia / (b[0].mean_inertia + b[1].mean_inertia);
      double* v = &s.springs.joint[SpringState::kJointValues * e];
      v[0] = translation, v[1] = per_step * inertia;
      if (joint.blocking_stiffness > 0.0) take_given_stiffness(m.properties[static_cast<std::size_t>(group.property)],
                                                               joint, held / (4.1 * dt * dt), inertia / (4.1 * dt * dt), v);
      v[2] = joint.critical_damping * std::sqrt(v[0] * reduced);
      v[3] = joint.critical_damping * std::sqrt(v[1] * reduced_inertia);
      double step = 1e30;
      const SpringGroupParameters& p = s.spring_groups[g];
      for (int a = 0; a < 2; ++a)  // each body held by each degree of freedom, a mass or its smallest moment
        for (std::size_t d = 0; d < p.dof.size(); ++d) {
          const bool rotation = d >= 3;
          const double held_by = rotation ? b[a].least_inertia : b[a].mass;
          step = std::min(step, joint.free(d) ? held_mass_step(held_by, p.dof[d].stiffness, p.dof[d].damping)
                                              : held_mass_step(held_by, v[rotation ? 1 : 0], v[rotation ? 3 : 2]));
        }
      v[4] = step;
    }
  }
  refresh_spring_steps(m, s);
}

void refresh_spring_steps(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Spring) continue;
    // A pretensioner steps on its own mass and K0, whatever its nodes carry (SP-22, measured).
    const SpringGroupParameters& p = s.spring_groups[g];
    // A joint steps on the bodies it joins (SP-25).
    for (auto e = static_cast<std::size_t>(group.begin); e < static_cast<std::size_t>(group.end); ++e)
      s.springs.nodal_step[e] = p.joint.on         ? s.springs.joint[SpringState::kJointValues * e + 4]
                                : p.pretension.on ? spring_critical_step(p)
                                                  : spring_nodal_step(s.springs, table.nodes_of(e), e);
  }
}

void setup_springs(const Model& m, SolverState& s) {
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  SpringState& st = s.springs;
  st.resize_elements(table.size());
  s.spring_groups.assign(m.element_groups.size(), SpringGroupParameters{});
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Spring) continue;
    const SpringSection& section = m.properties[static_cast<std::size_t>(group.property)].spring;
    SpringGroupParameters& group_p = s.spring_groups[g] = spring_parameters(section, m.functions);
    if (group_p.frame == SpringFrame::Global) group_p.skew = section.skew;  // SP-9b
    // The general spring's rest offset in its skew's axes at rest (every domain holds every node here).
    const SkewAxes axes = group_p.skew >= 0 ? skew_axes(m.skews[static_cast<std::size_t>(group_p.skew)], m.nodes.x,
                                                        m.nodes.y, m.nodes.z)
                                            : SkewAxes{};
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int32_t* n = table.nodes_of(ue);
      st.length0[ue] = element_measure(m.nodes, ElementKind::Spring, n);
      const SpringGroupParameters p = spring_of_length(group_p, st.length0[ue]);
      const Vec3 offset = m.nodes.position(n[1]) - m.nodes.position(n[0]);
      const Vec3 rest = group_p.joint.on ? joint_frame_at_rest(m, ue, group_p.joint, st) : to_skew(axes, offset);
      st.rest_offset[3 * ue] = rest.x, st.rest_offset[3 * ue + 1] = rest.y, st.rest_offset[3 * ue + 2] = rest.z;
      if (p.frame == SpringFrame::Beam && st.length0[ue] > 0.0) {  // SP-15: its Y at rest
        const Vec3 y = geometry::rest_frame_y(scaled(offset, 1.0 / st.length0[ue]), reference_y(m, group, ue));
        st.frame_y[3 * ue] = y.x, st.frame_y[3 * ue + 1] = y.y, st.frame_y[3 * ue + 2] = y.z;
      }
      st.mass[ue] = element_mass(m, ElementKind::Spring, ue);
      // The stiffness it gives each node in the nodal steps (SP-4a): a general spring's stiffest translation.
      st.step_stiffness[ue] = spring_step_stiffness(p, st.length0[ue]).translation;
      for (int a = 0; a < 2; ++a) s.nodes.inertia[static_cast<std::size_t>(n[a])] += 0.5 * p.inertia;  // half each
      if (p.pretension.on) st.internal_energy[ue] = pretension_stored_energy(p);  // SP-22, SP-22c: from t = 0
    }
  }
  setup_spring_steps(m, s);
}

}  // namespace crumple::solver
