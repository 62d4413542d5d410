#include "../context.hpp"

namespace crumple::deck {

void register_interface_keywords(KeywordTable& table) { (void)table; }

}  // namespace crumple::deck
