// /FUNCT: title, then one "x y" pair per line (20-column reals), abscissae strictly increasing.
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

}  // namespace

void register_function_keywords(KeywordTable& table) { table.push_back({"/FUNCT", DeckPart::Starter, read_function}); }

}  // namespace crumple::deck
