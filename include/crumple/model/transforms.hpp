#pragma once
// Node transformations (/TRANSFORM/TRA, /ROT, /SCA, /SYM, /MATRIX, /POSITION): each moves the nodes of one node group,
// in deck order, once the groups are known and before anything else uses the nodes' positions (docs/deck-format.md,
// "Transformations"; the order, resolve.cpp).
#include <array>
#include <cstdint>
#include <string>

#include "crumple/core/source_location.hpp"
#include "crumple/core/vec3.hpp"

namespace crumple {

enum class TransformKind : std::uint8_t { Translation, Rotation, Scaling, Symmetry, Matrix, Position };

struct Transform {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  TransformKind kind = TransformKind::Translation;
  std::int64_t group_id = 0;     // grnd_ID: the nodes moved
  std::int64_t submodel_id = 0;  // sub_ID: or the nodes of this //SUBMODEL block (docs/deck-format.md, "Submodels")
  // Nodes that define the transformation (0: none, the points are used). TRA, ROT, SYM: node_ID1, node_ID2; SCA:
  // node_IDc in [0]; POSITION: node_ID1..6. Their positions are taken when the transformation is applied, after the
  // transformations before it in the deck.
  std::array<std::int64_t, 6> node_ids{};
  // Points by coordinates [L]. ROT, SYM: point 1, point 2; POSITION: points 1 to 6.
  std::array<Vec3, 6> points{};
  Vec3 vector{};       // TRA: the translation [L]; SCA: the scale factors
  double angle = 0.0;  // ROT: degrees, right-handed about point 1 -> point 2
  // MATRIX: x' = M x + T, M's rows as written (M11 M12 M13 first).
  std::array<Vec3, 3> rows{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Vec3 shift{};  // MATRIX: Tx Ty Tz [L]
};

// The keyword of a transformation for messages, "/TRANSFORM/ROT/3".
inline std::string transform_keyword(const Transform& t) {
  constexpr const char* kTypes[] = {"TRA", "ROT", "SCA", "SYM", "MATRIX", "POSITION"};
  return std::string("/TRANSFORM/") + kTypes[static_cast<int>(t.kind)] + "/" + std::to_string(t.user_id);
}

}  // namespace crumple
