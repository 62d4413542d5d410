// /TH/NODE DRX DRY DRZ (include/crumple/solver/node_rotations.hpp, docs/output-format.md "NODE", eq. TH-1).
#include "crumple/solver/node_rotations.hpp"

#include "crumple/model/history_variables.hpp"

namespace crumple {

void setup_node_rotations(const Model& m, HistoryIntegrals& h) {
  h.rotation_nodes = objects_with_history(m, HistoryObject::Node, kNodeRotationVariables);
  h.rotation.assign(3 * h.rotation_nodes.size(), 0.0);
}

void integrate_node_rotations(const NodalState& n, double dt, HistoryIntegrals& h) {
  for (std::size_t i = 0; i < h.rotation_nodes.size(); ++i) {
    const auto k = static_cast<std::size_t>(h.rotation_nodes[i]);
    h.rotation[3 * i] += n.wx[k] * dt;
    h.rotation[3 * i + 1] += n.wy[k] * dt;
    h.rotation[3 * i + 2] += n.wz[k] * dt;
  }
}

}  // namespace crumple
