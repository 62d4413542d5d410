#pragma once
// Text inside XML attributes and elements (the XDMF file, the JUnit report).
#include <string>
#include <string_view>

namespace crumple {

// `s` with & < > " ' written as entities. Control characters that XML 1.0 cannot hold at all (below 0x20 except
// tab, newline and carriage return) become '?', so that any message (a console line of a crashed run) stays
// well-formed.
std::string xml_escaped(std::string_view s);

}  // namespace crumple
