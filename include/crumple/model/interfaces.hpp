#pragma once
// Contact interfaces as read from the deck (/INTER/TYPE7, ../shared/spec/type7.md §1; exact columns in
// docs/cards/loads-output-engine.md §5). Values are in working units. Zero means default; the contact module
// applies the defaults. The manual's "1000" codes of Istf, Igap, Idel and Inacti (= the default behaviour) are
// stored as 0, so that 0 is the only default code the contact module sees.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/core/source_location.hpp"
#include "crumple/model/sensors.hpp"
#include "crumple/model/ties.hpp"

namespace crumple {

struct Type7Interface {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  // line 1
  std::int64_t secondary_group_id = 0;  // Slav_id: node group of secondary nodes
  std::int64_t main_surface_id = 0;     // Mast_id: main surface
  std::int32_t secondary_group = -1;
  std::int32_t main_surface = -1;
  int istf = 0;   // 0 stiffness from the main side (Stfac scales it), 1 Stfac is the stiffness, 2..5 combined
  int ithe = 0;   // always 0 (thermal contact is rejected by the reader)
  int igap = 0;   // 0 constant gap, 1 variable, 2 variable and scaled
  int ibag = 0;   // 0 or 2 (no vent closure; 1 is rejected)
  int idel = 0;   // 0 none, 1 segment removed when all its elements are deleted, 2 when one is
  int icurv = 0;  // always 0 (curvature is rejected by the reader)
  int iadm = 0;   // always 0 (adaptive meshing is rejected by the reader)
  // line 2
  double fscale_gap = 0.0, gap_max = 0.0 /*[L]*/, fpenmax = 0.0;
  int itied = 0;  // 2020+ decks only; always 0 (tied contact is rejected)
  // line 3
  double stmin = 0.0, stmax = 0.0;  // [M T^-2]
  double mesh_size_percent = 0.0;
  double dtmin = 0.0;               // [T]
  int irem_gap = 0;                 // 0 or 1 (2 is rejected)
  int irem_i2 = 0;                  // 1: the nodes tied by /INTER/TYPE2 leave this contact; 0 (= 3): they stay (C-1b)
  // optional line (Icurv = 1 or 2): curvature centre or axis nodes
  std::array<std::int64_t, 2> curvature_node_ids{};
  // line 4
  double stfac = 0.0;  // a factor, or a stiffness [M T^-2] when istf == 1
  double fric = 0.0, gapmin = 0.0 /*[L]*/, tstart = 0.0 /*[T]*/, tstop = 0.0 /*[T]*/;
  // line 5
  std::array<bool, 3> ibc{};        // release boundary conditions of secondary nodes in x, y, z at impact
  int inacti = 0;                   // 0 none, 1, 2, 3, 5, 6 (type7.md §7)
  double viss = 0.0, visf = 0.0, bumult = 0.0;
  // line 6
  int ifric = 0, ifiltr = 0;
  double xfreq = 0.0;  // Ifiltr 1: a factor in (0, 1]; 2: a period [T]; 3: a frequency [T^-1]
  int iform = 0;
  std::int64_t sensor_id = 0;  // 0: none; else the interface acts only while the sensor is on (loads.md, L-7)
  SensorWindow sensor;          // resolved from sensor_id (model build)
  std::int64_t friction_function_id = 0;                  // always 0 (rejected by the reader)
  double ascale_f = 0.0;
  std::int64_t friction_id = 0;                           // always 0 (rejected by the reader)
  // line 7 (C1..C5 when Ifric > 0) and line 8 (C6 when Ifric > 1); dimensions depend on the law:
  // Ifric 1 (generalized viscous): C1 [1/P], C2 [1/V], C3 [1/(P V)], C4 [1/P^2], C5 [1/V^2];
  // Ifric 2 (Darmstad): C1 [1/P^2], C2 [1/V], C3 [1/P], C4 [1/V], C5 [-], C6 [1/V];
  // Ifric 3 (Renard): C1..C4 [-], C5 and C6 [V].
  std::array<double, 6> friction_c{};
  // optional line (Iadm = 2); kept for messages, the reader rejects Iadm != 0
  int nradm = 0;
  double padm = 0.0, angladm = 0.0;
};

// /INTER/TYPE2: secondary nodes tied to a main surface by a kinematic condition (docs/theory/tied-interfaces.md;
// columns in docs/cards/loads-output-engine.md §5b). Values in working units; 0 means default.
struct Type2Interface {
  SourceLocation where;
  std::int64_t user_id = 0;
  std::string title;
  std::int64_t secondary_group_id = 0;  // grnd_IDs: node group of the tied (secondary) nodes
  std::int64_t main_surface_id = 0;     // surf_IDm: the surface they are tied to
  std::int32_t secondary_group = -1;
  std::int32_t main_surface = -1;
  int ignore = 0;    // 0 (= 1000): a node that finds no segment is an error; 1, 2, 3: it is left out of the tie
  int spotflag = 0;  // formulation: 0 resolved to 5 (standard), 1 (spot welds), 2, 4 (rotations not carried)
  int isearch = 0;   // 0 (= 2) or 1: how the nearest segment is searched
  int idel2 = 0;     // 0 (= 1000) none; 1, 2: the condition is released when the main element(s) are deleted
  double dsearch = 0.0;  // [L] search distance; 0: the mean size of the main segments
  std::vector<Tie> ties;  // model build: each tied node with its segment and weights (model/ties.hpp)
};

}  // namespace crumple
