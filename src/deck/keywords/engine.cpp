#include "../context.hpp"

namespace crumple::deck {

void register_engine_keywords(KeywordTable& table) { (void)table; }

}  // namespace crumple::deck
