#pragma once
// Internal to the solver: step 7 of a cycle, the monitor (docs/theory/time-loop.md, "One cycle"): which outputs are
// due, the energies they need, the warnings and the /STOP limits, and the next output times.
#include <atomic>

#include "crumple/model/model.hpp"
#include "crumple/parallel/exchange.hpp"
#include "crumple/solver/run_events.hpp"
#include "crumple/solver/solver_state.hpp"
#include "solver/cycle.hpp"

namespace crumple::solver {

// 5b. After the kinematic conditions, before the positions move: the output-only integrals of the step, which no
// phase reads: a^n for the field frames, the /ACCEL filters, /TH/SECTIO WORK and /TH/NODE's rotations. A deck that
// asks none of them pays a test each.
void record_step_outputs(const Model& model, SolverState& state, const VelocityScratch& scratch, double dt_average,
                         double dt_next);

// The nodal results the engine deck's /ANIM cards ask for that the cycle keeps only then (SolverState::recorded):
// sized (zero) when asked for, emptied when not.
void keep_requested_results(const RunControl& run, SolverState& state);

// 7. Monitor: which outputs are due after a cycle, the energies they need, and the /STOP limits.
// T-0: a run with frames goes one cycle past its end time, for its end frame, when its last frame is this many
// cycles or more before that cycle (measured on the reference: a last frame 99 cycles before it does not, 100 do).
inline constexpr long long kEndFrameCycles = 100;
struct OutputSchedule {
  double next_frame, next_history;  // /ANIM/DT and /TFILE times [T] (infinite: none)
  long long print_every;            // listing row every |/PRINT| cycles (default 100)
  long long max_cycles;             // stop after this many cycles (-1: no limit)
  long long last_frame_cycle;       // the run's cycle of the last frame written (the cycles before it: none)
  // The first outputs of a run that starts at `time` (0, or where a continued run takes over).
  OutputSchedule(const RunControl& run, double time, long long max_cycles);
};
struct MonitorDue {
  bool finished, print, frame, history;
  bool energies() const;  // the kinetic energy and the stop limits are checked (also every 64 cycles)
  long long cycle;
};
MonitorDue outputs_due(const Model& model, const SolverState& state, const OutputSchedule& schedule, double dt_next);
// Whether a resumed state is the end of its engine deck already (T-0 decided it there, with the step it took
// next): a run resumed from the snapshot of its own end has no cycle left to run.
bool resumed_at_the_end(const Model& model, const SolverState& state, const OutputSchedule& schedule);
// A field frame is due at the state's time (also before the first cycle: the frame at t = 0).
bool frame_due(const SolverState& state, const OutputSchedule& schedule);
// The balance's energies, when it is checked: kinetic energies of v^(n+1/2), and the internal and hourglass
// energies as exact sums of each element's running energy (docs/theory/energy.md), combined over the domains
// (every domain calls it at the same cycles).
void update_energies(const Model& model, SolverState& state);
// NaN in the balance, /STOP added-mass and energy-error limits: recorded in `events.stop`.
void check_run_limits(const Model& model, const SolverState& state, RunEvents& events);
// Once per run: the step `dt` fell below 1/1000 of the elements' scaled step `element_step` (set by `control`).
void warn_step_drop(const SolverState& state, double element_step, double dt, const StepControl& control,
                    RunEvents& events);
// A stop asked from outside the solver (SolverOptions::stop_request, which the app's SIGINT and SIGTERM handlers
// set): recorded in `events.stop` at the end of the cycle; true when there is one. One relaxed load per cycle.
bool stop_requested(const std::atomic<int>* request, SolverState& state, RunEvents& events,
                    Exchange* exchange, bool check_now);
// The next output times once a frame or a history row has been written at the state's time.
void advance_schedule(const Model& model, const SolverState& state, const MonitorDue& due, OutputSchedule& schedule);

}  // namespace crumple::solver
