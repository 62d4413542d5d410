// Tied interfaces (/INTER/TYPE2): each tied node moves with its main segment, as a kinematic condition
// (docs/theory/tied-interfaces.md). Its mass is lumped on the segment's nodes at the start, its force and moment are
// passed to them every cycle, and its velocity follows theirs:
//   Spotflag 0, 2, 5  the segment's shape functions, rotations included (TI-3 to TI-5);
//   Spotflag 4        the same without rotations: the node keeps its own (TI-3 to TI-5);
//   Spotflag 1        the segment moves the node as a rigid body (TI-7 to TI-9).
// Several domains: a tie's nodes may live in different domains. Each node's values of the cycle travel from its owner
// to every domain (TiedState::values), so that every domain computes every tie alike and one domain gives the same
// bits as four (TI-11).
#include <algorithm>

#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

constexpr int kForceValues = 10;    // per tie node: force, moment, position, stiffness of the nodal steps
constexpr int kVelocityValues = 6;  // per tie node: velocity, angular velocity

int distinct_nodes(const std::array<std::int32_t, 4>& main) { return main[3] == main[2] ? 3 : 4; }
bool rigid_segment(int spotflag) { return spotflag == 1; }
bool carries_rotations(int spotflag) { return spotflag != 4; }
bool own_kinetic_energy(int spotflag) { return spotflag == 2 || spotflag == 4; }

Vec3 vec(const double* v) { return {v[0], v[1], v[2]}; }

// The segment as a rigid body (TI-7): its centre, axes (e3 its normal) and its nodes' in-plane places about the centre,
// with the polar moment and the inverse of the second-moment matrix of those places.
struct RigidSegment {
  int count = 4;
  Vec3 centre{}, e1{}, e2{}, e3{};
  std::array<double, 4> a{}, b{};  // the nodes' coordinates along e1, e2
  double polar = 0.0;              // sum (a^2 + b^2) [L^2]
  double s11 = 0.0, s12 = 0.0, s22 = 0.0;  // inverse of sum [a a, a b; a b, b b] [L^-2]
};

RigidSegment rigid_segment_of(const std::array<Vec3, 4>& x, int count) {
  RigidSegment g;
  g.count = count;
  for (int i = 0; i < count; ++i) g.centre = g.centre + scaled(x[static_cast<std::size_t>(i)], 1.0 / count);
  const Vec3 normal = count == 4 ? cross(x[2] - x[0], x[3] - x[1]) : cross(x[1] - x[0], x[2] - x[0]);
  g.e3 = unit(normal);
  const Vec3 side = x[1] - x[0];
  g.e1 = unit(side - scaled(g.e3, dot(side, g.e3)));
  g.e2 = cross(g.e3, g.e1);
  double saa = 0.0, sab = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    const Vec3 r = x[i] - g.centre;
    g.a[i] = dot(r, g.e1), g.b[i] = dot(r, g.e2);
    saa += g.a[i] * g.a[i], sab += g.a[i] * g.b[i], sbb += g.b[i] * g.b[i];
  }
  g.polar = saa + sbb;
  const double det = saa * sbb - sab * sab;
  g.s11 = sbb / det, g.s12 = -sab / det, g.s22 = saa / det;
  return g;
}

// TI-8: the segment's rigid angular velocity, the least-squares fit of its nodes' velocities: about the normal from
// their in-plane motion, about the in-plane axes from the plane fitted through their normal velocities.
Vec3 rigid_angular_velocity(const RigidSegment& g, const std::array<Vec3, 4>& v) {
  double spin = 0.0, wa = 0.0, wb = 0.0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i) {
    spin += g.a[i] * dot(v[i], g.e2) - g.b[i] * dot(v[i], g.e1);
    const double w = dot(v[i], g.e3);
    wa += g.a[i] * w, wb += g.b[i] * w;
  }
  const double slope_a = g.s11 * wa + g.s12 * wb, slope_b = g.s12 * wa + g.s22 * wb;  // dw/da, dw/db
  return scaled(g.e1, slope_b) + scaled(g.e2, -slope_a) + scaled(g.e3, spin / g.polar);
}

// TI-9: node i's share of a force F at the centre and a moment Mc about it, the transpose of TI-8: F / n, the spin's
// couple in the plane, the tilts' couple along the normal.
Vec3 rigid_share(const RigidSegment& g, std::size_t i, const Vec3& force, const Vec3& moment) {
  const double m1 = dot(moment, g.e1), m2 = dot(moment, g.e2), m3 = dot(moment, g.e3);
  const Vec3 spin = scaled(scaled(g.e2, g.a[i]) - scaled(g.e1, g.b[i]), m3 / g.polar);
  const double tilt = -m2 * (g.s11 * g.a[i] + g.s12 * g.b[i]) + m1 * (g.s12 * g.a[i] + g.s22 * g.b[i]);
  return scaled(force, 1.0 / g.count) + spin + scaled(g.e3, tilt);
}

// TI-7: the mass a rigid-segment tie adds so that the segment's nodes carry the node's inertia about the centre:
// (I + m |r|^2) / rho^2, rho half the segment's smaller width (measured on the reference: squares and rectangles).
double rigid_added_mass(const std::array<Vec3, 4>& x, const Vec3& r, double mass, double inertia) {
  const double width1 = norm(scaled(x[1] + x[2] - x[0] - x[3], 0.5)), width2 = norm(scaled(x[2] + x[3] - x[0] - x[1], 0.5));
  const double rho = 0.5 * std::min(width1, width2);
  return rho > 0.0 ? (inertia + mass * dot(r, r)) / (rho * rho) : 0.0;
}

// At the start, where every domain holds every node.
std::array<Vec3, 4> corners(const NodalState& n, const std::array<std::int32_t, 4>& main) {
  std::array<Vec3, 4> x;
  for (std::size_t a = 0; a < 4; ++a) {
    const auto k = static_cast<std::size_t>(main[a]);
    x[a] = {n.x[k], n.y[k], n.z[k]};
  }
  return x;
}

Vec3 interpolated(const std::array<Vec3, 4>& x, const std::array<double, 4>& w) {
  return scaled(x[0], w[0]) + scaled(x[1], w[1]) + scaled(x[2], w[2]) + scaled(x[3], w[3]);
}

// TI-3, TI-7: the tied node's mass (and inertia) go to its segment's nodes; it keeps none (Spotflag 4: its inertia).
void lump_tied_mass(TiedInterfaceState& in, std::size_t j, NodalState& n, double& mass_added) {
  const auto k = static_cast<std::size_t>(in.secondary[j]);
  const std::array<Vec3, 4> x = corners(n, in.main[j]);
  const int count = distinct_nodes(in.main[j]);
  const Vec3 p{n.x[k], n.y[k], n.z[k]};
  in.secondary_mass.push_back(n.mass[k]), in.secondary_inertia.push_back(n.inertia[k]);
  if (rigid_segment(in.spotflag)) {
    const double added = rigid_added_mass(x, p - rigid_segment_of(x, count).centre, n.mass[k], n.inertia[k]);
    for (int a = 0; a < count; ++a) n.mass[static_cast<std::size_t>(in.main[j][static_cast<std::size_t>(a)])] += (n.mass[k] + added) / count;
    mass_added += added;
    n.mass[k] = 0.0, n.inertia[k] = 0.0;
    return;
  }
  const Vec3 d = p - interpolated(x, in.weight[j]);
  for (int a = 0; a < count; ++a) {
    const auto i = static_cast<std::size_t>(in.main[j][static_cast<std::size_t>(a)]);
    const double w = in.weight[j][static_cast<std::size_t>(a)];
    n.mass[i] += w * n.mass[k];
    if (carries_rotations(in.spotflag)) n.inertia[i] += w * (n.inertia[k] + n.mass[k] * dot(d, d));
  }
  n.mass[k] = 0.0;
  if (carries_rotations(in.spotflag)) n.inertia[k] = 0.0;
}

// Every tie node's slot in TiedState::nodes.
void assign_slots(SolverState& s) {
  TiedState& t = s.ties;
  t.nodes.clear();
  for (const TiedInterfaceState& in : t.interfaces)
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      t.nodes.push_back(in.secondary[j]);
      t.nodes.insert(t.nodes.end(), in.main[j].begin(), in.main[j].end());
    }
  std::sort(t.nodes.begin(), t.nodes.end());
  t.nodes.erase(std::unique(t.nodes.begin(), t.nodes.end()), t.nodes.end());
  auto slot_of = [&t](std::int32_t node) {
    return static_cast<std::int32_t>(std::lower_bound(t.nodes.begin(), t.nodes.end(), node) - t.nodes.begin());
  };
  for (TiedInterfaceState& in : t.interfaces) {
    in.slot.clear();
    for (std::size_t j = 0; j < in.secondary.size(); ++j)
      in.slot.push_back({slot_of(in.secondary[j]), slot_of(in.main[j][0]), slot_of(in.main[j][1]),
                         slot_of(in.main[j][2]), slot_of(in.main[j][3])});
  }
}

// The tie nodes' values of the cycle, each from its owner, in every domain (TI-11).
template <class Pack>
void share_tie_values(SolverState& s, int width, Pack pack) {
  TiedState& t = s.ties;
  t.values.assign(static_cast<std::size_t>(width) * t.nodes.size(), 0.0);
  for (std::size_t slot = 0; slot < t.nodes.size(); ++slot) {
    const auto k = static_cast<std::size_t>(t.nodes[slot]);
    if (s.domain.owns(k)) pack(k, &t.values[static_cast<std::size_t>(width) * slot]);
  }
  if (s.domain.several()) s.reducer.exchange()->share(t.values, width, t.owner);
}

// TI-12: Spotflag 2 steps a spring on a tied node with the mass and inertia the node moves with, its segment's at its
// place (measured: the reference's step is then the shells', whatever the spring's own mass; Spotflag 1, 4 and 5
// step it with the node's own).
void hold_spot_weld_springs(const Model& m, SolverState& s) {
  if (s.springs.node_held.empty()) return;
  bool changed = false;
  for (const TiedInterfaceState& in : s.ties.interfaces) {
    if (in.spotflag != 2) continue;
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      double* held = &s.springs.node_held[SpringState::kNodeHeldValues * static_cast<std::size_t>(in.secondary[j])];
      held[4] = held[5] = 0.0;
      for (std::size_t a = 0; a < static_cast<std::size_t>(distinct_nodes(in.main[j])); ++a) {
        const auto i = static_cast<std::size_t>(in.main[j][a]);
        held[4] += in.weight[j][a] * s.nodes.mass[i], held[5] += in.weight[j][a] * s.nodes.inertia[i];
      }
      changed = true;
    }
  }
  if (changed) refresh_spring_steps(m, s);
}

// TI-15: the shells and bricks that use every node of each tie's segment (measured on the reference: an element on
// the segment's nodes counts whatever its part or surface).
void find_segment_elements(const Model& m, TiedInterfaceState& in) {
  std::vector<std::vector<ElementRef>> of_node(m.nodes.size());
  for (ElementKind kind : {ElementKind::Shell4, ElementKind::Shell3, ElementKind::Brick8}) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    for (std::size_t e = 0; e < table.size(); ++e)
      for (int a = 0; a < nodes_per_element(kind); ++a) {
        std::vector<ElementRef>& list = of_node[static_cast<std::size_t>(table.nodes_of(e)[a])];
        if (list.empty() || list.back().kind != kind || list.back().index != static_cast<std::int32_t>(e))
          list.push_back({kind, static_cast<std::int32_t>(e)});
      }
  }
  in.segment_elements_first.assign(1, 0);
  for (const auto& main : in.main) {
    for (const ElementRef& ref : of_node[static_cast<std::size_t>(main[0])]) {
      const ElementTable& table = m.elements[static_cast<std::size_t>(ref.kind)];
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(ref.index));
      const auto uses = [&](std::int32_t node) {
        return std::find(nodes, nodes + nodes_per_element(ref.kind), node) != nodes + nodes_per_element(ref.kind);
      };
      if (std::all_of(main.begin(), main.end(), uses)) in.segment_elements.push_back(ref);
    }
    in.segment_elements_first.push_back(static_cast<std::uint32_t>(in.segment_elements.size()));
  }
}

// TI-15: a tie whose main elements are deleted (all of them, Idel2 1; one, Idel2 2) lets its node go: the node takes
// its own mass and inertia back (the segment's nodes keep theirs: the model gains the node's mass, counted as added,
// as in the reference) and moves on its own from this cycle. Every domain decides alike from the elements'
// conditions, which the domains share; a resumed run finds the same ties released, its masses already restored.
void release_ties(SolverState& s) {
  NodalState& n = s.nodes;
  for (TiedInterfaceState& in : s.ties.interfaces) {
    if (in.idel2 == 0) continue;
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      if (in.released[j]) continue;
      std::size_t deleted = 0;
      const std::uint32_t first = in.segment_elements_first[j], last = in.segment_elements_first[j + 1];
      for (std::uint32_t q = first; q < last; ++q) {
        const ElementRef& ref = in.segment_elements[q];
        if (element_condition(element_state(s, ref.kind).deleted[static_cast<std::size_t>(ref.index)]) == kElementDeleted) ++deleted;
      }
      const bool release = in.idel2 == 1 ? last > first && deleted == last - first : deleted > 0;
      if (!release) continue;
      in.released[j] = 1;
      const auto k = static_cast<std::size_t>(in.secondary[j]);
      s.mass_added += in.secondary_mass[j] - n.mass[k];
      n.mass[k] = in.secondary_mass[j], n.inertia[k] = in.secondary_inertia[j];
      if (!s.contact.tied_mass.empty()) s.contact.tied_mass[k] = 0.0;
    }
  }
}

// TI-13: a tied node's contact springs push its segment's mass at its place (its own is on the segment now).
void hold_tied_contacts(SolverState& s) {
  if (s.contact.interfaces.empty()) return;
  s.contact.tied_mass.assign(s.nodes.size(), 0.0);
  for (const TiedInterfaceState& in : s.ties.interfaces)
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      const int count = distinct_nodes(in.main[j]);
      double mass = 0.0;
      for (std::size_t a = 0; a < static_cast<std::size_t>(count); ++a)
        mass += (rigid_segment(in.spotflag) ? 1.0 / count : in.weight[j][a]) * s.nodes.mass[static_cast<std::size_t>(in.main[j][a])];
      s.contact.tied_mass[static_cast<std::size_t>(in.secondary[j])] = mass;
    }
}

}  // namespace

void bind_ties_to_domain(SolverState& s) {
  TiedState& t = s.ties;
  t.owner.resize(t.nodes.size());
  for (std::size_t slot = 0; slot < t.nodes.size(); ++slot) t.owner[slot] = s.domain.node_owner[static_cast<std::size_t>(t.nodes[slot])];
}

void setup_ties(const Model& m, SolverState& s) {
  NodalState& n = s.nodes;
  s.ties = TiedState{};
  for (const Type2Interface& card : m.type2_interfaces) {
    TiedInterfaceState in;
    in.spotflag = card.spotflag == 0 ? 5 : card.spotflag;
    in.idel2 = card.idel2;
    for (const Tie& tie : card.ties) {
      in.secondary.push_back(tie.node), in.main.push_back(tie.main), in.weight.push_back(tie.weight);
      lump_tied_mass(in, in.secondary.size() - 1, n, s.mass_added);
    }
    in.released.assign(in.secondary.size(), 0);
    if (in.idel2 != 0) find_segment_elements(m, in);
    s.ties.interfaces.push_back(std::move(in));
  }
  hold_spot_weld_springs(m, s);
  hold_tied_contacts(s);
  assign_slots(s);
  bind_ties_to_domain(s);
}

// TI-4, TI-9: after the loads, each tied node's force and moment go to its segment's nodes; the node keeps none
// (Spotflag 4: its moment, which acts on its own rotation).
void transfer_tied_forces(SolverState& s) {
  TiedState& t = s.ties;
  if (t.nodes.empty()) return;
  release_ties(s);
  NodalState& n = s.nodes;
  std::vector<double>& element_k = s.nodal_stiffness;
  std::vector<double>& contact_k = s.contact.nodal_contact_stiffness;
  auto stiffness = [&](std::size_t k) {
    return (element_k.empty() ? 0.0 : element_k[k]) + (contact_k.empty() ? 0.0 : contact_k[k]);
  };
  share_tie_values(s, kForceValues, [&](std::size_t k, double* out) {
    const double v[kForceValues] = {n.fx[k], n.fy[k], n.fz[k], n.mx[k], n.my[k], n.mz[k], n.x[k], n.y[k], n.z[k], stiffness(k)};
    std::copy(v, v + kForceValues, out);
  });
  t.positions.resize(3 * t.nodes.size());
  for (std::size_t slot = 0; slot < t.nodes.size(); ++slot)
    std::copy_n(&t.values[kForceValues * slot + 6], 3, &t.positions[3 * slot]);
  for (TiedInterfaceState& in : t.interfaces) {
    in.normal_force = in.tangential_force = Vec3{0.0, 0.0, 0.0};
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      if (in.released[j]) continue;
      const double* own = &t.values[kForceValues * static_cast<std::size_t>(in.slot[j][0])];
      const Vec3 force = vec(own), moment = vec(own + 3), p = vec(own + 6);
      std::array<Vec3, 4> x;
      for (std::size_t a = 0; a < 4; ++a) x[a] = vec(&t.values[kForceValues * static_cast<std::size_t>(in.slot[j][a + 1]) + 6]);
      const int count = distinct_nodes(in.main[j]);
      const RigidSegment g = rigid_segment_of(x, count);
      const Vec3 d = p - interpolated(x, in.weight[j]);
      for (std::size_t a = 0; a < static_cast<std::size_t>(count); ++a) {
        const auto i = static_cast<std::size_t>(in.main[j][a]);
        if (!s.domain.is_local(i)) continue;
        const double w = in.weight[j][a];
        const Vec3 f = rigid_segment(in.spotflag) ? rigid_share(g, a, force, cross(p - g.centre, force) + moment)
                                                  : scaled(force, w);
        n.fx[i] += f.x, n.fy[i] += f.y, n.fz[i] += f.z;
        // TI-13: the node's stiffness in the nodal steps (its elements' and contacts') is held by the segment's
        // nodes, which carry its mass.
        if (!element_k.empty()) element_k[i] += w * own[9];
        if (carries_rotations(in.spotflag) && !rigid_segment(in.spotflag)) {
          const Vec3 mi = scaled(moment + cross(d, force), w);
          n.mx[i] += mi.x, n.my[i] += mi.y, n.mz[i] += mi.z;
        }
      }
      const auto k = static_cast<std::size_t>(in.secondary[j]);
      n.fx[k] = n.fy[k] = n.fz[k] = 0.0;
      if (!element_k.empty()) element_k[k] = 0.0;
      if (!contact_k.empty()) contact_k[k] = 0.0;
      if (carries_rotations(in.spotflag)) n.mx[k] = n.my[k] = n.mz[k] = 0.0;
      // TI-6: the force the tie passes, split along the segment's normal.
      const Vec3 along = scaled(g.e3, dot(force, g.e3));
      in.normal_force = in.normal_force + along, in.tangential_force = in.tangential_force + (force - along);
    }
  }
}

// TI-5, TI-8: after the segments' nodes have their velocities of the step, each tied node takes the velocity its
// segment gives its place, and the segment's rotation (Spotflag 4: only the velocity).
void tie_velocities(SolverState& s) {
  TiedState& t = s.ties;
  if (t.nodes.empty()) return;
  NodalState& n = s.nodes;
  share_tie_values(s, kVelocityValues, [&n](std::size_t k, double* out) {
    const double v[kVelocityValues] = {n.vx[k], n.vy[k], n.vz[k], n.wx[k], n.wy[k], n.wz[k]};
    std::copy(v, v + kVelocityValues, out);
  });
  for (TiedInterfaceState& in : t.interfaces) {
    in.kinetic_correction = 0.0;
    for (std::size_t j = 0; j < in.secondary.size(); ++j) {
      if (in.released[j]) continue;
      const auto k = static_cast<std::size_t>(in.secondary[j]);
      std::array<Vec3, 4> v, w;
      for (std::size_t a = 0; a < 4; ++a) {
        const double* slot = &t.values[kVelocityValues * static_cast<std::size_t>(in.slot[j][a + 1])];
        v[a] = vec(slot), w[a] = vec(slot + 3);
      }
      // The places of the cycle's start, as the forces' transfer had them.
      std::array<Vec3, 4> x;
      for (std::size_t a = 0; a < 4; ++a) x[a] = vec(&t.positions[3 * static_cast<std::size_t>(in.slot[j][a + 1])]);
      const Vec3 p = vec(&t.positions[3 * static_cast<std::size_t>(in.slot[j][0])]);
      Vec3 velocity, omega;
      if (rigid_segment(in.spotflag)) {
        const RigidSegment g = rigid_segment_of(x, distinct_nodes(in.main[j]));
        omega = rigid_angular_velocity(g, v);
        Vec3 centre_velocity{0.0, 0.0, 0.0};
        for (std::size_t a = 0; a < static_cast<std::size_t>(g.count); ++a) centre_velocity = centre_velocity + scaled(v[a], 1.0 / g.count);
        velocity = centre_velocity + cross(omega, p - g.centre);
      } else {
        omega = interpolated(w, in.weight[j]);
        velocity = interpolated(v, in.weight[j]);
        if (carries_rotations(in.spotflag)) velocity = velocity + cross(omega, p - interpolated(x, in.weight[j]));
      }
      n.vx[k] = velocity.x, n.vy[k] = velocity.y, n.vz[k] = velocity.z;
      if (carries_rotations(in.spotflag)) n.wx[k] = omega.x, n.wy[k] = omega.y, n.wz[k] = omega.z;
      if (!own_kinetic_energy(in.spotflag)) continue;
      // TI-10: the node's own mass at its velocity instead of the segment's shares at theirs.
      double shares = 0.0;
      for (std::size_t a = 0; a < static_cast<std::size_t>(distinct_nodes(in.main[j])); ++a) shares += in.weight[j][a] * dot(v[a], v[a]);
      in.kinetic_correction += 0.5 * in.secondary_mass[j] * (dot(velocity, velocity) - shares);
    }
  }
}

double tied_kinetic_correction(const SolverState& s) {
  double sum = 0.0;
  for (const TiedInterfaceState& in : s.ties.interfaces) sum += in.kinetic_correction;
  return sum;
}

}  // namespace crumple::solver
