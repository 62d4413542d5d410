// Text from a deck is valid UTF-8 before it reaches NAME.xdmf (XML), the summary (JSON) and HDF5 attributes
// (core/utf8.hpp): a part title typed in Latin-1 made NAME.xdmf invalid XML, which ParaView refused.
#include <gtest/gtest.h>

#include "crumple/core/utf8.hpp"
#include "crumple/deck/reader.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_utf8 {

using namespace crumple;
using test::I;
using test::R;

namespace {

TEST(ValidUtf8, KeepsAsciiAndWellFormedSequences) {
  EXPECT_EQ(valid_utf8("plate 1"), "plate 1");
  EXPECT_EQ(valid_utf8("t\xc3\xb4le \xe2\x82\xac \xf0\x9f\x9a\x97"), "t\xc3\xb4le \xe2\x82\xac \xf0\x9f\x9a\x97");
}

TEST(ValidUtf8, ReplacesEachStrayByteByOneQuestionMark) {
  EXPECT_EQ(valid_utf8("t\xf4le"), "t?le");                  // Latin-1: the deck's columns stay where they were
  EXPECT_EQ(valid_utf8("\xc3"), "?");                         // a sequence cut short
  EXPECT_EQ(valid_utf8("\xc0\xaf"), "??");                    // an overlong '/'
  EXPECT_EQ(valid_utf8("\xed\xa0\x80"), "???");               // a surrogate
  EXPECT_EQ(valid_utf8("\xf4\x90\x80\x80"), "????");          // above U+10FFFF
  EXPECT_EQ(valid_utf8("a\xff\xfe" "b"), "a??b");
}

TEST(ValidUtf8, ADeckTitleInLatin1IsReadAsValidText) {
  test::TempDir dir;
  const std::string starter = test::begin_card() + "/NODE\n" + I(1) + R(0.0) + R(0.0) + R(0.0) + "\n" + I(2) +
                              R(0.01) + R(0.0) + R(0.0) + "\n" + I(3) + R(0.01) + R(0.01) + R(0.0) + "\n" + I(4) +
                              R(0.0) + R(0.01) + R(0.0) + "\n/SHELL/1\n" + I(1) + I(1) + I(2) + I(3) + I(4) +
                              "\n/PART/1\nt\xf4le d'acier\n" + I(1) + I(1) + "\n/PROP/SHELL/1\nshell\n" + I(24) +
                              I(0) + I(0) + "\n" + R(0.0) + "\n" + I(3) + I(0) + R(0.001) +
                              "\n/MAT/ELAST/1\nsteel\n" + R(7800.0) + "\n" + R(2.1e11) + R(0.3) + "\n/END\n";
  dir.write("TEST_0001.rad", test::engine_cards());
  const Deck deck = read_deck(dir.write("TEST_0000.rad", starter));
  ASSERT_EQ(deck.model.parts.size(), 1u);
  EXPECT_EQ(deck.model.parts[0].title, "t?le d'acier");
}

}  // namespace

}  // namespace test_utf8
