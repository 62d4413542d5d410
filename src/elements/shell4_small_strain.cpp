// Small-strain switch of Ismstr 2 shells (docs/theory/shell4.md, eq. S-16).
#include "crumple/elements/shell4.hpp"
#include "shell4_section.hpp"

namespace crumple {
namespace {


// The element's current shape in its current co-rotational frame becomes its reference shape (the local
// coordinates the kernels use for the gradient operator, the area and the critical step).
template <int NN>
bool freeze_shape(const ElementTable& table, const ShellGroupParameters& p, const NodalState& nodes, ShellState& state,
                  std::size_t element) {
  const std::int32_t* n = table.nodes_of(element);
  Vec3 x[NN];
  for (int a = 0; a < NN; ++a) {
    const auto k = static_cast<std::size_t>(n[a]);
    x[a] = {nodes.x[k], nodes.y[k], nodes.z[k]};
  }
  shell_section::Frame frame;
  if (!shell_section::corotational_frame<NN>(x, frame)) return false;
  double lx[NN], ly[NN];
  for (int a = 0; a < NN; ++a) {
    const Vec3 r = x[a] - frame.centre;
    lx[a] = dot(r, frame.e1);
    ly[a] = dot(r, frame.e2);
  }
  const double area = shell_section::local_area<NN>(lx, ly);
  if (!(area > 0.0)) return false;
  double* shape = &state.initial_shape[2 * NN * element];
  for (int a = 0; a < NN; ++a) shape[a] = lx[a], shape[NN + a] = ly[a];
  // The step of the frozen shape is the element's step from now on (the step "becomes constant", S-16).
  state.initial_length[element] = p.fully_integrated ? shell_section::characteristic_length<NN>(lx, ly, area, true)
                                                     : shell_section::one_point_length<NN>(p, lx, ly, area);
  state.small_strain[element] = 1;
  return true;
}

}  // namespace

bool shell_switch_to_small_strain(const ElementTable& table, const ShellGroupParameters& p, const NodalState& nodes,
                                  ShellState& state, std::int32_t element) {
  const auto ue = static_cast<std::size_t>(element);
  if (!p.small_strain_switchable || element_condition(state.deleted[ue]) != kElementActive || state.small_strain[ue] != 0)
    return false;
  if (table.kind == ElementKind::Shell3) return freeze_shape<3>(table, p, nodes, state, ue);
  return freeze_shape<4>(table, p, nodes, state, ue);
}

}  // namespace crumple
