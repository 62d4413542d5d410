#pragma once
// State of the TYPE7 contact interfaces (docs/theory/contact.md). Built once by setup_contact from the model;
// the contact pass owns and updates it. Per-pair arrays are structures of arrays indexed by candidate pair.
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "crumple/core/exact_sum.hpp"
#include "crumple/core/vec3.hpp"

namespace crumple::contact {

// The friction law of an interface (eq. C-9a..C-9c; its coefficient: contact/kernels.hpp, friction_coefficient).
struct FrictionLaw {
  int kind = 0;             // Ifric: 0 Coulomb, 1 generalized viscous, 2 Darmstad, 3 Renard
  double fric = 0.0;        // Fric: Coulomb coefficient, the constant term of Ifric 1
  double c[6] = {0, 0, 0, 0, 0, 0};  // C1..C6 (dimensions in model/interfaces.hpp)
};

// A batch of candidate pairs gathered as structures of arrays (eq. C-1 over pairs): node positions and segment
// corners in, distance, weights and contact point out. closest_points runs the fan over the batch in one loop
// without branches, which the compiler vectorises. Scratch of the contact pass.
struct PairBatch {
  static constexpr int kSize = 64;
  double node[3][kSize];
  double corner[4][3][kSize];
  double distance[kSize];
  double weight[4][kSize];
  double point[3][kSize];
};

}  // namespace crumple::contact

namespace crumple {

struct InitialPenetration {
  std::int32_t node;     // dense node index
  std::int32_t segment;  // index into the interface's main segments
  double penetration;    // p0 = g - d at the start [L]
};

// Per interface, in the order of Model::type7_interfaces. Forces are those the interface applied during the last
// cycle; energies accumulate from the start.
struct InterfaceResult {
  Vec3 normal_force{};      // sum of the normal (penalty + damping) forces ON the secondary nodes [F]
  Vec3 tangential_force{};  // sum of the friction forces on the secondary nodes [F]
  double elastic_energy = 0.0;  // stored penalty energy now, sum of K0 g (-p - g ln((g - p) / g)) (eq. C-4) [E]
  double damping_work = 0.0;    // energy dissipated by the normal damping so far (>= 0) [E]
  double friction_work = 0.0;   // energy dissipated by friction so far (>= 0) [E]
  double absorbed = 0.0;        // minus the accumulated work of all contact forces on all nodes (E_contact) [E]
  // /TH/INTER |FNX| .. ||F|| (docs/output-format.md, "INTER"), summed over the pairs in contact in the last cycle
  // only when a request asks them (ContactInterface::sum_pair_forces), else 0: per pair, the absolute components
  // and the magnitude of its normal force and of its whole (normal plus friction) force [F].
  Vec3 pair_normal_abs{}, pair_force_abs{};
  double pair_normal_norm = 0.0, pair_force_norm = 0.0;
  int active_nodes = 0;         // secondary nodes with a non-zero force in the last cycle
  double dt = std::numeric_limits<double>::infinity();  // interface step of the last cycle, scaled [T]
  std::int32_t dt_node = -1;    // dense index of the secondary node controlling it
  double added_mass = 0.0;      // mass added by /DT/INTER/CST so far [M]
  double added_mass_energy = 0.0;  // kinetic energy the added mass took at its node's speed, sum dm |v|^2 / 2 [E]
  long long released = 0;       // contacts released by /DT/INTER/DEL or the card's dtmin so far
  std::vector<InitialPenetration> initial_penetrations;  // found before the run (type7.md §7)
  double max_penetration_ratio = 0.0;  // largest p / g seen in any cycle
};

// What the contact pass needs of one interface, fixed at setup, plus its search and friction state.
struct ContactInterface {
  // Parameters with the defaults applied (type7.md §1, §3, §4, §5).
  double stiffness_scale = 1.0;  // Stfac
  double damping = 0.05;         // VisS: critical-damping fraction of the normal force
  double friction_damping = 1.0; // VisF
  contact::FrictionLaw friction_law;      // Ifric, Fric, C1..C6 (eq. C-9a..c)
  bool friction = false;         // any friction at all (Fric > 0 or Ifric > 0)
  int friction_filter = 0;       // Ifiltr (eq. C-9d)
  double filter_value = 0.0;     // Xfreq: a factor, a period [T] or a frequency [T^-1]
  int friction_form = 1;         // Iform: 1 viscous, 2 stiffness (incremental)
  double t_start = 0.0, t_stop = std::numeric_limits<double>::infinity();  // [T]
  double dt_minimum = 0.0;       // card dtmin: contacts whose step falls below it are released [T]
  int idel = 0;
  std::uint8_t release_bc = 0;   // IBC: fixed dofs (bits x 1, y 2, z 4) released at a secondary node's first impact
  bool sum_pair_forces = false;  // a /TH/INTER asks |FNX| .. ||F||: the pass sums them (InterfaceResult)

  std::vector<std::int32_t> secondary_nodes;          // dense node indices
  // Per secondary node: the segment nodes of its /INTER/TYPE2 tie (all -1 when it is not tied). A tied node is
  // connected to those nodes' segments and never contacts them (C-1b).
  std::vector<std::array<std::int32_t, 4>> tied_to;
  std::vector<double> node_gap;                       // secondary gap per secondary node (variable gap) [L]
  std::vector<double> gap_reduction;                  // Inacti 5, 6: gap taken off per secondary node [L]
  std::vector<double> gap_clearance;                  // Inacti 6: the extra 5 % kept while the reduction shrinks [L]
  std::vector<std::uint8_t> node_active;              // 0: Inacti 1 or no live element left
  std::vector<std::uint8_t> node_impacted;            // 1 once the node has had a contact force (IBC)
  // Idel: the elements of each secondary node (CSR: node i owns element_of_node[node_elements[i] ..
  // node_elements[i+1]), kinds in element_kind_of_node); filled only when Idel > 0.
  std::vector<std::uint32_t> node_elements;
  std::vector<std::int32_t> element_of_node;
  std::vector<std::uint8_t> element_kind_of_node;
  std::vector<std::array<std::int32_t, 4>> segments;  // main segment nodes (triangles repeat the third)
  std::vector<double> segment_gap;                    // gap per segment (Igap 0: the constant gap) [L]
  std::vector<double> segment_stiffness;              // K0 per segment (eq. C-3) [F/L]
  std::vector<std::uint8_t> segment_active;           // 0: Inacti 2 or element deleted (Idel)
  std::vector<std::int32_t> segment_owner;            // owning element index (ElementTable of segment_owner_kind)
  std::vector<std::uint8_t> segment_owner_kind;       // ElementKind of the owner
  int stiffness_mode = 0;                             // Istf: 0 main side, 1 Stfac, 2..5 combined with the node's
  // Stiffest attached element's K0-like stiffness per secondary node (eq. C-11; times Stfac, the secondary side
  // of Istf 2..5) [F/L]
  std::vector<double> node_element_stiffness;
  bool variable_gap = false;
  double gap_min = 0.0, gap_max = std::numeric_limits<double>::infinity(), gap_scale = 1.0;
  double largest_gap = 0.0;                           // bound of every pair's gap, for the search [L]

  // Search (type7.md §2): candidate pairs of the last sort and the motion since.
  std::vector<std::int32_t> candidate_node;     // index into secondary_nodes
  std::vector<std::int32_t> candidate_segment;  // index into segments
  std::vector<double> friction_x, friction_y, friction_z;  // tangential force history per pair [F]
  // Ifiltr > 0, per secondary node: the filtered coefficient and the pass that last updated it (a node out of
  // contact for a pass starts again from the unfiltered value).
  std::vector<double> friction_mu;
  std::vector<long long> friction_mu_pass;
  long long passes = 0;             // contact passes run so far
  std::vector<double> node_area;    // Ifric > 0: the secondary node's share of its surface, for the pressure [L^2]
  std::vector<std::int32_t> main_nodes;         // the segments' nodes, each once (motion since the sort)
  // Forces of the last cycle, node by node as applied (secondary node and segment nodes), for the work (eq. C-10).
  std::vector<std::int32_t> applied_node;
  std::vector<double> applied_x, applied_y, applied_z;
  std::vector<std::uint8_t> node_touched;       // scratch: secondary node had a force this cycle
  std::vector<std::int32_t> touched_list;       // scratch: those nodes (index into secondary_nodes)
  std::vector<double> node_tangent_sum;         // scratch: sum of the node's pairs' tangent stiffnesses [F/L]
  std::vector<double> node_reach_stiffness;     // scratch: the same at the depth each pair can reach in a step [F/L]
  std::vector<double> node_unresolved_stiffness;  // scratch: at reach, what /DT/NODA/CST's mass does not hold (T-3b) [F/L]
  std::vector<double> node_entry_stiffness;     // scratch: K0 of its pairs about to enter the gap (/DT/INTER/CST) [F/L]
  std::vector<double> node_friction_viscosity;  // scratch: sum of its pairs' friction dashpots C_t (Iform 1) [F T/L]
  // The pairs this domain computes (ascending; a run of one domain: all), fixed at each sort (docs/parallel.md,
  // "Contact"): a pair belongs to the domain that owns its secondary node. pair_remote: 1 when one of the pair's
  // nodes is local to another domain too, so that its force must travel there. ghost_owner, per node (several
  // domains only): the owner of a node some domain needs for its pairs without advancing it, else -1.
  std::vector<std::int32_t> my_pairs;
  std::vector<std::uint8_t> pair_remote;
  std::vector<std::int32_t> ghost_owner;
  bool divided = false;  // my_pairs and the rest made for the current pairs (not kept in a restart file)
  // Pair screening (docs/theory/contact.md, C-12a): per candidate pair, its distance when last computed (< 0:
  // not since the sort) and the interface's motion then; the pairs of my_pairs this pass computes. Scratch, not
  // kept in a restart file: a pass that screens nothing gives the same results.
  std::vector<double> pair_distance, pair_motion;
  std::vector<std::int32_t> live_pairs;
  double margin = 0.0;                          // search margin beyond the gap [L]
  double bucket_scale = 0.2;                    // Bumult: bucket size factor
  double motion = std::numeric_limits<double>::infinity();  // accumulated largest nodal motion since the sort [L]
  long long sorts = 0;                          // number of bucket sorts so far
  // Scratch of the sort, kept between sorts so that a re-sort inside the cycle allocates nothing once warm.
  struct SortScratch {
    std::vector<double> lo, hi;                 // grown segment boxes
    std::vector<std::uint32_t> start, fill;     // bucket offsets
    std::vector<std::int32_t> entries;          // segments by bucket
    std::vector<std::int32_t> node, segment;    // the previous sort's pairs
    std::vector<double> fx, fy, fz;             // and their friction history
    std::vector<std::pair<std::uint64_t, std::size_t>> before, after;  // history matching
  } scratch;

  // Sizes the per-secondary-node state and scratch for `secondary_nodes`, every node active, nothing impacted, no
  // gap reduction and (Ifiltr > 0, eq. C-9d) no filtered coefficient yet.
  void size_node_arrays() {
    const std::size_t n = secondary_nodes.size();
    for (auto* v : {&gap_reduction, &gap_clearance, &node_tangent_sum, &node_reach_stiffness,
                    &node_unresolved_stiffness, &node_entry_stiffness, &node_friction_viscosity})
      v->assign(n, 0.0);
    node_active.assign(n, 1), node_touched.assign(n, 0), node_impacted.assign(n, 0);
    if (friction_filter > 0) friction_mu.assign(n, 0.0), friction_mu_pass.assign(n, -2);
  }

  // Gap of the pair (secondary node i, segment s), before the Inacti reduction (eq. C-2).
  double pair_gap(std::size_t i, std::size_t s) const {
    if (!variable_gap) return segment_gap[s];
    const double g = segment_gap[s] + node_gap[i];
    return (g < gap_min ? gap_min : g > gap_max ? gap_max : g) * gap_scale;
  }
  // Stiffness K0 of the pair (eq. C-3): Istf 2..5 combine the main and the secondary side.
  double pair_stiffness(std::size_t i, std::size_t s) const {
    const double km = segment_stiffness[s], ks = stiffness_scale * node_element_stiffness[i];
    switch (stiffness_mode) {
      case 2: return 0.5 * (km + ks);
      case 3: return km > ks ? km : ks;
      case 4: return km < ks ? km : ks;
      case 5: return km + ks > 0.0 ? km * ks / (km + ks) : 0.0;
      default: return km;
    }
  }
};

struct ContactState {
  std::vector<ContactInterface> interfaces;
  std::vector<InterfaceResult> results;
  std::vector<double> fx, fy, fz;  // per node: total contact force of the last cycle (all interfaces) [F]
  std::vector<std::int32_t> touched;  // nodes with a contact force this cycle (to clear and to sum work)
  // IBC: (node, dof mask) whose boundary conditions the time loop releases after this cycle's pass.
  std::vector<std::pair<std::int32_t, std::uint8_t>> bc_releases;
  // Per node: the mass of the rigid body the node moves with (0: none). Its contact springs then load the body,
  // so its step is the body's, and its own elements (carried by the body) add no stiffness (eq. C-11). The solver
  // keeps it as bodies switch on and off.
  std::vector<double> rigid_body_mass;
  // Per node: for a node tied by an /INTER/TYPE2 (which keeps no mass, TI-3), the mass of its segment at its place,
  // which its contact springs and dashpots push (C-11, TI-13); 0 for the others. Empty without ties.
  std::vector<double> tied_mass;
  // Under selective mass scaling (/DT/AMS): per node, the mass the scaling adds to its diagonal this cycle, set by
  // the solver before the pass (not owned; null without it). The pairs' and nodes' stiffness steps take it with the
  // node's mass, and leave out its elements, which the scaling holds at its step (docs/theory/time-step.md, SM-7).
  const std::vector<double>* selective_mass_added = nullptr;
  // Set by the solver when the interface nodal step (docs/theory/time-step.md, T-4) bounds the cycle: each pair then
  // gives its nodes the larger of its tangent stiffness and its viscous friction's (T-4b), and that step holds the
  // nodes' contact springs in place of their stiffness step (C-11; not for a node whose springs push another mass,
  // a rigid body's or a tie's, nor under an entry window, whose anticipated pairs are not in the gap yet).
  bool interface_nodal_step = false;
  // Per node, for the interface nodal step (docs/theory/time-step.md, T-4; empty when it is off): the contact
  // stiffness of the cycle, Kt of its pairs as a secondary node plus w Kt of each pair on a segment it carries.
  std::vector<double> nodal_contact_stiffness;
  double sort_seconds = 0.0;  // wall time of the searches so far (the positions gathered and the bucket sort) [s]
  contact::PairBatch batch;  // scratch of the pass: one batch of gathered pairs (eq. C-1)
  // Scratch of the pass: the forces of this domain's pairs in contact and the masses its nodes took (records of
  // kRecordWidth values, contact/contact_pass.cpp), those that travel, the other domains', and all in pair order.
  std::vector<double> own_records, sent_records, received_records, ordered_records;
  std::vector<std::size_t> order;       // scratch: the received pair records by pair
  std::vector<ExactSum> cycle_sums;     // scratch: one interface's sums of the cycle
};

}  // namespace crumple
