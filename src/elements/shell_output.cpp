// What a shell element's state holds, for output (include/crumple/elements/shell4.hpp, shell_element_output): the
// resultants of the kernels' own rule (shell4_section.hpp) from the stored stresses, nothing updated.
#include "crumple/elements/shell4.hpp"
#include "shell4_section.hpp"

namespace crumple {

ShellElementOutput shell_element_output(const ShellGroupParameters& p, const ShellState& state,
                                        const ElementGroup& group, std::int32_t element) {
  const auto ue = static_cast<std::size_t>(element);
  const auto np = static_cast<std::size_t>(p.points);
  // Ishell 12 keeps one section per Gauss point (eq. Q-2), the other formulations one per element.
  const std::size_t sections = p.fully_integrated ? 4 : 1;
  const std::size_t first = p.first_point + static_cast<std::size_t>(element - group.begin) * sections * np;
  const double t = state.thickness[ue];
  ShellElementOutput out;
  const double share = 1.0 / static_cast<double>(sections);
  for (std::size_t i = 0; i < sections; ++i) {
    const std::size_t at = first + i * np;
    const double* bending = !p.resultant_plasticity ? nullptr
                            : p.fully_integrated    ? &state.gauss_bending[12 * ue + 3 * i]
                                                    : &state.bending_stress[3 * ue];
    const shell_section::Resultants r = shell_section::resultants(p, state, at, bending, t);
    for (int c = 0; c < 3; ++c) out.n[c] += share * r.n[c], out.m[c] += share * r.m[c];
    const double* q = p.fully_integrated ? &state.gauss_shear[8 * ue + 2 * i] : nullptr;
    out.q[0] += share * (q != nullptr ? q[0] : state.qx[ue]);
    out.q[1] += share * (q != nullptr ? q[1] : state.qy[ue]);
    out.plastic_strain_lower += share * state.eps_p[at];
    out.plastic_strain_upper += share * state.eps_p[at + np - 1];
    for (std::size_t k = 0; k < np; ++k) out.strain_rate += share / static_cast<double>(np) * state.eps_rate[at + k];
  }
  return out;
}

std::array<double, 6> shell_stress_in_global_axes(const Vec3* x, int nodes, const double (&local)[3]) {
  shell_section::Frame f;
  bool framed = false;
  if (nodes == 4) {
    const Vec3 quad[4] = {x[0], x[1], x[2], x[3]};
    framed = shell_section::corotational_frame<4>(quad, f);
  } else {
    const Vec3 triangle[3] = {x[0], x[1], x[2]};
    framed = shell_section::corotational_frame<3>(triangle, f);
  }
  if (!framed) return {};
  const double a[3] = {f.e1.x, f.e1.y, f.e1.z}, b[3] = {f.e2.x, f.e2.y, f.e2.z};
  const auto component = [&](int i, int j) {
    return local[0] * a[i] * a[j] + local[1] * b[i] * b[j] + local[2] * (a[i] * b[j] + b[i] * a[j]);
  };
  return {component(0, 0), component(1, 1), component(2, 2), component(0, 1), component(1, 2), component(2, 0)};
}

}  // namespace crumple
