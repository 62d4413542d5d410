// //SUBMODEL ... //ENDSUB: a block of cards whose ids are shifted by offsets of their kind, and whose values are read
// in a unit system of their own (docs/deck-format.md, "Submodels"). The offsets themselves are applied where each id is
// read (Line::id, object_id).
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

// Vers_number, "V2019" or "V130" or blank: the input version of the block's cards. Crumple reads every card of a deck
// in one input version, so the block's must be the deck's.
void check_block_version(CardReader& reader, const DeckContext& context) {
  const auto& path = reader.card().path;
  if (path.size() < 5 || path[4].empty()) return;
  const std::string& text = path[4];
  const auto version = parse_integer(text.front() == 'V' ? std::string_view(text).substr(1) : std::string_view(text));
  if (!version)
    reader.fail("Vers_number", "an input version such as V2019, or blank", in_quotes(text));
  if (*version != context.model.input_version)
    reader.fail("Vers_number",
                fmt::format("blank or V{} (the deck's input version: a block in another version is not supported by "
                            "Crumple)",
                            context.model.input_version),
                in_quotes(text));
}

// off_def, off_nod, off_ele, off_part, off_mat, off_type, off_sub: each blank or 0 takes off_def (the manual).
IdOffsets read_offsets(const Line& line) {
  constexpr const char* kNames[] = {"off_def", "off_nod", "off_ele", "off_part", "off_mat", "off_type", "off_sub"};
  constexpr IdKind kKinds[] = {IdKind::Other, IdKind::Node,     IdKind::Element,  IdKind::Part,
                               IdKind::Material, IdKind::Property, IdKind::Submodel};
  std::array<std::int64_t, 7> value{};
  for (int k = 0; k < 7; ++k) {
    value[static_cast<std::size_t>(k)] = line.integer(1 + 10 * k, 10, kNames[k]);
    if (value[static_cast<std::size_t>(k)] < 0) line.fail(1 + 10 * k, 10, kNames[k], "a non-negative id offset");
  }
  IdOffsets own;
  for (int k = 0; k < 7; ++k) {
    const std::int64_t v = value[static_cast<std::size_t>(k)];
    own.by_kind[static_cast<std::size_t>(kKinds[k])] = v != 0 ? v : value[0];
  }
  return own;
}

// //SUBMODEL/submodel_ID/unit_ID/Vers_number; title; offsets. The header's own ids are the enclosing block's.
void open_submodel(CardReader& reader, DeckContext& context) {
  SubmodelScope scope;
  scope.where = reader.card().where;
  scope.user_id = reader.shifted_id(reader.path_id(2, "submodel_ID", true), IdKind::Submodel);
  if (scope.user_id <= 0) reader.fail("submodel_ID", "a positive submodel id", "0");
  if (const std::int64_t unit = reader.path_id(3, "unit_ID", false); unit != 0) {
    scope.unit_id = reader.shifted_id(unit, IdKind::Other);
    reader.use_local_units(scope.unit_id, "unit_ID");
  } else if (!context.open_submodels.empty()) {
    scope.unit_id = context.open_submodels.back().unit_id;  // an enclosing block's units go on
  }
  check_block_version(reader, context);
  if (reader.card().path.size() > 5)
    reader.fail("keyword", "nothing after Vers_number", in_quotes(reader.card().path[5]));
  if (context.submodels.count(scope.user_id) != 0 ||
      std::any_of(context.open_submodels.begin(), context.open_submodels.end(),
                  [&](const SubmodelScope& s) { return s.user_id == scope.user_id; }))
    reader.fail("submodel_ID", "a submodel id used once", fmt::format("{} again", scope.user_id));
  read_title(reader);
  const IdOffsets own = read_offsets(reader.next("off_def, off_nod, off_ele, off_part, off_mat, off_type, off_sub"));
  reader.finish();
  const IdOffsets* enclosing = reader.id_offsets();
  for (std::size_t k = 0; k < kIdKinds; ++k)
    scope.offsets.by_kind[k] = own.by_kind[k] + (enclosing != nullptr ? enclosing->by_kind[k] : 0);
  scope.first_node = context.model.nodes.size();
  context.open_submodels.push_back(std::move(scope));
}

void close_submodel(CardReader& reader, DeckContext& context) {
  if (context.open_submodels.empty())
    reader.fail("keyword", "//ENDSUB closing a //SUBMODEL block", "no open //SUBMODEL");
  reader.finish();
  SubmodelScope scope = std::move(context.open_submodels.back());
  context.open_submodels.pop_back();
  scope.end_node = context.model.nodes.size();
  if (!context.open_submodels.empty())  // what a nested block held, its enclosing one holds too
    for (const std::string& k : scope.keywords) context.open_submodels.back().keywords.push_back(k);
  context.submodels.emplace(scope.user_id, std::move(scope));
}

}  // namespace

void register_submodel_keywords(KeywordTable& table) {
  table.push_back({"//SUBMODEL", DeckPart::Starter, open_submodel, true});
  table.push_back({"//ENDSUB", DeckPart::Starter, close_submodel, true});
}

}  // namespace crumple::deck
