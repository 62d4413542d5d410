#include "../context.hpp"

namespace crumple::deck {

void register_rigid_keywords(KeywordTable& table) { (void)table; }

}  // namespace crumple::deck
