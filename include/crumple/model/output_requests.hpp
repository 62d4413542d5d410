#pragma once
// Output requests of the starter: time histories (/TH/...) and cut sections (/SECT).
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"

namespace crumple {

enum class HistoryObject : std::uint8_t {
  Node, Part, RigidWall, Interface, Shell, Sh3n, Brick, Subset, Section, RigidBody, Accelerometer, Spring, Truss, Beam
};

// Layouts: docs/cards/loads-output-engine.md §6.1. Variables are kept as written (upper case, each once, group names
// such as DEF not expanded: select_history_variables in history_variables.hpp expands them); objects are kept once
// each, in deck order.
struct TimeHistoryRequest {  // /TH/...
  SourceLocation where;
  std::string keyword;  // the card's keyword line, e.g. "/TH/SHELL/3", for messages
  std::int64_t user_id = 0;
  std::string title;
  HistoryObject object = HistoryObject::Node;
  std::vector<std::string> variables;   // e.g. "DEF"
  std::vector<std::int64_t> object_ids; // user ids of the objects
  std::vector<std::string> object_names;  // /TH/NODE, /TH/SHEL(L), /TH/SH3N, /TH/BRIC: the name of each object
                                          // (may be empty), parallel to object_ids; empty for the other kinds
  std::vector<std::int32_t> objects;    // dense indices (model build)
  // /TH/NODE: the skew each node's vectors are written in (SK-4), parallel to object_ids; 0 / -1: global axes.
  std::vector<std::int64_t> object_skew_ids;
  std::vector<std::int32_t> object_skews;  // dense indices (model build)
};

// /ACCEL (docs/cards/loads-output-engine.md §6.3): the acceleration of a node, filtered by a 4-pole Butterworth
// low-pass (docs/output-format.md, "ACCEL"), in the global axes or along a skew's (docs/theory/skews.md, SK-4).
struct Accelerometer {  // /ACCEL
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t node_id = 0;
  std::int64_t skew_id = 0;
  std::int32_t skew = -1;    // dense index (model build); -1: the global axes
  double cutoff = 0.0;       // Fcut: corner frequency of the filter [1/T]; 0 or blank: no filter
  std::int32_t node = -1;    // dense index (model build)
};

// /SECT (docs/cards/loads-output-engine.md §6.2; what /TH/SECTIO writes of it: docs/output-format.md, "SECTIO").
// The reader accepts ISAVE = 0 only, no moving frame, and element groups of the kinds Crumple has: 4-node shells
// (/GRSHEL), 3-node shells (/GRSH3N) and bricks (/GRBRIC); the other element-group ids stay 0.
struct Section {  // /SECT
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t node_ids[3] = {0, 0, 0};  // frame nodes N1, N2, N3
  std::int64_t node_group_id = 0;
  int isave = 0;
  std::int64_t frame_id = 0;
  double dt = 0.0;     // [T]
  double alpha = 0.0;
  std::string file_name;
  std::int64_t brick_group_id = 0, shell_group_id = 0, truss_group_id = 0, beam_group_id = 0,
               spring_group_id = 0, sh3n_group_id = 0;
  int ninter = 0;
  int iframe = 0;  // moment reference: 0 origin of the N1N2N3 frame, 1 geometric centre, 2 centre of gravity,
                   // 3 point (0,0,0); 10..13 the same with the axes of the global frame
  std::vector<std::int64_t> interface_ids;  // Ninter ids of interfaces whose forces cross the cut
  std::int32_t nodes[3] = {-1, -1, -1};     // frame nodes, dense indices (model build; -1 when blank)
  std::int32_t node_group = -1;
  std::int32_t shell_group = -1, sh3n_group = -1, brick_group = -1;
  std::vector<std::int32_t> interfaces;  // dense indices (model build)
};

}  // namespace crumple
