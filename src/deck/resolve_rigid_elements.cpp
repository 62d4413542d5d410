// /RBE2 and /RBE3: ids to indices, their node sets, and the combinations with other kinematic conditions that
// Crumple refuses rather than run with one condition silently overriding another (docs/theory/rigid-bodies.md,
// RE-6 and RI-6). Runs after the interfaces are resolved: a TYPE2 tied node is one of those conditions.
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "resolve.hpp"

namespace crumple::deck {
namespace {

// What already drives a node, named as the deck names it ("secondary node of /RBE2/3"); empty when nothing does.
class NodeClaims {
 public:
  explicit NodeClaims(std::size_t nodes) : by_(nodes, -1) {}
  void claim(std::int32_t node, std::string what) {
    if (node < 0 || by_[static_cast<std::size_t>(node)] >= 0) return;  // the first claim names the node
    by_[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(names_.size());
    names_.push_back(std::move(what));
  }
  const std::string* held(std::int32_t node) const {
    const std::int32_t k = by_[static_cast<std::size_t>(node)];
    return k < 0 ? nullptr : &names_[static_cast<std::size_t>(k)];
  }

 private:
  std::vector<std::int32_t> by_;
  std::vector<std::string> names_;
};

const std::vector<std::int32_t>& group_nodes(const Model& m, std::int32_t group) {
  return m.node_groups[static_cast<std::size_t>(group)].nodes;
}

// The conditions that set a node's velocity, in two kinds: those that may drive an /RBE2's main node (the group
// follows them, RE-4) and those that may drive none of its nodes (a body carrying the node, a wall, a tie or a final
// geometry acting after the /RBE2 has placed it). Every /RBE2 secondary and /RBE3 dependent node is refused both.
struct KinematicClaims {
  NodeClaims drivers, carriers;
};

KinematicClaims kinematic_claims(const Model& m) {
  KinematicClaims k{NodeClaims(m.nodes.size()), NodeClaims(m.nodes.size())};
  for (const BoundaryCondition& bc : m.boundary_conditions)
    if (bc.node_group >= 0)
      for (std::int32_t n : group_nodes(m, bc.node_group)) k.drivers.claim(n, fmt::format("held by /BCS/{}", bc.user_id));
  for (const ImposedMotion& im : m.imposed)
    if (im.kind != ImposedKind::Force && im.node_group >= 0)
      for (std::int32_t n : group_nodes(m, im.node_group))
        k.drivers.claim(n, fmt::format("driven by {}/{}", im.kind == ImposedKind::Velocity ? "/IMPVEL" : "/IMPDISP",
                                       im.user_id));
  for (const RigidBody& b : m.rigid_bodies) {
    k.carriers.claim(b.main_node, fmt::format("the main node of /RBODY/{}", b.user_id));
    if (b.node_group >= 0)
      for (std::int32_t n : group_nodes(m, b.node_group)) k.carriers.claim(n, fmt::format("in /RBODY/{}", b.user_id));
  }
  for (const FinalGeometry& g : m.final_geometries)
    for (std::int32_t n : g.nodes) k.carriers.claim(n, fmt::format("driven by /IMPDISP/FGEO/{}", g.user_id));
  for (const RigidWall& w : m.rigid_walls) {
    k.carriers.claim(w.node, fmt::format("the node of /RWALL/{}", w.user_id));
    for (std::int32_t n : w.secondary_nodes) k.carriers.claim(n, fmt::format("held by /RWALL/{}", w.user_id));
  }
  for (const Type2Interface& i : m.type2_interfaces)
    for (const Tie& t : i.ties) k.carriers.claim(t.node, fmt::format("tied by /INTER/TYPE2/{}", i.user_id));
  return k;
}

void refuse_claimed(Resolver& r, const NodeClaims& claims, std::int32_t node, const SourceLocation& where,
                    const std::string& kw, std::string_view field, std::string_view role) {
  const std::string* held = claims.held(node);
  if (held == nullptr) return;
  r.error(where, kw, std::string(field),
          fmt::format("{} that no other kinematic condition drives (Crumple moves a node by one condition)", role),
          fmt::format("node {} is {}", r.model.nodes.user_id[static_cast<std::size_t>(node)], *held));
}

// The main node drives its secondary nodes; /BCS, /IMPVEL and /IMPDISP on the main node act on the whole group
// (RE-4), so they are claims only for the secondary nodes. A secondary node in the main node's own group is
// dropped, as the reference does (its warning 1624).
void resolve_rbe2(Resolver& r, RigidElement& e, const KinematicClaims& others, NodeClaims& rigid_nodes) {
  Model& m = r.model;
  const std::string kw = fmt::format("/RBE2/{}", e.user_id);
  e.main_node = r.find(m.index.nodes, e.main_node_id, e.where, kw, "node_ID", "node");
  e.node_group = r.find(m.index.node_groups, e.node_group_id, e.where, kw, "grnod_ID", "node group");
  r.find_optional(m.index.skews, e.skew_id, e.where, kw, "skew_ID", "skew");  // with 111 111 it changes nothing (RE-1)
  if (e.main_node < 0 || e.node_group < 0) return;
  for (std::int32_t n : group_nodes(m, e.node_group))
    if (n != e.main_node) e.secondary_nodes.push_back(n);
  if (e.secondary_nodes.size() < group_nodes(m, e.node_group).size())
    r.context.warn(e.where, kw, fmt::format("main node {} is in its secondary node group {}: left out of it",
                                            e.main_node_id, e.node_group_id));
  if (e.secondary_nodes.empty())
    r.context.warn(e.where, kw, fmt::format("node group {} has no secondary node: the /RBE2 does nothing",
                                            e.node_group_id));
  if (const std::string* held = rigid_nodes.held(e.main_node))
    r.error(e.where, kw, "node_ID", "a main node in no other /RBE2 (chains of /RBE2 are not supported by Crumple)",
            fmt::format("node {} is {}", e.main_node_id, *held));
  refuse_claimed(r, others.carriers, e.main_node, e.where, kw, "node_ID", "a main node");
  for (const NodeClaims* c : {static_cast<const NodeClaims*>(&rigid_nodes), &others.drivers, &others.carriers})
    for (std::int32_t n : e.secondary_nodes) refuse_claimed(r, *c, n, e.where, kw, "grnod_ID", "secondary nodes");
  rigid_nodes.claim(e.main_node, fmt::format("the main node of {}", kw));
  for (std::int32_t n : e.secondary_nodes) rigid_nodes.claim(n, fmt::format("a secondary node of {}", kw));
}

// I_modif (RI-2, measured): 2 keeps the weights; 1 scales each translation k of the nodes that carry it (and their
// rotation k) by W / W_k, so that every translation carries the whole weight; 3 sets every weight to 1 first.
void apply_weight_modification(InterpolationConstraint& c, const std::vector<std::array<bool, 6>>& codes) {
  double total = 0.0;
  std::array<double, 3> carried{};
  for (std::size_t i = 0; i < c.independent.size(); ++i) {
    InterpolationNode& node = c.independent[i];
    const double w = c.i_modif == 3 ? 1.0 : node.given_weight;
    total += w;
    for (std::size_t d = 0; d < 6; ++d) node.weight[d] = codes[i][d] ? w : 0.0;
    for (std::size_t k = 0; k < 3; ++k) carried[k] += node.weight[k];
  }
  if (c.i_modif == 2) return;
  for (InterpolationNode& node : c.independent)
    for (std::size_t k = 0; k < 3; ++k) {
      const double factor = carried[k] > 0.0 ? total / carried[k] : 1.0;
      node.weight[k] *= factor, node.weight[3 + k] *= factor;
    }
}

// The dependent node carries no element (the reference switches such an /RBE3 to a penalty formulation, its warning
// 3097) and no other kinematic condition; its independent sets are node groups without it.
void resolve_rbe3(Resolver& r, InterpolationConstraint& c, const KinematicClaims& others, NodeClaims& rigid_nodes,
                  const std::vector<std::uint8_t>& in_element) {
  Model& m = r.model;
  const std::string kw = fmt::format("/RBE3/{}", c.user_id);
  c.dependent_node = r.find(m.index.nodes, c.dependent_node_id, c.where, kw, "Node_IDr", "node");
  if (c.dependent_node >= 0) {
    if (in_element[static_cast<std::size_t>(c.dependent_node)] != 0)
      r.error(c.where, kw, "Node_IDr", "a dependent node that no element uses (the reference's penalty formulation "
              "for such a node is not supported by Crumple)", fmt::format("node {}", c.dependent_node_id));
    for (const NodeClaims* claims : {&others.drivers, &others.carriers, static_cast<const NodeClaims*>(&rigid_nodes)})
      refuse_claimed(r, *claims, c.dependent_node, c.where, kw, "Node_IDr", "a dependent node");
    rigid_nodes.claim(c.dependent_node, fmt::format("the dependent node of {}", kw));
  }
  std::vector<std::array<bool, 6>> codes;
  std::vector<std::int32_t> seen;
  for (InterpolationSet& set : c.sets) {
    set.node_group = r.find(m.index.node_groups, set.node_group_id, c.where, kw, "grnod_IDi", "node group");
    r.find_optional(m.index.skews, set.skew_id, c.where, kw, "skew_IDi", "skew");  // no effect on its codes (RI-1)
    if (set.node_group < 0) continue;
    for (std::int32_t n : group_nodes(m, set.node_group)) {
      if (n == c.dependent_node) {
        r.error(c.where, kw, "grnod_IDi", "independent nodes other than the dependent node",
                fmt::format("node {} is in node group {}", c.dependent_node_id, set.node_group_id));
        continue;
      }
      // A node in two sets: the reference's error 705 where their weights differ; Crumple takes each node once.
      if (std::find(seen.begin(), seen.end(), n) != seen.end()) {
        r.error(c.where, kw, "grnod_IDi", "each independent node in one set",
                fmt::format("node {} is in two sets", m.nodes.user_id[static_cast<std::size_t>(n)]));
        continue;
      }
      seen.push_back(n);
      c.independent.push_back({n, {}, set.weight});
      codes.push_back({set.translation[0], set.translation[1], set.translation[2], set.rotation[0], set.rotation[1],
                       set.rotation[2]});
      c.total_weight += set.weight;
    }
  }
  if (c.independent.empty() && r.errors.empty())
    r.error(c.where, kw, "grnod_IDi", "at least one independent node", "empty node groups");
  apply_weight_modification(c, codes);
}

}  // namespace

void resolve_rigid_elements(Resolver& r) {
  Model& m = r.model;
  if (m.rigid_elements.empty() && m.interpolation_constraints.empty()) return;
  r.index(m.rigid_elements, m.index.rigid_elements, "/RBE2");
  r.index(m.interpolation_constraints, m.index.interpolation_constraints, "/RBE3");
  if (m.run.dt_ams.given)
    r.error(m.run.dt_ams.where, "/DT/AMS", "", "a model without /RBE2 or /RBE3 (selective mass scaling of their "
            "groups is not supported by Crumple)", "/DT/AMS");
  const KinematicClaims others = kinematic_claims(m);
  NodeClaims rigid_nodes(m.nodes.size());
  for (RigidElement& e : m.rigid_elements) resolve_rbe2(r, e, others, rigid_nodes);
  std::vector<std::uint8_t> in_element(m.nodes.size(), 0);
  for (const ElementTable& table : m.elements)
    for (std::int32_t node : table.connectivity) in_element[static_cast<std::size_t>(node)] = 1;
  for (InterpolationConstraint& c : m.interpolation_constraints) resolve_rbe3(r, c, others, rigid_nodes, in_element);
  // An independent node that is another /RBE3's dependent node would make a chain, which Crumple does not solve.
  std::vector<std::int32_t> dependent_of(m.nodes.size(), -1);
  for (std::size_t k = 0; k < m.interpolation_constraints.size(); ++k)
    if (const std::int32_t d = m.interpolation_constraints[k].dependent_node; d >= 0)
      dependent_of[static_cast<std::size_t>(d)] = static_cast<std::int32_t>(k);
  for (const InterpolationConstraint& c : m.interpolation_constraints)
    for (const InterpolationNode& i : c.independent)
      if (const std::int32_t k = dependent_of[static_cast<std::size_t>(i.node)]; k >= 0)
        r.error(c.where, fmt::format("/RBE3/{}", c.user_id), "grnod_IDi",
                "independent nodes that are no /RBE3's dependent node (chains of /RBE3 are not supported by Crumple)",
                fmt::format("node {} is the dependent node of /RBE3/{}", m.nodes.user_id[static_cast<std::size_t>(i.node)],
                            m.interpolation_constraints[static_cast<std::size_t>(k)].user_id));
}

}  // namespace crumple::deck

namespace crumple::deck {

namespace {

// SP-25f: a joint's frame nodes, node_ID3 away from its first node where its type needs it or it is given, and
// node_ID4 off the line of the two where the universal or the free joint needs it or it is given; a Skew_ID1 beside
// node_ID3 is named once per property (`skew_noted`).
void check_joint_frame_nodes(Resolver& r, const Property& p, const ElementTable& table, std::size_t e,
                             char& skew_noted) {
  const Model& m = r.model;
  const std::int32_t* n = table.nodes_of(e);
  const std::int32_t third = table.orientation_node.empty() ? -1 : table.orientation_node[e];
  const std::int32_t fourth = table.plane_node.empty() ? -1 : table.plane_node[e];
  const int needs = p.spring.joint.frame_nodes();
  const std::string keyword = fmt::format("/PROP/TYPE45/{}", p.user_id);
  const std::string spring = fmt::format("/SPRING {}", table.user_id[e]);
  const auto from_first = [&](std::int32_t k) { return m.nodes.position(k) - m.nodes.position(n[0]); };
  if ((needs >= 1 || third >= 0 || fourth >= 0) && (third < 0 || !(norm(from_first(third)) > 0.0))) {
    r.error(p.where, keyword, "node_ID3",
            "on the joint's /SPRING card a third node away from its first, which sets the joint's frame (every type "
            "but 1 and 8 needs it, or a Skew_ID1)",
            spring);
    return;
  }
  if (third >= 0 && p.spring.joint.skew_id != 0 && !skew_noted) {
    skew_noted = 1;
    r.context.note(p.where, keyword, "Skew_ID1",
                   "sets the frame only where the /SPRING card gives no node_ID3; ignored, as by the reference",
                   SkipKind::Unsupported);
  }
  if (needs < 2 && fourth < 0) return;
  const Vec3 axis = from_first(third), plane = fourth < 0 ? Vec3{} : from_first(fourth);
  if (fourth < 0 || !(norm(cross(axis, plane)) > 1e-9 * norm(axis) * norm(plane)))
    r.error(p.where, keyword, "node_ID4",
            "on the joint's /SPRING card a fourth node off the line of its first and third, which with them sets the "
            "joint's frame (Type 5 and 9 need it)",
            spring);
}

}  // namespace

// SP-25: a joint's blocking stiffness follows from the masses and inertias of the two rigid bodies it joins, one per
// node (the reference's automatic stiffness "from rigid bodies"); a node off every body has none that Crumple takes.
void refuse_joints_off_bodies(Resolver& r) {
  const Model& m = r.model;
  std::vector<std::int32_t> body_of(m.nodes.size(), -1);
  for (std::size_t b = 0; b < m.rigid_bodies.size(); ++b) {
    const RigidBody& body = m.rigid_bodies[b];
    if (body.node_group >= 0)
      for (std::int32_t node : m.node_groups[static_cast<std::size_t>(body.node_group)].nodes)
      body_of[static_cast<std::size_t>(node)] = static_cast<std::int32_t>(b);
    body_of[static_cast<std::size_t>(body.main_node)] = static_cast<std::int32_t>(b);
  }
  const ElementTable& table = m.elements[static_cast<int>(ElementKind::Spring)];
  std::vector<char> skew_noted(m.properties.size(), 0);
  for (const ElementGroup& group : m.element_groups) {
    if (group.kind != ElementKind::Spring) continue;
    const Property& p = m.properties[static_cast<std::size_t>(group.property)];
    if (!p.spring.joint.on) continue;
    for (auto e = static_cast<std::size_t>(group.begin); e < static_cast<std::size_t>(group.end); ++e) {
      const std::int32_t* n = table.nodes_of(e);
      check_joint_frame_nodes(r, p, table, e, skew_noted[static_cast<std::size_t>(group.property)]);
      const std::int32_t a = body_of[static_cast<std::size_t>(n[0])], b = body_of[static_cast<std::size_t>(n[1])];
      if (a >= 0 && b >= 0 && a != b) continue;
      r.error(p.where, fmt::format("/PROP/TYPE45/{}", p.user_id), "Kn",
              "a joint whose two nodes are each on a /RBODY of its own (the automatic blocking stiffness of "
              "deformable bodies is not supported by Crumple)",
              fmt::format("/SPRING {} between nodes {} and {}", table.user_id[e],
                          m.nodes.user_id[static_cast<std::size_t>(n[0])], m.nodes.user_id[static_cast<std::size_t>(n[1])]));
    }
  }
}

}  // namespace crumple::deck
