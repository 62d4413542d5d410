// Warnings a run raises once (docs/theory/energy.md): an energy error beyond 10 % is said in the listing and on
// the console, so that a run whose balance is lost never ends "normal" without a word.
#include <gtest/gtest.h>

#include "crumple/output/run_recorder.hpp"
#include "solver/monitor.hpp"

namespace crumple::test_run_warnings {
namespace {

TEST(RunWarnings, EnergyErrorBeyondTenPercentIsRaisedOnce) {
  Model model;
  SolverState s;
  s.energy.initial_kinetic = 100.0;
  s.energy.internal = 50.0, s.energy.kinetic_translational = 41.0;  // error -9 %: no warning
  RunEvents events;
  solver::check_run_limits(model, s, events);
  EXPECT_TRUE(events.pending.empty());
  s.energy.kinetic_translational = 30.0;  // -20 %
  s.cycle = 12, s.time = 0.5;
  solver::check_run_limits(model, s, events);
  ASSERT_EQ(events.pending.size(), 1u);
  const RunEvent& e = events.pending[0];
  EXPECT_EQ(e.kind, RunEvent::Kind::EnergyErrorLarge);
  EXPECT_DOUBLE_EQ(e.value, -20.0);
  EXPECT_NE(describe(e, model).find("WARNING: energy error -20 % (beyond 10 %)"), std::string::npos)
      << describe(e, model);
  EXPECT_FALSE(events.stop.stopped()) << "a warning, not a stop (/STOP Emax stops)";
  s.energy.kinetic_translational = 0.0;  // worse: still one event
  solver::check_run_limits(model, s, events);
  EXPECT_EQ(events.pending.size(), 1u);
}

// Under an --accuracy preset the warning comes at 5 % and names the knobs the preset moved (issue 26).
TEST(RunWarnings, UnderAPresetTheEnergyErrorBeyondFivePercentNamesItsKnobs) {
  Model model;
  model.run.energy_error_warning = 5.0;  // what apply_accuracy_preset sets for draft and fine
  SolverState s;
  s.energy.initial_kinetic = 100.0;
  s.energy.internal = 50.0, s.energy.kinetic_translational = 46.0;  // -4 %: no warning
  RunEvents events;
  solver::check_run_limits(model, s, events);
  EXPECT_TRUE(events.pending.empty());
  s.energy.kinetic_translational = 44.0;  // -6 %
  solver::check_run_limits(model, s, events);
  ASSERT_EQ(events.pending.size(), 1u);
  EXPECT_NE(describe(events.pending[0], model).find("energy error -6 % (beyond 5 %)"), std::string::npos)
      << describe(events.pending[0], model);
  RunStart draft;
  draft.accuracy = "draft";
  draft.approximations = {"[output-only] deck:4: /PRINT/-500: field Nline: output-only",
                          "--accuracy draft: /DT/NODA/CST 0.67 0.0005796: nodal mass scaling"};
  EXPECT_EQ(preset_knobs_to_loosen(draft),
            "; under --accuracy draft loosen the knob it moved (/DT/NODA/CST 0.67 0.0005796: nodal mass scaling), or "
            "run --accuracy standard");
  EXPECT_EQ(preset_knobs_to_loosen(RunStart{}), "");
}

}  // namespace
}  // namespace crumple::test_run_warnings
