#include "app/run.hpp"

#include <fmt/ostream.h>

#include "app/exit_codes.hpp"

namespace crumple::app {

int run_deck(const RunOptions& options, std::ostream& out, std::ostream& err) {
  ReadOptions read;
  read.skip_unknown = options.skip_unknown;
  read.require_engine = true;
  const Deck deck = read_deck(options.deck, read);
  for (const auto& w : deck.report.warnings) fmt::print(err, "warning: {}\n", w.text());
  fmt::print(out, "crumple run: deck {} read ({} nodes)\n", options.deck.string(), deck.model.nodes.size());
  fmt::print(err, "crumple run: the explicit solver is not part of this build yet; nothing was computed\n");
  return kExitRunFailed;
}

}  // namespace crumple::app
