#pragma once
// Run control from the engine deck. Zero or negative means "not given"; the solver applies the defaults.
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/deck/error.hpp"

namespace crumple {

struct TimeStepControl {  // /DT, /DT/NODA/CST, /DT/SHELL, /DT/BRICK, /DT/INTER/..., /DT/SH_3N
  double scale = 0.0;     // Δt_sca (0: default 0.9)
  double minimum = 0.0;   // Δt_min [T]
  bool given = false;
};

struct RunControl {
  bool present = false;         // an engine part was read
  SourceLocation where;         // its /RUN card
  std::string run_name;
  int run_number = 1;
  double end_time = 0.0;        // [T]
  double history_interval = 0.0;   // /TFILE [T]
  double anim_start = 0.0, anim_interval = 0.0;  // /ANIM/DT [T]
  std::vector<std::string> anim_element_fields, anim_vector_fields, anim_nodal_fields;
  bool anim_gzip = false;
  std::int64_t print_every = 0;  // /PRINT: listing every n cycles (negative: also on screen)
  TimeStepControl dt;             // /DT
  TimeStepControl dt_nodal_cst;   // /DT/NODA/CST
  TimeStepControl dt_shell, dt_brick, dt_sh3n;
  TimeStepControl dt_inter_del, dt_inter_cst;
  bool parith = true;
  bool monitor = false;
  double stop_energy_error = 0.0;  // /STOP Emax [%] (0: none)
  double stop_mass_error = 0.0;    // /STOP Mmax (0: none)
  std::int64_t stop_nodes = 0;
  std::int64_t restart_every = 0;  // /RFILE
  std::vector<std::int64_t> rbody_on, rbody_off;
};

}  // namespace crumple
