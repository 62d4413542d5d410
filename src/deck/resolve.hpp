#pragma once
// Second stage of reading: user ids -> dense indices, cross-references and geometry checks, element grouping
// and the lumped mass. Every problem becomes a DeckError naming the card that holds the reference.
#include <string>
#include <string_view>
#include <vector>

#include "context.hpp"

namespace crumple::deck {

class Resolver {
 public:
  explicit Resolver(DeckContext& deck_context) : context(deck_context), model(deck_context.model) {}

  DeckContext& context;
  Model& model;
  std::vector<DeckError> errors;

  void error(const SourceLocation& where, std::string keyword, std::string field, std::string expected,
             std::string found) {
    if (errors.size() < 100)
      errors.emplace_back(where, std::move(keyword), std::move(field), std::move(expected), std::move(found));
  }

  // Builds user id -> index for records with `user_id` and `where`, reporting duplicates.
  template <class Record>
  void index(const std::vector<Record>& records, IdMap& map, std::string_view keyword) {
    map.reserve(records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
      const auto [it, inserted] = map.emplace(records[i].user_id, static_cast<std::int32_t>(i));
      if (!inserted)
        error(records[i].where, std::string(keyword) + "/" + std::to_string(records[i].user_id), "id",
              "an id not used by another " + std::string(keyword),
              "duplicate of the one at " + records[static_cast<std::size_t>(it->second)].where.file + ":" +
                  std::to_string(records[static_cast<std::size_t>(it->second)].where.line));
    }
  }

  // Dense index of `id` in `map`; reports "X n not defined" and returns -1 when missing.
  std::int32_t find(const IdMap& map, std::int64_t id, const SourceLocation& where, const std::string& keyword,
                    std::string_view field, std::string_view what) {
    if (const auto it = map.find(id); it != map.end()) return it->second;
    error(where, keyword, std::string(field), "an existing " + std::string(what),
          std::string(what) + " " + std::to_string(id) + " not defined");
    return -1;
  }
  // As find, but id 0 means "none" and gives -1 without error.
  std::int32_t find_optional(const IdMap& map, std::int64_t id, const SourceLocation& where,
                             const std::string& keyword, std::string_view field, std::string_view what) {
    return id == 0 ? -1 : find(map, id, where, keyword, field, what);
  }

  // A field naming a feature Crumple does not implement: a clear error rather than a silent default. With
  // --skip-unknown the value is recorded as a skipped option and set to its default, 0.
  template <class T>
  void require_zero(T& value, const SourceLocation& where, const std::string& keyword, std::string_view field,
                    std::string_view feature) {
    if (value == 0) return;
    const DeckError e(where, keyword, std::string(field), default_only(feature), std::to_string(value));
    if (!context.skip_unsupported) {
      if (errors.size() < 100) errors.push_back(e);
      return;
    }
    context.unsupported(e);
    value = 0;
  }

  void throw_if_errors();
};

// `continued_runs`: the run controls of NAME_0002.rad... (their times converted, their references resolved).
void resolve_model(DeckContext& context, std::vector<RunControl>& continued_runs);

// Stages, in order (src/deck/resolve_*.cpp).
void resolve_definitions(Resolver& r);  // nodes, functions, materials, properties, parts
void resolve_elements(Resolver& r);     // connectivity, part order, groups, geometry checks
void resolve_sets(Resolver& r);         // node and element groups, surfaces, subsets
void apply_transforms(Resolver& r);     // /TRANSFORM: the nodes of their groups moved, in deck order
// A rigid wall's keyword for its messages, "/RWALL/PLANE/3".
std::string rigid_wall_keyword(const RigidWall& w);
// The window of the sensor a card names in `field` (docs/theory/loads.md, L-7); id 0: always on, clock from 0.
SensorWindow sensor_window(Resolver& r, std::int64_t sensor_id, const SourceLocation& where, const std::string& kw,
                           std::string_view field = "sensor_ID");
void resolve_load_references(Resolver& r);    // loads, imposed motion, added mass, rigid walls and bodies
void resolve_output_references(Resolver& r, std::vector<RunControl>& continued_runs);
void refuse_joints_off_bodies(Resolver& r);  // /PROP/TYPE45: each node on a /RBODY of its own (SP-25)
void resolve_rigid_elements(Resolver& r);  // /RBE2, /RBE3: node sets, conflicts with other kinematic conditions  // interfaces, sections, time histories, run control

}  // namespace crumple::deck
