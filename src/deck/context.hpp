#pragma once
// Internal to the deck reader: what keyword handlers share while a deck is read.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string_view>
#include <vector>

#include "crumple/deck/fields.hpp"
#include "crumple/deck/reader.hpp"
#include "crumple/model/model.hpp"
#include "crumple/model/transforms.hpp"

namespace crumple::deck {

// Elements as read, with node and part user ids; the model build resolves and groups them.
struct RawElements {
  std::vector<std::int64_t> user_id;
  std::vector<std::int64_t> part_id;
  std::vector<std::int64_t> node_ids;  // nodes_per_element per element
  std::vector<SourceLocation> where;
  std::vector<double> thickness;       // shells: the card's own thickness [L], 0 = the part's or property's
  std::vector<std::int64_t> orientation_node_id;  // springs, beams: node_ID3, the orientation node (0: none)
  std::vector<SourceLocation> orientation_where;
  std::vector<std::int64_t> plane_node_id;  // springs: node_ID4, a joint's second frame node (0: none)
  std::vector<double> orientation_vector;  // beams: Vx Vy Vz, 3 per beam
};

// A //SUBMODEL block being read, and what it held once closed (docs/deck-format.md, "Submodels").
struct SubmodelScope {
  std::int64_t user_id = 0;  // shifted by the enclosing submodels' off_sub
  SourceLocation where;      // the //SUBMODEL line
  IdOffsets offsets;         // its own plus the enclosing submodels'
  std::int64_t unit_id = 0;  // the /UNIT its cards read their values in (0: /BEGIN's input units)
  std::size_t first_node = 0, end_node = 0;  // the nodes it defines (nested blocks included): [first, end)
  std::vector<std::string> keywords;         // the keywords it holds (nested blocks included)
};

// /MOVE_FUNCT/fct_ID: the function's points become (Ascale_x x + Ashift_x, Fscale_y y + Fshift_y), in deck order
// (resolve_definitions.cpp).
struct FunctionMove {
  SourceLocation where;
  std::string keyword;
  std::int64_t function_id = 0;
  double scale_x = 1.0, scale_y = 1.0, shift_x = 0.0, shift_y = 0.0;
};

struct DeckContext {
  Model& model;
  DeckReport& report;
  bool skip_unsupported = false;  // --skip-unknown: options Crumple lacks become warnings and skipped options
  std::array<RawElements, kElementKinds> raw_elements;
  std::vector<SourceLocation> node_where;  // location of each /NODE line, parallel to model.nodes
  // /UNIT systems by id, read right after /BEGIN: a card with a unit_ID reads its values in one (its input sizes,
  // a blank field being /BEGIN's input unit, and the deck's working units; docs/deck-format.md, "Units").
  std::map<std::int64_t, UnitSystem> local_units;
  std::map<std::int64_t, SourceLocation> local_units_where;
  bool begin_seen = false;
  bool run_seen = false;
  int engine_deck = 1;  // the engine deck being read: 1 for NAME_0001.rad, k for NAME_000k.rad
  // /TRANSFORM cards in deck order: they act on the nodes' positions during resolution and leave nothing else in
  // the model (resolve_transforms.cpp).
  std::vector<Transform> transforms = {};
  std::vector<FunctionMove> function_moves = {};
  std::vector<SubmodelScope> open_submodels = {};              // innermost last
  std::map<std::int64_t, SubmodelScope> submodels = {};        // closed ones, by id

  void warn(const SourceLocation& where, std::string_view keyword, std::string message) {
    report.warnings.push_back({where, std::string(keyword), std::move(message)});
  }

  // A card or field Crumple reads but does not act on by design (output-only, performance hint): a named warning,
  // listed among the skipped options.
  void note(const SourceLocation& where, std::string_view keyword, std::string field, std::string what,
            SkipKind kind);

  // A non-default value of an option Crumple lacks: throws `error`, or with --skip-unknown records it as a warning
  // and a skipped option and returns, after which the caller goes on with the option's default. `skipped` says
  // what was skipped (default: "skipped (--skip-unknown): expected ..., found ...").
  void unsupported(const DeckError& error, std::string skipped = {});
};

// The "expected" text of a field whose non-default value asks for an option Crumple lacks:
// "0 or blank (<feature> not supported by Crumple)", e.g. feature "kinematic hardening (Chard) is".
std::string default_only(std::string_view feature);

using KeywordHandler = std::function<void(CardReader&, DeckContext&)>;

enum class DeckPart : std::uint8_t { Starter, Engine };

struct KeywordSpec {
  std::string_view name;  // leading path parts, e.g. "/MAT/PLAS_JOHNS"
  DeckPart part;
  KeywordHandler handler;  // empty: accepted without effect (listed in the report)
  // The card has one layout in every input version (the reference describes no 8-column one): it is never read in
  // the narrow layout of versions 41 to 44 (docs/deck-format.md, "Input versions").
  bool same_layout_in_every_version = false;
};

// Input versions 41 to 44 (43 read as 42, as the reference's reader has no layout of its own for it).
inline bool narrow_layout_version(int input_version) { return input_version >= 41 && input_version <= 50; }

using KeywordTable = std::vector<KeywordSpec>;

// Each family of keywords registers its handlers (src/deck/keywords/*.cpp).
void register_control_keywords(KeywordTable& table);
void register_mesh_keywords(KeywordTable& table);
void register_material_keywords(KeywordTable& table);
void register_property_keywords(KeywordTable& table);
void register_function_keywords(KeywordTable& table);
void register_set_keywords(KeywordTable& table);
void register_load_keywords(KeywordTable& table);
void register_damping_keywords(KeywordTable& table);
void register_rigid_keywords(KeywordTable& table);
void register_skew_keywords(KeywordTable& table);
void register_sensor_keywords(KeywordTable& table);
void register_box_keywords(KeywordTable& table);
void register_transform_keywords(KeywordTable& table);
void register_submodel_keywords(KeywordTable& table);
void register_interface_keywords(KeywordTable& table);
void register_output_keywords(KeywordTable& table);
void register_engine_keywords(KeywordTable& table);

const KeywordTable& keyword_table();

// Shared card pieces.
std::string read_title(CardReader& reader);  // the title line that follows many keyword lines (may be blank)
// Integer ids of objects of `kind` in 10-column fields, 10 per line, until the end of the card; blank fields are
// skipped.
std::vector<std::int64_t> read_id_list(CardReader& reader, std::string_view name, IdKind kind);
// The kind of object a keyword's path id names: the object the card defines, or on an element card its part.
IdKind defined_kind(const Card& card);
// The text quoted for an error message's "found" part.
std::string in_quotes(std::string_view text);
// `/KEYWORD/.../id[/unit_ID]`: the object id at path part `index`, then an optional unit id (read_unit_id). A word
// where the
// id belongs is another form of the keyword (/IMPVEL/FGEO, /RBODY/LAGMUL...), which Crumple does not read.
std::int64_t card_id(CardReader& reader, std::size_t index);
// The keyword's object id (path part `index`), shifted by the enclosing //SUBMODEL's offset; must be positive.
std::int64_t object_id(CardReader& reader, std::size_t index);
// The optional unit_ID at path part `index`: 0 or blank, the deck's input units; else the card's values are read in
// that /UNIT system (an undefined one is an error).
void read_unit_id(CardReader& reader, std::size_t index);
// Cards whose layout in input versions 41 to 44 is not the 2017 one narrowed (other lines, other fields), which
// Crumple does not read: an error in those versions (docs/deck-format.md, "Input versions").
void refuse_narrow_layout(const CardReader& reader);

}  // namespace crumple::deck
