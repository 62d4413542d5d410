#include "app/accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "crumple/core/precision.hpp"
#include "crumple/elements/critical_step.hpp"

namespace crumple::app {

namespace {

constexpr double kDefaultStepScale = 0.9;  // /DT's scale when the deck gives none

// Where a change applies: the engine deck it is in when the run has several.
std::string in_deck(std::size_t k, std::size_t decks) {
  return decks > 1 ? fmt::format(" (engine deck {})", k + 1) : std::string();
}

// fine: every step scale the deck sets, and the run's own, at most kFineStepScale.
void cap_step_scales(RunControl& run, const std::string& where, std::vector<std::string>& changes) {
  const double run_scale = run.dt.scale > 0.0 ? run.dt.scale : kDefaultStepScale;
  if (run_scale > kFineStepScale) {
    changes.push_back(fmt::format("/DT scale {:g} -> {:g}{}", run_scale, kFineStepScale, where));
    run.dt.scale = kFineStepScale;
  }
  for (const ElementKindDescription& kind : kElementKindTable) {
    TimeStepControl* control = &(run.*kind.step_control);
    if (control->given && control->scale > kFineStepScale) {
      changes.push_back(fmt::format("/DT/{} scale {:g} -> {:g}{}", kind.step_card, control->scale, kFineStepScale, where));
      control->scale = kFineStepScale;
    }
  }
}

// fine: no added mass, neither the nodal mass scaling nor the contact's, nor the selective one.
void remove_mass_scaling(RunControl& run, const std::string& where, std::vector<std::string>& changes) {
  for (auto [card, control] : {std::pair{"/DT/NODA/CST", &run.dt_nodal_cst}, {"/DT/INTER/CST", &run.dt_inter_cst}}) {
    if (!control->given) continue;
    changes.push_back(fmt::format("{} {:g} {:g} removed: no added mass{}", card, control->scale, control->minimum, where));
    *control = TimeStepControl{};
  }
  if (run.dt_ams.given) {
    changes.push_back(fmt::format("/DT/AMS {:g} {:g} removed: no selective mass scaling{}", run.dt_ams.scale,
                                  run.dt_ams.minimum, where));
    run.dt_ams = SelectiveMassControl{};
  }
}

// fine: TYPE7 nodes closing in count K0 in the step kFineContactEntryWindow steps before they enter the gap.
void anticipate_contact_entry(const Model& model, RunControl& run, const std::string& where,
                              std::vector<std::string>& changes) {
  if (model.type7_interfaces.empty() || run.contact_entry_window >= kFineContactEntryWindow) return;
  changes.push_back(fmt::format("TYPE7 contact steps count K0 from {} steps before a node enters the gap (standard: "
                                "from the cycle it is in the gap){}",
                                kFineContactEntryWindow, where));
  run.contact_entry_window = kFineContactEntryWindow;
}

// The unscaled nodal step of /DT/NODA/CST (T-2, T-2a) below which `share` of the elements lie, each alone on its
// initial geometry.
double nodal_step_quantile(const Model& m, double share) {
  std::vector<double> steps;
  for (const ElementGroup& g : m.element_groups)
    for (std::int32_t e = g.begin; e < g.end; ++e)
      steps.push_back(initial_element_nodal_step(m, g.kind, static_cast<std::size_t>(e)));
  if (steps.empty()) return 0.0;
  const auto at = steps.begin() + static_cast<std::ptrdiff_t>(share * static_cast<double>(steps.size() - 1));
  std::nth_element(steps.begin(), at, steps.end());
  return *at;
}

// draft: nodal mass scaling (T-2, T-3) at the nodal scale kDraftNodalScale, to kDraftStepShare of the nodal step
// (at the deck's /DT scale) its kDraftMassScaledShare quantile of elements starts with: the folds stop cutting the
// step, the nodes are held with a margin to their stability (the nodal estimate is not a bound), and the rails and
// tubes of docs/performance.md ("The presets") stay within 5 % of the reference; never below the deck's own step
// (T-3c). A deck that already scales to a larger step, or selectively (its /DT/AMS holds the elements, time-step.md
// SM-0), keeps its own.
void scale_nodal_mass(const Model& m, RunControl& run, const std::string& where, std::vector<std::string>& changes) {
  const double quantile = nodal_step_quantile(m, kDraftMassScaledShare);
  if (!(quantile > 0.0)) return;  // no element
  const double deck_scale = run.dt.scale > 0.0 ? run.dt.scale : kDefaultStepScale;
  const double target = kDraftStepShare * deck_scale * quantile;
  if (run.dt_nodal_cst.given && run.dt_nodal_cst.minimum >= target) return;  // the deck scales further already
  if (run.dt_ams.given) return;
  changes.push_back(fmt::format("/DT/NODA/CST {:g} {:.4g}: the step is the nodes' at scale {:g} instead of the "
                                "elements' at /DT scale {:g}, and mass is added where it would fall below {:g} times "
                                "the nodal step the {:g} % smallest elements start with at that scale ({:.4g}){}{}",
                                kDraftNodalScale, target, kDraftNodalScale, deck_scale, kDraftStepShare,
                                100.0 * kDraftMassScaledShare, deck_scale * quantile,
                                run.dt_inter_cst.given ? "" : "; the deck's own step where it is larger", where));
  run.dt_nodal_cst.scale = kDraftNodalScale, run.dt_nodal_cst.minimum = target, run.dt_nodal_cst.given = true;
  // eq. T-3c; with /DT/INTER/CST the contact pass sizes the contacts' masses and gives no step as written
  run.nodal_step_at_least_as_written = !run.dt_inter_cst.given;
}

// fine: the shells' points through the thickness, at least `points`. N = 0 (resultant plasticity) and N = 1 (a
// membrane) keep theirs: more points would change what the section is, not how well it is integrated. draft keeps
// the deck's: 3 points instead of 5 cost 4 to 10 % of the crush force on the tubes (docs/performance.md).
void raise_shell_points(Model& m, int points, std::vector<std::string>& changes) {
  for (std::size_t p = 0; p < m.properties.size(); ++p) {
    const Property& property = m.properties[p];
    int& n = m.formulations[p].n_points;
    if (property.kind != PropertyKind::Shell || n < 2 || n >= points) continue;
    changes.push_back(fmt::format("/PROP/SHELL/{} N {} -> {} points through the thickness", property.user_id, n, points));
    n = points;
  }
}

}  // namespace

AccuracyPreset accuracy_preset(const std::string& name) {
  if (name == "draft") return AccuracyPreset::Draft;
  if (name == "standard") return AccuracyPreset::Standard;
  if (name == "fine") return AccuracyPreset::Fine;
  throw std::invalid_argument(fmt::format("--accuracy {}: expected draft, standard or fine", name));
}

const char* accuracy_preset_name(AccuracyPreset preset) {
  switch (preset) {
    case AccuracyPreset::Draft: return "draft";
    case AccuracyPreset::Standard: return "standard";
    case AccuracyPreset::Fine: return "fine";
  }
  return "standard";
}

std::vector<std::string> apply_accuracy_preset(AccuracyPreset preset, Model& model, std::vector<RunControl*> runs) {
  std::vector<std::string> changes;
  if (preset == AccuracyPreset::Standard) return changes;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string where = in_deck(k, runs.size());
    runs[k]->energy_error_warning = kPresetEnergyErrorWarning;
    if (preset == AccuracyPreset::Fine) {
      cap_step_scales(*runs[k], where, changes);
      remove_mass_scaling(*runs[k], where, changes);
      anticipate_contact_entry(model, *runs[k], where, changes);
    } else {
      scale_nodal_mass(model, *runs[k], where, changes);
    }
  }
  if (preset == AccuracyPreset::Fine) raise_shell_points(model, kFineShellPoints, changes);
  for (std::string& c : changes) c = fmt::format("--accuracy {}: {}", accuracy_preset_name(preset), c);
  return changes;
}

std::vector<std::string> precision_approximations() {
  if (!kMixedPrecision) return {};
  return {fmt::format("precision {}: the integration points' stresses, plastic strains, strain rates and kept "
                      "hardening terms are stored in single precision (docs/theory/precision.md); coordinates, "
                      "velocities, forces and energies in double",
                      kPrecision)};
}

}  // namespace crumple::app
