#include "../context.hpp"

namespace crumple::deck {

void register_load_keywords(KeywordTable& table) { (void)table; }

}  // namespace crumple::deck
