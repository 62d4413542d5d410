#pragma once
// Elements as structures of arrays, one table per element kind, ordered by part. The solver walks them in
// ElementGroups: contiguous runs of at most kElementGroupSize elements of one kind, part, property and material,
// sized so that a kernel's inner loop over a group vectorises.
#include <cstdint>
#include <string_view>
#include <vector>

namespace crumple {

enum class ElementKind : std::uint8_t { Shell4, Shell3, Brick8 };
inline constexpr int kElementKinds = 3;
inline constexpr int kElementGroupSize = 128;

constexpr int nodes_per_element(ElementKind kind) {
  return kind == ElementKind::Shell4 ? 4 : kind == ElementKind::Shell3 ? 3 : 8;
}
constexpr std::string_view element_kind_name(ElementKind kind) {
  return kind == ElementKind::Shell4 ? "SHELL" : kind == ElementKind::Shell3 ? "SH3N" : "BRICK";
}

struct ElementTable {
  ElementKind kind = ElementKind::Shell4;
  std::vector<std::int64_t> user_id;       // id as written in the deck
  std::vector<std::int32_t> part;          // dense part index
  std::vector<std::int32_t> connectivity;  // nodes_per_element(kind) dense node indices per element, deck order
  std::vector<double> thickness;           // shells: the element's own thickness [L] (0 = not given), else empty
  std::size_t size() const { return user_id.size(); }
  const std::int32_t* nodes_of(std::size_t element) const {
    return connectivity.data() + element * static_cast<std::size_t>(nodes_per_element(kind));
  }
};

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
