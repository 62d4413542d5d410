#pragma once
// `crumple run --accuracy draft|standard|fine`: the speed–accuracy presets (docs/performance.md, "The
// speed-accuracy trade"). A preset edits the model before the run, and every change is said: each is one line
// of the listing's and the summary's "approximations", so that no knob moves silently.
#include <string>
#include <vector>

#include "crumple/contact/kernels.hpp"
#include "crumple/model/model.hpp"
#include "crumple/model/run_control.hpp"

namespace crumple::app {

enum class AccuracyPreset { Draft, Standard, Fine };

// The preset named `name` ("draft", "standard", "fine"); throws std::invalid_argument naming the choices.
AccuracyPreset accuracy_preset(const std::string& name);
const char* accuracy_preset_name(AccuracyPreset preset);

// What each preset sets (docs/performance.md; the figures that chose them are measured there):
inline constexpr double kFineStepScale = 0.6;       // fine: every /DT scale at most this
inline constexpr int kFineShellPoints = 5;          // fine: shells with 1 to 4 points get 5 (N = 0 stays resultant)
inline constexpr int kFineContactEntryWindow = contact::kAnticipatedEntrySteps;  // fine: TYPE7 entry anticipated
inline constexpr double kDraftMassScaledShare = 0.01;  // draft: /DT/NODA/CST's target from the nodal step (T-2,
                                                       // T-2a) the elements' 1st percentile starts with at /DT scale,
inline constexpr double kDraftStepShare = 0.63;        // this share of it (0.6 of the elements' step on QEPH, nu 0.3),
inline constexpr double kDraftNodalScale = 0.67;       // at this nodal scale

inline constexpr double kPresetEnergyErrorWarning = 5.0;  // draft and fine: the run warns beyond this energy
                                                          // error [%], naming the knobs the preset moved

// Applies `preset` to the model's properties and to the run controls of every engine deck (`runs`: the first
// engine deck's, then the continued runs'). Returns one line per change, empty for `standard`.
std::vector<std::string> apply_accuracy_preset(AccuracyPreset preset, Model& model, std::vector<RunControl*> runs);

// The approximation the build itself makes (core/precision.hpp): one line for the mixed build, none for double.
std::vector<std::string> precision_approximations();

}  // namespace crumple::app
