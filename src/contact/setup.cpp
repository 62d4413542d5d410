// TYPE7 interfaces from the model (docs/theory/contact.md, "Gap" and "Stiffness"; type7.md §1, §3, §4, §7).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "crumple/contact/contact.hpp"
#include "crumple/contact/kernels.hpp"
#include "crumple/core/deck_error.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/model/history_variables.hpp"
#include "crumple/model/mass.hpp"

namespace crumple::contact {
namespace {

struct ElementFacts {  // what a segment or a node needs of an element
  bool shell = false;
  double thickness = 0.0;  // shells [L]
  double stiffness = 0.0;  // K0 it gives a segment of area `area` (eq. C-3), before Stfac [F/L]
};

double brick_volume(const Model& m, std::int32_t e) {
  const std::int32_t* c = m.elements[static_cast<int>(ElementKind::Brick8)].nodes_of(static_cast<std::size_t>(e));
  return std::abs(geometry::brick_volume(m.nodes.x, m.nodes.y, m.nodes.z, c));
}

double segment_area(const Model& m, const std::array<std::int32_t, 4>& s) {
  auto X = [&](int a) { return m.nodes.position(s[static_cast<std::size_t>(a)]); };
  return s[2] == s[3] ? geometry::triangle_area(X(0), X(1), X(2)) : geometry::quad_area(X(0), X(1), X(2), X(3));
}

double shortest_side(const Model& m, const std::array<std::int32_t, 4>& s) {
  double shortest = std::numeric_limits<double>::infinity();
  const int corners = s[2] == s[3] ? 3 : 4;
  for (int a = 0; a < corners; ++a) {
    const auto i = static_cast<std::size_t>(s[static_cast<std::size_t>(a)]);
    const auto j = static_cast<std::size_t>(s[static_cast<std::size_t>((a + 1) % corners)]);
    shortest = std::min(shortest, std::hypot(m.nodes.x[i] - m.nodes.x[j], m.nodes.y[i] - m.nodes.y[j],
                                             m.nodes.z[i] - m.nodes.z[j]));
  }
  return shortest;
}

ElementFacts facts_of(const Model& m, ElementRef ref, double area) {
  ElementFacts f;
  const ElementTable& table = m.elements[static_cast<int>(ref.kind)];
  const Part& part = m.parts[static_cast<std::size_t>(table.part[static_cast<std::size_t>(ref.index)])];
  const Material& mat = m.materials[static_cast<std::size_t>(part.material)];
  if (ref.kind == ElementKind::Brick8) {
    // B A^2 / (2 V), the half that the shell's E t / 2 has too (eq. C-3); for a node (area 0) the element's own
    // face, A = V^(2/3): B V^(1/3) / 2.
    const double volume = brick_volume(m, ref.index);
    const double face = area > 0.0 ? area : std::cbrt(volume * volume);
    f.stiffness = 0.5 * mat.bulk_modulus() * face * face / volume;
  } else {
    f.shell = true;
    f.thickness = shell_thickness(m, ref.kind, static_cast<std::size_t>(ref.index));
    f.stiffness = 0.5 * mat.young * f.thickness;
  }
  return f;
}

}  // namespace

namespace {

// Irem_i2 1: the nodes an /INTER/TYPE2 ties leave the interface's secondary nodes (C-1b).
void drop_tied_nodes(const std::vector<const Tie*>& tie_of, ContactInterface& in) {
  std::erase_if(in.secondary_nodes, [&tie_of](std::int32_t node) { return tie_of[static_cast<std::size_t>(node)] != nullptr; });
}

// C-1b: each secondary node tied by an /INTER/TYPE2, with its tie's segment nodes.
void mark_tied_nodes(const std::vector<const Tie*>& tie_of, ContactInterface& in) {
  in.tied_to.clear();
  if (tie_of.empty()) return;
  in.tied_to.assign(in.secondary_nodes.size(), {-1, -1, -1, -1});
  for (std::size_t i = 0; i < in.secondary_nodes.size(); ++i)
    if (const Tie* tie = tie_of[static_cast<std::size_t>(in.secondary_nodes[i])]) in.tied_to[i] = tie->main;
}

}  // namespace

ContactState setup_contact(const Model& m, NodalState& nodes, std::vector<std::string>& notes) {
  ContactState state;
  state.fx.assign(nodes.size(), 0.0), state.fy.assign(nodes.size(), 0.0), state.fz.assign(nodes.size(), 0.0);
  // Per node: largest attached shell thickness and the stiffest attached element (secondary side, Igap, Istf).
  std::vector<double> node_thickness(nodes.size(), 0.0), node_stiffness(nodes.size(), 0.0);
  for (int kind = 0; kind < kElementKinds; ++kind) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
    for (std::size_t e = 0; e < table.size(); ++e) {
      const ElementFacts f = facts_of(m, {table.kind, static_cast<std::int32_t>(e)}, 0.0);
      const int count = nodes_per_element(table.kind);
      for (int a = 0; a < count; ++a) {
        const auto k = static_cast<std::size_t>(table.nodes_of(e)[a]);
        if (f.shell) node_thickness[k] = std::max(node_thickness[k], f.thickness);
        node_stiffness[k] = std::max(node_stiffness[k], f.stiffness);
      }
    }
  }
  std::vector<double> surface_area;  // per node, computed once when some interface has a friction law
  const std::vector<std::int32_t> summed = objects_with_history(m, HistoryObject::Interface, kInterfacePairSums);
  // The tied nodes (C-1b); empty without /INTER/TYPE2.
  const std::vector<const Tie*> tie_of = m.type2_interfaces.empty() ? std::vector<const Tie*>{} : ties_by_node(m);
  for (const Type7Interface& card : m.type7_interfaces) {
    ContactInterface in;
    InterfaceResult result;
    in.sum_pair_forces =
        std::binary_search(summed.begin(), summed.end(), static_cast<std::int32_t>(state.interfaces.size()));
    // Fields the reader accepts but the module does not implement yet: said by name, never silently dropped.
    const std::string label = fmt::format("INTER {}", card.user_id);
    if (card.ifric > 1 && card.fric > 0.0)
      notes.push_back(fmt::format("{}: WARNING Fric = {:g} is not used by Ifric = {} (the law's C1..C6 give the "
                                  "whole coefficient)", label, card.fric, card.ifric));
    in.release_bc = static_cast<std::uint8_t>((card.ibc[0] ? 1u : 0u) | (card.ibc[1] ? 2u : 0u) | (card.ibc[2] ? 4u : 0u));
    if (card.irem_gap == 1)
      notes.push_back(fmt::format("{}: WARNING Irem_gap = 1 is not implemented yet: no node is removed for a gap "
                                  "larger than its elements", label));
    in.stiffness_scale = card.stfac > 0.0 ? card.stfac : 1.0;
    in.damping = card.viss > 0.0 ? card.viss : 0.05;
    in.friction_damping = card.visf > 0.0 ? card.visf : 1.0;
    in.friction_law.kind = card.ifric;
    in.friction_law.fric = card.fric;
    std::copy(card.friction_c.begin(), card.friction_c.end(), in.friction_law.c);
    in.friction = card.fric > 0.0 || card.ifric > 0;
    in.friction_filter = in.friction ? card.ifiltr : 0;
    in.filter_value = card.xfreq;
    in.friction_form = card.iform == 2 ? 2 : 1;
    // Tstart, Tstop and the sensor's window all bound the interface's (loads.md, L-7; measured on the reference).
    in.t_start = std::max(card.tstart, card.sensor.on);
    in.t_stop = std::min(card.tstop > 0.0 ? card.tstop : std::numeric_limits<double>::infinity(), card.sensor.off);
    in.dt_minimum = card.dtmin;
    in.idel = card.idel;
    in.bucket_scale = card.bumult > 0.0 ? card.bumult : 0.2;
    in.stiffness_mode = card.istf;
    in.secondary_nodes = m.node_groups[static_cast<std::size_t>(card.secondary_group)].nodes;
    if (card.irem_i2 == 1 && !tie_of.empty()) drop_tied_nodes(tie_of, in);
    mark_tied_nodes(tie_of, in);
    const Surface& surface = m.surfaces[static_cast<std::size_t>(card.main_surface)];
    double thickness_sum = 0.0, shortest_side_all = std::numeric_limits<double>::infinity();
    int shell_segments = 0;
    for (const Segment& seg : surface.segments) {
      in.segments.push_back(seg.nodes);
      in.segment_owner.push_back(seg.owner.index);
      in.segment_owner_kind.push_back(static_cast<std::uint8_t>(seg.owner.kind));
      const ElementFacts f = seg.owner.index >= 0 ? facts_of(m, seg.owner, segment_area(m, seg.nodes)) : ElementFacts{};
      // Eq. C-3: K0 from the owning element (Istf 0) or Stfac itself (Istf 1), clamped to [Stmin, Stmax].
      double k0 = card.istf == 1 ? in.stiffness_scale : in.stiffness_scale * f.stiffness;
      k0 = std::clamp(k0, card.stmin, card.stmax > 0.0 ? card.stmax : 1e30);
      in.segment_stiffness.push_back(k0);
      in.segment_gap.push_back(f.shell ? 0.5 * f.thickness : 0.0);
      if (f.shell) thickness_sum += f.thickness, ++shell_segments;
      shortest_side_all = std::min(shortest_side_all, shortest_side(m, seg.nodes));
    }
    in.segment_active.assign(in.segments.size(), 1);
    for (const auto& seg : in.segments) in.main_nodes.insert(in.main_nodes.end(), seg.begin(), seg.end());
    std::sort(in.main_nodes.begin(), in.main_nodes.end());
    in.main_nodes.erase(std::unique(in.main_nodes.begin(), in.main_nodes.end()), in.main_nodes.end());
    // Eq. C-2: constant gap (Igap 0) from Gapmin or the main surface; variable gap (Igap 1, 2) per pair.
    in.variable_gap = card.igap == 1 || card.igap == 2;
    in.gap_min = card.gapmin;
    in.gap_max = card.gap_max > 0.0 ? card.gap_max : std::numeric_limits<double>::infinity();
    in.gap_scale = card.igap == 2 && card.fscale_gap > 0.0 ? card.fscale_gap : 1.0;
    for (std::int32_t n : in.secondary_nodes) {
      in.node_gap.push_back(0.5 * node_thickness[static_cast<std::size_t>(n)]);
      in.node_element_stiffness.push_back(node_stiffness[static_cast<std::size_t>(n)]);
    }
    if (card.ifric > 0) {
      // Pressure of the friction laws (eq. C-9a..c): normal force over the node's share of its surface. Only these
      // interfaces pay for the areas. A node on no surface (no shell, no boundary brick face) takes the mean.
      if (surface_area.empty()) surface_area = node_surface_areas(m);
      double sum = 0.0;
      long long bare = 0;
      for (std::int32_t n : in.secondary_nodes) {
        const double a = surface_area[static_cast<std::size_t>(n)];
        in.node_area.push_back(a);
        sum += a;
        bare += a > 0.0 ? 0 : 1;
      }
      const auto count = static_cast<long long>(in.secondary_nodes.size());
      const double mean = count > bare ? sum / static_cast<double>(count - bare) : 1.0;
      for (double& a : in.node_area)
        if (!(a > 0.0)) a = mean;
      if (bare > 0)
        notes.push_back(fmt::format("{}: WARNING {} secondary nodes lie on no surface; their friction pressure uses "
                                    "the mean node area {:.4g}", label, bare, mean));
    }
    if (!in.variable_gap) {
      double gap = card.gapmin;
      // Computed default (eq. C-2): the mean shell thickness, but never more than half the smallest side of the
      // main segments (so that the gap of a segment cannot swallow its neighbours' nodes in self contact on coarse
      // meshes of thick shells; the reference's starter listings show exactly this bound); brick surfaces: a
      // tenth of the smallest side.
      if (!(gap > 0.0)) {
        const double side = std::isfinite(shortest_side_all) ? shortest_side_all : 0.0;
        gap = shell_segments > 0 ? std::min(thickness_sum / shell_segments, 0.5 * side) : 0.1 * side;
      }
      std::fill(in.segment_gap.begin(), in.segment_gap.end(), gap);
      std::fill(in.node_gap.begin(), in.node_gap.end(), 0.0);
      in.gap_min = 0.0, in.gap_max = std::numeric_limits<double>::infinity(), in.gap_scale = 1.0;
    }
    double largest_segment = 0.0, largest_node = 0.0;
    for (double g : in.segment_gap) largest_segment = std::max(largest_segment, g);
    for (double g : in.node_gap) largest_node = std::max(largest_node, g);
    in.largest_gap = std::min(std::max(largest_segment + largest_node, in.gap_min), in.gap_max) * in.gap_scale;
    in.margin = in.largest_gap;  // re-sort after the nodes have moved by a gap (eq. C-12)
    in.size_node_arrays();
    if (in.idel > 0) {
      // Idel: a secondary node leaves the interface once none of its elements is left (type7.md §2).
      std::vector<std::int32_t> slot(nodes.size(), -1);
      for (std::size_t i = 0; i < in.secondary_nodes.size(); ++i) slot[static_cast<std::size_t>(in.secondary_nodes[i])] = static_cast<std::int32_t>(i);
      std::vector<std::vector<std::pair<std::uint8_t, std::int32_t>>> attached(in.secondary_nodes.size());
      for (int kind = 0; kind < kElementKinds; ++kind) {
        const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
        for (std::size_t e = 0; e < table.size(); ++e)
          for (int a = 0; a < nodes_per_element(table.kind); ++a) {
            const std::int32_t i = slot[static_cast<std::size_t>(table.nodes_of(e)[a])];
            if (i >= 0) attached[static_cast<std::size_t>(i)].emplace_back(static_cast<std::uint8_t>(kind), static_cast<std::int32_t>(e));
          }
      }
      in.node_elements.assign(1, 0);
      for (std::size_t i = 0; i < attached.size(); ++i) {
        for (const auto& [kind, e] : attached[i]) in.element_kind_of_node.push_back(kind), in.element_of_node.push_back(e);
        in.node_elements.push_back(static_cast<std::uint32_t>(in.element_of_node.size()));
        if (attached[i].empty()) in.node_active[i] = 0;  // a node of no element is never a secondary node
      }
    }
    if (!(in.largest_gap > 0.0))
      throw DeckError(card.where, fmt::format("/INTER/TYPE7/{}", card.user_id), "Gapmin",
                      "a positive gap (the main surface gives none: no thickness and no side length)", "0");

    // Initial penetrations (type7.md §7): every candidate pair whose distance is already inside the gap.
    sort_candidates(in, nodes);
    std::vector<double> worst(in.secondary_nodes.size(), 0.0);
    std::vector<std::int32_t> worst_segment(in.secondary_nodes.size(), -1);
    std::vector<std::array<double, 3>> outward(in.secondary_nodes.size());
    for (std::size_t q = 0; q < in.candidate_node.size(); ++q) {
      const auto i = static_cast<std::size_t>(in.candidate_node[q]);
      const auto s = static_cast<std::size_t>(in.candidate_segment[q]);
      const auto n = static_cast<std::size_t>(in.secondary_nodes[i]);
      double x[4][3];
      for (int a = 0; a < 4; ++a) {
        const auto k = static_cast<std::size_t>(in.segments[s][static_cast<std::size_t>(a)]);
        x[a][0] = nodes.x[k], x[a][1] = nodes.y[k], x[a][2] = nodes.z[k];
      }
      const double p[3] = {nodes.x[n], nodes.y[n], nodes.z[n]};
      const SegmentPoint c = closest_point_on_segment(p, x);
      const double g = in.pair_gap(i, s);
      // Inacti 2: every segment a node starts inside the gap of leaves, not only its deepest: a node 99 % into
      // the gap of one segment is as deep in its neighbours' (stability.BallPlate penetration cases).
      if (card.inacti == 2 && c.distance < g) in.segment_active[s] = 0;
      if (c.distance < g && g - c.distance > worst[i]) {
        worst[i] = g - c.distance, worst_segment[i] = static_cast<std::int32_t>(s);
        for (int d = 0; d < 3; ++d) outward[i][static_cast<std::size_t>(d)] = c.distance > 0.0 ? (p[d] - c.point[d]) / c.distance : 0.0;
      }
    }
    const std::string name = fmt::format("INTER {}", card.user_id);
    double deepest = 0.0;
    std::int32_t deepest_node = -1;
    for (std::size_t i = 0; i < worst.size(); ++i) {
      if (worst_segment[i] < 0) continue;
      const std::int32_t n = in.secondary_nodes[i];
      result.initial_penetrations.push_back({n, worst_segment[i], worst[i]});
      if (worst[i] > deepest) deepest = worst[i], deepest_node = n;
      switch (card.inacti) {
        case 1: in.node_active[i] = 0; break;
        case 2: break;  // its segments are removed above
        case 3: {
          const auto k = static_cast<std::size_t>(n);
          nodes.x[k] += worst[i] * outward[i][0], nodes.y[k] += worst[i] * outward[i][1], nodes.z[k] += worst[i] * outward[i][2];
          break;
        }
        case 5: in.gap_reduction[i] = worst[i]; break;
        case 6:
          in.gap_clearance[i] = 0.05 * (in.largest_gap - worst[i]);
          in.gap_reduction[i] = worst[i] + in.gap_clearance[i];
          break;
        default: break;
      }
    }
    if (!result.initial_penetrations.empty()) {
      static constexpr const char* action[7] = {"no action: they start with a contact force",
                                                "their stiffness is removed (Inacti 1)",
                                                "every segment they start inside the gap of is removed (Inacti 2)",
                                                "they are moved out of the gap (Inacti 3)", "", 
                                                "their gap is reduced to the initial distance (Inacti 5)",
                                                "their gap is reduced to the initial distance less 5 % (Inacti 6)"};
      notes.push_back(fmt::format("{}: {} secondary node(s) start inside the gap, deepest node {} with "
                                  "penetration {:.4g} (gap {:.4g}); {}",
                                  name, result.initial_penetrations.size(), m.nodes.user_id[static_cast<std::size_t>(deepest_node)],
                                  deepest, in.largest_gap, action[std::clamp(card.inacti, 0, 6)]));
      std::size_t listed = 0;
      for (const InitialPenetration& ip : result.initial_penetrations) {
        if (++listed > 20) {
          notes.push_back(fmt::format("{}: ... and {} more initially penetrated nodes", name,
                                      result.initial_penetrations.size() - 20));
          break;
        }
        const auto k = static_cast<std::size_t>(ip.node);
        notes.push_back(fmt::format("{}: node {} segment {} penetration {:.4g}{}", name, m.nodes.user_id[k],
                                    ip.segment + 1, ip.penetration,
                                    card.inacti == 3 ? fmt::format(" moved to ({:.6g}, {:.6g}, {:.6g})", nodes.x[k], nodes.y[k], nodes.z[k]) : ""));
      }
    }
    in.motion = std::numeric_limits<double>::infinity();  // sort again at the first cycle (Inacti 3 moved nodes)
    state.interfaces.push_back(std::move(in));
    state.results.push_back(std::move(result));
  }
  return state;
}

}  // namespace crumple::contact
