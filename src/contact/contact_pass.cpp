// The contact pass of one cycle (docs/theory/contact.md): for each candidate pair, the closest point, the
// penetration, the penalty and damping force, friction, the interface step; forces go to the nodes equal and
// opposite, the segment's share by the shape functions of the contact point.
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>

#include "crumple/contact/contact.hpp"
#include "crumple/state/element_status.hpp"
#include "crumple/contact/kernels.hpp"

namespace crumple::contact {
namespace {

// A record of the pass (ContactState scratch): a pair in contact, {q, force x y z, weights 0..3, IBC dofs, tangent
// stiffness Kt}, its force on the secondary node and, times -weight, on the segment's nodes; or a node's new
// /DT/INTER/CST mass, {-1 - node, mass, 0 ...}.
constexpr std::size_t kRecordWidth = 10;

// The interface's sums of one cycle (ContactState::cycle_sums), exact so that the domains' shares combine into
// one domain's result.
enum CycleSum : std::size_t {
  kNormalForce = 0, kTangentialForce = 3, kPairNormalAbs = 6, kPairForceAbs = 9, kPairNormalNorm = 12,
  kPairForceNorm = 13, kElasticEnergy = 14, kDampingWork = 15, kFrictionWork = 16, kAddedMass = 17,
  kAddedMassEnergy = 18, kActiveNodes = 19, kReleased = 20, kCycleSums = 21
};

// The smallest step candidate of the cycle and its place in the pass: the pairs in pair order, then the touched
// nodes by secondary node (seq = pairs + node), which is the order one domain meets them in; the first one wins.
struct StepCandidate {
  double dt = std::numeric_limits<double>::infinity();
  std::int32_t seq = -1;
  void consider(double value, std::size_t place) {
    if (value < dt) dt = value, seq = static_cast<std::int32_t>(place);
  }
};

// Largest nodal speed of the interface's nodes this domain owns, for the motion since the last sort (eq. C-12).
double largest_speed(const ContactInterface& in, const NodalState& n, const ContactScope& scope) {
  double v2 = 0.0;
  auto visit = [&](std::int32_t node) {
    const auto k = static_cast<std::size_t>(node);
    if (scope.owns(k)) v2 = std::max(v2, n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]);
  };
  for (std::int32_t node : in.secondary_nodes) visit(node);
  for (std::int32_t node : in.main_nodes) visit(node);
  return std::sqrt(v2);
}

// After a sort: the pairs this domain computes (those of the secondary nodes it owns), those whose force must
// reach another domain, and the nodes some domain needs without advancing them (docs/parallel.md, "Contact").
void divide_pairs(ContactInterface& in, std::size_t nodes, ContactDomains* domains) {
  const std::size_t pairs = in.candidate_node.size();
  in.my_pairs.clear();
  in.pair_remote.assign(pairs, 0);
  if (domains == nullptr) {
    for (std::size_t q = 0; q < pairs; ++q) in.my_pairs.push_back(static_cast<std::int32_t>(q));
    return;
  }
  const ContactScope& scope = domains->scope();
  std::vector<std::int32_t>& ghost = in.ghost_owner;
  ghost.assign(nodes, 0);
  for (std::size_t q = 0; q < pairs; ++q) {
    const auto n = static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(in.candidate_node[q])]);
    if (!scope.owns(n)) continue;
    in.my_pairs.push_back(static_cast<std::int32_t>(q));
    bool remote = !scope.only_here(n);
    for (std::int32_t node : in.segments[static_cast<std::size_t>(in.candidate_segment[q])]) {
      const auto k = static_cast<std::size_t>(node);
      if (!scope.is_local(k)) ghost[k] = 1;
      remote = remote || !scope.only_here(k);
    }
    in.pair_remote[q] = remote;
  }
  domains->union_of(ghost);
  for (std::size_t k = 0; k < nodes; ++k) ghost[k] = ghost[k] != 0 ? (*scope.node_owner)[k] : -1;
}

// One secondary node's share of the interface's cycle sums: its pairs' values summed in plain doubles in pair order,
// then added to the exact sums once (docs/parallel.md, "Sums over many domains"). A node's pairs are contiguous
// (the search lists them node by node) and all run, in the same order, in the domain of the node, so these partial
// sums do not depend on the partition; a node with four pairs makes a quarter of the exact additions.
struct NodeSums {
  static_assert(kCycleSums <= 32, "one bit per sum");
  std::size_t node = std::numeric_limits<std::size_t>::max();
  double value[kCycleSums] = {};
  std::uint32_t used = 0;  // bit s: value[s] has a term
  void add(std::size_t s, double term) { value[s] += term, used |= 1u << s; }
  // The pass moves on to pair q of node i: the previous node's sums go into the exact ones.
  void at_node(std::size_t i, std::vector<ExactSum>& sum) {
    if (i != node) flush(sum), node = i;
  }
  void flush(std::vector<ExactSum>& sum) {
    for (; used != 0; used &= used - 1) {
      const auto s = static_cast<std::size_t>(std::countr_zero(used));
      sum[s].add(value[s]), value[s] = 0.0;
    }
  }
};

// /TH/INTER |FNX| .. ||F||: one pair's normal force fn n and whole force into its node's sums.
void add_pair_forces(NodeSums& sum, double fn, const double (&normal)[3], const double (&force)[3]) {
  for (std::size_t k = 0; k < 3; ++k) {
    sum.add(kPairNormalAbs + k, std::abs(fn * normal[k]));
    sum.add(kPairForceAbs + k, std::abs(force[k]));
  }
  sum.add(kPairNormalNorm, std::abs(fn));
  sum.add(kPairForceNorm, std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]));
}

// What one interface's pass has of the cycle besides its records: the sums, the deepest penetration, the step.
struct InterfaceCycle {
  std::vector<ExactSum>& sum;
  double max_ratio = 0.0;
  StepCandidate step;
  StepCandidate step_as_written;  // without the nodal mass holding the pairs (T-3c)
  // A kinematic step (C-11) bounds both: no mass holds a pair closing in.
  void consider_kinematic(double dt, std::size_t place) {
    step.consider(dt, place);
    step_as_written.consider(dt, place);
  }
};

struct PassSettings {
  double time, dt_previous, dt_estimate, scale, release_step, mass_step;
  double entry_window;  // RunControl::contact_entry_window [steps]
  double nodal_mass_step;  // /DT/NODA/CST's dt_min when alone: the nodal mass holds the contacts (time-step.md, T-2)
  double speed = 0.0;  // the interface's largest nodal speed this pass [L/T]
};

// The pairs of my_pairs this pass must compute (eq. C-12a): a pair whose distance, less what its node and segment
// can have moved since it was last computed, is still beyond the gap by more than three steps of the fastest
// closing, and whose kinematic step would stay above the elements' step, can add no force, no stiffness and no
// step: it is skipped. Its node must have no Inacti 5 / 6 gap reduction (computing a far pair shrinks that).
void screen_pairs(ContactInterface& in, const PassSettings& ps) {
  const std::size_t pairs = in.candidate_node.size();
  if (in.pair_distance.size() != pairs) in.pair_distance.assign(pairs, -1.0), in.pair_motion.assign(pairs, 0.0);
  in.live_pairs.clear();
  const double closing = 2.02 * ps.speed;  // node and contact point each at most `speed`, with a margin
  const bool screening = std::isfinite(ps.dt_estimate) && ps.dt_estimate > 0.0 && std::isfinite(in.motion);
  for (std::int32_t q : in.my_pairs) {
    const auto uq = static_cast<std::size_t>(q);
    const double known = in.pair_distance[uq];
    if (screening && known >= 0.0 && in.gap_reduction[static_cast<std::size_t>(in.candidate_node[uq])] == 0.0) {
      const double beyond = known - 2.02 * (in.motion - in.pair_motion[uq]) - in.largest_gap;  // [L], lower bound
      if (beyond > 3.0 * closing * ps.dt_estimate &&
          ps.scale * 0.5 * (beyond + in.largest_gap) > closing * ps.dt_estimate)
        continue;
    }
    in.live_pairs.push_back(q);
  }
}

// The mass a node's contact springs and dashpots push: its own, or a tied node's segment's (TI-13).
double contact_mass(const ContactState& c, const NodalState& nodes, std::size_t n) {
  return !c.tied_mass.empty() && c.tied_mass[n] > 0.0 ? c.tied_mass[n] : nodes.mass[n];
}

// The mass a node's contact springs push for the step: its own, with selective mass scaling's diagonal (SM-7).
double scaled_mass(const ContactState& c, const NodalState& nodes, std::size_t n) {
  return contact_mass(c, nodes, n) + (c.selective_mass_added != nullptr ? (*c.selective_mass_added)[n] : 0.0);
}

// The pairs of `in` this domain computes (eqs. C-1 to C-9, C-11): their forces into records (applied below, in pair
// order), the node-local sums of their secondary nodes, the cycle's sums and step.
void compute_pairs(ContactState& c, ContactInterface& in, const NodalState& nodes, const PassSettings& ps,
                   InterfaceCycle& out) {
  const double viss = in.damping;
  const bool filtered = in.friction_filter > 0;
  const double alpha = filtered ? friction_filter_weight(in.friction_filter, in.filter_value, ps.dt_previous) : 1.0;
  const double scale = ps.scale, dt_previous = ps.dt_previous, dt_estimate = ps.dt_estimate;
  PairBatch& batch = c.batch;
  NodeSums node_sums;
  screen_pairs(in, ps);
  const std::size_t mine = in.live_pairs.size();
  for (std::size_t first = 0; first < mine; first += PairBatch::kSize) {
    const int count = static_cast<int>(std::min<std::size_t>(PairBatch::kSize, mine - first));
    for (int j = 0; j < count; ++j) {
      const auto q = static_cast<std::size_t>(in.live_pairs[first + static_cast<std::size_t>(j)]);
      const auto n = static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(in.candidate_node[q])]);
      const auto& seg = in.segments[static_cast<std::size_t>(in.candidate_segment[q])];
      batch.node[0][j] = nodes.x[n], batch.node[1][j] = nodes.y[n], batch.node[2][j] = nodes.z[n];
      for (int a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]);
        batch.corner[a][0][j] = nodes.x[k], batch.corner[a][1][j] = nodes.y[k], batch.corner[a][2][j] = nodes.z[k];
      }
    }
    closest_points(batch, count);
    for (int j = 0; j < count; ++j) {
      const auto q = static_cast<std::size_t>(in.live_pairs[first + static_cast<std::size_t>(j)]);
      in.pair_distance[q] = batch.distance[j], in.pair_motion[q] = in.motion;
      const auto i = static_cast<std::size_t>(in.candidate_node[q]);
      const auto s = static_cast<std::size_t>(in.candidate_segment[q]);
      node_sums.at_node(i, out.sum);
      double* friction[3] = {&in.friction_x[q], &in.friction_y[q], &in.friction_z[q]};
      // Out of contact: the pair forgets its friction force.
      auto forget = [&] { *friction[0] = *friction[1] = *friction[2] = 0.0; };
      if (!in.node_active[i] || !in.segment_active[s]) continue;
      const auto n = static_cast<std::size_t>(in.secondary_nodes[i]);
      double v[4][3];
      for (int a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(in.segments[s][static_cast<std::size_t>(a)]);
        v[a][0] = nodes.vx[k], v[a][1] = nodes.vy[k], v[a][2] = nodes.vz[k];
      }
      const double p_node[3] = {batch.node[0][j], batch.node[1][j], batch.node[2][j]};
      const SegmentPoint cp{{batch.point[0][j], batch.point[1][j], batch.point[2][j]},
                            {batch.weight[0][j], batch.weight[1][j], batch.weight[2][j], batch.weight[3][j]},
                            batch.distance[j]};
      // Gap of the pair (eq. C-2), less the Inacti 5 / 6 reduction, which shrinks as the node moves out.
      const double full_gap = in.pair_gap(i, s);
      // The corrected gap g - r only grows: to the node's distance (less the Inacti 6 clearance) as it moves out.
      if (in.gap_reduction[i] > 0.0)
        in.gap_reduction[i] = std::min(in.gap_reduction[i], std::max(0.0, full_gap - cp.distance + in.gap_clearance[i]));
      const double g = full_gap - in.gap_reduction[i];
      const double d = cp.distance, p = g - d;
      if (d < 1e-10 * g) {  // at the mid-surface: released (eq. C-4)
        forget();
        continue;
      }
      const double normal[3] = {(p_node[0] - cp.point[0]) / d, (p_node[1] - cp.point[1]) / d, (p_node[2] - cp.point[2]) / d};
      double vr[3];  // velocity of the node relative to the contact point
      for (int k = 0; k < 3; ++k)
        vr[k] = (k == 0 ? nodes.vx[n] : k == 1 ? nodes.vy[n] : nodes.vz[n]) -
                (cp.weight[0] * v[0][k] + cp.weight[1] * v[1][k] + cp.weight[2] * v[2][k] + cp.weight[3] * v[3][k]);
      const double vn = vr[0] * normal[0] + vr[1] * normal[1] + vr[2] * normal[2];
      const double penetration_rate = -vn;
      if (!(d < g)) {
        // Outside the gap: no force, but a candidate closing in must not cross the mid-surface within a step: the
        // kinematic step 0.5 (g - p) / (dp/dt) = 0.5 d / (dp/dt) holds for it too (eq. C-11).
        forget();
        const double approach = scale * kinematic_step(g, p, penetration_rate);
        if (!(ps.release_step > 0.0 && approach < ps.release_step)) out.consider_kinematic(approach, q);
        // With an entry window (`--accuracy fine`), a node within that many steps of its normal motion of the gap
        // may enter it within the next steps (or turn back into it as it leaves) and meets the penalty's initial
        // stiffness K0: its first force acts over the mean of that step and the one before, so both are made
        // stable for K0 and the entry is resolved with a step of margin (eq. C-11). Without (the deck as written,
        // as the reference solver), the node counts its stiffness from the cycle it is in the gap, unless
        // /DT/INTER/CST will mass scale it there: its added mass must be in place before its first force, so
        // its K0 is kept aside and taken where it would need mass (node_steps, C-11c). A node at rest near the gap
        // never counts.
        const double window = ps.entry_window > 0.0 ? ps.entry_window : ps.mass_step > 0.0 ? kAnticipatedEntrySteps : 0.0;
        if (window > 0.0 && d - g < window * std::abs(penetration_rate) * dt_estimate) {
          if (in.node_touched[i] == 0) in.node_touched[i] = 1, in.touched_list.push_back(static_cast<std::int32_t>(i));
          if (ps.entry_window > 0.0) {
            in.node_tangent_sum[i] += in.pair_stiffness(i, s);
            if (ps.mass_step > 0.0) in.node_reach_stiffness[i] += in.pair_stiffness(i, s);
          } else {
            in.node_entry_stiffness[i] += in.pair_stiffness(i, s);
          }
        }
        continue;
      }
      const double k0 = in.pair_stiffness(i, s);
      const double kt = tangent_stiffness(k0, g, p);
      const double mass = contact_mass(c, nodes, n);
      const double body_mass = c.rigid_body_mass.empty() ? 0.0 : c.rigid_body_mass[n];
      const double step_mass = body_mass > 0.0 ? body_mass : scaled_mass(c, nodes, n);  // what the springs push [M]
      // The viscous friction's dashpot (eq. C-9, Iform 1, on the node's own mass), which the step must hold too
      // (eq. C-11b).
      const bool viscous_friction = in.friction && in.friction_form != 2;
      const double ct = viscous_friction ? friction_viscosity(in.friction_damping, kt, mass) : 0.0;
      // Interface step of the pair (eq. C-11): /DT/INTER/DEL (or the card's dtmin) releases the pair when it
      // would fall below the minimum (/DT/INTER/CST acts per node, below).
      const double pair_step = std::min(scale * kinematic_step(g, p, penetration_rate),
                                        scaled_stiffness_step(step_mass, kt, ct, viss, scale));
      if (ps.release_step > 0.0 && pair_step < ps.release_step) {
        node_sums.add(kReleased, 1.0);
        forget();
        continue;
      }
      // The stiffness step is taken per node below, with the tangent stiffnesses of all its pairs summed (a node
      // at an edge or corner feels two or three segments at once); here the kinematic part.
      out.consider_kinematic(scale * kinematic_step(g, p, penetration_rate), q);
      in.node_tangent_sum[i] += kt;
      // With /DT/INTER/CST: the penetration the node can reach within the step (at most half its remaining
      // distance, the kinematic bound), and the stiffness there, which the added mass must hold (eq. C-11c).
      if (ps.mass_step > 0.0)
        in.node_reach_stiffness[i] += tangent_stiffness(k0, g, reach_penetration(g, p, penetration_rate, dt_estimate));
      in.node_friction_viscosity[i] += ct;
      // What the pair gives its nodes' nodal step (time-step.md, T-4): its tangent stiffness and its normal dashpot
      // over the last step, or with viscous friction the friction's dashpot over it where stiffer (T-4b, T-4c; none
      // at the first cycle). Under /DT/NODA/CST
      // the mass holds it (T-2) if the target step resolves the pair (its kinematic step above it), at most as stiff
      // as at half its gap (deeper the spring, and the mass, would grow without bound), with the friction's dashpot
      // over the target step where stiffer (T-4b; from the second cycle on, as the reference); the rest bounds the
      // step (T-3b).
      double nodal = c.interface_nodal_step
                         ? nodal_pair_stiffness(kt, k0, secant_stiffness(k0, g, p), viss,
                                                viscous_friction ? in.friction_damping : 0.0, mass, dt_previous)
                         : kt;
      if (ps.nodal_mass_step > 0.0) {
        const double half = 0.5 * g;
        const bool resolved = scale * kinematic_step(g, p, penetration_rate) >= ps.nodal_mass_step;
        const double held = resolved ? std::min(kt, tangent_stiffness(k0, g, half)) : 0.0;
        const double ks = std::min(secant_stiffness(k0, g, p), secant_stiffness(k0, g, half));
        const double over = dt_previous > 0.0 ? ps.nodal_mass_step : 0.0;
        nodal = resolved && viscous_friction
                    ? nodal_friction_stiffness(held, k0, ks, in.friction_damping, mass, over)
                    : held;
        if (!resolved || kt > held)
          in.node_unresolved_stiffness[i] +=
              tangent_stiffness(k0, g, reach_penetration(g, p, penetration_rate, dt_estimate)) - held;
      }
      // Normal force: penalty plus damping, never attractive (eqs. C-5, C-8).
      const double elastic = penalty_force(k0, g, p);
      const double damping = damping_force(viss, kt, mass, penetration_rate, elastic);
      const double fn = elastic + damping;
      node_sums.add(kElasticEnergy, elastic_energy(k0, g, p));
      node_sums.add(kDampingWork, damping * penetration_rate * dt_previous);
      out.max_ratio = std::max(out.max_ratio, p / g);
      // Friction (eq. C-9): trial force in the tangent plane, capped by the Coulomb cone.
      double ft[3] = {0.0, 0.0, 0.0};
      if (in.friction) {
        const double vt[3] = {vr[0] - vn * normal[0], vr[1] - vn * normal[1], vr[2] - vn * normal[2]};
        // Coefficient (eq. C-9a..c) for the pressure on the node's share of the surface and the sliding speed,
        // then filtered in time (eq. C-9d).
        double mu = in.friction_law.fric;
        if (in.friction_law.kind > 0)
          mu = friction_coefficient(in.friction_law, fn / in.node_area[i],
                                    std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]));
        if (filtered) {  // once per node and pass (its first active pair), restarted after a pass out of contact
          double& mu_f = in.friction_mu[i];
          long long& last = in.friction_mu_pass[i];
          if (last != in.passes) mu_f = last == in.passes - 1 ? alpha * mu + (1.0 - alpha) * mu_f : mu;
          last = in.passes;
          mu = mu_f;
        }
        if (in.friction_form == 2) {
          // Stiffness form: the old force turned into the new tangent plane plus Kt times the sliding increment.
          const double along = *friction[0] * normal[0] + *friction[1] * normal[1] + *friction[2] * normal[2];
          for (int k = 0; k < 3; ++k) ft[k] = *friction[k] - along * normal[k] - kt * vt[k] * dt_previous;
        } else {
          // Viscous form: C_t = VisF sqrt(2 Kt M) times the sliding velocity.
          for (int k = 0; k < 3; ++k) ft[k] = -ct * vt[k];
        }
        friction_cone(ft, mu * fn);
        node_sums.add(kFrictionWork, -(ft[0] * vt[0] + ft[1] * vt[1] + ft[2] * vt[2]) * dt_previous);
      }
      *friction[0] = ft[0], *friction[1] = ft[1], *friction[2] = ft[2];
      const double force[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
      for (std::size_t k = 0; k < 3; ++k) {
        node_sums.add(kNormalForce + k, fn * normal[k]);
        node_sums.add(kTangentialForce + k, ft[k]);
      }
      if (in.sum_pair_forces) add_pair_forces(node_sums, fn, normal, force);
      if (in.node_touched[i] == 0) in.touched_list.push_back(static_cast<std::int32_t>(i));
      if (in.node_touched[i] != 2) in.node_touched[i] = 2, node_sums.add(kActiveNodes, 1.0);
      const bool releases = in.release_bc != 0 && !in.node_impacted[i];
      in.node_impacted[i] = 1;
      // Equal and opposite: the node gets `force`, the segment nodes -weight_a force (momentum conserved).
      const double record[kRecordWidth] = {static_cast<double>(q), force[0],     force[1],     force[2],
                                           cp.weight[0],           cp.weight[1], cp.weight[2], cp.weight[3],
                                           releases ? double(in.release_bc) : 0.0, nodal};
      c.own_records.insert(c.own_records.end(), record, record + kRecordWidth);
    }
  }
  node_sums.flush(out.sum);
}

// Stiffness step per node (eq. C-11) on the sum of its pairs' tangent stiffnesses plus the stiffness of its own
// elements: the node sits between the contact springs and its element, and both act in the same cycle; with
// viscous friction, the pairs' dashpots too (eq. C-11b). The nodes are this domain's (its pairs' secondary nodes).
// /DT/INTER/CST adds mass to the node so that this step stays at the minimum (reported as added mass; a node other
// domains advance too gets a mass record); with /DT/INTER/DEL the pairs release themselves below the minimum, so
// the step does not follow them down.
void node_steps(ContactState& c, ContactInterface& in, NodalState& nodes, const PassSettings& ps,
                const ContactScope& scope, InterfaceCycle& out) {
  const double viss = in.damping;
  const std::size_t pairs = in.candidate_node.size();
  for (std::int32_t i : in.touched_list) {
    const auto ui = static_cast<std::size_t>(i);
    const auto n = static_cast<std::size_t>(in.secondary_nodes[ui]);
    // A node carried by a rigid body: the springs act on the body's mass, its elements are not computed.
    const double body_mass = c.rigid_body_mass.empty() ? 0.0 : c.rigid_body_mass[n];
    const double element = body_mass > 0.0 || c.selective_mass_added != nullptr ? 0.0 : in.node_element_stiffness[ui];
    double stiffness = in.node_tangent_sum[ui] + element;
    const double viscosity = in.node_friction_viscosity[ui];
    // Pairs about to enter (/DT/INTER/CST without an entry window): anticipated where their K0 needs mass, and
    // still once it was added, which brought that step up to the minimum (to rounding: the 1e-6).
    const double entry = in.node_entry_stiffness[ui];
    if (entry > 0.0 && scaled_stiffness_step(body_mass > 0.0 ? body_mass : nodes.mass[n], stiffness + entry,
                                             viscosity, viss, ps.scale) < ps.mass_step * (1.0 + 1e-6)) {
      stiffness += entry;
      in.node_reach_stiffness[ui] += entry;
    }
    // The interface nodal step holds the springs of a node that carries its own mass (T-4): no stiffness step here,
    // unless an entry window counts pairs not yet in the gap, which that step does not see.
    if (c.interface_nodal_step && ps.entry_window == 0.0 && !(body_mass > 0.0) &&
        contact_mass(c, nodes, n) == nodes.mass[n])
      continue;
    double node_step = scaled_stiffness_step(body_mass > 0.0 ? body_mass : scaled_mass(c, nodes, n), stiffness,
                                             viscosity, viss, ps.scale);
    if (!(ps.release_step > 0.0 && node_step < ps.release_step)) out.step_as_written.consider(node_step, pairs + ui);
    if (ps.nodal_mass_step > 0.0 && !(body_mass > 0.0)) {
      // Under /DT/NODA/CST the node's mass holds its elements and resolved pairs at the target step T (T-2), at
      // most the stiffness 2 M (scale / T)^2; the pairs closing faster than T resolves add theirs at the depth they
      // can reach (C-11c) and bound the step (T-3b); none: the nodal step is the node's.
      const double unresolved = in.node_unresolved_stiffness[ui];
      if (!(unresolved > 0.0)) continue;
      const double held = 2.0 * nodes.mass[n] * (ps.scale / ps.nodal_mass_step) * (ps.scale / ps.nodal_mass_step);
      node_step = ps.scale * std::sqrt(2.0 * nodes.mass[n] / (held + unresolved));
    }
    if (ps.mass_step > 0.0 && node_step < ps.mass_step) {
      // The dashpots grow with sqrt(M): C = (C / sqrt(M)) sqrt(M).
      const double c_unit = viscosity > 0.0 ? viscosity / std::sqrt(nodes.mass[n]) : 0.0;
      const double needed =
          std::max(nodes.mass[n], mass_for_step(in.node_reach_stiffness[ui] + element, c_unit, viss, ps.scale, ps.mass_step));
      out.sum[kAddedMass].add(needed - nodes.mass[n]);
      // The added mass moves at the node's speed: kinetic energy created by the scaling, the balance's error.
      out.sum[kAddedMassEnergy].add(0.5 * (needed - nodes.mass[n]) *
                                    (nodes.vx[n] * nodes.vx[n] + nodes.vy[n] * nodes.vy[n] + nodes.vz[n] * nodes.vz[n]));
      nodes.mass[n] = needed;
      if (!scope.only_here(n)) {
        const double record[kRecordWidth] = {-1.0 - static_cast<double>(n), needed, 0, 0, 0, 0, 0, 0, 0, 0};
        c.own_records.insert(c.own_records.end(), record, record + kRecordWidth);
      }
      node_step = ps.mass_step;
    }
    if (ps.release_step > 0.0 && node_step < ps.release_step) continue;
    out.step.consider(node_step, pairs + ui);
  }
}

// The records of every domain in pair order (ContactState::ordered_records): this domain's own pairs, merged with
// the other domains' pairs that reach it; the mass records are applied at once.
const std::vector<double>& ordered_records(ContactState& c, const ContactInterface& in, NodalState& nodes,
                                           const ContactScope& scope, ContactDomains* domains) {
  if (domains == nullptr) return c.own_records;
  c.sent_records.clear();
  for (std::size_t r = 0; r < c.own_records.size(); r += kRecordWidth) {
    const double key = c.own_records[r];
    if (key < 0.0 || in.pair_remote[static_cast<std::size_t>(key)] || c.own_records[r + 8] != 0.0)
      c.sent_records.insert(c.sent_records.end(), c.own_records.begin() + static_cast<std::ptrdiff_t>(r),
                            c.own_records.begin() + static_cast<std::ptrdiff_t>(r + kRecordWidth));
  }
  domains->gather(c.sent_records, c.received_records);
  // The other domains' pair records (a domain's own come back in `received` too: skipped), sorted by pair; mass
  // records set the node's mass.
  c.order.clear();
  for (std::size_t r = 0; r < c.received_records.size(); r += kRecordWidth) {
    const double key = c.received_records[r];
    if (key < 0.0) {
      nodes.mass[static_cast<std::size_t>(-1.0 - key)] = c.received_records[r + 1];
      continue;
    }
    const auto n = static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(in.candidate_node[static_cast<std::size_t>(key)])]);
    if (!scope.owns(n)) c.order.push_back(r);
  }
  std::sort(c.order.begin(), c.order.end(),
            [&](std::size_t a, std::size_t b) { return c.received_records[a] < c.received_records[b]; });
  c.ordered_records.clear();
  std::size_t own = 0, other = 0;
  auto append = [&](const std::vector<double>& from, std::size_t at) {
    c.ordered_records.insert(c.ordered_records.end(), from.begin() + static_cast<std::ptrdiff_t>(at),
                             from.begin() + static_cast<std::ptrdiff_t>(at + kRecordWidth));
  };
  while (own < c.own_records.size() || other < c.order.size()) {
    if (own < c.own_records.size() && c.own_records[own] < 0.0) {  // this domain's mass records: already set
      own += kRecordWidth;
      continue;
    }
    const bool take_own = other == c.order.size() ||
                          (own < c.own_records.size() && c.own_records[own] < c.received_records[c.order[other]]);
    if (take_own) append(c.own_records, own), own += kRecordWidth;
    else append(c.received_records, c.order[other]), ++other;
  }
  return c.ordered_records;
}

// The forces of the records, in pair order, on this domain's local nodes (and kept per node for the outputs and
// the work, eq. C-10); IBC releases for the time loop.
void apply_records(ContactState& c, ContactInterface& in, NodalState& nodes, const ContactScope& scope,
                   const std::vector<double>& records) {
  for (std::size_t r = 0; r < records.size(); r += kRecordWidth) {
    const double* rec = &records[r];
    if (rec[0] < 0.0) continue;
    const auto q = static_cast<std::size_t>(rec[0]);
    const auto n = static_cast<std::size_t>(in.secondary_nodes[static_cast<std::size_t>(in.candidate_node[q])]);
    const auto& seg = in.segments[static_cast<std::size_t>(in.candidate_segment[q])];
    auto apply = [&](std::size_t k, double w) {
      if (!scope.is_local(k)) return;
      // The pair's tangent stiffness at the node, by its share (eq. T-4).
      if (!c.nodal_contact_stiffness.empty()) c.nodal_contact_stiffness[k] += std::abs(w) * rec[9];
      const double gx = w * rec[1], gy = w * rec[2], gz = w * rec[3];
      nodes.fx[k] += gx, nodes.fy[k] += gy, nodes.fz[k] += gz;
      if (c.fx[k] == 0.0 && c.fy[k] == 0.0 && c.fz[k] == 0.0) c.touched.push_back(static_cast<std::int32_t>(k));
      c.fx[k] += gx, c.fy[k] += gy, c.fz[k] += gz;
      in.applied_node.push_back(static_cast<std::int32_t>(k));
      in.applied_x.push_back(gx), in.applied_y.push_back(gy), in.applied_z.push_back(gz);
    };
    apply(n, 1.0);
    for (int a = 0; a < 4; ++a)  // a triangle's repeated third node gets its share twice
      if (rec[4 + a] != 0.0) apply(static_cast<std::size_t>(seg[static_cast<std::size_t>(a)]), -rec[4 + a]);
    if (rec[8] != 0.0) c.bc_releases.emplace_back(static_cast<std::int32_t>(n), static_cast<std::uint8_t>(rec[8]));
  }
}

// The secondary node of a step candidate (its place: a pair, or pairs + the node's index), -1 for none.
std::int32_t step_node(const ContactInterface& in, const StepCandidate& candidate) {
  if (candidate.seq < 0) return -1;
  const auto seq = static_cast<std::size_t>(candidate.seq), pairs = in.candidate_node.size();
  const std::size_t i = seq < pairs ? static_cast<std::size_t>(in.candidate_node[seq]) : seq - pairs;
  return in.secondary_nodes[i];
}

// The interface's results of the cycle from the sums over every domain.
void finish_interface(const ContactInterface& in, InterfaceResult& res, const InterfaceCycle& cycle, double& added_mass) {
  const std::vector<ExactSum>& sum = cycle.sum;
  for (std::size_t k = 0; k < 3; ++k) {
    res.normal_force[k] = sum[kNormalForce + k].value();
    res.tangential_force[k] = sum[kTangentialForce + k].value();
    res.pair_normal_abs[k] = sum[kPairNormalAbs + k].value();
    res.pair_force_abs[k] = sum[kPairForceAbs + k].value();
  }
  res.pair_normal_norm = sum[kPairNormalNorm].value(), res.pair_force_norm = sum[kPairForceNorm].value();
  res.elastic_energy = sum[kElasticEnergy].value();
  res.damping_work += sum[kDampingWork].value();
  res.friction_work += sum[kFrictionWork].value();
  const double added = sum[kAddedMass].value();
  res.added_mass += added, added_mass += added;
  res.added_mass_energy += sum[kAddedMassEnergy].value();
  res.active_nodes = static_cast<int>(sum[kActiveNodes].value());
  res.released += static_cast<long long>(sum[kReleased].value());
  res.max_penetration_ratio = std::max(res.max_penetration_ratio, cycle.max_ratio);
  res.dt = cycle.step.dt, res.dt_node = step_node(in, cycle.step);
}

}  // namespace

ContactStep contact_forces(const Model& m, ContactState& c, NodalState& nodes, double time, double dt_previous,
                           double dt_estimate, double scale, double& added_mass, ContactDomains* domains) {
  ContactStep step;
  const ContactScope whole;
  const ContactScope& scope = domains != nullptr ? domains->scope() : whole;
  for (std::int32_t node : c.touched) {
    const auto k = static_cast<std::size_t>(node);
    c.fx[k] = c.fy[k] = c.fz[k] = 0.0;
  }
  c.touched.clear();
  std::fill(c.nodal_contact_stiffness.begin(), c.nodal_contact_stiffness.end(), 0.0);
  const RunControl& rc = m.run;
  const PassSettings settings{time,
                              dt_previous,
                              dt_estimate,
                              scale,
                              0.0,
                              rc.dt_inter_cst.given ? rc.dt_inter_cst.minimum : 0.0,
                              static_cast<double>(rc.contact_entry_window),
                              rc.dt_nodal_cst.given && !rc.dt_inter_cst.given ? rc.dt_nodal_cst.minimum : 0.0};
  // The deck as written's step beside the mass-scaled one, where the step takes the larger (time-step.md, T-3c).
  const bool as_written = rc.nodal_step_at_least_as_written && settings.nodal_mass_step > 0.0;
  for (std::size_t f = 0; f < c.interfaces.size(); ++f) {
    ContactInterface& in = c.interfaces[f];
    InterfaceResult& res = c.results[f];
    res.normal_force = {0.0, 0.0, 0.0}, res.tangential_force = {0.0, 0.0, 0.0};
    res.pair_normal_abs = {0.0, 0.0, 0.0}, res.pair_force_abs = {0.0, 0.0, 0.0};
    res.pair_normal_norm = res.pair_force_norm = 0.0;
    res.elastic_energy = 0.0, res.active_nodes = 0, res.dt = std::numeric_limits<double>::infinity(), res.dt_node = -1;
    in.applied_node.clear(), in.applied_x.clear(), in.applied_y.clear(), in.applied_z.clear();
    if (time < in.t_start || time > in.t_stop) continue;
    // Search only when the nodes may have moved by more than the margin since the last sort (eq. C-12): a node
    // and a segment closing at the largest speed each.
    double speed = largest_speed(in, nodes, scope);
    if (domains != nullptr) speed = domains->max(speed);
    in.motion += speed * dt_previous;
    const bool sort = 2.0 * in.motion > in.margin;
    if (sort) {
      // The margin covers a few steps of the fastest node, so that a node closing in is a candidate, and under
      // the kinematic step, before it can reach the gap (eq. C-12).
      in.margin = std::max(in.largest_gap, 4.0 * speed * (std::isfinite(dt_estimate) ? dt_estimate : dt_previous));
      const auto search_start = std::chrono::steady_clock::now();  // the search's share of the run (profile)
      if (domains != nullptr) domains->gather_positions(in);
      sort_candidates(in, nodes);
      c.sort_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - search_start).count();
      in.divided = false;
      in.pair_distance.clear();  // new candidates: each is computed once before it may be screened
    }
    const bool divide = !in.divided;
    if (divide) divide_pairs(in, nodes.size(), domains), in.divided = true;
    if (domains != nullptr) domains->share_ghosts(in, divide);
    PassSettings ps = settings;
    ps.speed = speed;
    ps.release_step = std::max(in.dt_minimum, rc.dt_inter_del.given ? rc.dt_inter_del.minimum : 0.0);
    ++in.passes;
    for (std::int32_t i : in.touched_list) {
      in.node_touched[static_cast<std::size_t>(i)] = 0;
      in.node_tangent_sum[static_cast<std::size_t>(i)] = 0.0;
      in.node_reach_stiffness[static_cast<std::size_t>(i)] = 0.0;
      in.node_unresolved_stiffness[static_cast<std::size_t>(i)] = 0.0;
      in.node_entry_stiffness[static_cast<std::size_t>(i)] = 0.0;
      in.node_friction_viscosity[static_cast<std::size_t>(i)] = 0.0;
    }
    in.touched_list.clear();
    c.cycle_sums.assign(kCycleSums, ExactSum{});
    InterfaceCycle cycle{c.cycle_sums, 0.0, StepCandidate{}, StepCandidate{}};
    c.own_records.clear();
    compute_pairs(c, in, nodes, ps, cycle);
    node_steps(c, in, nodes, ps, scope, cycle);
    apply_records(c, in, nodes, scope, ordered_records(c, in, nodes, scope, domains));
    if (domains != nullptr) {
      domains->sum(c.cycle_sums);
      cycle.max_ratio = domains->max(cycle.max_ratio);
      domains->min_with_index(cycle.step.dt, cycle.step.seq);
    }
    finish_interface(in, res, cycle, added_mass);
    if (res.dt < step.dt) step.dt = res.dt, step.interface = static_cast<int>(f), step.node = res.dt_node;
    if (as_written) {  // eq. T-3c
      if (domains != nullptr) domains->min_with_index(cycle.step_as_written.dt, cycle.step_as_written.seq);
      if (cycle.step_as_written.dt < step.dt_as_written)
        step.dt_as_written = cycle.step_as_written.dt, step.interface_as_written = static_cast<int>(f),
        step.node_as_written = step_node(in, cycle.step_as_written);
    }
  }
  return step;
}

void add_contact_work(const ContactState& c, const NodalState& n, const std::vector<double>* v_old,
                      const std::vector<std::int32_t>& node_owner, std::int32_t me, ExactSum* power) {
  for (std::size_t f = 0; f < c.interfaces.size(); ++f) {
    const ContactInterface& in = c.interfaces[f];
    for (std::size_t e = 0; e < in.applied_node.size(); ++e) {
      const auto k = static_cast<std::size_t>(in.applied_node[e]);
      if (node_owner[k] != me) continue;
      power[f].add(in.applied_x[e] * 0.5 * (v_old[0][k] + n.vx[k]) + in.applied_y[e] * 0.5 * (v_old[1][k] + n.vy[k]) +
                   in.applied_z[e] * 0.5 * (v_old[2][k] + n.vz[k]));
    }
  }
}

double absorb_contact_work(ContactState& c, const ExactSum* power, double dt_average) {
  double total = 0.0;
  for (std::size_t f = 0; f < c.interfaces.size(); ++f) {
    c.results[f].absorbed -= power[f].value() * dt_average;
    total += c.results[f].absorbed;
  }
  return total;
}

void remove_deleted_elements(ContactState& c, const std::array<const std::vector<std::uint8_t>*, kElementKinds>& deleted) {
  auto is_deleted = [&](std::uint8_t kind, std::int32_t element) {
    const std::vector<std::uint8_t>* flags = deleted[kind];
    return flags != nullptr && element >= 0 && element_condition((*flags)[static_cast<std::size_t>(element)]) == kElementDeleted;
  };
  for (ContactInterface& in : c.interfaces) {
    if (in.idel == 0) continue;
    for (std::size_t s = 0; s < in.segments.size(); ++s)
      if (is_deleted(in.segment_owner_kind[s], in.segment_owner[s])) in.segment_active[s] = 0;
    for (std::size_t i = 0; i + 1 < in.node_elements.size(); ++i) {
      if (!in.node_active[i]) continue;
      bool alive = false;
      for (std::uint32_t k = in.node_elements[i]; k < in.node_elements[i + 1] && !alive; ++k)
        alive = !is_deleted(in.element_kind_of_node[k], in.element_of_node[k]);
      if (!alive) in.node_active[i] = 0;
    }
  }
}

}  // namespace crumple::contact
