#pragma once
// Parts and the sets that cards refer to: node groups, element groups, surfaces, subsets.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/model/elements.hpp"

namespace crumple {

struct Part {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t property_id = 0;
  std::int64_t material_id = 0;
  std::int64_t subset_id = 0;
  std::int32_t property = -1;  // dense index (model build)
  std::int32_t material = -1;  // dense index (model build)
};

// How a group card lists its members: explicit ids, the parts whose elements give the members, other groups, or a
// box (/GRNOD/BOX, /GRSHEL/BOX, /BOX2...: one box id in `items`).
enum class SetSource : std::uint8_t { Ids, Parts, Groups, Surfaces, Boxes };  // Surfaces: /GRNOD/SURF only

struct NodeGroup {  // /GRNOD/NODE, /GRNOD/PART, /GRNOD/GRNOD, /GRNOD/SURF, /GRNOD/BOX
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  SetSource source = SetSource::Ids;
  std::vector<std::int64_t> items;  // user ids of nodes, parts or node groups; negative removes (docs/deck-format.md)
  std::vector<std::int32_t> nodes;  // dense node indices, sorted, unique (model build)
};

// A group of elements of one kind: /GRSHEL/SHEL, /GRSHEL/PART, /GRSHEL/BOX, /GRSHEL/BOX2 (4-node shells), the same
// four of /GRSH3N (3-node shells) and of /GRBRIC (bricks).
struct ElementSet {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  SetSource source = SetSource::Ids;
  ElementKind kind = ElementKind::Shell4;
  std::vector<std::int64_t> items;      // user ids of elements or parts, or the box id
  bool any_node_in_box = false;         // source Boxes: /BOX2 (one node in the box), else /BOX (every node)
  std::vector<std::int32_t> elements;   // dense indices into the kind's table, sorted, unique (model build)
};
using ShellGroup = ElementSet;

// A surface segment: 4 nodes (a triangle repeats its third node), oriented by the owning element.
struct Segment {
  std::array<std::int32_t, 4> nodes;  // dense node indices
  ElementRef owner;                    // element the segment belongs to (for thickness, gap, deletion)
};

struct Surface {  // /SURF/PART, /SURF/SEG, /SURF/GRSHEL, /SURF/GRSH3N
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  SetSource source = SetSource::Ids;
  std::vector<std::int64_t> parts;                    // /SURF/PART: part user ids
  // /SURF/GRSHEL, /SURF/GRSH3N (source Groups): the element groups' user ids and their kind.
  std::vector<std::int64_t> element_groups;
  ElementKind group_kind = ElementKind::Shell4;
  bool all_parts = false;                             // /SURF/PART/ALL: every part of the model
  std::vector<std::array<std::int64_t, 4>> raw_segments;  // /SURF/SEG: node user ids (n4 = 0 for triangles)
  std::vector<SourceLocation> raw_segment_where;
  std::vector<Segment> segments;                      // model build
};

// A line: a set of 2-node segments. /LINE/SURF: every edge of its surfaces' segments, once; /LINE/EDGE: their free
// edges, those of one segment only (measured on the reference: docs/deck-format.md, "Lines").
enum class LineSource : std::uint8_t { SurfaceEdges, SurfaceFreeEdges };

struct LineSet {  // /LINE/SURF, /LINE/EDGE
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  LineSource source = LineSource::SurfaceEdges;
  std::vector<std::int64_t> surfaces;                  // surface user ids
  std::vector<std::array<std::int32_t, 2>> segments;  // dense node indices (model build)
};

struct Subset {  // /SUBSET
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::vector<std::int64_t> children;  // subset user ids
};

}  // namespace crumple
