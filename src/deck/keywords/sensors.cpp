// /SENSOR/TIME: a sensor that turns on at Tdelay and, from input version 2023, off at Tstop (docs/theory/loads.md,
// L-7; layout in docs/cards/loads-output-engine.md). The loads that name it are resolved in resolve_loads.cpp.
// The other sensor types watch a quantity of the run (an accelerometer, a distance, an interface force...):
// Crumple does not have them, and refuses them by name.
#include <fmt/format.h>

#include "../context.hpp"

namespace crumple::deck {
namespace {

void read_time_sensor(CardReader& reader, DeckContext& context) {
  refuse_narrow_layout(reader);  // the reference describes sensors from input version 51 on
  Sensor s;
  s.where = reader.card().where;
  s.user_id = card_id(reader, 2);
  s.title = read_title(reader);
  const Line delay = reader.next("Tdelay");
  s.on = delay.real(1, 20, "Tdelay", dim::time);
  if (s.on < 0.0) delay.fail(1, 20, "Tdelay", "a time of 0 or more (the time the sensor turns on)");
  if (context.model.input_version >= 2023 && reader.has_data()) {
    const Line stop = reader.next("Tstop");
    const double off = stop.real(1, 20, "Tstop", dim::time);
    if (off != 0.0) s.off = off;
    if (s.off < s.on) stop.fail(1, 20, "Tstop", "0 or blank (never off), or a time not before Tdelay");
  }
  reader.finish();
  context.model.sensors.push_back(std::move(s));
}

void read_sensor(CardReader& reader, DeckContext& context) {
  const auto& path = reader.card().path;
  const std::string type = path.size() > 1 ? path[1] : "";
  if (type == "TIME") return read_time_sensor(reader, context);
  context.unsupported(reader.error(
      "type", "TIME in /SENSOR/type/sens_ID (sensors that watch the run are not supported by Crumple)",
      in_quotes(type)));
}

}  // namespace

void register_sensor_keywords(KeywordTable& table) {
  table.push_back({"/SENSOR", DeckPart::Starter, read_sensor});
}

}  // namespace crumple::deck
