// Regression tests for reader bugs found by the mutation fuzzer (tests/fuzz) and by the review that came with it.
// Each deck here was once accepted with garbage in the model, or gave a broken message or a hang.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>

#include "crumple/deck/fields.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_reader_robustness {

using namespace crumple;
using test::I;
using test::R;

namespace {

// A starter deck only (no engine file): the plate of deck_files.hpp with `extra` cards before /END.
std::filesystem::path write_starter(const test::TempDir& dir, const std::string& extra,
                                    const std::string& begin = test::begin_card()) {
  return dir.write("TEST_0000.rad", begin + test::plate_cards() + extra + "/END\n");
}

// Every error message of a read, one per line, as the user sees them (what() as a C string); empty when the deck
// reads fine.
std::string all_errors(const std::filesystem::path& starter) {
  std::string text;
  try {
    read_deck(starter);
  } catch (const DeckErrors& e) {
    for (const DeckError& each : e.errors()) text += std::string(each.what()) + "\n";
  } catch (const DeckError& e) {
    text = std::string(e.what()) + "\n";
  }
  return text;
}

}  // namespace

// Fuzzer: a NUL byte in a keyword line ended what() (a C string) inside the keyword, so the user saw
// "TEST_0000.rad:19: /NO" without what was expected. Control characters are now shown as \xNN.
TEST(ReaderRobustness, ControlCharactersInAKeywordDoNotCutTheMessage) {
  test::TempDir dir;
  const char keyword[] = "/NO\0DE/\x1b[2J\n";
  const auto starter = write_starter(dir, std::string(keyword, sizeof keyword - 1) + I(99) + R(0.0) + "\n");
  const std::string errors = all_errors(starter);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors.find("/NO\\x00DE/\\x1b[2J"), std::string::npos) << errors;
  EXPECT_NE(errors.find("expected a Crumple or Radioss keyword"), std::string::npos) << errors;
  EXPECT_EQ(errors.find('\x1b'), std::string::npos) << errors;
}

// Fuzzer: a coordinate of -1E308 gave an infinite shell area, which passed the "positive area" check, and an
// infinite model mass.
TEST(ReaderRobustness, HugeCoordinatesGiveAnErrorNotAnInfiniteArea) {
  test::TempDir dir;
  const auto starter =
      write_starter(dir, "/NODE\n" + I(7) + R("-1E308") + R(0.0) + R(0.0) + "\n" + I(8) + R("1E308") + R(1.0) + R(0.0) +
                             "\n/SHELL/1\n" + I(3) + I(7) + I(8) + I(6) + I(5) + "\n");
  const std::string errors = all_errors(starter);
  EXPECT_NE(errors.find("SHELL 3 with an infinite area"), std::string::npos) << errors;
}

// Review of the same finding: finite density, thickness and area whose product overflows.
TEST(ReaderRobustness, AnOverflowingElementMassIsAnError) {
  test::TempDir dir;
  std::string plate = test::plate_cards();
  plate.replace(plate.find(R(7800.0)), 20, R("1.7E308"));
  plate.replace(plate.find(R(0.001)), 20, R(1e10));
  const auto starter = dir.write("TEST_0000.rad", test::begin_card() + plate + "/END\n");
  const std::string errors = all_errors(starter);
  EXPECT_NE(errors.find("/PART/1: expected elements of finite mass"), std::string::npos) << errors;
  EXPECT_NE(errors.find("SHELL 1 of mass inf"), std::string::npos) << errors;
}

// Fuzzer: /BEGIN units of 1e-200 m (or 4.9e-324 kg...) make some conversion factors infinite. Values then read
// as infinity (E inf, density inf were accepted), and blank fields as 0 x inf = NaN, which passes every range
// check. The unit system is now refused at /BEGIN.
TEST(ReaderRobustness, UnitsWithAnInfiniteConversionFactorAreRefused) {
  test::TempDir dir;
  const std::string begin =
      "/BEGIN\nTEST\n      2019         0\n" + R("kg") + R("1e-200") + R("s") + "\n" + R("kg") + R("m") + R("s") + "\n";
  const std::string errors = all_errors(write_starter(dir, "", begin));
  EXPECT_NE(errors.find("/BEGIN: field units: expected input and working units whose conversion factors stay "
                        "finite and non-zero"),
            std::string::npos)
      << errors;
}

// Fuzzer: with finite factors, a value such as 1E308 in kilotonnes still overflows once converted.
TEST(ReaderRobustness, AValueThatOverflowsInWorkingUnitsIsAnError) {
  test::TempDir dir;
  const std::string begin =
      "/BEGIN\nTEST\n      2019         0\n" + R("t") + R("m") + R("s") + "\n" + R("g") + R("m") + R("s") + "\n";
  const std::string errors =
      all_errors(write_starter(dir, "/MAT/ELAST/2\nhuge\n" + R(7.8) + "\n" + R("1E308") + R(0.3) + "\n", begin));
  EXPECT_NE(errors.find("/MAT/ELAST/2: field E (columns 1-20)"), std::string::npos) << errors;
}

// Review: "+-5" read as -5 (the '+' was dropped, then the '-' parsed).
TEST(ReaderRobustness, TwoSignsAreNotAnInteger) {
  EXPECT_EQ(parse_integer("+-5"), std::nullopt);
  EXPECT_EQ(parse_integer("+5"), 5);
  EXPECT_EQ(parse_integer("-5"), -5);
  test::TempDir dir;
  const std::string errors = all_errors(write_starter(dir, "/PART/2\nplate\n       +-1" + I(1) + "\n"));
  EXPECT_NE(errors.find("field prop_ID (columns 1-10): expected an integer, found '+-1'"), std::string::npos) << errors;
}

// Review: an integer flag wider than 32 bits wrapped when stored as an int: Ishell 4294967320 became 24.
TEST(ReaderRobustness, AnIntegerFlagWiderThan32BitsIsAnError) {
  test::TempDir dir;
  std::string plate = test::plate_cards();
  plate.replace(plate.find("/PROP/SHELL/1\nshell\n") + 20, 10, "4294967320");
  const auto starter = dir.write("TEST_0000.rad", test::begin_card() + plate + "/END\n");
  const std::string errors = all_errors(starter);
  EXPECT_NE(errors.find("field Ishell (columns 1-10)"), std::string::npos) << errors;
}

// Review: `#include` of a named pipe blocked read_deck forever (and /dev/zero never ended). Only regular files
// are read now. The helper thread unblocks a reader that would open the pipe, so a regression fails instead of
// hanging the test.
TEST(ReaderRobustness, IncludeOfAPipeOrDeviceIsAnErrorNotAHang) {
  test::TempDir dir;
  const auto fifo = dir.path() / "pipe.inc";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::atomic<bool> done{false};
  std::thread unblock([&] {
    while (!done) {
      const int fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // succeeds only when a reader waits
      if (fd >= 0) close(fd);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  const auto start = std::chrono::steady_clock::now();
  const std::string pipe_errors = all_errors(write_starter(dir, "#include pipe.inc\n"));
  done = true;
  unblock.join();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(pipe_errors.find("expected a regular deck file, found special file"), std::string::npos) << pipe_errors;

  const std::string device_errors = all_errors(write_starter(dir, "#include /dev/null\n"));
  EXPECT_NE(device_errors.find("expected a regular deck file, found special file '/dev/null'"), std::string::npos)
      << device_errors;
}

}  // namespace test_reader_robustness
