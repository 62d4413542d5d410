#pragma once
// TYPE7 contact module (docs/theory/contact.md, ../shared/spec/type7.md). The time loop calls contact_forces once
// per cycle, and only when the model has an interface: a deck without contact runs none of this code.
#include <array>
#include <cstdint>
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
  // Under /DT/NODA/CST with RunControl::nodal_step_at_least_as_written: the step the interfaces would bound
  // without the nodal mass holding them, the deck as written's (C-11, time-step.md T-3c), its interface and node.
  double dt_as_written = 1e300;
  int interface_as_written = -1;
  std::int32_t node_as_written = -1;
};

// Which nodes a domain of a run of several owns and advances (parallel/domain.hpp), as the contact pass needs it:
// it computes the pairs whose secondary node it owns and applies forces to its local nodes. A run of one domain
// leaves every pointer null: every pair, every node.
struct ContactScope {
  const std::vector<std::int32_t>* node_owner = nullptr;
  std::int32_t me = 0;
  const std::vector<std::uint8_t>* local = nullptr;        // per node: 1 when this domain advances it
  const std::vector<std::uint8_t>* multi_local = nullptr;  // per node: 1 when several domains advance it
  bool owns(std::size_t k) const { return node_owner == nullptr || (*node_owner)[k] == me; }
  bool is_local(std::size_t k) const { return local == nullptr || (*local)[k] != 0; }
  bool only_here(std::size_t k) const { return is_local(k) && (multi_local == nullptr || (*multi_local)[k] == 0); }
};

// What the contact pass needs of the other domains, at its named points (docs/parallel.md, "Contact"); the solver
// implements it over its exchange. A run of one domain passes none.
class ContactDomains {
 public:
  virtual ~ContactDomains() = default;
  virtual const ContactScope& scope() const = 0;
  virtual double max(double value) = 0;                                    // over the domains
  virtual void sum(std::vector<ExactSum>& sums) = 0;                       // slot-wise, exact
  virtual void min_with_index(double& value, std::int32_t& index) = 0;     // the smallest, then the first index
  virtual void union_of(std::vector<std::int32_t>& flags) = 0;             // slot-wise maximum
  // Before a sort: every node of the interface at its owner's position.
  virtual void gather_positions(const ContactInterface& interface) = 0;
  // Every cycle: the positions and velocities of the nodes whose ghost_owner is set, from their owners. `changed`
  // after a sort, when ghost_owner has changed.
  virtual void share_ghosts(const ContactInterface& interface, bool changed) = 0;
  // Every domain's `mine` (whole records), concatenated in domain order into `all`.
  virtual void gather(const std::vector<double>& mine, std::vector<double>& all) = 0;
};

// One cycle at x^n with v^(n-1/2): forces added to the nodal forces (and kept in state.fx..), energies and steps
// per interface. `dt_previous` is dt^(n-1/2), `dt_estimate` the elements' step for the coming cycle (search
// margin); `scale` the /DT scale of the steps; /DT/INTER/CST mass goes into nodes.mass and `added_mass`. With
// `domains`, this domain's share of the pass, and every result the same as one domain's, bit for bit.
ContactStep contact_forces(const Model& model, ContactState& state, NodalState& nodes, double time,
                           double dt_previous, double dt_estimate, double scale, double& added_mass,
                           ContactDomains* domains = nullptr);

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
