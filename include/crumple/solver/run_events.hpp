#pragma once
// What happens during a run, as data: what bounds the time step, the events of a cycle (deletions, releases) and
// why a run stops. The solver records them; output/ turns them into listing text and messages
// (docs/theory/time-loop.md, "Events").
#include <cstdint>
#include <vector>

#include "crumple/model/elements.hpp"

namespace crumple {

// What sets dt^(n+1/2): the listing's ELEMENT column.
struct StepControl {
  enum class Source : std::uint8_t { None, Element, Interface, Node, LastStep, MaximumStep, InitialStep };
  Source source = Source::None;
  ElementKind kind = ElementKind::Shell4;  // Element: its kind
  std::int32_t index = -1;                 // Element: index in its kind's table; Interface, Node: dense node
  std::int32_t interface = -1;             // Interface: index into Model::type7_interfaces

  static StepControl element(ElementKind kind, std::int32_t index) { return {Source::Element, kind, index, -1}; }
  static StepControl node(std::int32_t node) { return {Source::Node, ElementKind::Shell4, node, -1}; }
  static StepControl contact(std::int32_t interface, std::int32_t node) {
    return {Source::Interface, ElementKind::Shell4, node, interface};
  }
};

// Something the listing reports once, at the cycle it happened.
struct RunEvent {
  enum class Kind : std::uint8_t {
    ElementDeletedBelowMinimumStep,  // /DT/<type>/DEL: element (kind, index), value = its scaled step [T]
    ElementSwitchedToSmallStrain,    // /DT/<type>/CST: element (kind, index), value = its scaled step [T]
    ShellDeletedInverted,            // shells turned inside out in a group this cycle: the last (kind, index),
                                     // value = how many of the group
    ContactBoundaryReleased,         // TYPE7 IBC: node index, value = the released dof mask
    HourglassShare,                  // hourglass energy above 10 % of the internal energy: value = the ratio
    EnergyErrorLarge,                // |energy error| above RunControl::energy_error_warning: value = the error,
                                     // second_value = that threshold, in percent
    StepDropped,                     // the step fell below 1/1000 of the elements' own: value = the step,
                                     // second_value = the elements' step [T], `control` what set it
    Rebalanced,                      // several domains repartitioned: value, second_value = estimated imbalance
                                     // before and after (largest domain's cost over the mean)
  };
  Kind kind;
  long long cycle = 0;
  double time = 0.0;
  ElementKind element_kind = ElementKind::Shell4;
  std::int32_t index = -1;
  double value = 0.0;
  double second_value = 0.0;
  StepControl control{};  // StepDropped: what set the step
};

// An energy error beyond this [%] (the balance off by ten thousand times the energy put in) is no modelling choice
// but a run blowing up: it stops as an error whatever /STOP says (docs/theory/energy.md, "A diverged run").
inline constexpr double kDivergedEnergyErrorPercent = 1.0e6;

// Why a run ended before its end time. `kind` None while it runs on.
struct StopReason {
  enum class Kind : std::uint8_t {
    None,
    NonFiniteForces,          // element forces NaN or infinite: element (kind, index)
    InvertedElement,          // negative volume or area: element (kind, index)
    ElementStepBelowMinimum,  // /DT/<type>/STOP: element (kind, index), dt, minimum
    StepBelowMinimum,         // /DT Δt_min: dt, minimum, control
    NoStableStep,             // nothing bounds the step at the start
    EnergyNotFinite,          // NaN or Inf in the energy balance
    Diverged,                 // the energy balance off by more than kDivergedEnergyErrorPercent: value = error %
    AddedMassLimit,           // /STOP Mmax: value = added mass, minimum = the card's ratio
    EnergyErrorLimit,         // /STOP Emax: value = |error| ratio
    Requested,                // asked from outside (SolverOptions::stop_request): index = the signal number
    MassScalingDiverged,      // /DT/AMS: the solve did not converge: index = iterations, value = residual ratio,
                              // minimum = Tol_AMS
    EveryElementLost,         // no element left, some deleted by numerical causes: index = shells turned inside
                              // out, value = elements below their minimum step (/DT/<type>/DEL)
  };
  Kind kind = Kind::None;
  long long cycle = 0;
  double time = 0.0;
  ElementKind element_kind = ElementKind::Shell4;
  std::int32_t index = -1;
  double dt = 0.0, minimum = 0.0, value = 0.0;
  StepControl control;

  bool stopped() const { return kind != Kind::None; }
  // /STOP limits end the run as "stopped"; everything else is an error.
  bool is_limit() const { return kind == Kind::AddedMassLimit || kind == Kind::EnergyErrorLimit; }
  // SIGINT or SIGTERM asked the run to stop: it ends as "stopped" at the end of the cycle.
  bool requested() const { return kind == Kind::Requested; }
};

// Events of the run: the solver appends, the output drains `pending` at every monitor phase.
struct RunEvents {
  std::vector<RunEvent> pending;
  StopReason stop;
  long long deleted_below_minimum_step = 0;  // elements deleted by /DT/<type>/DEL over the run
  long long switched_to_small_strain = 0;    // elements switched by /DT/<type>/CST over the run
  long long deleted_inverted = 0;            // shells deleted as turned inside out over the run
  long long numerical_deletions_checked = 0;  // those two summed, when the run last looked for an element left
  bool hourglass_warned = false;             // the HourglassShare event has been raised
  bool energy_error_warned = false;          // the EnergyErrorLarge event has been raised
  bool step_drop_warned = false;             // the StepDropped event has been raised
};

}  // namespace crumple
