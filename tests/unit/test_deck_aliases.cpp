// Spellings real Radioss decks use that Crumple must read as Radioss does: a trailing slash on the keyword line,
// law numbers with a leading zero, /PROC in the engine deck, /SURF/PART/ALL, output requests Crumple does not write.
#include <gtest/gtest.h>

#include <algorithm>

#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_deck_aliases {

using namespace crumple;
using test::I;
using test::R;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Deck read_files(const std::string& starter, const std::string& engine) {
  test::TempDir dir;
  dir.write("TEST_0001.rad", engine);
  return read_deck(dir.write("TEST_0000.rad", starter));
}

bool noted(const Deck& d, const std::string& keyword, SkipKind kind) {
  return std::any_of(d.report.skipped_options.begin(), d.report.skipped_options.end(),
                     [&](const SkippedOption& o) { return o.keyword == keyword && o.kind == kind; });
}

}  // namespace

// "/BEGIN/" and "/RUN/name/1/": the trailing slash ends the keyword line.
TEST(DeckAliases, TrailingSlashOnTheKeywordLine) {
  std::string begin = test::begin_card();
  begin.replace(0, 6, "/BEGIN/");
  const Deck d = read_files(begin + test::plate_cards() + "/END\n", "/RUN/TEST/1/\n2e-3\n");
  EXPECT_EQ(d.model.run_name, "TEST");
  EXPECT_EQ(d.model.run.run_name, "TEST");
  EXPECT_EQ(d.model.run.run_number, 1);
  EXPECT_DOUBLE_EQ(d.model.run.end_time, 2e-3);
}

// /MAT/LAW01 is /MAT/LAW1 (QA deck contact_idel), /MAT/LAW02 is /MAT/LAW2, /MAT/LAW036 is /MAT/LAW36.
TEST(DeckAliases, LawNumbersWithLeadingZeros) {
  std::string plate = test::plate_cards();
  plate.replace(plate.find("/MAT/ELAST/1"), 12, "/MAT/LAW01/1");
  const Deck d = read_files(test::begin_card() + plate + "/END\n", test::engine_cards());
  ASSERT_EQ(d.model.materials.size(), 1u);
  EXPECT_EQ(d.model.materials[0].law, MaterialLaw::Elastic);
  EXPECT_DOUBLE_EQ(d.model.materials[0].young, 2.1e11);
  const std::string jc = "/MAT/LAW02/2\njc\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n" + R(2e8) + R(4e8) +
                         R(0.5) + "\n";
  const Deck d2 = read_files(test::begin_card() + test::plate_cards() + jc + "/END\n", test::engine_cards());
  ASSERT_EQ(d2.model.materials.size(), 2u);
  EXPECT_EQ(d2.model.materials[1].law, MaterialLaw::JohnsonCook);
  EXPECT_DOUBLE_EQ(d2.model.materials[1].johnson_cook.b, 4e8);
}

// /PROC in the engine deck (QA deck twisted_beam: /PROC/1/0) is a performance hint.
TEST(DeckAliases, ProcInTheEngineDeck) {
  const Deck d = read_files(test::begin_card() + test::plate_cards() + "/END\n", test::engine_cards() + "/PROC/1/0\n");
  EXPECT_TRUE(noted(d, "/PROC/1/0", SkipKind::PerformanceHint));
}

// /SURF/PART/ALL/id: every part of the model, whatever order the cards come in; /SURF/PART/EXT is not read.
TEST(DeckAliases, SurfacePartAll) {
  const std::string surface = "/SURF/PART/ALL/9\neverything\n";
  const Deck d = read_files(test::begin_card() + surface + test::plate_cards() + "/END\n", test::engine_cards());
  ASSERT_EQ(d.model.surfaces.size(), 1u);
  EXPECT_EQ(d.model.surfaces[0].user_id, 9);
  EXPECT_EQ(d.model.surfaces[0].parts, (std::vector<std::int64_t>{1}));
  EXPECT_EQ(d.model.surfaces[0].segments.size(), 2u);  // both shells of the plate
  test::TempDir dir;
  const std::string ext = test::first_error(test::write_deck(dir, "/SURF/PART/EXT/9\nouter\n" + I(1) + "\n"));
  EXPECT_TRUE(contains(ext, "/SURF/PART/EXT, which is not supported by Crumple")) << ext;
}

// Output requests of real decks that Crumple does not write: accepted with a warning naming each card; those it
// writes are accepted without one.
TEST(DeckAliases, OutputRequestsCrumpleDoesNotWrite) {
  const std::string engine = test::engine_cards() + "/ANIM/TENS/STRAIN/MEMB\n/ANIM/NODA/DT\n/ANIM/VECT/FOPT\n"
                                                    "/ANIM/TENS/STRESS/MEMB\n/ANIM/MASS\n/ANIM/VECT/ACCEL\n"
                                                    "/ANIM/VECT/VEL\n";
  const Deck d = read_files(test::begin_card() + test::plate_cards() + "/ANIM/VERS/44\n/END\n", engine);
  EXPECT_TRUE(noted(d, "/ANIM/TENS/STRAIN/MEMB", SkipKind::OutputOnly));
  EXPECT_TRUE(noted(d, "/ANIM/NODA/DT", SkipKind::OutputOnly));
  EXPECT_TRUE(noted(d, "/ANIM/VECT/FOPT", SkipKind::OutputOnly));
  EXPECT_TRUE(noted(d, "/ANIM/VERS/44", SkipKind::OutputOnly));  // the starter's /ANIM/VERS
  for (const char* written : {"/ANIM/TENS/STRESS/MEMB", "/ANIM/MASS", "/ANIM/VECT/ACCEL", "/ANIM/VECT/VEL"})
    EXPECT_FALSE(noted(d, written, SkipKind::OutputOnly)) << written;
  EXPECT_TRUE(d.model.run.anim.nodal_mass && d.model.run.anim.acceleration);
}

// A 0 in the columns of /ANALY and /IOFLAG that no input version uses (11-20) is read as blank, as decks written by
// other tools put it in every field; other text there stays an error (issue 27).
TEST(DeckAliases, ZeroInAnUnusedColumnOfAnalyAndIoflag) {
  const std::string cards = "/ANALY\n" + I(0) + I(0) + I(0) + I(0) + "\n/IOFLAG\n" + I(0) + I(0) + I(0) + I(0) + "\n";
  const Deck d = read_files(test::begin_card() + test::plate_cards() + cards + "/END\n", test::engine_cards());
  EXPECT_TRUE(noted(d, "/IOFLAG", SkipKind::OutputOnly));
  for (const std::string& card : {std::string("/ANALY\n"), std::string("/IOFLAG\n")}) {
    try {
      read_files(test::begin_card() + test::plate_cards() + card + I(0) + I(7) + "\n/END\n", test::engine_cards());
      ADD_FAILURE() << card << "a 7 in columns 11-20 must be refused";
    } catch (const DeckErrors& e) {
      EXPECT_TRUE(contains(e.what(), "blank or 0 in columns 11-20")) << e.what();
    }
  }
}

// /RANDOM moves every node by up to Xalea along each axis, the same way for the same seed (issue 27; the reference
// moves each axis within +-Xalea, measured, with its own sequence).
TEST(DeckAliases, RandomNoiseMovesEveryNodeWithinItsAmplitude) {
  const auto read_with = [](const std::string& random) {
    return read_files(test::begin_card() + test::plate_cards() + random + "/END\n", test::engine_cards());
  };
  const Deck plain = read_with("");
  const Deck noisy = read_with("/RANDOM\n" + R(1e-4) + R(0.3) + "\n");
  const Deck again = read_with("/RANDOM\n" + R(1e-4) + R(0.3) + "\n");
  const Deck other = read_with("/RANDOM\n" + R(1e-4) + R(0.7) + "\n");
  ASSERT_EQ(noisy.model.nodes.size(), plain.model.nodes.size());
  double largest = 0.0;
  bool differs = false;
  for (std::size_t k = 0; k < plain.model.nodes.size(); ++k) {
    for (const auto axis : {&Nodes::x, &Nodes::y, &Nodes::z}) {
      const double moved = (noisy.model.nodes.*axis)[k] - (plain.model.nodes.*axis)[k];
      largest = std::max(largest, std::abs(moved));
      EXPECT_EQ((noisy.model.nodes.*axis)[k], (again.model.nodes.*axis)[k]) << "the same seed, the same model";
      differs = differs || (other.model.nodes.*axis)[k] != (noisy.model.nodes.*axis)[k];
    }
  }
  EXPECT_LE(largest, 1e-4);
  EXPECT_GT(largest, 1e-5) << "the nodes moved";
  EXPECT_TRUE(differs) << "another seed, another model";
  try {
    read_with("/RANDOM\n" + R(1e-4) + R(1.0) + "\n");
    ADD_FAILURE() << "Seed 1 is outside [0, 1)";
  } catch (const DeckErrors& e) {
    EXPECT_TRUE(contains(e.what(), "field Seed")) << e.what();
  }
}

}  // namespace test_deck_aliases
