// The QA decks of ../shared/qa parse, with the counts of the issue and the reference listing's total mass.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "crumple/deck/reader.hpp"
#include "crumple/elements/critical_step.hpp"

namespace {

const std::filesystem::path kQa = CRUMPLE_QA_DIR;

// TOTAL MASS of the first cycle line of the reference engine listing (second-to-last column).
double reference_total_mass(const std::filesystem::path& listing) {
  std::ifstream in(listing);
  std::string line;
  while (std::getline(in, line))
    if (line.find("TOTAL MASS") != std::string::npos) break;
  std::getline(in, line);
  std::istringstream fields(line);
  std::vector<std::string> tokens;
  for (std::string t; fields >> t;) tokens.push_back(t);
  if (tokens.size() < 2) return -1.0;
  return std::stod(tokens[tokens.size() - 2]);
}

struct QaCase {
  const char* folder;
  const char* deck;
  std::size_t nodes;
  std::size_t shells;
};

class QaCheck : public ::testing::TestWithParam<QaCase> {};

TEST_P(QaCheck, CountsAndMassMatchTheReference) {
  const QaCase& c = GetParam();
  const auto starter = kQa / c.folder / (std::string(c.deck) + "_0000.rad");
  ASSERT_TRUE(std::filesystem::exists(starter)) << starter;
  const crumple::Deck deck = crumple::read_deck(starter);
  const crumple::Model& m = deck.model;
  EXPECT_EQ(m.nodes.size(), c.nodes);
  EXPECT_EQ(m.elements[static_cast<int>(crumple::ElementKind::Shell4)].size(), c.shells);
  EXPECT_EQ(m.elements[static_cast<int>(crumple::ElementKind::Shell3)].size(), 0u);
  EXPECT_TRUE(m.run.present);
  const double reference = reference_total_mass(kQa / c.folder / "reference" / (std::string(c.deck) + "_0001.out"));
  ASSERT_GT(reference, 0.0);
  // The listing prints 4 significant digits; 0.5 % is the acceptance tolerance of issue 3.
  EXPECT_NEAR(m.total_mass(), reference, 0.005 * reference) << "reference " << reference;
  EXPECT_GT(crumple::smallest_element_time_step(m).time_step, 0.0);
}

INSTANTIATE_TEST_SUITE_P(SharedQa, QaCheck,
                         ::testing::Values(QaCase{"ball_on_wall", "BOULE1V4", 149, 113},
                                           QaCase{"box_crush", "BOX1BL", 155, 140}),
                         [](const auto& test_info) { return std::string(test_info.param.folder); });

}  // namespace
