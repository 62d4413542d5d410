// /DAMP, starter and engine (docs/theory/damping.md; layouts: docs/cards/starter-model.md, engine.md).
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

// The full format's lines 2 to 6 (alpha and beta for y, z, xx, yy, zz): accepted where they repeat line 1's pair,
// the short format's meaning; damping that differs by direction is not supported.
void read_direction_lines(CardReader& reader, DeckContext& context, const RayleighDamping& d) {
  constexpr const char* kDirections[] = {"y", "z", "xx", "yy", "zz"};
  for (const char* direction : kDirections) {
    if (!reader.has_data()) return;
    const Line line = reader.next(fmt::format("alpha_{0}, beta_{0}", direction));
    const double alpha = line.real(1, 20, fmt::format("alpha_{}", direction), dim::rate);
    const double beta = line.real(21, 20, fmt::format("beta_{}", direction), dim::time);
    if (alpha != d.alpha)
      context.unsupported(line.error(1, 20, fmt::format("alpha_{}", direction),
                                     fmt::format("line 1's alpha ({:g}: damping that differs by direction is not "
                                                 "supported by Crumple)", d.alpha)));
    if (beta != d.beta)
      context.unsupported(line.error(21, 20, fmt::format("beta_{}", direction),
                                     fmt::format("line 1's beta ({:g}: damping that differs by direction is not "
                                                 "supported by Crumple)", d.beta)));
  }
}

// Starter: alpha, beta, grnod_ID, skew_ID, Tstart, Tstop, then the full format's direction lines.
void read_damping(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);
  RayleighDamping d;
  d.where = reader.card().where;
  d.user_id = object_id(reader, 1);
  read_unit_id(reader, 2);
  read_title(reader);
  const Line line = reader.next("alpha, beta, grnod_ID, skew_ID, Tstart, Tstop");
  d.alpha = line.real(1, 20, "alpha", dim::rate);
  d.beta = line.real(21, 20, "beta", dim::time);
  if (d.alpha < 0.0) line.fail(1, 20, "alpha", "a non-negative mass damping coefficient");
  if (d.beta < 0.0) line.fail(21, 20, "beta", "a non-negative stiffness damping coefficient");
  d.node_group_id = line.id(41, 10, "grnod_ID", IdKind::Other);
  if (d.node_group_id <= 0) line.fail(41, 10, "grnod_ID", "a positive node group id");
  if (line.optional_id(51, 10, "skew_ID") != 0)
    context.unsupported(line.error(51, 10, "skew_ID", default_only("damping in a skew (every direction is damped "
                                                                   "alike here) is")));
  d.start = line.real(61, 20, "Tstart", dim::time);
  const double stop = line.real(81, 20, "Tstop", dim::time);
  if (stop != 0.0) d.stop = stop;  // 0 or blank: 1e30
  if (d.stop < d.start) line.fail(81, 20, "Tstop", fmt::format("a stop time after Tstart ({:g})", d.start));
  read_direction_lines(reader, context, d);
  reader.finish();
  context.model.dampings.push_back(d);
}

// Engine /DAMP/damp_ID: alpha beta, free format, from the start of this engine deck.
void read_engine_damping(CardReader& reader, DeckContext& context) {
  DampingChange change;
  change.where = reader.card().where;
  change.damping_id = object_id(reader, 1);
  const Line line = reader.next("alpha, beta");
  if (line.token_count() > 2)
    line.fail_value("alpha, beta", "two values, alpha and beta", fmt::format("{} values", line.token_count()));
  // Engine values stay in input units until the model build converts the run control (resolve_output.cpp).
  change.alpha = line.token_real(0, "alpha", dim::none, 0.0);
  change.beta = line.token_real(1, "beta", dim::none, 0.0);
  if (change.alpha < 0.0) line.fail_value("alpha (value 1)", "a non-negative mass damping coefficient",
                                          fmt::format("{}", change.alpha));
  if (change.beta < 0.0) line.fail_value("beta (value 2)", "a non-negative stiffness damping coefficient",
                                        fmt::format("{}", change.beta));
  reader.finish();
  context.model.run.damping_changes.push_back(change);
}

}  // namespace

void register_damping_keywords(KeywordTable& table) {
  table.push_back({"/DAMP", DeckPart::Starter, read_damping});
  table.push_back({"/DAMP", DeckPart::Engine, read_engine_damping});
}

}  // namespace crumple::deck
