// Bucket sort of candidate pairs (docs/theory/contact.md, "Search", eq. C-12).
#include <algorithm>
#include <cmath>
#include <limits>

#include "crumple/contact/contact.hpp"

namespace crumple::contact {
namespace {

// Whether a segment shares a node with a tie's segment (C-1b).
bool connected(const std::array<std::int32_t, 4>& segment, const std::array<std::int32_t, 4>& tie) {
  for (std::int32_t a : segment)
    for (std::int32_t b : tie)
      if (a == b) return true;
  return false;
}

}  // namespace

void sort_candidates(ContactInterface& in, const NodalState& nodes) {
  const std::size_t segments = in.segments.size(), secondary = in.secondary_nodes.size();
  // Keep the friction history of the pairs that survive the sort (swapped into the scratch, capacity kept).
  ContactInterface::SortScratch& w = in.scratch;
  std::swap(w.node, in.candidate_node), std::swap(w.segment, in.candidate_segment);
  std::swap(w.fx, in.friction_x), std::swap(w.fy, in.friction_y), std::swap(w.fz, in.friction_z);
  const std::vector<std::int32_t>& old_node = w.node;
  const std::vector<std::int32_t>& old_segment = w.segment;
  const std::vector<double>& old_fx = w.fx;
  const std::vector<double>& old_fy = w.fy;
  const std::vector<double>& old_fz = w.fz;
  in.candidate_node.clear(), in.candidate_segment.clear();
  in.friction_x.clear(), in.friction_y.clear(), in.friction_z.clear();
  in.motion = 0.0;
  ++in.sorts;
  if (segments == 0 || secondary == 0) return;

  // Segment boxes grown by the reach: the largest gap plus the margin (a pair is a candidate when the node is
  // inside the grown box).
  const double reach = in.largest_gap + in.margin;
  std::vector<double>& lo = w.lo;
  std::vector<double>& hi = w.hi;
  lo.assign(3 * segments, 0.0), hi.assign(3 * segments, 0.0);
  double box_lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
  double box_hi[3] = {-box_lo[0], -box_lo[1], -box_lo[2]};
  double size_sum = 0.0;
  const std::vector<double>* coordinate[3] = {&nodes.x, &nodes.y, &nodes.z};
  for (std::size_t s = 0; s < segments; ++s) {
    double extent = 0.0;
    for (int d = 0; d < 3; ++d) {
      double a = std::numeric_limits<double>::infinity(), b = -a;
      for (std::int32_t n : in.segments[s]) {
        const double v = (*coordinate[d])[static_cast<std::size_t>(n)];
        a = std::min(a, v), b = std::max(b, v);
      }
      lo[3 * s + d] = a - reach, hi[3 * s + d] = b + reach;
      extent = std::max(extent, b - a);
      box_lo[d] = std::min(box_lo[d], a - reach), box_hi[d] = std::max(box_hi[d], b + reach);
    }
    size_sum += extent;
  }
  // Bucket edge: the mean segment size plus the reach, scaled by 1 + Bumult; at most ~ 8 (nodes + segments)
  // buckets in all.
  double edge = (1.0 + in.bucket_scale) * (size_sum / static_cast<double>(segments) + 2.0 * reach);
  int cells[3];
  for (;;) {
    double total = 1.0;
    for (int d = 0; d < 3; ++d) {
      cells[d] = std::max(1, static_cast<int>(std::ceil((box_hi[d] - box_lo[d]) / edge)));
      total *= cells[d];
    }
    if (total <= 8.0 * static_cast<double>(segments + secondary) + 64.0) break;
    edge *= 1.5;
  }
  auto cell_of = [&](double v, int d) {
    return std::clamp(static_cast<int>((v - box_lo[d]) / edge), 0, cells[d] - 1);
  };
  const auto total_cells = static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) * static_cast<std::size_t>(cells[2]);
  auto flat = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(cells[1]) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(cells[0]) + static_cast<std::size_t>(i);
  };
  // Counting sort of (cell, segment) entries: count, prefix sum, fill. O(segments x cells per segment).
  std::vector<std::uint32_t>& start = w.start;
  start.assign(total_cells + 1, 0);
  auto for_cells = [&](std::size_t s, auto&& f) {
    const int i0 = cell_of(lo[3 * s], 0), i1 = cell_of(hi[3 * s], 0), j0 = cell_of(lo[3 * s + 1], 1),
              j1 = cell_of(hi[3 * s + 1], 1), k0 = cell_of(lo[3 * s + 2], 2), k1 = cell_of(hi[3 * s + 2], 2);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f(flat(i, j, k));
  };
  for (std::size_t s = 0; s < segments; ++s)
    if (in.segment_active[s]) for_cells(s, [&](std::size_t c) { ++start[c + 1]; });
  for (std::size_t c = 0; c < total_cells; ++c) start[c + 1] += start[c];
  std::vector<std::int32_t>& entries = w.entries;
  entries.assign(start[total_cells], 0);
  std::vector<std::uint32_t>& fill = w.fill;
  fill.assign(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < segments; ++s)
    if (in.segment_active[s]) for_cells(s, [&](std::size_t c) { entries[fill[c]++] = static_cast<std::int32_t>(s); });

  // Each secondary node meets the segments listed in its own bucket: a segment reaches every bucket its grown box
  // touches, so each pair is found once.
  for (std::size_t i = 0; i < secondary; ++i) {
    if (!in.node_active[i]) continue;
    const auto n = static_cast<std::size_t>(in.secondary_nodes[i]);
    const double p[3] = {nodes.x[n], nodes.y[n], nodes.z[n]};
    if (p[0] < box_lo[0] || p[0] > box_hi[0] || p[1] < box_lo[1] || p[1] > box_hi[1] || p[2] < box_lo[2] ||
        p[2] > box_hi[2])
      continue;
    const std::size_t c = flat(cell_of(p[0], 0), cell_of(p[1], 1), cell_of(p[2], 2));
    for (std::uint32_t e = start[c]; e < start[c + 1]; ++e) {
      const auto s = static_cast<std::size_t>(entries[e]);
      if (p[0] < lo[3 * s] || p[0] > hi[3 * s] || p[1] < lo[3 * s + 1] || p[1] > hi[3 * s + 1] ||
          p[2] < lo[3 * s + 2] || p[2] > hi[3 * s + 2])
        continue;
      // Self contact: never against a segment the node belongs to.
      const auto& seg = in.segments[s];
      if (std::find(seg.begin(), seg.end(), static_cast<std::int32_t>(n)) != seg.end()) continue;
      // A tied node: never against the segments its tie connects it to (C-1b).
      if (!in.tied_to.empty() && in.tied_to[i][0] >= 0 && connected(seg, in.tied_to[i])) continue;
      in.candidate_node.push_back(static_cast<std::int32_t>(i));
      in.candidate_segment.push_back(static_cast<std::int32_t>(s));
    }
  }
  // Friction history: pairs are produced in node order, segments in bucket order; match the old pairs by a merge
  // over (node, segment) after sorting both lists' indices.
  const std::size_t pairs = in.candidate_node.size();
  in.friction_x.assign(pairs, 0.0), in.friction_y.assign(pairs, 0.0), in.friction_z.assign(pairs, 0.0);
  if (old_node.empty()) return;
  auto key = [](std::int32_t a, std::int32_t b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  };
  auto& before = w.before;
  auto& after = w.after;
  before.clear(), after.clear();
  for (std::size_t q = 0; q < old_node.size(); ++q)
    if (old_fx[q] != 0.0 || old_fy[q] != 0.0 || old_fz[q] != 0.0) before.emplace_back(key(old_node[q], old_segment[q]), q);
  if (before.empty()) return;
  for (std::size_t q = 0; q < pairs; ++q) after.emplace_back(key(in.candidate_node[q], in.candidate_segment[q]), q);
  std::sort(before.begin(), before.end()), std::sort(after.begin(), after.end());
  for (std::size_t a = 0, b = 0; a < after.size() && b < before.size();) {
    if (after[a].first < before[b].first) ++a;
    else if (before[b].first < after[a].first) ++b;
    else {
      const std::size_t q = after[a].second, o = before[b].second;
      in.friction_x[q] = old_fx[o], in.friction_y[q] = old_fy[o], in.friction_z[q] = old_fz[o];
      ++a, ++b;
    }
  }
}

}  // namespace crumple::contact
