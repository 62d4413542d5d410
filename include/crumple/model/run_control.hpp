#pragma once
// Run control from the engine deck (docs/cards/loads-output-engine.md §7). Values are in working units once
// read_deck returns. Zero means "not given"; the solver applies the defaults.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/model/damping.hpp"

#include "crumple/core/source_location.hpp"

namespace crumple {

// What happens when an element reaches Δt_min (/DT/<type>/<Keyword3>). Default: bricks stop the run, shells
// (4- and 3-node) delete the controlling element.
enum class TimeStepAction : std::uint8_t { Default, Stop, Delete, SmallStrain };

struct TimeStepControl {  // /DT, /DT/NODA/CST, /DT/SHELL, /DT/BRICK, /DT/INTER/..., /DT/SH_3N
  double scale = 0.0;     // Δt_sca in (0, 1] (0: default 0.9)
  double minimum = 0.0;   // Δt_min [T]
  TimeStepAction action = TimeStepAction::Default;  // /DT/SHELL, /DT/BRICK, /DT/SH_3N only
  bool given = false;
  SourceLocation where;   // the card
};

// What the field frames hold beyond the fields every frame has (docs/output-format.md, "/frames/NNNN"): set by
// the /ANIM cards that ask for them. A request for one element kind adds the field for every kind that has it.
// /DT/AMS/Iflag: advanced (selective) mass scaling on the parts of the starter's /AMS (docs/theory/time-step.md,
// "Selective mass scaling", SM-1 to SM-6). Zero means "not given"; the solver applies the defaults.
struct SelectiveMassControl {
  double scale = 0.0;               // Δt_sca in (0, 1] (0: default 0.9)
  double minimum = 0.0;             // Δt_min: the step the scaled elements are held at [T] (0: no scaling)
  double tolerance = 0.0;           // Tol_AMS, relative residual of the solve (0: default 1e-3)
  std::int64_t max_iterations = 0;  // Niter (0: default 1000)
  bool given = false;
  SourceLocation where;             // the card
  double scale_or_default() const { return scale > 0.0 ? scale : 0.9; }
  double tolerance_or_default() const { return tolerance > 0.0 ? tolerance : 1e-3; }
  std::int64_t max_iterations_or_default() const { return max_iterations > 0 ? max_iterations : 1000; }
};

struct FrameRequests {
  bool pressure = false;          // P
  bool energy_density = false;    // ENER: internal energy over element mass
  bool hourglass_energy = false;  // HOURG
  bool time_step = false;         // DT: the element's critical step
  bool bending_stress = false;    // /ANIM/[SHELL/]TENS/STRESS/BEND
  bool surface_stress = false;    // /ANIM/[SHELL/]TENS/STRESS/UPPER or LOWER (both written)
  bool contact_force = false;     // /ANIM/VECT/CONT: also written (zero) without contact interfaces
  bool acceleration = false;      // /ANIM/VECT/ACC
  bool internal_force = false;    // /ANIM/VECT/FINT
  bool external_force = false;    // /ANIM/VECT/FEXT
  bool angular_velocity = false;  // /ANIM/VECT/VROT
  bool nodal_mass = false;        // /ANIM/MASS
  bool added_mass = false;        // /ANIM/NODA/DMAS
};

struct RunControl {
  bool present = false;         // the engine part has its /RUN card
  SourceLocation where;         // its /RUN card
  std::string run_name;
  int run_number = 1;
  double end_time = 0.0;        // [T]
  double history_interval = 0.0;   // /TFILE [T] (0: every cycle when /TFILE is given, as the reference writes)
  int history_format = 0;          // /TFILE/type: 1 binary, 2 coded ASCII, 3 ASCII, 4 IEEE 32-bit (0: no /TFILE)
  bool history_every_cycle() const { return history_format != 0 && history_interval == 0.0; }
  double anim_start = 0.0, anim_interval = 0.0;  // /ANIM/DT [T] (interval 0: no field output)
  FrameRequests anim;
  bool anim_gzip = false;
  int anim_version = 0;           // /ANIM/VERS/n
  std::int64_t print_every = 0;   // /PRINT/n: listing every |n| cycles (negative: also on screen)
  int print_header_lines = 0;     // /PRINT/n/Nline: repeat the column header every Nline lines
  TimeStepControl dt;             // /DT
  TimeStepControl dt_nodal_cst;   // /DT/NODA/CST
  // --accuracy draft: the step is the larger of the nodal step and the deck as written's (its elements' and its
  // contacts' steps), both stable bounds (docs/theory/time-step.md, T-3c); a deck's /DT/NODA/CST takes the nodal.
  bool nodal_step_at_least_as_written = false;
  TimeStepControl dt_shell, dt_brick, dt_sh3n, dt_spring, dt_truss, dt_beam;  // /DT/<kind>: ElementKindDescription::step_control
  TimeStepControl dt_inter_del, dt_inter_cst;
  SelectiveMassControl dt_ams;    // /DT/AMS
  // Steps ahead of its entry into the gap that a TYPE7 node closing in counts K0 in its step (eq. C-11). 0: from
  // the cycle it is in the gap, as the reference solver (the deck as written); 3 with `--accuracy fine`.
  int contact_entry_window = 0;
  // The energy error [%] beyond which the run warns, once (docs/theory/energy.md): 10 for the deck as written, 5
  // under an --accuracy preset, whose warning names the knobs it moved.
  double energy_error_warning = 10.0;
  bool parith = true;
  bool monitor = false;
  double stop_energy_error = 0.0;      // /STOP Emax: energy error ratio (0: no limit)
  double stop_mass_error = 0.0;        // /STOP Mmax: total added mass / initial mass (0: no limit)
  double stop_node_mass_error = 0.0;   // /STOP Nmax: largest nodal added mass / initial nodal mass (0: no limit)
  bool stop_write_history = false;     // /STOP NTH: write a time-history point when stopping
  bool stop_write_animation = false;   // /STOP NANIM: write field output when stopping
  bool stop_positive_error_only = false;  // /STOP NERR_POSIT: only a positive energy error counts
  std::int64_t restart_every = 0;  // /RFILE Ncycle (0: no restart files)
  int restart_sets = 0;            // /RFILE/n: rotating restart sets (0: one)
  int engine_version = 0;          // /VERS/n of the engine deck (no effect)
  // /RBODY/ON, /RBODY/OFF: rigid bodies named by their main node id, activated or deactivated from the start of
  // this engine deck (model build: dense indices into Model::rigid_bodies).
  std::vector<std::int64_t> rbody_on, rbody_off;
  std::vector<SourceLocation> rbody_on_where, rbody_off_where;  // the line of each id, parallel
  std::vector<std::int32_t> bodies_on, bodies_off;
  // /VEL/TRA/dirs[/skew_ID]: nodes that move together along the listed axes (a rigid link): each cycle their
  // velocity along each axis is their mass-weighted mean, and at the start of the engine deck too
  // (docs/theory/loads.md, L-8).
  struct VelocityLink {
    SourceLocation where;
    std::array<bool, 3> along{};      // X, Y, Z of the global axes or of the skew
    std::int64_t skew_id = 0;
    std::int32_t skew = -1;           // -1: the global axes (model build)
    std::vector<std::int64_t> node_ids;
    std::vector<std::int32_t> nodes;  // dense indices, sorted, unique (model build)
  };
  std::vector<VelocityLink> velocity_links;
  std::vector<DampingChange> damping_changes;  // engine /DAMP, in deck order
  // /DTIX: the step of this engine deck's first cycle is at most dt_initial, every step at most dt_max [T]
  // (0: no bound).
  double dt_initial = 0.0, dt_max = 0.0;
};

}  // namespace crumple
