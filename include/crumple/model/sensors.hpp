#pragma once
// Sensors (/SENSOR/TIME): a switch that turns on at Tdelay and, from input version 2023, off at Tstop. A load, an
// imposed motion or a gravity field that names a sensor acts only while it is on, and its time function runs on a
// clock that starts when the sensor turns on (docs/theory/loads.md, L-7). Only the time sensor is read: the others
// watch a quantity of the run and are refused by name.
#include <cstdint>
#include <limits>
#include <string>

#include "crumple/core/source_location.hpp"

namespace crumple {

struct Sensor {  // /SENSOR/TIME
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  double on = 0.0;                                         // Tdelay [T]: the time the sensor turns on
  double off = std::numeric_limits<double>::infinity();  // Tstop [T] (2023 on); blank or 0: never off
};

// When a load that names a sensor acts, and the origin of its function's clock (eq. L-7). Without a sensor: always,
// from t = 0.
struct SensorWindow {
  double on = 0.0;                                         // [T]
  double off = std::numeric_limits<double>::infinity();  // [T]
  bool holds(double t) const { return t >= on && t <= off; }
  bool holds_during(double from, double to) const { return to >= on && from <= off; }  // any part of [from, to]
  double clock(double t) const { return t - on; }  // the function's time
};

}  // namespace crumple
