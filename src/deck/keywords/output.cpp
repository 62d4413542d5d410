#include "../context.hpp"

namespace crumple::deck {

void register_output_keywords(KeywordTable& table) { (void)table; }

}  // namespace crumple::deck
