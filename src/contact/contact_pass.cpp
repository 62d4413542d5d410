// The contact pass of one cycle (docs/theory/contact.md): for each candidate pair, the closest point, the
// penetration, the penalty and damping force, friction, the interface step; forces go to the nodes equal and
// opposite, the segment's share by the shape functions of the contact point.
#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/contact/contact.hpp"
#include "crumple/state/element_status.hpp"
#include "crumple/contact/kernels.hpp"

namespace crumple::contact {
namespace {

// Largest nodal speed of the interface's nodes, for the motion since the last sort (eq. C-12).
double largest_speed(const ContactInterface& in, const NodalState& n) {
  double v2 = 0.0;
  auto visit = [&](std::int32_t node) {
    const auto k = static_cast<std::size_t>(node);
    v2 = std::max(v2, n.vx[k] * n.vx[k] + n.vy[k] * n.vy[k] + n.vz[k] * n.vz[k]);
  };
  for (std::int32_t node : in.secondary_nodes) visit(node);
  for (std::int32_t node : in.main_nodes) visit(node);
  return std::sqrt(v2);
}

// /TH/INTER |FNX| .. ||F||: one pair's normal force fn n and whole force into the interface's sums.
void add_pair_forces(InterfaceResult& res, double fn, const double (&normal)[3], const double (&force)[3]) {
  for (std::size_t k = 0; k < 3; ++k) {
    res.pair_normal_abs[k] += std::abs(fn * normal[k]);
    res.pair_force_abs[k] += std::abs(force[k]);
  }
  res.pair_normal_norm += std::abs(fn);
  res.pair_force_norm += std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
}

}  // namespace

ContactStep contact_forces(const Model& m, ContactState& c, NodalState& nodes, double time, double dt_previous,
                           double dt_estimate, double scale, double& added_mass) {
  ContactStep step;
  for (std::int32_t node : c.touched) {
    const auto k = static_cast<std::size_t>(node);
    c.fx[k] = c.fy[k] = c.fz[k] = 0.0;
  }
  c.touched.clear();
  const RunControl& rc = m.run;
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
    const double speed = largest_speed(in, nodes);
    in.motion += speed * dt_previous;
    if (2.0 * in.motion > in.margin) {
      // The margin covers a few steps of the fastest node, so that a node closing in is a candidate, and under
      // the kinematic step, before it can reach the gap (eq. C-12).
      in.margin = std::max(in.largest_gap, 4.0 * speed * (std::isfinite(dt_estimate) ? dt_estimate : dt_previous));
      sort_candidates(in, nodes);
    }
    const double release_step = std::max(in.dt_minimum, rc.dt_inter_del.given ? rc.dt_inter_del.minimum : 0.0);
    const double mass_step = rc.dt_inter_cst.given ? rc.dt_inter_cst.minimum : 0.0;
    const double viss = in.damping;
    const bool filtered = in.friction_filter > 0;
    ++in.passes;
    const double alpha = filtered ? friction_filter_weight(in.friction_filter, in.filter_value, dt_previous) : 1.0;
    for (std::int32_t i : in.touched_list) {
      in.node_touched[static_cast<std::size_t>(i)] = 0;
      in.node_tangent_sum[static_cast<std::size_t>(i)] = 0.0;
      in.node_reach_stiffness[static_cast<std::size_t>(i)] = 0.0;
      in.node_friction_viscosity[static_cast<std::size_t>(i)] = 0.0;
    }
    in.touched_list.clear();

    // Pairs in batches: gather the coordinates, the closest points of the whole batch in one vectorised loop
    // (eq. C-1), then the forces pair by pair (most pairs of a batch are outside their gap and stop early).
    PairBatch& batch = c.batch;
    const std::size_t pairs = in.candidate_node.size();
    for (std::size_t first = 0; first < pairs; first += PairBatch::kSize) {
      const int count = static_cast<int>(std::min<std::size_t>(PairBatch::kSize, pairs - first));
      for (int j = 0; j < count; ++j) {
        const std::size_t q = first + static_cast<std::size_t>(j);
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
        const std::size_t q = first + static_cast<std::size_t>(j);
        const auto i = static_cast<std::size_t>(in.candidate_node[q]);
        const auto s = static_cast<std::size_t>(in.candidate_segment[q]);
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
          if (approach < res.dt && !(release_step > 0.0 && approach < release_step))
            res.dt = approach, res.dt_node = static_cast<std::int32_t>(n);
          // A node within three steps of its normal motion of the gap may enter it within the next steps (or turn
          // back into it as it leaves) and meet the penalty's initial stiffness K0: its first force acts over the
          // mean of that step and the one before, so both must already be stable for K0, and the entry is better
          // resolved with a step of margin (eq. C-11). A node at rest near the gap does not count.
          if (d - g < 3.0 * std::abs(penetration_rate) * dt_estimate) {
            if (in.node_touched[i] == 0) in.node_touched[i] = 1, in.touched_list.push_back(static_cast<std::int32_t>(i));
            in.node_tangent_sum[i] += in.pair_stiffness(i, s);
            if (mass_step > 0.0) in.node_reach_stiffness[i] += in.pair_stiffness(i, s);
          }
          continue;
        }
        const double k0 = in.pair_stiffness(i, s);
        const double kt = tangent_stiffness(k0, g, p);
        const double mass = nodes.mass[n];
        const double body_mass = c.rigid_body_mass.empty() ? 0.0 : c.rigid_body_mass[n];
        const double step_mass = body_mass > 0.0 ? body_mass : mass;  // what the springs and dashpots push [M]
        // The viscous friction's dashpot (eq. C-9, Iform 1, on the node's own mass), which the step must hold too
        // (eq. C-11b).
        const bool viscous_friction = in.friction && in.friction_form != 2;
        const double ct = viscous_friction ? friction_viscosity(in.friction_damping, kt, mass) : 0.0;
        // Interface step of the pair (eq. C-11): /DT/INTER/DEL (or the card's dtmin) releases the pair when it
        // would fall below the minimum (/DT/INTER/CST acts per node, below).
        const double pair_step = std::min(scale * kinematic_step(g, p, penetration_rate),
                                          scaled_stiffness_step(step_mass, kt, ct, viss, scale));
        if (release_step > 0.0 && pair_step < release_step) {
          ++res.released;
          forget();
          continue;
        }
        // The stiffness step is taken per node below, with the tangent stiffnesses of all its pairs summed (a node
        // at an edge or corner feels two or three segments at once); here the kinematic part.
        const double closing = scale * kinematic_step(g, p, penetration_rate);
        if (closing < res.dt) res.dt = closing, res.dt_node = static_cast<std::int32_t>(n);
        in.node_tangent_sum[i] += kt;
        // With /DT/INTER/CST: the penetration the node can reach within the step (at most half its remaining
        // distance, the kinematic bound), and the stiffness there, which the added mass must hold (eq. C-11c).
        if (mass_step > 0.0) {
          const double reach = std::min(p + std::max(penetration_rate, 0.0) * dt_estimate, p + 0.5 * (g - p));
          in.node_reach_stiffness[i] += tangent_stiffness(k0, g, reach);
        }
        in.node_friction_viscosity[i] += ct;
        // Normal force: penalty plus damping, never attractive (eqs. C-5, C-8).
        const double elastic = penalty_force(k0, g, p);
        const double damping = damping_force(viss, kt, mass, penetration_rate, elastic);
        const double fn = elastic + damping;
        res.elastic_energy += elastic_energy(k0, g, p);
        res.damping_work += damping * penetration_rate * dt_previous;
        res.max_penetration_ratio = std::max(res.max_penetration_ratio, p / g);
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
          res.friction_work -= (ft[0] * vt[0] + ft[1] * vt[1] + ft[2] * vt[2]) * dt_previous;
        }
        *friction[0] = ft[0], *friction[1] = ft[1], *friction[2] = ft[2];
        const double force[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
        for (int k = 0; k < 3; ++k) res.normal_force[static_cast<std::size_t>(k)] += fn * normal[k];
        for (int k = 0; k < 3; ++k) res.tangential_force[static_cast<std::size_t>(k)] += ft[k];
        if (in.sum_pair_forces) add_pair_forces(res, fn, normal, force);
        if (in.node_touched[i] == 0) in.touched_list.push_back(static_cast<std::int32_t>(i));
        if (in.node_touched[i] != 2) in.node_touched[i] = 2, ++res.active_nodes;
        if (in.release_bc != 0 && !in.node_impacted[i]) c.bc_releases.emplace_back(static_cast<std::int32_t>(n), in.release_bc);
        in.node_impacted[i] = 1;
        // Equal and opposite: the node gets `force`, the segment nodes -weight_a force (momentum conserved).
        auto apply = [&](std::size_t k, double w) {
          const double gx = w * force[0], gy = w * force[1], gz = w * force[2];
          nodes.fx[k] += gx, nodes.fy[k] += gy, nodes.fz[k] += gz;
          if (c.fx[k] == 0.0 && c.fy[k] == 0.0 && c.fz[k] == 0.0) c.touched.push_back(static_cast<std::int32_t>(k));
          c.fx[k] += gx, c.fy[k] += gy, c.fz[k] += gz;
          in.applied_node.push_back(static_cast<std::int32_t>(k));
          in.applied_x.push_back(gx), in.applied_y.push_back(gy), in.applied_z.push_back(gz);
        };
        apply(n, 1.0);
        for (int a = 0; a < 4; ++a)  // a triangle's repeated third node gets its share twice
          if (cp.weight[a] != 0.0) apply(static_cast<std::size_t>(in.segments[s][static_cast<std::size_t>(a)]), -cp.weight[a]);
      }
    }
    // Stiffness step per node (eq. C-11) on the sum of its pairs' tangent stiffnesses plus the stiffness of its own
    // elements: the node sits between the contact springs and its element, and both act in the same cycle; with
    // viscous friction, the pairs' dashpots too (eq. C-11b).
    // /DT/INTER/CST adds mass to the node so that this step stays at the minimum (reported as added mass); with
    // /DT/INTER/DEL the pairs release themselves below the minimum, so the step does not follow them down.
    for (std::int32_t i : in.touched_list) {
      const auto ui = static_cast<std::size_t>(i);
      const auto n = static_cast<std::size_t>(in.secondary_nodes[ui]);
      // A node carried by a rigid body: the springs act on the body's mass, its elements are not computed.
      const double body_mass = c.rigid_body_mass.empty() ? 0.0 : c.rigid_body_mass[n];
      const double element = body_mass > 0.0 ? 0.0 : in.node_element_stiffness[ui];
      const double stiffness = in.node_tangent_sum[ui] + element;
      const double viscosity = in.node_friction_viscosity[ui];
      double node_step = scaled_stiffness_step(body_mass > 0.0 ? body_mass : nodes.mass[n], stiffness, viscosity,
                                               viss, scale);
      if (mass_step > 0.0 && node_step < mass_step) {
        // The dashpots grow with sqrt(M): C = (C / sqrt(M)) sqrt(M).
        const double c_unit = viscosity > 0.0 ? viscosity / std::sqrt(nodes.mass[n]) : 0.0;
        const double needed =
            std::max(nodes.mass[n], mass_for_step(in.node_reach_stiffness[ui] + element, c_unit, viss, scale, mass_step));
        added_mass += needed - nodes.mass[n];
        res.added_mass += needed - nodes.mass[n];
        // The added mass moves at the node's speed: kinetic energy created by the scaling, the balance's error.
        res.added_mass_energy += 0.5 * (needed - nodes.mass[n]) *
                                 (nodes.vx[n] * nodes.vx[n] + nodes.vy[n] * nodes.vy[n] + nodes.vz[n] * nodes.vz[n]);
        nodes.mass[n] = needed;
        node_step = mass_step;
      }
      if (release_step > 0.0 && node_step < release_step) continue;
      if (node_step < res.dt) res.dt = node_step, res.dt_node = static_cast<std::int32_t>(n);
    }
    if (res.dt < step.dt) step.dt = res.dt, step.interface = static_cast<int>(f), step.node = res.dt_node;
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
