#pragma once
// What /DAMP keeps from one cycle to the next (docs/theory/damping.md).
#include <vector>

namespace crumple {

struct DampingState {
  std::vector<double> alpha, beta;  // per /DAMP: the coefficients this engine deck runs with [1/T], [T] (D-1)
  // Stiffness damping (a beta > 0), per node and degree of freedom (6 per node, x y z rx ry rz), sized only then:
  std::vector<double> element_force_before;  // the elements' force on the node last cycle [F], [F L] (D-5)
  std::vector<double> stiffness_force;       // this cycle's stiffness damping force (D-5)
  bool stiffness() const { return !element_force_before.empty(); }
};

}  // namespace crumple
