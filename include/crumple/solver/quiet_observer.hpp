#pragma once
// An observer that writes nothing (solver/run_observer.hpp): the domains of a run of several whose results domain
// 0 writes, and tests that look at the state only. Its summary has the run's cycles, time, step, energies and
// status; the text of the stop reason is the output layer's (RunRecorder).
#include "crumple/solver/run_observer.hpp"

namespace crumple {

class QuietObserver final : public RunObserver {
 public:
  void start(const SolverState&, const std::vector<std::string>&) override {}
  void row(const SolverState&, double, const StepControl&) override {}
  void events(RunEvents& events) override { events.pending.clear(); }
  bool progress_due() override { return false; }
  void progress(const SolverState&, double, const StepControl&) override {}
  void frame(const SolverState&) override {}
  void history(const SolverState&, double, const VelocityChange&) override {}
  void restart(SolverState&, ResumeMarks&) override {}
  RunSummary finish(const SolverState& state, const RunEvents& events, const PhaseTimes& phases, double dt,
                    double wall_seconds) override;
};

}  // namespace crumple
