#pragma once
// The model: everything the deck defines, in working units, with user ids resolved to dense indices.
// Built once by the deck reader (deck/ -> model/build) and read-only to the solver kernels afterwards.
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "crumple/core/units.hpp"
#include "crumple/model/boxes.hpp"
#include "crumple/model/damping.hpp"
#include "crumple/model/elements.hpp"
#include "crumple/model/functions.hpp"
#include "crumple/model/interfaces.hpp"
#include "crumple/model/loads.hpp"
#include "crumple/model/materials.hpp"
#include "crumple/model/nodes.hpp"
#include "crumple/model/output_requests.hpp"
#include "crumple/model/properties.hpp"
#include "crumple/model/rigid.hpp"
#include "crumple/model/run_control.hpp"
#include "crumple/model/sensors.hpp"
#include "crumple/model/sets.hpp"
#include "crumple/model/skews.hpp"

namespace crumple {

using IdMap = std::unordered_map<std::int64_t, std::int32_t>;  // user id -> dense index

struct Model {
  std::string run_name;  // from /BEGIN
  std::string title;     // from /TITLE
  int input_version = 0; // Invers of /BEGIN
  UnitSystem units;

  Nodes nodes;
  std::array<ElementTable, kElementKinds> elements = empty_element_tables();
  std::vector<ElementGroup> element_groups;

  std::vector<Part> parts;
  std::vector<Property> properties;
  std::vector<ResolvedFormulation> formulations;  // one per property: effective element flags
  std::vector<Material> materials;
  std::vector<Function> functions;
  ShellDefaults shell_defaults;
  SolidDefaults solid_defaults;

  std::vector<NodeGroup> node_groups;
  std::vector<ShellGroup> shell_groups;   // /GRSHEL
  std::vector<ElementSet> sh3n_groups;    // /GRSH3N
  std::vector<ElementSet> brick_groups;   // /GRBRIC
  std::vector<Surface> surfaces;
  std::vector<LineSet> lines;  // /LINE/SURF, /LINE/EDGE
  std::vector<Subset> subsets;
  std::vector<Skew> skews;  // /SKEW/FIX, /SKEW/MOV, /SKEW/MOV2
  std::vector<Sensor> sensors;  // /SENSOR/TIME
  std::vector<Box> boxes;       // /BOX/RECTA, /BOX/CYLIN, /BOX/SPHER, /BOX/BOX

  std::vector<BoundaryCondition> boundary_conditions;
  std::vector<ImposedMotion> imposed;  // /IMPVEL, /IMPDISP, /CLOAD
  std::vector<FinalGeometry> final_geometries;  // /IMPDISP/FGEO
  std::vector<InitialVelocity> initial_velocities;
  std::vector<Gravity> gravity;
  std::vector<AddedMass> added_masses;
  std::vector<RigidWall> rigid_walls;
  std::vector<RigidBody> rigid_bodies;
  std::vector<RigidElement> rigid_elements;                       // /RBE2
  std::vector<InterpolationConstraint> interpolation_constraints;  // /RBE3
  std::vector<RayleighDamping> dampings;  // /DAMP
  std::vector<Type7Interface> type7_interfaces;
  std::vector<Type2Interface> type2_interfaces;  // /INTER/TYPE2; /TH/INTER numbers them after the TYPE7 ones
  std::vector<TimeHistoryRequest> histories;
  std::vector<Section> sections;
  std::vector<Accelerometer> accelerometers;

  RunControl run;
  // /RANDOM: every node's coordinates moved by up to `random_noise` [L] in each direction, from `random_seed`
  // (docs/deck-format.md, "/RANDOM"); 0: none.
  double random_noise = 0.0, random_seed = 0.0;
  // /AMS: the parts /DT/AMS scales (the whole model: the only selection Crumple reads); `ams_where` its card.
  bool ams_selected = false;
  SourceLocation ams_where;

  // Lumped nodal mass [M]: element mass plus /ADMAS and /RBODY mass (model build, docs/theory/mass.md).
  std::vector<double> nodal_mass;
  double element_mass = 0.0;  // sum of element masses [M]
  double added_mass = 0.0;    // /ADMAS and /RBODY masses [M]

  struct Index {
    IdMap nodes, parts, properties, materials, functions, node_groups, shell_groups, sh3n_groups, brick_groups,
        surfaces, lines, subsets, skews, sensors, boxes, rigid_walls, rigid_bodies, rigid_elements,
        interpolation_constraints, interfaces, sections,
        accelerometers, dampings;
    std::array<IdMap, kElementKinds> elements;
  } index;

  double total_mass() const { return element_mass + added_mass; }
};

}  // namespace crumple
