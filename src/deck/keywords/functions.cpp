// /FUNCT: title, then one "x y" pair per line (20-column reals), abscissae strictly increasing; /MOVE_FUNCT.
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

void read_function(CardReader& reader, DeckContext& context) {
  Function f;
  f.where = reader.card().where;
  f.user_id = object_id(reader, 1);
  // Units: functions carry no dimension of their own; the card that uses one scales it. A unit id must name a
  // /UNIT, and changes no value (the reference converts none: docs/deck-format.md, "Units").
  read_unit_id(reader, 2);
  f.title = read_title(reader);
  while (auto line = reader.next_nonblank()) {
    const double x = line->real(1, 20, "X", dim::none);
    const double y = line->real(21, 20, "Y", dim::none);
    if (!f.x.empty() && x <= f.x.back())
      line->fail(1, 20, "X", fmt::format("an abscissa above the previous one ({})", f.x.back()));
    f.x.push_back(x);
    f.y.push_back(y);
  }
  if (f.x.empty()) reader.fail("X, Y", "at least one point of the function", "no point");
  context.model.functions.push_back(std::move(f));
}

// /MOVE_FUNCT/fct_ID: title; Ascale_x Fscale_y Ashift_x Fshift_y. The function is scaled first and shifted after
// (the manual); a blank or 0 scale is 1, as the reference reads it (measured: docs/deck-format.md, "Functions"). No
// value is unit-converted, as a function's are not.
void read_function_move(CardReader& reader, DeckContext& context) {
  FunctionMove move;
  move.where = reader.card().where;
  move.keyword = reader.card().keyword;
  move.function_id = object_id(reader, 1);
  if (reader.card().path.size() > 2) reader.fail("keyword", "nothing after fct_ID", in_quotes(reader.card().path[2]));
  read_title(reader);
  const Line line = reader.next("Ascale_x, Fscale_y, Ashift_x, Fshift_y");
  const double ascale = line.real(1, 20, "Ascale_x", dim::none);
  const double fscale = line.real(21, 20, "Fscale_y", dim::none);
  if (ascale < 0.0)
    line.fail(1, 20, "Ascale_x",
              "a positive abscissa scale, or 0 or blank for 1 (a negative one reverses the abscissae)");
  move.scale_x = ascale == 0.0 ? 1.0 : ascale;
  move.scale_y = fscale == 0.0 ? 1.0 : fscale;
  move.shift_x = line.real(41, 20, "Ashift_x", dim::none);
  move.shift_y = line.real(61, 20, "Fshift_y", dim::none);
  reader.finish();
  context.function_moves.push_back(std::move(move));
}

}  // namespace

void register_function_keywords(KeywordTable& table) {
  table.push_back({"/FUNCT", DeckPart::Starter, read_function});
  table.push_back({"/MOVE_FUNCT", DeckPart::Starter, read_function_move});
}

}  // namespace crumple::deck
