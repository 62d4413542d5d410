// Rigid bodies (/RBODY): mass and inertia from the nodes, 6-dof motion driven by the gathered nodal forces,
// exact rigid placement of the secondary nodes every cycle (docs/theory/rigid-bodies.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/state/element_status.hpp"
#include "crumple/elements/critical_step.hpp"
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

using Mat3 = std::array<double, 9>;

Vec3 mul(const Mat3& a, const Vec3& v) {
  return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
          a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}
Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(3 * i + j)] += a[static_cast<std::size_t>(3 * i + k)] * b[static_cast<std::size_t>(3 * k + j)];
  return c;
}
Mat3 transpose(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

// Solves I w = L for a symmetric positive semi-definite I; directions of zero inertia get no rotation.
Vec3 solve(const Mat3& I, const Vec3& L) {
  const double det = I[0] * (I[4] * I[8] - I[5] * I[7]) - I[1] * (I[3] * I[8] - I[5] * I[6]) +
                     I[2] * (I[3] * I[7] - I[4] * I[6]);
  const double scale = std::abs(I[0]) + std::abs(I[4]) + std::abs(I[8]);
  if (!(std::abs(det) > 1e-30 * scale * scale * scale)) return {0.0, 0.0, 0.0};
  const Mat3 inv{(I[4] * I[8] - I[5] * I[7]) / det, (I[2] * I[7] - I[1] * I[8]) / det, (I[1] * I[5] - I[2] * I[4]) / det,
                 (I[5] * I[6] - I[3] * I[8]) / det, (I[0] * I[8] - I[2] * I[6]) / det, (I[2] * I[3] - I[0] * I[5]) / det,
                 (I[3] * I[7] - I[4] * I[6]) / det, (I[1] * I[6] - I[0] * I[7]) / det, (I[0] * I[4] - I[1] * I[3]) / det};
  return mul(inv, L);
}

// Rotation by the vector phi (Rodrigues): exp([phi]x).
Mat3 rotation_of(const Vec3& phi) {
  const double angle = std::sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]);
  if (angle < 1e-300) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const Vec3 k{phi[0] / angle, phi[1] / angle, phi[2] / angle};
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {t * k[0] * k[0] + c,        t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1],
          t * k[0] * k[1] + s * k[2], t * k[1] * k[1] + c,        t * k[1] * k[2] - s * k[0],
          t * k[0] * k[2] - s * k[1], t * k[1] * k[2] + s * k[0], t * k[2] * k[2] + c};
}



// Adds the inertia of a point mass at r from the reference point: m (|r|^2 1 - r r^T).
void add_point_inertia(Mat3& I, double mass, Vec3 r) {
  const double rr = dot(r, r);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) I[3 * i + j] += mass * ((i == j ? rr : 0.0) - r[i] * r[j]);
}

// The body's centre by ICoG (eq. RB-0e): 1 the centre of all its masses, 2 of its secondary nodes' masses (the
// main node's and the card's mass put there), 3 and 4 the main node where it is. `main_mass` is the main node's
// mass (the card's included), `secondary` the first moment and mass of the secondary nodes.
Vec3 body_centre(int icog, Vec3 main, double main_mass, Vec3 secondary_moment, double secondary_mass) {
  if (icog == 1 && main_mass + secondary_mass > 0.0)
    return scaled(scaled(main, main_mass) + secondary_moment, 1.0 / (main_mass + secondary_mass));
  if (icog == 2 && secondary_mass > 0.0) return scaled(secondary_moment, 1.0 / secondary_mass);
  return main;  // ICoG 3, 4, or no mass to weigh: the main node stays
}

// Mass, centre, inertia and velocity field of a body from its nodes' current positions, masses and velocities
// (eqs. RB-0a to RB-0e); the main node moves to the centre. ICoG 4 drops the secondary nodes' masses at the start:
// the body is the main node's mass and the card's inertia, as in the reference (measured: its total mass drops).
// `at_start`: the first forming, where the main node's initial velocity moves the body (RB-0c); a body formed
// again by /RBODY/ON takes its nodes' momentum.
void form_body(const RigidBody& rb, const Model& m, SolverState& s, std::int32_t index, RigidBodyState& b,
               bool at_start) {
  NodalState& n = s.nodes;
  b.main_node = rb.main_node;
  b.secondary.clear(), b.rx.clear(), b.ry.clear(), b.rz.clear();
  for (std::int32_t node : m.node_groups[static_cast<std::size_t>(rb.node_group)].nodes)
    if (node != rb.main_node) b.secondary.push_back(node);
  const auto main = static_cast<std::size_t>(rb.main_node);
  if (rb.icog == 4 && at_start)
    for (std::int32_t node : b.secondary) n.mass[static_cast<std::size_t>(node)] = 0.0;
  double secondary_mass = 0.0;
  Vec3 secondary_moment{}, momentum{n.mass[main] * n.vx[main], n.mass[main] * n.vy[main], n.mass[main] * n.vz[main]};
  for (std::int32_t node : b.secondary) {
    const auto k = static_cast<std::size_t>(node);
    secondary_moment = secondary_moment + scaled(node_position(n, node), n.mass[k]);
    momentum = momentum + scaled({n.vx[k], n.vy[k], n.vz[k]}, n.mass[k]);
    secondary_mass += n.mass[k];
    s.rigid_owner[k] = index;
  }
  const double mass = n.mass[main] + secondary_mass;
  b.mass = mass;
  s.rigid_owner[main] = index;
  // A body without mass (inertia from the card only) keeps the velocity its main node has.
  if (!(mass > 0.0)) momentum = {n.vx[main], n.vy[main], n.vz[main]};
  const Vec3 main_at = node_position(n, rb.main_node);
  const Vec3 cog = body_centre(rb.icog, main_at, n.mass[main], secondary_moment, secondary_mass);
  n.x[main] = cog[0], n.y[main] = cog[1], n.z[main] = cog[2];
  // Inertia about the centre: the card's added inertia (written in its skew, if any, SK-6), the main node's mass
  // where it was (ICoG 1; 3 and 4 have it at the centre; 2 puts it there), then the secondary nodes' (RB-0e). The
  // main node's part is not carried by a nodal mass there any more: it counts with the card's.
  Mat3 I{rb.inertia[0], rb.inertia[3], rb.inertia[5], rb.inertia[3], rb.inertia[1], rb.inertia[4],
         rb.inertia[5], rb.inertia[4], rb.inertia[2]};
  if (rb.skew >= 0) {
    const SkewAxes& a = s.skew_axes[static_cast<std::size_t>(rb.skew)];
    const Mat3 Q{a.axis[0].x, a.axis[1].x, a.axis[2].x, a.axis[0].y, a.axis[1].y, a.axis[2].y,
                 a.axis[0].z, a.axis[1].z, a.axis[2].z};  // columns: the skew's axes
    I = mul(mul(Q, I), transpose(Q));
  }
  if (rb.icog != 2) add_point_inertia(I, n.mass[main], main_at - cog);  // ICoG 2 puts it at the centre
  b.inertia_added = I;
  Vec3 angular{};
  b.first_moment = {};
  for (std::int32_t node : b.secondary) {
    const auto k = static_cast<std::size_t>(node);
    const Vec3 p = node_position(n, node);
    const Vec3 r{p[0] - cog[0], p[1] - cog[1], p[2] - cog[2]};
    b.rx.push_back(r[0]), b.ry.push_back(r[1]), b.rz.push_back(r[2]);
    const double mk = n.mass[k];
    add_point_inertia(I, mk, r);
    b.first_moment = b.first_moment + scaled(r, mk);
    const Vec3 h = cross(r, {n.vx[k], n.vy[k], n.vz[k]});
    for (int d = 0; d < 3; ++d) angular[static_cast<std::size_t>(d)] += mk * h[static_cast<std::size_t>(d)];
  }
  // Ispher 1: the inertia made spherical, the mean of its principal moments about every axis (RB-0d); the part of
  // it the nodes do not carry counts as added inertia, so that the kinetic energy stays that of the body.
  if (rb.ispher == 1) {
    const double spherical = (I[0] + I[4] + I[8]) / 3.0;
    for (std::size_t c = 0; c < 9; ++c) {
      const double target = c % 4 == 0 ? spherical : 0.0;
      b.inertia_added[c] += target - I[c];
      I[c] = target;
    }
  }
  b.inertia_body = I;
  b.rotation = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  // The body starts with one velocity field (RB-0c): the main node's velocity when the start gives it one (an
  // /INIVEL on the main node moves the whole body, as in the reference, whatever the main node's mass), else the
  // nodes' mean translation and their angular momentum.
  Vec3 velocity{momentum[0] / (mass > 0.0 ? mass : 1.0), momentum[1] / (mass > 0.0 ? mass : 1.0),
              momentum[2] / (mass > 0.0 ? mass : 1.0)};
  const Vec3 main_velocity{n.vx[main], n.vy[main], n.vz[main]}, main_spin{n.wx[main], n.wy[main], n.wz[main]};
  const bool driven_by_main = at_start && (main_velocity != Vec3{} || main_spin != Vec3{});
  if (driven_by_main) {
    velocity = main_velocity;
    angular = mul(I, main_spin);
  }
  b.momentum_angular = angular;
  b.omega = driven_by_main ? main_spin : solve(I, angular);
  b.velocity = velocity;
  n.vx[main] = velocity[0], n.vy[main] = velocity[1], n.vz[main] = velocity[2];
  n.wx[main] = b.omega[0], n.wy[main] = b.omega[1], n.wz[main] = b.omega[2];
  for (std::size_t i = 0; i < b.secondary.size(); ++i) {
    const auto k = static_cast<std::size_t>(b.secondary[i]);
    const Vec3 spin = cross(b.omega, {b.rx[i], b.ry[i], b.rz[i]});
    n.vx[k] = velocity[0] + spin[0], n.vy[k] = velocity[1] + spin[1], n.vz[k] = velocity[2] + spin[2];
  }
  b.active = true;
}

// Fixed dofs (/BCS) and /IMPVEL, /IMPDISP cards of the main node act on the whole body (eq. RB-4): they replace
// the free velocity or angular velocity in those dofs (the angular momentum follows, L = I w). Returns their
// work, the change of momentum times the mid-step velocity, like any other kinematic condition (energy.md).
double drive_body(const Model& m, const SolverState& s, RigidBodyState& b, const Vec3& velocity_before,
                  const Vec3& omega_before, const Mat3& inertia, double dt_next) {
  std::array<double, 6> v{b.velocity[0], b.velocity[1], b.velocity[2], b.omega[0], b.omega[1], b.omega[2]};
  if (!drive_main_node(m, s, b.main_node, b.main_node_conditions, b.main_node_skewed_fixes, v, dt_next)) return 0.0;
  const Vec3 momentum_free = b.momentum_angular;
  double work = 0.0;
  for (std::size_t d = 0; d < 3; ++d) {
    work += b.mass * (v[d] - b.velocity[d]) * 0.5 * (v[d] + velocity_before[d]);
    b.velocity[d] = v[d], b.omega[d] = v[d + 3];
  }
  b.momentum_angular = mul(inertia, b.omega);
  for (std::size_t d = 0; d < 3; ++d)
    work += (b.momentum_angular[d] - momentum_free[d]) * 0.5 * (b.omega[d] + omega_before[d]);
  return work;
}

// Elements whose every node belongs to one active rigid body are carried by it and not computed (the reference
// manual: "all the elements belonging to the rigid body are deactivated"); the others are computed again, e.g.
// after /RBODY/OFF. Deleted elements stay deleted.
void mark_elements_in_rigid_bodies(const Model& m, SolverState& s) {
  for (const ElementTable& table : m.elements) {
    std::vector<std::uint8_t>& status = element_state(s, table.kind).deleted;
    const int n = nodes_per_element(table.kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      if (element_condition(status[e]) == kElementDeleted) continue;
      const std::int32_t* nodes = table.nodes_of(e);
      const std::int32_t owner = s.rigid_owner[static_cast<std::size_t>(nodes[0])];
      bool inside = owner >= 0 && s.bodies[static_cast<std::size_t>(owner)].active;
      for (int a = 1; a < n && inside; ++a) inside = s.rigid_owner[static_cast<std::size_t>(nodes[a])] == owner;
      status[e] = static_cast<std::uint8_t>((status[e] & kElementElsewhere) | (inside ? kElementInRigidBody : kElementActive));
    }
  }
}

// The rigid-body mass of every node for the contact step (ContactState::rigid_body_mass, eq. C-11).
void mark_contact_nodes_in_rigid_bodies(SolverState& s) {
  if (s.contact.interfaces.empty()) return;
  s.contact.rigid_body_mass.assign(s.nodes.size(), 0.0);
  for (std::size_t k = 0; k < s.nodes.size(); ++k) {
    const std::int32_t owner = s.rigid_owner[k];
    if (owner >= 0 && s.bodies[static_cast<std::size_t>(owner)].active)
      s.contact.rigid_body_mass[k] = s.bodies[static_cast<std::size_t>(owner)].mass;
  }
}

}  // namespace

bool drive_main_node(const Model& m, const SolverState& s, std::int32_t main_node,
                     const std::vector<std::int32_t>& conditions, const std::vector<std::int32_t>& skewed_fixes,
                     std::array<double, 6>& v, double dt_next) {
  const auto main = static_cast<std::size_t>(main_node);
  std::uint8_t driven = s.fixed[main];
  for (int d = 0; d < 6; ++d)
    if (driven & (1u << d)) v[static_cast<std::size_t>(d)] = 0.0;
  // A condition in a skew sets the component along the skew's axis (eq. SK-5) of the translation or the rotation.
  auto set_along = [&v](bool rotation, Vec3 e, double value) {
    const std::size_t first = rotation ? 3 : 0;
    const Vec3 set = with_component({v[first], v[first + 1], v[first + 2]}, e, value);
    v[first] = set.x, v[first + 1] = set.y, v[first + 2] = set.z;
  };
  for (std::int32_t c : skewed_fixes) {
    const BoundaryCondition& bc = m.boundary_conditions[static_cast<std::size_t>(c)];
    const SkewAxes& a = s.skew_axes[static_cast<std::size_t>(bc.skew)];
    for (std::size_t d = 0; d < 3; ++d) {
      if (bc.fixed_translation[d]) set_along(false, a.axis[d], 0.0);
      if (bc.fixed_rotation[d]) set_along(true, a.axis[d], 0.0);
    }
    driven = static_cast<std::uint8_t>(driven | 64u);
  }
  for (std::int32_t c : conditions) {
    const ImposedMotion& im = m.imposed[static_cast<std::size_t>(c)];
    if (const auto value = imposed_velocity(m, s, im, main, s.time, dt_next)) {
      if (im.skew < 0)
        v[static_cast<std::size_t>(im.dof)] = *value;
      else
        set_along(is_rotation(im.dof), s.skew_axes[static_cast<std::size_t>(im.skew)].axis[dof_axis(im.dof)], *value);
      driven = static_cast<std::uint8_t>(driven | 64u);
    }
  }
  return driven != 0;
}

void find_main_node_conditions(const Model& m, std::int32_t main_node, std::vector<std::int32_t>& conditions,
                               std::vector<std::int32_t>& skewed_fixes) {
  for (std::size_t c = 0; c < m.imposed.size(); ++c) {
    const ImposedMotion& im = m.imposed[c];
    if (im.kind == ImposedKind::Force) continue;
    const auto& nodes = m.node_groups[static_cast<std::size_t>(im.node_group)].nodes;
    if (std::find(nodes.begin(), nodes.end(), main_node) != nodes.end()) conditions.push_back(static_cast<std::int32_t>(c));
  }
  for (std::size_t c = 0; c < m.boundary_conditions.size(); ++c) {
    const BoundaryCondition& bc = m.boundary_conditions[c];
    const auto& nodes = m.node_groups[static_cast<std::size_t>(bc.node_group)].nodes;
    if (bc.skew >= 0 && std::find(nodes.begin(), nodes.end(), main_node) != nodes.end())
      skewed_fixes.push_back(static_cast<std::int32_t>(c));
  }
}

void setup_rigid_bodies(const Model& m, SolverState& s) {
  for (std::size_t index = 0; index < m.rigid_bodies.size(); ++index) {
    const RigidBody& rb = m.rigid_bodies[index];
    RigidBodyState b;
    form_body(rb, m, s, static_cast<std::int32_t>(index), b, true);
    const auto main = static_cast<std::size_t>(rb.main_node);
    s.x0[main] = s.nodes.x[main], s.y0[main] = s.nodes.y[main], s.z0[main] = s.nodes.z[main];
    find_main_node_conditions(m, rb.main_node, b.main_node_conditions, b.main_node_skewed_fixes);
    s.bodies.push_back(std::move(b));
  }
  if (!s.bodies.empty()) mark_elements_in_rigid_bodies(m, s), mark_contact_nodes_in_rigid_bodies(s);
}

namespace {

// The body's nodes move on their own from now, with the velocities the body gave them.
void release_body(SolverState& s, RigidBodyState& b) {
  b.active = false;
  for (std::int32_t node : b.secondary) s.rigid_owner[static_cast<std::size_t>(node)] = -1;
  s.rigid_owner[static_cast<std::size_t>(b.main_node)] = -1;
}

}  // namespace

void switch_rigid_bodies(const Model& m, SolverState& s) {
  for (std::int32_t body : m.run.bodies_off) release_body(s, s.bodies[static_cast<std::size_t>(body)]);
  for (std::int32_t body : m.run.bodies_on) {
    RigidBodyState& b = s.bodies[static_cast<std::size_t>(body)];
    if (!b.active) form_body(m.rigid_bodies[static_cast<std::size_t>(body)], m, s, body, b, false);
  }
  if (!m.run.bodies_on.empty() || !m.run.bodies_off.empty())
    mark_elements_in_rigid_bodies(m, s), mark_contact_nodes_in_rigid_bodies(s);
}

StepBound sensor_bodies_step(const Model& m, double scale) {
  StepBound bound;
  std::vector<std::int32_t> body_of(m.nodes.size(), -1);  // the sensor body each node is in
  for (std::size_t i = 0; i < m.rigid_bodies.size(); ++i) {
    const RigidBody& rb = m.rigid_bodies[i];
    if (rb.sensor_id == 0) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(rb.node_group)].nodes)
      body_of[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(i);
    body_of[static_cast<std::size_t>(rb.main_node)] = static_cast<std::int32_t>(i);
  }
  for (const ElementTable& table : m.elements)
    for (std::size_t e = 0; e < table.size(); ++e) {
      const std::int32_t* nodes = table.nodes_of(e);
      const std::int32_t body = body_of[static_cast<std::size_t>(nodes[0])];
      bool carried = body >= 0;
      for (int a = 1; a < nodes_per_element(table.kind) && carried; ++a)
        carried = body_of[static_cast<std::size_t>(nodes[a])] == body;
      if (!carried) continue;
      const double dt = scale * initial_element_time_step(m, table.kind, e);
      if (dt < bound.dt) bound.dt = dt, bound.control = StepControl::element(table.kind, static_cast<std::int32_t>(e));
    }
  return bound;
}

bool rigid_bodies_have_sensors(const Model& m) {
  return std::any_of(m.rigid_bodies.begin(), m.rigid_bodies.end(), [](const RigidBody& b) { return b.sensor_id != 0; });
}

// A body with a sensor is off while the sensor is on (RB-6): released when it turns on, formed again from its nodes'
// positions and velocities when it turns off. Every domain decides alike from the time.
void switch_rigid_bodies_by_sensors(const Model& m, SolverState& s) {
  bool switched = false;
  for (std::size_t i = 0; i < m.rigid_bodies.size(); ++i) {
    const RigidBody& rb = m.rigid_bodies[i];
    RigidBodyState& b = s.bodies[i];
    const bool on = !rb.sensor.holds(s.time);
    if (rb.sensor_id == 0 || on == b.active) continue;
    if (on) form_body(rb, m, s, static_cast<std::int32_t>(i), b, false);
    else release_body(s, b);
    switched = true;
  }
  if (switched) mark_elements_in_rigid_bodies(m, s), mark_contact_nodes_in_rigid_bodies(s);
}

// Each body's resultant about its centre (eq. RB-1, RB-2): exact sums of its nodes' forces and moments, each node
// from the domain that owns it, combined over the domains, so that every domain moves the body alike.
void gather_rigid_body_forces(SolverState& s) {
  NodalState& n = s.nodes;
  std::vector<ExactSum>& sums = s.reducer.sums;
  sums.assign(6 * s.bodies.size(), ExactSum{});
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    RigidBodyState& b = s.bodies[i];
    if (!b.active) continue;
    ExactSum* resultant = &sums[6 * i];  // fx fy fz mx my mz
    const auto main = static_cast<std::size_t>(b.main_node);
    if (s.domain.owns(main)) {
      const double own[6] = {n.fx[main], n.fy[main], n.fz[main], n.mx[main], n.my[main], n.mz[main]};
      for (int c = 0; c < 6; ++c) resultant[c].add(own[c]);
    }
    const Vec3 cog = node_position(n, b.main_node);
    for (std::int32_t node : b.secondary) {
      const auto k = static_cast<std::size_t>(node);
      if (s.domain.owns(k)) {
        const Vec3 r{n.x[k] - cog[0], n.y[k] - cog[1], n.z[k] - cog[2]};
        const Vec3 f{n.fx[k], n.fy[k], n.fz[k]};
        const Vec3 t = cross(r, f);
        const double terms[6] = {f[0], f[1], f[2], t[0] + n.mx[k], t[1] + n.my[k], t[2] + n.mz[k]};
        for (int c = 0; c < 6; ++c) resultant[c].add(terms[c]);
      }
      n.fx[k] = n.fy[k] = n.fz[k] = n.mx[k] = n.my[k] = n.mz[k] = 0.0;
    }
  }
  if (s.bodies.empty()) return;
  s.reducer.sum(sums);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const RigidBodyState& b = s.bodies[i];
    if (!b.active) continue;
    const auto main = static_cast<std::size_t>(b.main_node);
    const ExactSum* resultant = &sums[6 * i];
    n.fx[main] = resultant[0].value(), n.fy[main] = resultant[1].value(), n.fz[main] = resultant[2].value();
    n.mx[main] = resultant[3].value(), n.my[main] = resultant[4].value(), n.mz[main] = resultant[5].value();
  }
}

std::array<double, 9> body_inertia_global(const RigidBodyState& b) {
  return mul(mul(b.rotation, b.inertia_body), transpose(b.rotation));
}

double update_rigid_bodies(const Model& m, SolverState& s, double dt_average, double dt_next) {
  NodalState& n = s.nodes;
  double work = 0.0;
  for (RigidBodyState& b : s.bodies) {
    if (!b.active) continue;
    const auto main = static_cast<std::size_t>(b.main_node);
    const Vec3 velocity_before = b.velocity, omega_before = b.omega;
    // Newton for the whole body (eq. RB-1): the gathered force over the total mass.
    if (b.mass > 0.0)
      for (int d = 0; d < 3; ++d)
        b.velocity[static_cast<std::size_t>(d)] +=
            dt_average * (d == 0 ? n.fx[main] : d == 1 ? n.fy[main] : n.fz[main]) / b.mass;
    // Angular momentum about the centre of mass: dL/dt = torque (eq. RB-2); omega = I(t)^-1 L.
    for (int d = 0; d < 3; ++d)
      b.momentum_angular[static_cast<std::size_t>(d)] += dt_average * (d == 0 ? n.mx[main] : d == 1 ? n.my[main] : n.mz[main]);
    // omega belongs to the half step (eq. RB-2b): take it from the inertia at the mid-step attitude, predicted
    // with the attitude-of-t^n omega. The explicit Lie-Euler step (omega at t^n) lets the kinetic energy of a
    // tumbling body drift at first order in dt; the mid-step attitude makes the update second order.
    auto inertia_at = [&](const Mat3& attitude) { return mul(mul(attitude, b.inertia_body), transpose(attitude)); };
    const Vec3 omega_start = solve(inertia_at(b.rotation), b.momentum_angular);
    const double half = 0.5 * dt_next;
    const Mat3 inertia_mid = inertia_at(mul(rotation_of({omega_start[0] * half, omega_start[1] * half, omega_start[2] * half}), b.rotation));
    b.omega = solve(inertia_mid, b.momentum_angular);
    work += drive_body(m, s, b, velocity_before, omega_before, inertia_mid, dt_next);
    const Vec3 velocity = b.velocity;
    n.vx[main] = velocity[0], n.vy[main] = velocity[1], n.vz[main] = velocity[2];
    n.wx[main] = b.omega[0], n.wy[main] = b.omega[1], n.wz[main] = b.omega[2];
    // Secondary nodes: velocities that land them exactly on the rigid placement at t^(n+1) (eq. RB-3).
    const Mat3 next = mul(rotation_of({b.omega[0] * dt_next, b.omega[1] * dt_next, b.omega[2] * dt_next}), b.rotation);
    const Vec3 cog_next{n.x[main] + velocity[0] * dt_next, n.y[main] + velocity[1] * dt_next,
                      n.z[main] + velocity[2] * dt_next};
    for (std::size_t i = 0; i < b.secondary.size(); ++i) {
      const auto k = static_cast<std::size_t>(b.secondary[i]);
      const Vec3 r = mul(next, Vec3{b.rx[i], b.ry[i], b.rz[i]});
      if (dt_next > 0.0) {
        n.vx[k] = (cog_next[0] + r[0] - n.x[k]) / dt_next;
        n.vy[k] = (cog_next[1] + r[1] - n.y[k]) / dt_next;
        n.vz[k] = (cog_next[2] + r[2] - n.z[k]) / dt_next;
      }
      n.wx[k] = b.omega[0], n.wy[k] = b.omega[1], n.wz[k] = b.omega[2];
    }
    b.rotation = next;
  }
  return work;
}

}  // namespace crumple::solver
