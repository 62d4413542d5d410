#include <fmt/format.h>

#include "crumple/core/utf8.hpp"
#include "context.hpp"

namespace crumple::deck {

const KeywordTable& keyword_table() {
  static const KeywordTable table = [] {
    KeywordTable t;
    register_control_keywords(t);
    register_mesh_keywords(t);
    register_material_keywords(t);
    register_property_keywords(t);
    register_function_keywords(t);
    register_set_keywords(t);
    register_load_keywords(t);
    register_damping_keywords(t);
    register_rigid_keywords(t);
    register_skew_keywords(t);
    register_sensor_keywords(t);
    register_box_keywords(t);
    register_transform_keywords(t);
    register_submodel_keywords(t);
    register_interface_keywords(t);
    register_output_keywords(t);
    register_engine_keywords(t);
    return t;
  }();
  return table;
}

std::string read_title(CardReader& reader) {
  if (reader.narrow()) return valid_utf8(reader.keyword_title());  // on the keyword line (versions 41 to 44)
  if (reader.at_end()) return {};
  // Titles reach NAME.xdmf, the summary and HDF5 attributes: a Latin-1 byte is read as '?' (docs/deck-format.md).
  return valid_utf8(reader.next("the title").text(1, 100));
}

std::vector<std::int64_t> read_id_list(CardReader& reader, std::string_view name, IdKind kind) {
  std::vector<std::int64_t> ids;
  while (auto line = reader.next_nonblank()) {
    for (int column = 1; column <= 91; column += 10) {
      const std::int64_t id = line->id(column, 10, name, kind);
      if (id != 0) ids.push_back(id);
    }
    if (line->content().size() > 100 && !trim(std::string_view(line->content()).substr(100)).empty())
      line->fail(101, static_cast<int>(line->content().size()) - 100, name, "at most 10 ids of 10 columns per line");
  }
  return ids;
}

std::string in_quotes(std::string_view text) { return fmt::format("'{}'", text); }

std::string default_only(std::string_view feature) {
  return fmt::format("0 or blank ({} not supported by Crumple)", feature);
}

void DeckContext::note(const SourceLocation& where, std::string_view keyword, std::string field, std::string what,
                       SkipKind kind) {
  warn(where, keyword, field.empty() ? what : fmt::format("field {}: {}", field, what));
  report.skipped_options.push_back({where, std::string(keyword), std::move(field), std::move(what), kind});
}

void DeckContext::unsupported(const DeckError& error, std::string skipped) {
  if (!skip_unsupported) throw error;
  if (skipped.empty()) {
    skipped = fmt::format("skipped (--skip-unknown): expected {}", error.expected());
    if (!error.found().empty()) skipped += fmt::format(", found {}", error.found());
  }
  note(error.where(), error.keyword(), error.field(), std::move(skipped), SkipKind::Unsupported);
}

std::int64_t card_id(CardReader& reader, std::size_t index) {
  const Card& card = reader.card();
  if (index < card.path.size() && !card.path[index].empty() && !parse_integer(card.path[index])) {
    std::string form;
    for (std::size_t k = 0; k <= index; ++k) form += "/" + card.path[k];
    reader.fail("id", fmt::format("a numeric id (the {} form is not supported by Crumple)", form),
                in_quotes(card.path[index]));
  }
  const std::int64_t id = object_id(reader, index);
  read_unit_id(reader, index + 1);
  if (reader.narrow()) return id;  // versions 41 to 44: the title follows the id
  if (card.path.size() > index + 2)
    reader.fail("keyword", "nothing after the unit id", in_quotes(card.path[index + 2]));
  return id;
}

IdKind defined_kind(const Card& card) {
  const std::string_view head = card.path.empty() ? std::string_view() : std::string_view(card.path[0]);
  if (head == "PART") return IdKind::Part;
  if (head == "MAT" || head == "FAIL" || head == "EOS") return IdKind::Material;
  if (head == "PROP") return IdKind::Property;
  for (std::string_view element : {"SHELL", "SH3N", "BRICK", "SPRING", "BEAM", "TRUSS", "QUAD", "TRIA", "TETRA4",
                                   "TETRA10", "PENTA6", "SHEL16", "BRIC20"})
    if (head == element) return IdKind::Part;  // an element card's path id is its part's
  return IdKind::Other;
}

std::int64_t object_id(CardReader& reader, std::size_t index) {
  const std::int64_t id = reader.path_id(index, "id", true);
  if (id <= 0) reader.fail("id", "a positive id in the keyword line", fmt::format("{}", id));
  return reader.shifted_id(id, defined_kind(reader.card()));
}

void read_unit_id(CardReader& reader, std::size_t index) {
  if (reader.narrow()) {  // input versions 41 to 44: the title takes the place of the unit id
    reader.title_after(index);
    return;
  }
  if (const std::int64_t id = reader.path_id(index, "unit_ID", false); id != 0)
    reader.use_local_units(reader.shifted_id(id, IdKind::Other), "unit_ID");
}

void refuse_narrow_layout(const CardReader& reader) {
  if (reader.narrow())
    reader.fail("layout",
                "the card in the layout of input version 51 or later (its own layout in versions 41 to 44 is not "
                "supported by Crumple)",
                "an input version of 41 to 44 in /BEGIN");
}

}  // namespace crumple::deck
