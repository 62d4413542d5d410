#pragma once
#include <array>
#include <cstdint>

#include "crumple/model/model.hpp"

namespace crumple {

// Lumped nodal mass (docs/theory/mass.md): each element's mass rho*t*A (shells) or rho*V (bricks) shared by its
// nodes (corner_mass_fractions), plus /ADMAS masses and /RBODY masses at the main node. Fills nodal_mass, element_mass, added_mass.
void compute_mass(Model& model);

// The share of an element's mass (and, for shells, of its rotational inertia) each of its nodes takes, in node
// order: equal for quadrilaterals and bricks, by the corner angles for 3-node shells (docs/theory/shell4.md,
// eq. S-9c). `nodes`: the element's node indices.
std::array<double, 8> corner_mass_fractions(const Model& model, ElementKind kind, const std::int32_t* nodes);

// The volume a one-point brick (Isolid 1, 2, 24) integrates over its exact volume: 8 det J(0) / V for a brick that
// repeats nodes (3/4 for a tetrahedron or a pyramid, 1 for a prism), as the reference integrates them; 1 for every
// other brick (docs/theory/brick8.md, eq. B-2b). Its mass, forces and length take the factor.
double one_point_volume_scale(const Model& model, std::size_t brick);

// A shell's thickness [L]: its own (/SHELL, /SH3N Thick), else its property's (/PART Thick is a virtual thickness
// for contact gaps, not the shell's: measured on the reference solver's part masses).
double shell_thickness(const Model& model, ElementKind kind, std::size_t shell);

// What an element's nodes span, by its kind's measure (ElementKindDescription::measure): a shell's mid-surface
// area [L^2], a brick's exact volume [L^3]. `n`: its node indices.
double element_measure(const Nodes& nodes, ElementKind kind, const std::int32_t* n);

// Mass of one element [M]: rho t A (shells), rho V (bricks, with the one-point volume scale).
double element_mass(const Model& model, ElementKind kind, std::size_t element);

}  // namespace crumple
