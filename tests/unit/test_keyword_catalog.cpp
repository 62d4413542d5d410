// The Radioss keyword list (src/deck/data/radioss_keywords.txt) and the four answers the reader gives a card it
// has no handler for: another deck part's keyword (error), an output-only or performance card (named warning), a
// Radioss keyword Crumple lacks ("not supported by Crumple", exit 2) and a word that is no keyword ("unknown", with
// the nearest known keyword).
#include <gtest/gtest.h>

#include <algorithm>

#include "deck/keyword_catalog.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_keyword_catalog {

using namespace crumple;
using test::I;
using test::R;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string error_of(const std::string& starter_extra, const std::string& engine = test::engine_cards()) {
  test::TempDir dir;
  return test::first_error(test::write_deck(dir, starter_extra, engine));
}

Deck read(const std::string& starter_extra, const std::string& engine = test::engine_cards(), bool skip = false) {
  test::TempDir dir;
  ReadOptions options;
  options.skip_unknown = skip;
  return read_deck(test::write_deck(dir, starter_extra, engine), options);
}

std::vector<SkippedOption> skipped_of_kind(const Deck& d, SkipKind kind) {
  std::vector<SkippedOption> out;
  std::copy_if(d.report.skipped_options.begin(), d.report.skipped_options.end(), std::back_inserter(out),
               [kind](const SkippedOption& o) { return o.kind == kind; });
  return out;
}

}  // namespace

TEST(KeywordCatalog, ListHoldsBothDeckPartsWithMultiPartForms) {
  using deck::DeckPart;
  const auto& list = deck::radioss_keywords();
  EXPECT_GT(list.size(), 500u);
  auto found = [&](std::vector<std::string> path, DeckPart part) {
    const auto* k = deck::find_radioss_keyword(path, part);
    return k == nullptr ? std::string() : k->name;
  };
  EXPECT_EQ(found({"MAT", "LAW36", "3"}, DeckPart::Starter), "/MAT/LAW36");
  EXPECT_EQ(found({"MAT", "PLAS_TAB", "3"}, DeckPart::Starter), "/MAT/PLAS_TAB");
  EXPECT_EQ(found({"ANIM", "VERS", "44"}, DeckPart::Starter), "/ANIM/VERS");
  EXPECT_EQ(found({"ANIM", "SHELL", "TENS", "STRESS"}, DeckPart::Engine), "/ANIM/SHELL");
  EXPECT_EQ(found({"DT", "NODA", "CST"}, DeckPart::Engine), "/DT");
  EXPECT_EQ(found({"DTIX"}, DeckPart::Engine), "/DTIX");
  EXPECT_EQ(found({"DTIX"}, DeckPart::Starter), "");  // an engine keyword only
  EXPECT_EQ(found({"MAT", "LAW99", "7"}, DeckPart::Starter), "");  // no such law
}

TEST(KeywordCatalog, EditDistanceAndNearestKeyword) {
  EXPECT_EQ(deck::edit_distance("", "abc"), 3u);
  EXPECT_EQ(deck::edit_distance("/MAT/LAW2", "/MAT/LAW2"), 0u);
  EXPECT_EQ(deck::edit_distance("/MAT/PLAS_JOHN", "/MAT/PLAS_JOHNS"), 1u);
  EXPECT_EQ(deck::edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(deck::nearest_keyword("/MAT/PLAS_JOHN"), "/MAT/PLAS_JOHNS");
  EXPECT_EQ(deck::nearest_keyword("/GRNOD/NOD"), "/GRNOD/NODE");
  EXPECT_EQ(deck::nearest_keyword("/XYZZYQWERTY/FOO"), "");  // nothing close
}

// Class 1: a Radioss model keyword Crumple lacks is an error that says so, with file, line and keyword.
TEST(KeywordCatalog, RadiossKeywordCrumpleLacksIsNotSupported) {
  const std::string e = error_of("/MAT/LAW44/3\ncowper\n" + R(7800.0) + "\n");
  EXPECT_TRUE(contains(e, "TEST_0000.rad:")) << e;
  EXPECT_TRUE(contains(e, "/MAT/LAW44/3: expected a keyword Crumple supports")) << e;
  EXPECT_TRUE(contains(e, "the Radioss starter keyword /MAT/LAW44, which is not supported by Crumple")) << e;
  const std::string engine = error_of("", test::engine_cards() + "/DYREL\n0.5 1e-3\n");
  EXPECT_TRUE(contains(engine, "TEST_0001.rad:")) << engine;
  EXPECT_TRUE(contains(engine, "the Radioss engine keyword /DYREL, which is not supported by Crumple")) << engine;
  // A keyword of the other deck part keeps its own message.
  EXPECT_TRUE(contains(error_of("/DTIX\n0.1\n"), "belongs to the engine deck")) << error_of("/DTIX\n0.1\n");
}

TEST(KeywordCatalog, UnknownKeywordNamesTheNearestKnownOne) {
  const std::string e = error_of("/MAT/PLAS_JOHN/3\nsteel\n");
  EXPECT_TRUE(contains(e, "found unknown keyword '/MAT/PLAS_JOHN/3'")) << e;
  EXPECT_TRUE(contains(e, "nearest known keyword: /MAT/PLAS_JOHNS")) << e;
}

// Class 2: output-only cards are warnings naming the card, listed as skipped output.
TEST(KeywordCatalog, OutputOnlyCardsAreNamedWarnings) {
  const std::string quads = "/TH/QUAD/1\nquads\nDEF\n" + I(1) + "\n";
  const Deck d = read(quads, test::engine_cards() + "/ANIM/TENS/STRAIN/MEMB\n/ANIM/GPS1\n/H3D/ELEM/VONM\n");
  const auto output = skipped_of_kind(d, SkipKind::OutputOnly);
  std::vector<std::string> keywords;
  for (const auto& o : output) keywords.push_back(o.keyword);
  for (const std::string k : {"/TH/QUAD/1", "/ANIM/TENS/STRAIN/MEMB", "/ANIM/GPS1", "/H3D/ELEM/VONM"})
    EXPECT_NE(std::find(keywords.begin(), keywords.end(), k), keywords.end()) << k;
  bool warned = false;
  for (const auto& w : d.report.warnings) warned |= contains(w.text(), "/TH/QUAD/1: output-only card");
  EXPECT_TRUE(warned);
}

// Class 3: performance hints are warnings too, and change nothing in the model.
TEST(KeywordCatalog, PerformanceHintsAreNamedWarnings) {
  const std::string spmd = "/SPMD\n" + I(0) + I(4) + I(0) + I(0) + I(0) + I(0) + "\n";
  const Deck d = read(spmd + "/MEMORY\n" + I(100) + "\n", test::engine_cards() + "/PROC/1/0\n");
  const auto hints = skipped_of_kind(d, SkipKind::PerformanceHint);
  ASSERT_EQ(hints.size(), 3u);
  EXPECT_EQ(hints[0].keyword, "/SPMD");
  EXPECT_EQ(hints[1].keyword, "/MEMORY");
  EXPECT_EQ(hints[2].keyword, "/PROC/1/0");
  EXPECT_TRUE(contains(hints[2].text(), "[performance hint]")) << hints[2].text();
}

// --skip-unknown turns the errors of the first class and of unknown keywords into warnings, each recorded.
TEST(KeywordCatalog, SkipUnknownRecordsEverySkippedKeyword) {
  const Deck d = read("/MAT/LAW44/3\ncowper\n/MAT/PLAS_JOHN/4\nsteel\n", test::engine_cards(), true);
  const auto skipped = skipped_of_kind(d, SkipKind::Unsupported);
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_EQ(skipped[0].keyword, "/MAT/LAW44/3");
  EXPECT_TRUE(contains(skipped[0].what, "/MAT/LAW44 is not supported by Crumple")) << skipped[0].what;
  EXPECT_TRUE(contains(skipped[1].what, "unknown keyword skipped")) << skipped[1].what;
  EXPECT_TRUE(contains(skipped[1].text(), "[skipped]")) << skipped[1].text();
}

}  // namespace test_keyword_catalog
