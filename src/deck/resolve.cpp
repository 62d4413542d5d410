#include "resolve.hpp"

#include "crumple/model/mass.hpp"

namespace crumple::deck {

void Resolver::throw_if_errors() {
  if (!errors.empty()) throw DeckErrors(std::move(errors));
}

void resolve_model(DeckContext& context) {
  Resolver r(context);
  resolve_definitions(r);
  r.throw_if_errors();  // later stages need valid nodes, parts, materials and properties
  resolve_elements(r);
  r.throw_if_errors();
  resolve_sets(r);
  resolve_load_references(r);
  resolve_output_references(r);
  r.throw_if_errors();
  compute_mass(context.model);
}

}  // namespace crumple::deck
