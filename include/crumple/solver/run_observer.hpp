#pragma once
// What the time loop reports while a run goes (docs/theory/time-loop.md, "Monitor"): the solver says what happened
// and when; the output layer (output/run_recorder.hpp) decides how it is written. Called at output times only,
// never inside a phase's loops, so the virtual calls cost nothing measurable.
#include <string>
#include <vector>

#include "crumple/solver/run_events.hpp"
#include "crumple/solver/run_summary.hpp"
#include "crumple/solver/snapshot.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // An engine deck starts from `state` (its kinetic energy up to date); `notes` are its start-up remarks.
  virtual void start(const SolverState& state, const std::vector<std::string>& notes) = 0;
  // A printout cycle: the energies with the step dt^(n+1/2) and what bounds it.
  virtual void row(const SolverState& state, double dt, const StepControl& control) = 0;
  // The events of the last cycles (deletions, releases, warnings); empties `events.pending`.
  virtual void events(RunEvents& events) = 0;
  // Whether a progress report is due (cheap; the loop then brings the kinetic energy up to date).
  virtual bool progress_due() = 0;
  virtual void progress(const SolverState& state, double dt, const StepControl& control) = 0;
  // A field frame, and a history row with the cycle's velocity update (accelerations, reactions).
  virtual void frame(const SolverState& state) = 0;
  virtual void history(const SolverState& state, double dt, const VelocityChange& change) = 0;
  // A restart snapshot of the state with the monitor's marks.
  virtual void restart(SolverState& state, ResumeMarks& marks) = 0;
  // The engine deck is over: returns its summary (the caller adds what only it knows).
  virtual RunSummary finish(const SolverState& state, const RunEvents& events, const PhaseTimes& phases, double dt,
                            double wall_seconds) = 0;
};

}  // namespace crumple
