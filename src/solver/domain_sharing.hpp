#pragma once
// Internal to the solver: what the domains of a run of several exchange at the named points of a cycle
// (docs/parallel.md, "Exchange", "Assembly", "Contact"): the elements' results between the two halves of step 1, the
// contact pass's view of the other domains, and the whole state before an output or a restart snapshot.
#include <cstdint>
#include <vector>

#include "crumple/contact/contact.hpp"
#include "crumple/model/model.hpp"
#include "crumple/parallel/exchange.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple::solver {

// Between the two halves of step 1 (cycle.hpp: run_element_kernels, combine_group_results) in a run of several
// domains (docs/parallel.md, "Assembly"): what each domain computed of its own elements reaches every domain, and
// every node's sum is assembled in the model's order.
void share_element_results(const Model& model, SolverState& state, Exchange& exchange);
// Before an output of a run of several domains: every element's whole state from the domain that computes it, so
// that the domain that writes (0) writes what one domain writes.
enum class ElementStateNeed : std::uint8_t { None, Energies, All };
void share_element_state(SolverState& state, Exchange& exchange, ElementStateNeed need = ElementStateNeed::All);
// Before an output of a run of several domains: every node's state (and the output-only integrals of the nodes)
// from the domain that owns it; between outputs a domain keeps only its local nodes right (parallel/domain.hpp).
// `restart`: before a restart snapshot, with the contact state of the pairs each domain computes.
void share_node_state(const Model& model, SolverState& state, Exchange& exchange, bool restart);
// What the model's time histories read of the elements: their whole state (shells, bricks, sections), their
// energies (parts, subsets) or nothing.
ElementStateNeed history_needs(const Model& model);
// Whether a history row reads nodal state (/TH/NODE, PART, SUBS, SECTIO, ACCEL); the others (rigid walls and
// bodies, interfaces, the energies) read what every domain holds alike.
bool histories_read_nodes(const Model& model);

// The contact pass's view of the other domains (contact/contact.hpp, ContactDomains), over the run's exchange.
class ContactExchange final : public contact::ContactDomains {
 public:
  ContactExchange(SolverState& s, Exchange& exchange) : s_(s), exchange_(exchange) {
    scope_.node_owner = &s.domain.node_owner, scope_.me = s.domain.index;
    scope_.local = &s.domain.local, scope_.multi_local = &s.domain.multi_local;
  }
  const contact::ContactScope& scope() const override { return scope_; }
  double max(double value) override {
    values_.assign(1, value);
    exchange_.max(values_);
    return values_[0];
  }
  void sum(std::vector<ExactSum>& sums) override { exchange_.sum(sums); }
  void min_with_index(double& value, std::int32_t& index) override {
    values_.assign(1, value), indices_.assign(1, index);
    exchange_.min_with_index(values_, indices_);
    value = values_[0], index = indices_[0];
  }
  void union_of(std::vector<std::int32_t>& flags) override { exchange_.max(flags); }
  void gather_positions(const ContactInterface& in) override {
    const std::vector<std::int32_t>& owner = interface_owner(in);
    NodalState& n = s_.nodes;
    for (auto* v : {&n.x, &n.y, &n.z}) exchange_.share(*v, 1, owner);
  }
  void share_ghosts(const ContactInterface& in, bool changed) override {
    if (changed) exchange_.renew(in.ghost_owner);
    NodalState& n = s_.nodes;
    for (auto* v : {&n.x, &n.y, &n.z, &n.vx, &n.vy, &n.vz}) exchange_.share(*v, 1, in.ghost_owner);
  }
  void gather(const std::vector<double>& mine, std::vector<double>& all) override { exchange_.gather(mine, all); }

 private:
  // Per node, its owner when it is one of the interface's nodes, else -1 (kept: the exchange's layouts use it).
  const std::vector<std::int32_t>& interface_owner(const ContactInterface& in) {
    const auto f = static_cast<std::size_t>(&in - s_.contact.interfaces.data());
    std::vector<std::vector<std::int32_t>>& owners = s_.domain_scratch.group_share.interface_node_owner;
    if (owners.size() <= f) owners.resize(s_.contact.interfaces.size());
    std::vector<std::int32_t>& owner = owners[f];
    if (owner.empty()) {
      owner.assign(s_.nodes.size(), -1);
      for (std::int32_t k : in.secondary_nodes) owner[static_cast<std::size_t>(k)] = s_.domain.node_owner[static_cast<std::size_t>(k)];
      for (std::int32_t k : in.main_nodes) owner[static_cast<std::size_t>(k)] = s_.domain.node_owner[static_cast<std::size_t>(k)];
    }
    return owner;
  }

  SolverState& s_;
  Exchange& exchange_;
  contact::ContactScope scope_;
  std::vector<double> values_;
  std::vector<std::int32_t> indices_;
};

}  // namespace crumple::solver
