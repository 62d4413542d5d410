// Each node's share of the surface it lies on, for the contact pressure of the friction laws (docs/theory/
// contact.md, "Friction", eq. C-9a..c): a quarter (a third) of every shell (triangle) around it, and a quarter of
// every brick face on the boundary of the brick mesh (a face that belongs to one brick only).
#include <algorithm>
#include <array>

#include "crumple/contact/contact.hpp"
#include "crumple/core/geometry.hpp"

namespace crumple::contact {

using geometry::quad_area;

std::vector<double> node_surface_areas(const Model& m) {
  std::vector<double> area(m.nodes.size(), 0.0);
  auto X = [&](std::int32_t n) { return m.nodes.position(n); };
  for (ElementKind kind : {ElementKind::Shell4, ElementKind::Shell3}) {
    const ElementTable& table = m.elements[static_cast<int>(kind)];
    const int count = nodes_per_element(kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      const std::int32_t* c = table.nodes_of(e);
      const double a = count == 4 ? quad_area(X(c[0]), X(c[1]), X(c[2]), X(c[3]))
                                  : geometry::triangle_area(X(c[0]), X(c[1]), X(c[2]));
      for (int k = 0; k < count; ++k) area[static_cast<std::size_t>(c[k])] += a / count;
    }
  }
  // Brick faces: sorted node quadruples; a quadruple met once is on the boundary.
  const ElementTable& bricks = m.elements[static_cast<int>(ElementKind::Brick8)];
  static constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  struct Face {
    std::array<std::int32_t, 4> key, nodes;
  };
  std::vector<Face> faces;
  faces.reserve(6 * bricks.size());
  for (std::size_t e = 0; e < bricks.size(); ++e) {
    const std::int32_t* c = bricks.nodes_of(e);
    for (const auto& f : kFaces) {
      Face face{{c[f[0]], c[f[1]], c[f[2]], c[f[3]]}, {c[f[0]], c[f[1]], c[f[2]], c[f[3]]}};
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j == i + 1) {
      const auto& n = faces[i].nodes;
      const double a = quad_area(X(n[0]), X(n[1]), X(n[2]), X(n[3]));
      for (std::int32_t k : n) area[static_cast<std::size_t>(k)] += 0.25 * a;
    }
    i = j;
  }
  return area;
}

}  // namespace crumple::contact
