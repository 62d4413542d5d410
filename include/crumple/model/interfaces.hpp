#pragma once
// Contact interfaces as read from the deck (/INTER/TYPE7, ../shared/spec/type7.md §1). Zero means default;
// the contact module applies the defaults.
#include <array>
#include <cstdint>
#include <string>

#include "crumple/deck/error.hpp"

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
  int istf = 0, ithe = 0, igap = 0, ibag = 0, idel = 0, icurv = 0, iadm = 0;
  // line 2
  double fscale_gap = 0.0, gap_max = 0.0 /*[L]*/, fpenmax = 0.0;
  // line 3
  double stmin = 0.0, stmax = 0.0;  // [M T^-2]
  double mesh_size_percent = 0.0;
  double dtmin = 0.0;               // [T]
  int irem_gap = 0, irem_i2 = 0;
  // line 4
  double stfac = 0.0, fric = 0.0, gapmin = 0.0 /*[L]*/, tstart = 0.0 /*[T]*/, tstop = 0.0 /*[T]*/;
  // line 5
  std::array<bool, 3> ibc{};        // release boundary conditions of secondary nodes in x, y, z at impact
  int inacti = 0;
  double viss = 0.0, visf = 0.0, bumult = 0.0;
  // line 6
  int ifric = 0, ifiltr = 0;
  double xfreq = 0.0;
  int iform = 0;
  std::int64_t sensor_id = 0, friction_function_id = 0;
  double ascale_f = 0.0;
  std::int64_t friction_id = 0;
  // line 7 (Ifric > 0)
  std::array<double, 6> friction_c{};  // C1..C6
};

}  // namespace crumple
