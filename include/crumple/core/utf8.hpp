#pragma once
// Text that reaches XML (NAME.xdmf), JSON (the summary) and HDF5 attributes must be valid UTF-8. Decks are ASCII
// by the format, but titles come from editors in Latin-1 and other code pages (docs/deck-format.md, "Text").
#include <string>
#include <string_view>

namespace crumple {

// `text` with every byte that does not belong to a well-formed UTF-8 sequence replaced by '?': one byte for one,
// so that the deck's columns stay where they were.
std::string valid_utf8(std::string_view text);

}  // namespace crumple
