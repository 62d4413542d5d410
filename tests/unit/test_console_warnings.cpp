// The deck's warnings on the console (app/console.hpp, print_warnings): each once, the same message on several cards
// of one keyword named on one line with their count, and files under the deck's folder named relative to it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/console.hpp"

namespace test_console_warnings {

using namespace crumple;

DeckWarning warning(const std::string& file, int line, const std::string& keyword, const std::string& message) {
  return DeckWarning{SourceLocation{file, line}, keyword, message};
}

TEST(ConsoleWarnings, EachMessageOnceWithItsCardsAndRelativePaths) {
  const std::string deck = "../decks/beam/BEAM_0000.rad";
  const std::vector<DeckWarning> warnings{
      warning(deck, 45, "/IOFLAG", "output-only card: the printout level"),
      warning(deck, 117, "/PROP/SHELL/1", "Istrain 1 (strain output) has no effect"),
      warning(deck, 126, "/PROP/SHELL/2", "Istrain 1 (strain output) has no effect"),
      warning(deck, 135, "/PROP/SHELL/3", "Istrain 1 (strain output) has no effect"),
      warning("../decks/beam/BEAM_0001.rad", 11, "/PRINT/-50/55", "field Nline: output-only"),
      warning("/elsewhere/mesh.inc", 3, "/PROP/SHELL/4", "Istrain 1 (strain output) has no effect"),
      warning(deck, 140, "/MAT/LAW2/1", "Istrain 1 (strain output) has no effect"),
  };
  std::ostringstream out;
  app::print_warnings(warnings, deck, out);
  EXPECT_EQ(out.str(),
            "warning: BEAM_0000.rad:45: /IOFLAG: output-only card: the printout level\n"
            "warning: BEAM_0000.rad:117: /PROP/SHELL/1: Istrain 1 (strain output) has no effect (4 cards; also "
            "/PROP/SHELL/2 at line 126, /PROP/SHELL/3 at line 135, /PROP/SHELL/4 at line 3)\n"
            "warning: BEAM_0001.rad:11: /PRINT/-50/55: field Nline: output-only\n"
            "warning: BEAM_0000.rad:140: /MAT/LAW2/1: Istrain 1 (strain output) has no effect\n");
}

TEST(ConsoleWarnings, ManyCardsAreCountedNotListed) {
  std::vector<DeckWarning> warnings;
  for (int k = 1; k <= 9; ++k) warnings.push_back(warning("D_0000.rad", 10 * k, "/PART/" + std::to_string(k), "same"));
  std::ostringstream out;
  app::print_warnings(warnings, "D_0000.rad", out);
  EXPECT_EQ(out.str(), "warning: D_0000.rad:10: /PART/1: same (9 cards; also /PART/2 at line 20, /PART/3 at line 30, "
                       "/PART/4 at line 40, /PART/5 at line 50 and 4 more)\n");
}

}  // namespace test_console_warnings
