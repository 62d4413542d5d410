#pragma once
// Elements as structures of arrays, one table per element kind, ordered by part. The solver walks them in
// ElementGroups: contiguous runs of at most kElementGroupSize elements of one kind, part, property and material,
// sized so that a kernel's inner loop over a group vectorises.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "crumple/model/properties.hpp"
#include "crumple/model/run_control.hpp"

namespace crumple {

enum class ElementKind : std::uint8_t { Shell4, Shell3, Brick8, Spring, Truss, Beam };
inline constexpr int kElementKinds = 6;
inline constexpr ElementKind kAllElementKinds[kElementKinds] = {ElementKind::Shell4, ElementKind::Shell3,
                                                                ElementKind::Brick8, ElementKind::Spring,
                                                                ElementKind::Truss,  ElementKind::Beam};
inline constexpr int kElementGroupSize = 128;

// What an element kind is, as data: one row per kind in kElementKindTable, which the reader, the model, the
// solver and the output read instead of asking the kind (docs/architecture.md, "Adding an element kind").
struct ElementKindDescription {
  ElementKind kind;
  std::string_view name;       // the listing's word for one element: "SHELL 12 of part 3"
  std::string_view what;       // the messages' word: "4-node shell"
  std::string_view counted;    // the counts' word in `crumple check` and the listing: "4-node shells"
  std::string_view card;       // the element card: /SHELL
  std::string_view step_card;  // its /DT/<type> option: /DT/SHELL/DEL
  int nodes;                   // nodes per element
  int values_per_node;         // what an element hands each node: force (3), and moment (6) for kinds with rotations
  PropertyKind property;       // the property kind its parts take
  std::string_view measure;    // what its nodes span: "area", "volume" or "length"
  std::string_view valid_shape;  // the rule an element's measure must keep, as the reader's errors state it
  bool may_degenerate;           // written with repeated nodes for a prism, pyramid or tetrahedron (bricks)
  // Element groups of this kind: /GRSHEL/SHEL/6 reads its members by "shell_ID".
  std::string_view group_card, group_item, group_field;
  std::string_view mesh_group, xdmf_topology;  // NAME.h5's /mesh/<group> and its XDMF TopologyType
  TimeStepControl RunControl::*step_control;   // /DT/SHELL, /DT/SH_3N, /DT/BRICK
};

inline constexpr ElementKindDescription kElementKindTable[kElementKinds] = {
    {ElementKind::Shell4, "SHELL", "4-node shell", "4-node shells", "/SHELL", "SHELL", 4, 6, PropertyKind::Shell, "area",
     "a shell of positive area", false, "/GRSHEL", "SHEL", "shell_ID", "shell4", "Quadrilateral", &RunControl::dt_shell},
    {ElementKind::Shell3, "SH3N", "3-node shell", "3-node shells", "/SH3N", "SH_3N", 3, 6, PropertyKind::Shell, "area",
     "a shell of positive area", false, "/GRSH3N", "SH3N", "sh3n_ID", "shell3", "Triangle", &RunControl::dt_sh3n},
    {ElementKind::Brick8, "BRICK", "brick", "8-node bricks", "/BRICK", "BRICK", 8, 3, PropertyKind::Solid, "volume",
     "a brick of positive volume (nodes 1-4 one face, 5-8 the opposite face)", true, "/GRBRIC",
     "BRIC", "brick_ID", "brick8", "Hexahedron", &RunControl::dt_brick},
    {ElementKind::Spring, "SPRING", "spring", "springs", "/SPRING", "SPRING", 2, 6, PropertyKind::Spring, "length",
     "a spring of positive length", false, "/GRSPRI", "SPRI", "spring_ID", "spring2", "Polyline",
     &RunControl::dt_spring},
    {ElementKind::Truss, "TRUSS", "truss", "trusses", "/TRUSS", "TRUSS", 2, 3, PropertyKind::Truss, "length",
     "a truss of positive length", false, "/GRTRUS", "TRUS", "truss_ID", "truss2", "Polyline",
     &RunControl::dt_truss},
    {ElementKind::Beam, "BEAM", "beam", "beams", "/BEAM", "BEAM", 2, 6, PropertyKind::Beam, "length",
     "a beam of positive length", false, "/GRBEAM", "BEAM", "beam_ID", "beam2", "Polyline", &RunControl::dt_beam},
};

constexpr const ElementKindDescription& describe(ElementKind kind) {
  return kElementKindTable[static_cast<int>(kind)];
}
constexpr int nodes_per_element(ElementKind kind) { return describe(kind).nodes; }
constexpr std::string_view element_kind_name(ElementKind kind) { return describe(kind).name; }

struct ElementTable {
  ElementKind kind = ElementKind::Shell4;
  std::vector<std::int64_t> user_id;       // id as written in the deck
  std::vector<std::int32_t> part;          // dense part index
  std::vector<std::int32_t> connectivity;  // nodes_per_element(kind) dense node indices per element, deck order
  std::vector<double> thickness;           // shells: the element's own thickness [L] (0 = not given), else empty
  // Springs and beams: a beam-type spring's or a beam's orientation node, its Y at rest towards it (dense index,
  // -1: none); else empty.
  std::vector<std::int32_t> orientation_node;
  // Joints: node_ID4, which with node_ID3 sets the plane of the joint's frame (docs/theory/spring.md, SP-25f; dense
  // index, -1: none); empty when no element has one.
  std::vector<std::int32_t> plane_node;
  std::vector<double> orientation_vector;  // beams: 3 per beam, the card's Vx Vy Vz (used without a node); else empty
  std::size_t size() const { return user_id.size(); }
  const std::int32_t* nodes_of(std::size_t element) const {
    return connectivity.data() + element * static_cast<std::size_t>(nodes_per_element(kind));
  }
};

// One empty table per kind, in kAllElementKinds order (Model::elements).
inline std::array<ElementTable, kElementKinds> empty_element_tables() {
  std::array<ElementTable, kElementKinds> tables;
  for (ElementKind kind : kAllElementKinds) tables[static_cast<std::size_t>(kind)].kind = kind;
  return tables;
}

struct ElementGroup {
  ElementKind kind;
  std::int32_t part;      // dense part index
  std::int32_t property;  // dense property index
  std::int32_t material;  // dense material index
  std::int32_t begin;     // first element (index into the kind's ElementTable)
  std::int32_t end;       // one past the last element
};

// Reference to one element of any kind.
struct ElementRef {
  ElementKind kind;
  std::int32_t index;
};

}  // namespace crumple
