#pragma once
// Checks of the shell formulation flags shared by /PROP/SHELL (= /PROP/TYPE1) and /DEF_SHELL
// (docs/theory/shell4.md, "Formulation flags"): a value the reference defines and Crumple does not run is refused
// at its field, with the file, line, keyword and columns.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include "../context.hpp"

namespace crumple::deck::shell_flags {

inline bool one_of(std::int64_t value, std::initializer_list<std::int64_t> allowed) {
  for (std::int64_t a : allowed)
    if (value == a) return true;
  return false;
}

inline void check_ishell(const Line& line, int column, std::int64_t ishell) {
  if (ishell == 4)
    line.fail(column, 10, "Ishell", "0, 1, 2, 3, 12 or 24: Ishell 4 (orthogonalisation for warped elements) is not "
                                    "supported by Crumple");
  if (!one_of(ishell, {0, 1, 2, 3, 12, 24}))
    line.fail(column, 10, "Ishell", "a 4-node shell formulation: 0 (default), 1, 2, 3, 12 or 24");
}
inline void check_ismstr(const Line& line, int column, std::int64_t ismstr) {
  if (!one_of(ismstr, {0, 1, 2, 3, 4}))
    line.fail(column, 10, "Ismstr", "0 (default), 1, 2, 3 or 4 (automatic choice -1, -2 and the total-strain "
                                    "formulations 10 to 12 are not supported by Crumple)");
}
inline void check_idrill(const Line& line, int column, std::int64_t idrill) {
  if (!one_of(idrill, {0, 2}))
    line.fail(column, 10, "Idrill", "0 or 2 (no drilling stiffness; drilling stiffness, 1, is not supported by Crumple)");
}
inline void check_ithick(const Line& line, int column, std::int64_t ithick) {
  if (!one_of(ithick, {0, 1, 2}))
    line.fail(column, 10, "Ithick", "0 (default), 1 (thickness change) or 2 (constant thickness)");
}
// Iplas: 1 iterative projection, 2 radial return; which of them Crumple runs depends on N and on the material
// (resolve_definitions.cpp).
inline void check_iplas(const Line& line, int column, std::int64_t iplas) {
  if (!one_of(iplas, {0, 1, 2})) line.fail(column, 10, "Iplas", "0 (default), 1 or 2");
}
// A field of a newer layout that Crumple does not run: blank or 0.
inline void require_blank_or_zero(const Line& line, int column, std::string_view name, std::string_view feature) {
  if (line.integer(column, 10, name) != 0)
    line.fail(column, 10, name, "blank or 0 (" + std::string(feature) + " is not supported by Crumple)");
}

// Istrain: strain output only (1 or 0: strains for post-processing, 2: none); Crumple writes none.
inline void check_istrain(const Line& line, int column, std::int64_t istrain) {
  if (!one_of(istrain, {0, 1, 2})) line.fail(column, 10, "Istrain", "0 (default), 1 or 2");
}

}  // namespace crumple::deck::shell_flags
