#pragma once
// The precision Crumple was built with (docs/theory/precision.md). `double` (the default) computes and stores
// everything in double precision. `mixed` (cmake -DCRUMPLE_PRECISION=mixed, the preset `mixed`) stores the
// elements' integration-point state in single precision: the stresses, the equivalent plastic strains, the
// filtered strain rates and Johnson-Cook's kept hardening term. Coordinates, velocities, forces, the per-element
// histories, energies and every operation stay in double, so that positions keep their accuracy (eq. PR-1): each
// point value is rounded to single once a cycle, when it is stored (eq. PR-2).
namespace crumple {

#if defined(CRUMPLE_MIXED_PRECISION)
using point_real = float;  // an integration point's stored state
#else
using point_real = double;
#endif
inline constexpr bool kMixedPrecision = sizeof(point_real) < sizeof(double);
inline constexpr const char* kPrecision = kMixedPrecision ? "mixed" : "double";

// A point value rounded to what is stored (eq. PR-2): explicit, so that the narrowing shows in the kernels.
constexpr point_real stored(double value) { return static_cast<point_real>(value); }

}  // namespace crumple
