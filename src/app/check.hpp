#pragma once
#include <filesystem>
#include <iosfwd>

#include "crumple/deck/reader.hpp"

namespace crumple::app {

// Prints the model summary of `crumple check` for a deck that was read successfully.
void print_check_report(const Deck& deck, std::ostream& out);

}  // namespace crumple::app
