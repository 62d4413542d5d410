#pragma once
// The explicit time loop (docs/theory/time-loop.md): central difference with velocities at half steps.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/parallel/exchange.hpp"
#include "crumple/parallel/partition.hpp"
#include "crumple/solver/run_observer.hpp"

namespace crumple {

// What the time loop needs to know besides the model (output options: output/run.hpp, SimulationOptions).
struct SolverOptions {
  long long max_cycles = -1;                 // stop after this many cycles (tests); -1: no limit
  // Optional: called with the whole state at every time-history output time (/TFILE interval), after the
  // energies are updated; for tests and tools that read the state. It must not keep references past the call.
  std::function<void(const SolverState&)> on_history_row;
  // Restart (docs/theory/time-loop.md, "Restart"): the engine deck being run (1 for NAME_0001.rad), and for a run
  // that resumes a restart file the marks read with its state, so that the cycle goes on exactly where it stopped.
  int engine_deck = 1;
  const ResumeMarks* resume = nullptr;
  // Optional: the run stops at the end of the first cycle that finds it nonzero (status stopped, the last state
  // written); the value is kept as the reason, a signal number. The app points it at its SIGINT and SIGTERM flag.
  const std::atomic<int>* stop_request = nullptr;
  // A run of several domains: how this domain talks to the others (parallel/exchange.hpp); none for one domain.
  Exchange* exchange = nullptr;
  // A run of several domains (tests): at each rebalancing check, the partition to take instead of the estimated
  // one (docs/parallel.md, "Rebalancing"); empty: rebalance on the estimate.
  Repartition repartition;
};

// The state of a model before its first cycle; `notes` receives the start-up remarks for the listing.
SolverState initial_state(const Model& model, std::vector<std::string>& notes);
// The same for one domain of a run of several (docs/parallel.md): it computes its own elements only, and its
// options' exchange shares them with the other domains every cycle.
SolverState initial_state(const Model& model, std::vector<std::string>& notes, Domain domain);
// After a restart is read into a domain's state: the elements of the other domains are marked as computed
// elsewhere again (a restart file holds the elements' conditions only).
void mark_domain(SolverState& state);

// One engine deck from `state` (a fresh state, or the state a previous engine deck left: the snapshot a
// continued run carries on) to the end time of `model.run`, reported to `observer`. `state` is left at the end of
// the run. `notes` are the start-up remarks for the listing. Returns the observer's summary: a run that ends
// abnormally (NaN, inverted element, time step below the minimum, /STOP limit, a stop request) has status error or
// stopped with the reason in `message`, its last good state reported.
RunSummary run_engine_deck(const Model& model, const SolverOptions& options, RunObserver& observer,
                           SolverState& state, const std::vector<std::string>& notes);

// Before the next engine deck of a continued run: its cycle count and energy error start again from 0
// (docs/theory/time-loop.md, "Continued runs").
void continue_from(SolverState& state);

}  // namespace crumple
