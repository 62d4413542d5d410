#pragma once
#include "crumple/model/model.hpp"

namespace crumple {

// Lumped nodal mass (docs/theory/mass.md): each element's mass rho*t*A (shells) or rho*V (bricks) shared equally
// by its nodes, plus /ADMAS masses and /RBODY masses at the main node. Fills nodal_mass, element_mass, added_mass.
void compute_mass(Model& model);

// Mass of one element [M].
double element_mass(const Model& model, ElementKind kind, std::size_t element);

}  // namespace crumple
