#pragma once
#include <filesystem>
#include <iosfwd>

#include "crumple/deck/reader.hpp"
#include "crumple/parallel/partition.hpp"

namespace crumple::app {

// Prints the model summary of `crumple check` for a deck that was read successfully.
void print_check_report(const Deck& deck, std::ostream& out);

// The decomposition's quality for `crumple check --ranks N` (docs/parallel.md, "Decomposition").
void print_partition_report(const Partition& partition, std::ostream& out);

}  // namespace crumple::app
