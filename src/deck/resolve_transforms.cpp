// /TRANSFORM: each transformation, in deck order, moves the nodes of its group: x' = A x + b. Its nodes (axis, centre,
// plane, frames) are taken where the transformations before it left them, as the reference does (measured:
// docs/deck-format.md, "Transformations").
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string_view>

#include "crumple/core/geometry.hpp"
#include "resolve.hpp"

namespace crumple::deck {
namespace {

struct Affine {
  std::array<Vec3, 3> rows{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Vec3 shift{};
  Vec3 operator()(Vec3 p) const { return Vec3{dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)} + shift; }
};

// x' = c + A (x - c): A about a centre c.
Affine about(const std::array<Vec3, 3>& rows, Vec3 c) {
  Affine a;
  a.rows = rows;
  a.shift = c - Vec3{dot(rows[0], c), dot(rows[1], c), dot(rows[2], c)};
  return a;
}

// The positions that define a transformation: its nodes' current ones, or its points. Nodes missing: nullopt
// (reported).
std::optional<std::array<Vec3, 6>> defining_points(Resolver& r, const Transform& t, std::size_t count) {
  std::array<Vec3, 6> p = t.points;
  if (t.node_ids[0] == 0) return p;
  bool ok = true;
  for (std::size_t k = 0; k < count; ++k) {
    const std::string field = t.kind == TransformKind::Scaling ? "node_IDc" : fmt::format("node_ID{}", k + 1);
    const auto n = r.find(r.model.index.nodes, t.node_ids[k], t.where, transform_keyword(t), field, "node");
    if (n >= 0) p[k] = r.model.nodes.position(n);
    ok = ok && n >= 0;
  }
  return ok ? std::optional(p) : std::nullopt;
}

// The field that names an axis or a plane: the nodes or the points.
std::string axis_field(const Transform& t) {
  return t.node_ids[0] != 0 ? "node_ID2" : "X_point_2, Y_point_2, Z_point_2";
}

// Rodrigues: rotation by `degrees`, right-handed about the unit axis e: c I + (1 - c) e e^T + s [e]x.
std::array<Vec3, 3> rotation_rows(Vec3 e, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a), k = 1.0 - c;
  return {Vec3{c + k * e.x * e.x, k * e.x * e.y - s * e.z, k * e.x * e.z + s * e.y},
          Vec3{k * e.y * e.x + s * e.z, c + k * e.y * e.y, k * e.y * e.z - s * e.x},
          Vec3{k * e.z * e.x - s * e.y, k * e.z * e.y + s * e.x, c + k * e.z * e.z}};
}

// Orthonormal frame of three points: e1 along p1 -> p2, e3 normal to their plane (p1 -> p2 x p1 -> p3), e2 = e3 x e1
// (the reference's rotation matrices match it to the digits printed, measured). nullopt when the points are
// collinear.
std::optional<std::array<Vec3, 3>> frame(Vec3 p1, Vec3 p2, Vec3 p3) {
  const Vec3 u = p2 - p1, normal = cross(u, p3 - p1);
  if (norm(u) == 0.0 || norm(normal) == 0.0) return std::nullopt;
  const Vec3 e1 = unit(u), e3 = unit(normal);
  return std::array<Vec3, 3>{e1, cross(e3, e1), e3};
}

bool orthonormal(const std::array<Vec3, 3>& m) {
  // The reference accepts M rounded to 4 digits (a 30-degree rotation: |M M^T - I| 4.4e-5) and refuses it rounded to
  // 2 (6.9e-3), measured; Crumple's bound lies between.
  constexpr double kTolerance = 1e-4;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (std::abs(dot(m[i], m[j]) - (i == j ? 1.0 : 0.0)) > kTolerance) return false;
  return true;
}

// POSITION: the frame of points 1, 2, 3 carried onto that of points 4, 5, 6, point 1 onto point 4:
// x' = p4 + R (x - p1), R = sum_k E_k S_k^T.
std::optional<Affine> position_affine(Resolver& r, const Transform& t) {
  const auto p = defining_points(r, t, 6);
  if (!p) return std::nullopt;
  const auto start = frame((*p)[0], (*p)[1], (*p)[2]), end = frame((*p)[3], (*p)[4], (*p)[5]);
  if (!start || !end) {
    const bool nodes = t.node_ids[0] != 0;
    const std::string field =
        nodes ? (start ? "node_ID4..6" : "node_ID1..3") : (start ? "points 4 to 6" : "points 1 to 3");
    r.error(t.where, transform_keyword(t), field, "three points that span a plane (a frame)",
            "collinear or coincident points");
    return std::nullopt;
  }
  std::array<Vec3, 3> rows{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) rows[i][j] += (*end)[k][i] * (*start)[k][j];
  Affine a = about(rows, (*p)[0]);
  a.shift = a.shift + ((*p)[3] - (*p)[0]);
  return a;
}

std::optional<Affine> affine_of(Resolver& r, const Transform& t) {
  const std::string keyword = transform_keyword(t);
  switch (t.kind) {
    case TransformKind::Translation: {
      const auto p = defining_points(r, t, 2);
      if (!p) return std::nullopt;
      Affine a;
      a.shift = t.node_ids[0] != 0 ? (*p)[1] - (*p)[0] : t.vector;
      return a;
    }
    case TransformKind::Rotation:
    case TransformKind::Symmetry: {
      const auto p = defining_points(r, t, 2);
      if (!p) return std::nullopt;
      const Vec3 axis = (*p)[1] - (*p)[0];
      if (norm(axis) == 0.0) {
        r.error(t.where, keyword, axis_field(t), "two different points (an axis)", "both at one point");
        return std::nullopt;
      }
      const Vec3 e = unit(axis);
      if (t.kind == TransformKind::Rotation) return about(rotation_rows(e, t.angle), (*p)[0]);
      std::array<Vec3, 3> mirror;
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) mirror[i][j] = (i == j ? 1.0 : 0.0) - 2.0 * e[i] * e[j];
      return about(mirror, (*p)[0]);
    }
    case TransformKind::Scaling: {
      const auto p = defining_points(r, t, 1);
      if (!p) return std::nullopt;
      const Vec3 centre = t.node_ids[0] != 0 ? (*p)[0] : Vec3{};
      return about({Vec3{t.vector.x, 0, 0}, Vec3{0, t.vector.y, 0}, Vec3{0, 0, t.vector.z}}, centre);
    }
    case TransformKind::Matrix:
      if (!orthonormal(t.rows)) {
        r.error(t.where, keyword, "M11..M33", "an orthonormal matrix (as the reference requires; blank entries are 0)",
                "a matrix whose rows are not orthonormal");
        return std::nullopt;
      }
      return Affine{t.rows, t.shift};
    case TransformKind::Position:
      return position_affine(r, t);
  }
  return std::nullopt;
}

// A mirror (SYM, or a MATRIX of determinant -1) turns bricks inside out. The reference reads such a brick as the same
// brick (measured: a cube compressed after /TRANSFORM/SYM gives the energies and the cycles of the cube as written, to
// the last digit): Crumple renumbers it, its faces 1-2-3-4 and 5-6-7-8 swapped, which is the same brick the right way
// out, and turns the surface segments it owns to face out again. A brick still inside out is an error.
void renumber_mirrored_bricks(Resolver& r, const std::vector<std::int32_t>& moved_by) {
  Model& m = r.model;
  ElementTable& bricks = m.elements[static_cast<int>(ElementKind::Brick8)];
  std::vector<char> renumbered(bricks.size(), 0);
  std::vector<long long> count(r.context.transforms.size(), 0);
  for (std::size_t e = 0; e < bricks.size(); ++e) {
    std::int32_t* n = bricks.connectivity.data() + 8 * e;
    std::int32_t last = -1;
    for (std::size_t a = 0; a < 8; ++a) last = std::max(last, moved_by[static_cast<std::size_t>(n[a])]);
    if (last < 0 || geometry::brick_volume(m.nodes.x, m.nodes.y, m.nodes.z, n) > 0.0) continue;
    std::swap_ranges(n, n + 4, n + 4);
    const double volume = geometry::brick_volume(m.nodes.x, m.nodes.y, m.nodes.z, n);
    const Transform& t = r.context.transforms[static_cast<std::size_t>(last)];
    if (!(volume > 0.0)) {
      r.error(t.where, transform_keyword(t), "grnd_ID", "transformed bricks of positive volume",
              fmt::format("BRICK {} of volume {:.6g} after it, renumbered or not", bricks.user_id[e], volume));
      return;
    }
    renumbered[e] = 1;
    ++count[static_cast<std::size_t>(last)];
  }
  for (Surface& s : m.surfaces)
    for (Segment& seg : s.segments)
      if (seg.owner.kind == ElementKind::Brick8 && seg.owner.index >= 0 &&
          renumbered[static_cast<std::size_t>(seg.owner.index)] != 0)
        seg.nodes[3] == seg.nodes[2] ? std::swap(seg.nodes[0], seg.nodes[1]) : std::swap(seg.nodes[1], seg.nodes[3]);
  for (std::size_t k = 0; k < count.size(); ++k)
    if (count[k] > 0) {
      const Transform& t = r.context.transforms[k];
      r.context.warn(t.where, transform_keyword(t),
                     fmt::format("{} bricks it turned inside out (a mirror) are renumbered, faces 1-4 and 5-8 swapped: "
                                 "the same bricks the right way out, as the reference reads them",
                                 count[k]));
    }
}


// Cards whose values hold positions or directions that a transformation of their //SUBMODEL block would have to carry
// too (the manual: a submodel's transformation is complete). Crumple moves the block's nodes only, so such a card in
// a transformed block is refused: positions for any transformation, directions for all but a translation.
constexpr std::array<std::string_view, 3> kBlockPositionCards = {"/SKEW/FIX", "/RWALL", "/FRAME"};
constexpr std::array<std::string_view, 9> kBlockDirectionCards = {"/INIVEL", "/GRAV",  "/CLOAD", "/IMPVEL", "/IMPDISP",
                                                                  "/BCS",    "/RBODY", "/ACCEL", "/TH/NODE"};

bool starts_with_any(const std::string& keyword, std::span<const std::string_view> cards) {
  return std::any_of(cards.begin(), cards.end(), [&](std::string_view c) { return keyword.starts_with(c); });
}

// The dense indices of the nodes a transformation moves: its group's, or its //SUBMODEL block's.
std::optional<std::vector<std::int32_t>> moved_nodes(Resolver& r, const Transform& t) {
  const std::string keyword = transform_keyword(t);
  if ((t.group_id != 0) == (t.submodel_id != 0)) {
    r.error(t.where, keyword, "grnd_ID", "a node group id or a sub_ID (one of them)",
            t.group_id != 0 ? "both" : "neither");
    return std::nullopt;
  }
  if (t.group_id != 0) {
    const auto g = r.find(r.model.index.node_groups, t.group_id, t.where, keyword, "grnd_ID", "node group");
    if (g < 0) return std::nullopt;
    return r.model.node_groups[static_cast<std::size_t>(g)].nodes;
  }
  const auto block = r.context.submodels.find(t.submodel_id);
  if (block == r.context.submodels.end()) {
    r.error(t.where, keyword, "sub_ID", "the id of a //SUBMODEL block of the deck", fmt::format("{}", t.submodel_id));
    return std::nullopt;
  }
  for (const std::string& card : block->second.keywords)
    if (starts_with_any(card, kBlockPositionCards) ||
        (t.kind != TransformKind::Translation && starts_with_any(card, kBlockDirectionCards))) {
      r.error(t.where, keyword, "sub_ID",
              "a block whose cards hold no positions or directions besides its nodes (Crumple moves only the nodes "
              "of a transformed //SUBMODEL)",
              fmt::format("{} in block {}", card, t.submodel_id));
      return std::nullopt;
    }
  std::vector<std::int32_t> nodes;
  for (std::size_t n = block->second.first_node; n < block->second.end_node; ++n)
    nodes.push_back(static_cast<std::int32_t>(n));
  return nodes;
}

}  // namespace

void apply_transforms(Resolver& r) {
  Model& m = r.model;
  std::vector<std::int32_t> moved_by(m.nodes.size(), -1);  // the last transformation that moved each node
  for (std::size_t k = 0; k < r.context.transforms.size(); ++k) {
    const Transform& t = r.context.transforms[k];
    const auto nodes = moved_nodes(r, t);
    const auto a = affine_of(r, t);
    if (!nodes || !a) continue;
    for (std::int32_t n : *nodes) {
      const Vec3 p = (*a)(m.nodes.position(n));
      const auto i = static_cast<std::size_t>(n);
      m.nodes.x[i] = p.x, m.nodes.y[i] = p.y, m.nodes.z[i] = p.z;
      moved_by[i] = static_cast<std::int32_t>(k);
    }
  }
  if (r.errors.empty()) renumber_mirrored_bricks(r, moved_by);
}

}  // namespace crumple::deck
