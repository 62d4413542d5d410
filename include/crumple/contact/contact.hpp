#pragma once
// TYPE7 contact module (docs/theory/contact.md, ../shared/spec/type7.md). The time loop calls contact_forces once
// per cycle, and only when the model has an interface: a deck without contact runs none of this code.
#include <array>
#include <string>
#include <vector>

#include "crumple/state/contact_state.hpp"
#include "crumple/core/exact_sum.hpp"
#include "crumple/model/model.hpp"
#include "crumple/state/nodal_state.hpp"

namespace crumple::contact {

// Builds the interfaces: secondary nodes, main segments, gaps (eq. C-2), stiffness (eq. C-3); finds the initial
// penetrations and applies Inacti (3 moves nodes of `nodes`). Start-up remarks go to `notes`.
ContactState setup_contact(const Model& model, NodalState& nodes, std::vector<std::string>& notes);

// Bucket sort of one interface (eq. C-12): the candidate pairs (secondary node, main segment) whose distance can
// fall within the gap before the accumulated motion exceeds the margin. O(nodes + segments).
void sort_candidates(ContactInterface& interface, const NodalState& nodes);

// Each node's share of the shell and boundary brick-face area around it (for the friction laws' pressure) [L^2].
std::vector<double> node_surface_areas(const Model& model);

struct ContactStep {
  double dt = 1e300;        // smallest interface step of the cycle, scaled [T]
  int interface = -1;       // its interface (index into Model::type7_interfaces)
  std::int32_t node = -1;   // its secondary node (dense index)
};

// One cycle at x^n with v^(n-1/2): forces added to the nodal forces (and kept in state.fx..), energies and steps
// per interface. `dt_previous` is dt^(n-1/2), `dt_estimate` the elements' step for the coming cycle (search
// margin); `scale` the /DT scale of the steps; /DT/INTER/CST mass goes into nodes.mass and `added_mass`.
ContactStep contact_forces(const Model& model, ContactState& state, NodalState& nodes, double time,
                           double dt_previous, double dt_estimate, double scale, double& added_mass);

// Idel 1, 2 (type7.md §2): segments whose element has been deleted leave the main surface, and secondary nodes
// none of whose elements is left leave the secondary set. `deleted` holds the deletion flags of each element
// kind (nullptr for a kind without them).
void remove_deleted_elements(ContactState& state,
                             const std::array<const std::vector<std::uint8_t>*, kElementKinds>& deleted);

// Power of the last cycle's contact forces over the step, with v_old = v^(n-1/2) and the nodes' v^(n+1/2):
// F . (v_old + v_new) / 2 per force, into power[f] for interface f, for the forces on the nodes `me` owns
// (node_owner; one domain: all of them) (eq. C-10).
void add_contact_work(const ContactState& state, const NodalState& nodes, const std::vector<double>* v_old,
                      const std::vector<std::int32_t>& node_owner, std::int32_t me, ExactSum* power);
// The power of every domain's forces (summed over the domains) times dt_average, accumulated as each interface's
// absorbed energy; returns the sum over the interfaces.
double absorb_contact_work(ContactState& state, const ExactSum* power, double dt_average);

}  // namespace crumple::contact
