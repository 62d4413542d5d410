// /NODE, the element cards (/SHELL, /SH3N, /BRICK, /SPRING, /TRUSS, /BEAM) and /PART (docs/deck-format.md).
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

void read_nodes(CardReader& reader, DeckContext& context) {
  Nodes& nodes = context.model.nodes;
  read_unit_id(reader, 1);
  while (auto line = reader.next_nonblank()) {
    const std::int64_t id = line->id(1, 10, "node_ID", IdKind::Node);
    if (id < 0) line->fail(1, 10, "node_ID", "a positive node id");
    const double x = line->real(11, 20, "X", dim::length), y = line->real(31, 20, "Y", dim::length),
                 z = line->real(51, 20, "Z", dim::length);
    if (id == 0) {  // the reference keeps it; no card can name it (0 is none everywhere): it would carry nothing
      context.warn(line->where(), "/NODE", "a node of id 0, which no card can name, is skipped");
      continue;
    }
    nodes.user_id.push_back(id);
    nodes.x.push_back(x), nodes.y.push_back(y), nodes.z.push_back(z);
    context.node_where.push_back(line->where());
  }
}

// Shells: an orthotropy angle (20 columns), then the element's own thickness (20 columns).
void read_shell_extras(const Line& line, int after, RawElements& raw, DeckContext&) {
  line.real(after, 20, "Phi", dim::none);
  const double thick = line.real(after + 20, 20, "Thick", dim::length);
  if (thick < 0.0) line.fail(after + 20, 20, "Thick", "a non-negative thickness (0 or blank: the property's)");
  raw.thickness.push_back(thick);
}
void read_no_extras(const Line&, int, RawElements&, DeckContext&) {}
// Springs: node_ID3 (a beam-type spring's orientation node, a joint's axis), node_ID4 (a joint's second frame node),
// node_ID5 and node_ID6 (the multi-node springs' nodes), then Skew_ID (columns 91-100).
void read_spring_extras(const Line& line, int after, RawElements& raw, DeckContext& context) {
  raw.orientation_node_id.push_back(line.optional_id(after, 10, "node_ID3", IdKind::Node));
  raw.orientation_where.push_back(line.where());
  raw.plane_node_id.push_back(line.optional_id(after + 10, 10, "node_ID4", IdKind::Node));
  for (int k = 2; k < 4; ++k)
    if (line.optional_id(after + 10 * k, 10, fmt::format("node_ID{}", k + 3), IdKind::Node) != 0)
      context.unsupported(line.error(after + 10 * k, 10, fmt::format("node_ID{}", k + 3),
                                     default_only("a spring of more than three nodes is")));
  if (line.optional_id(91, 10, "Skew_ID") != 0)
    context.unsupported(line.error(91, 10, "Skew_ID", default_only("a spring skew (/PROP/TYPE4 acts along its nodes) is")));
}

// Beams: node_ID3 (the orientation node), then Vx, Vy, Vz (columns 41-100), the orientation used without a node
// (docs/theory/beam.md, BM-0).
void read_beam_extras(const Line& line, int after, RawElements& raw, DeckContext&) {
  raw.orientation_node_id.push_back(line.optional_id(after, 10, "node_ID3", IdKind::Node));
  raw.orientation_where.push_back(line.where());
  for (const auto& [column, name] : {std::pair{41, "Vx"}, {61, "Vy"}, {81, "Vz"}})
    raw.orientation_vector.push_back(line.real(column, 20, name, dim::none));
}

// Each element card: its kind and what its lines hold after the nodes.
struct ElementCard {
  ElementKind kind;
  void (*read_extras)(const Line& line, int after, RawElements& raw, DeckContext& context);
};
constexpr ElementCard kElementCards[] = {{ElementKind::Shell4, read_shell_extras},
                                         {ElementKind::Shell3, read_shell_extras},
                                         {ElementKind::Brick8, read_no_extras},
                                         {ElementKind::Spring, read_spring_extras},
                                         {ElementKind::Truss, read_no_extras},
                                         {ElementKind::Beam, read_beam_extras}};

// Elements: "id n1 .. nk" in 10-column fields, then the kind's extras.
void read_elements(CardReader& reader, DeckContext& context, const ElementCard& card) {
  const ElementKind kind = card.kind;
  const std::int64_t part_id = object_id(reader, 1);
  read_unit_id(reader, 2);
  RawElements& raw = context.raw_elements[static_cast<int>(kind)];
  const int n = nodes_per_element(kind);
  while (auto line = reader.next_nonblank()) {
    const std::int64_t id = line->id(1, 10, "elem_ID", IdKind::Element);
    if (id <= 0) line->fail(1, 10, "elem_ID", "a positive element id");
    for (int k = 0; k < n; ++k) {
      const std::string name = fmt::format("node_ID{}", k + 1);
      const std::int64_t node = line->id(11 + 10 * k, 10, name, IdKind::Node);
      if (node <= 0) line->fail(11 + 10 * k, 10, name, "a positive node id");
      raw.node_ids.push_back(node);
    }
    card.read_extras(*line, 11 + 10 * n, raw, context);
    raw.user_id.push_back(id);
    raw.part_id.push_back(part_id);
    raw.where.push_back(line->where());
  }
}

void read_part(CardReader& reader, DeckContext& context) {
  Part part;
  part.where = reader.card().where;
  part.user_id = object_id(reader, 1);
  read_unit_id(reader, 2);
  part.title = read_title(reader);
  const Line line = reader.next("prop_ID, mat_ID, subset_ID");
  part.property_id = line.id(1, 10, "prop_ID", IdKind::Property);
  part.material_id = line.id(11, 10, "mat_ID", IdKind::Material);
  part.subset_id = line.id(21, 10, "subset_ID", IdKind::Other);
  if (part.property_id <= 0) line.fail(1, 10, "prop_ID", "a positive property id");
  // mat_ID 0: a part whose property carries the law (springs); the model build checks the property's kind.
  if (part.material_id < 0) line.fail(11, 10, "mat_ID", "a positive material id (0 for a spring part)");
  // Thick (columns 31-50) is the part's virtual thickness: the reference keeps its shells' thickness and mass
  // (measured: its starter listing's part mass, "VIRT. THICKN") and uses it for contact gaps, which Crumple does not.
  if (line.real(31, 20, "Thick", dim::length) != 0.0)
    context.unsupported(line.error(31, 20, "Thick",
                                   default_only("the part's virtual thickness (for contact gaps; the shells keep "
                                                "their own) is")));
  reader.finish();
  context.model.parts.push_back(std::move(part));
}

}  // namespace

void register_mesh_keywords(KeywordTable& table) {
  table.push_back({"/NODE", DeckPart::Starter, read_nodes});
  for (const ElementCard& card : kElementCards)
    table.push_back({describe(card.kind).card, DeckPart::Starter,
                     [&card](CardReader& r, DeckContext& c) { read_elements(r, c, card); }, true});
  table.push_back({"/PART", DeckPart::Starter, read_part});
}

}  // namespace crumple::deck
