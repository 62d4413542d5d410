#pragma once
// State owned by the spring kernels (docs/theory/spring.md): per spring, its length at rest, its elongation and
// the force it carries.
#include <cstddef>
#include <vector>

#include "crumple/state/element_kind_state.hpp"

namespace crumple {

struct SpringState : ElementKindState {  // no integration points: points and eps_p stay empty
  // Per element (index in the Spring ElementTable).
  std::vector<double> length0;     // length at t = 0 [L]
  std::vector<double> elongation;  // delta = l - l0, positive in tension [L] (eq. SP-1)
  std::vector<double> force;       // axial force, positive in tension: K delta + C d(delta)/dt [F] (eq. SP-2)
  std::vector<double> elastic_force;  // the spring's part of it, without the dashpot [F]
  // Hardening springs (H 1, 2): H 1, the hardening displacement x (SP-6) and 0; H 2, the plastic elongations of the
  // tension and of the compression side (SP-7) [L].
  std::vector<double> plastic_a, plastic_b;
  std::vector<double> step_stiffness;  // the stiffness of its step, which it gives each node in the nodal steps [F/L]

  void resize_elements(std::size_t n) {
    resize_common(n);
    for (auto* v : {&length0, &elongation, &force, &elastic_force, &plastic_a, &plastic_b, &step_stiffness}) v->assign(n, 0.0);
  }
};

}  // namespace crumple
