#pragma once
// Output requests of the starter: time histories (/TH/...) and cut sections (/SECT).
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/deck/error.hpp"

namespace crumple {

enum class HistoryObject : std::uint8_t { Node, Part, RigidWall, Interface, Shell, Sh3n, Brick, Subset, Section, RigidBody };

struct TimeHistoryRequest {  // /TH/...
  SourceLocation where;
  std::string keyword;  // the card's keyword line, for messages
  std::int64_t user_id = 0;
  std::string title;
  HistoryObject object = HistoryObject::Node;
  std::vector<std::string> variables;   // e.g. "DEF"
  std::vector<std::int64_t> object_ids; // user ids of the objects
  std::vector<std::int32_t> objects;    // dense indices (model build)
};

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
  int iframe = 0;
  std::vector<std::int64_t> interface_ids;
  std::int32_t node_group = -1;
  std::int32_t shell_group = -1;
};

}  // namespace crumple
