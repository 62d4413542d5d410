#pragma once
// Deck cards of the contact verification scenes: /INTER/TYPE7, /SURF/PART, second shell parts and properties.
#include <string>
#include <vector>

#include "verification_support.hpp"

namespace crumple::verification {

struct Type7Options {
  double gapmin = 0.0, stfac = 0.0, fric = 0.0, viss = 0.0, dtmin = 0.0;
  int istf = 0, igap = 0, inacti = 0, iform = 0;
};

// /INTER/TYPE7/id: secondary node group, main surface, the fields of Type7Options, everything else default.
inline std::string type7_card(long long id, long long group, long long surface, const Type7Options& o) {
  const std::string blank10(10, ' ');
  std::string s = "/INTER/TYPE7/" + std::to_string(id) + "\ncontact\n";
  s += I(group) + I(surface) + I(o.istf) + I(0) + I(o.igap) + blank10 + I(0) + I(0) + I(0) + I(0) + "\n";
  s += R(0.0) + R(0.0) + R(0.0) + "\n";
  s += R(0.0) + R(0.0) + R(0.0) + R(o.dtmin) + I(0) + I(0) + "\n";
  s += R(o.stfac) + R(o.fric) + R(o.gapmin) + R(0.0) + R(0.0) + "\n";
  s += "       000" + std::string(20, ' ') + I(o.inacti) + R(o.viss) + R(0.0) + R(0.0) + "\n";
  s += I(0) + I(0) + R(0.0) + I(o.iform) + I(0) + I(0) + R(0.0) + I(0) + "\n";
  return s;
}

inline std::string surface_of_part(long long id, long long part) {
  return "/SURF/PART/" + std::to_string(id) + "\nsurface\n" + I(part) + "\n";
}

// /PART/id with property and material 1.
inline std::string part_card(long long id) { return "/PART/" + std::to_string(id) + "\npart\n" + I(1) + I(1) + "\n"; }

}  // namespace crumple::verification
