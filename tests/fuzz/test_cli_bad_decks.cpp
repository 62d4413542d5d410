// `crumple check` on fixed corrupted decks: every one is bad input (exit code 2), never an internal error (3), a
// crash or a success.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "deck_files.hpp"

namespace crumple::test {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

struct CliResult {
  int exit_code = -1;  // -1: killed by a signal
  std::string err;
};

CliResult crumple_check(const fs::path& starter, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt";
  const fs::path err = dir / "stderr.txt";
  // Built with a stream: GCC 12 at -O3 gives a false -Wrestrict on the equivalent chain of string additions.
  std::ostringstream command;
  command << "'" << CRUMPLE_EXE << "' check '" << starter.string() << "' >'" << out.string() << "' 2>'"
          << err.string() << "'";
  const int status = std::system(command.str().c_str());
  CliResult run;
  if (status != -1 && WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  run.err = read_text(err);
  return run;
}

struct BadDeck {
  std::string what;
  std::string starter;
  std::string engine;  // written as TEST_0001.rad when not empty
};

std::vector<BadDeck> bad_decks() {
  const std::string base = begin_card() + plate_cards();
  const std::string qa = read_text(fs::path(CRUMPLE_QA_DIR) / "box_crush" / "BOX1BL_0000.rad");
  return {
      {"a real field that is not a number", base + "/NODE\n" + I(7) + R("1.2.3") + R(0.0) + R(0.0) + "\n/END\n", ""},
      {"a huge real field", base + "/NODE\n" + I(7) + R("1E999") + R(0.0) + R(0.0) + "\n/END\n", ""},
      {"no /END", base, ""},
      {"a missing include file", base + "#include no_such_file.inc\n/END\n", ""},
      {"an include of itself", base + "#include TEST_0000.rad\n/END\n", ""},
      {"a truncated card", base + "/MAT/ELAST/2\nsteel\n/END\n", ""},
      {"binary garbage",
       std::string("\x7f"
                   "ELF\x02\x01\x01\x00\x00\xff\xfe/\n\x00\x00",
                   16),
       ""},
      {"an empty file", "", ""},
      {"a keyword line without a name", base + "/\n/END\n", ""},
      {"an engine deck without /RUN", base + "/END\n", "/TFILE\n1e-4\n"},
      {"the QA box deck cut in half", qa.substr(0, qa.size() / 2), ""},
  };
}

TEST(CliBadDecks, CheckExitsWithBadInputCode) {
  ASSERT_TRUE(fs::is_regular_file(CRUMPLE_EXE)) << CRUMPLE_EXE;
  for (const BadDeck& deck : bad_decks()) {
    SCOPED_TRACE(deck.what);
    TempDir dir;
    if (!deck.engine.empty()) dir.write("TEST_0001.rad", deck.engine);
    const fs::path starter = dir.write("TEST_0000.rad", deck.starter);
    const CliResult run = crumple_check(starter, dir.path());
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("error: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(dir.path().string()), std::string::npos) << run.err;  // names the file
  }
}

TEST(CliBadDecks, CheckOfAMissingDeckIsBadInput) {
  TempDir dir;
  const CliResult run = crumple_check(dir.path() / "NOPE_0000.rad", dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

// `crumple run --skip-unknown`: a Radioss keyword Crumple lacks becomes a warning, and the run's summary lists it
// with the output-only request it did not write, under "approximations".
int crumple_run(const fs::path& starter, const fs::path& dir, const std::string& flags) {
  std::ostringstream command;
  command << "'" << CRUMPLE_EXE << "' run '" << starter.string() << "' -o '" << (dir / "out").string() << "' "
          << flags << " >'" << (dir / "stdout.txt").string() << "' 2>'" << (dir / "stderr.txt").string() << "'";
  const int status = std::system(command.str().c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CliBadDecks, SkipUnknownListsTheSkippedOptionsInTheSummaryAndTheListing) {
  TempDir dir;
  dir.write("TEST_0001.rad", "/RUN/TEST/1\n2e-6\n/TFILE\n1e-6\n");
  const std::string skipped = "/MAT/LAW44/3\ncowper\n" + R(7800.0) + "\n";
  const std::string quads = "/TH/QUAD/1\nquads\nDEF\n" + I(1) + "\n";  // an output card Crumple does not write
  const fs::path starter = dir.write("TEST_0000.rad", begin_card() + plate_cards() + skipped + quads + "/END\n");
  EXPECT_EQ(crumple_run(starter, dir.path(), ""), 2) << read_text(dir.path() / "stderr.txt");
  ASSERT_EQ(crumple_run(starter, dir.path(), "--skip-unknown"), 0) << read_text(dir.path() / "stderr.txt");
  const std::string err = read_text(dir.path() / "stderr.txt");
  EXPECT_NE(err.find("warning: "), std::string::npos) << err;
  EXPECT_NE(err.find("/MAT/LAW44/3: keyword skipped (--skip-unknown)"), std::string::npos) << err;
  const std::string summary = read_text(dir.path() / "out" / "TEST.summary.json");
  const auto at = summary.find("\"approximations\": [");
  ASSERT_NE(at, std::string::npos) << summary;
  const std::string list = summary.substr(at);
  EXPECT_NE(list.find("[skipped] "), std::string::npos) << list;
  EXPECT_NE(list.find("TEST_0000.rad:"), std::string::npos) << list;  // each entry names the file and line
  EXPECT_NE(list.find("/MAT/LAW44/3: keyword skipped (--skip-unknown): the Radioss starter keyword /MAT/LAW44 is "
                      "not supported by Crumple"),
            std::string::npos)
      << list;
  EXPECT_NE(list.find("[output-only] "), std::string::npos) << list;
  EXPECT_NE(list.find("/TH/QUAD/1: output-only card (/TH/QUAD): not written by Crumple"), std::string::npos) << list;
  // The listing carries the same list in its header.
  const std::string listing = read_text(dir.path() / "out" / "TEST.out");
  const auto header = listing.find("OPTIONS SKIPPED OR APPROXIMATED:");
  ASSERT_NE(header, std::string::npos) << listing;
  EXPECT_NE(listing.find("/MAT/LAW44/3: keyword skipped (--skip-unknown)", header), std::string::npos) << listing;
  EXPECT_NE(listing.find("/TH/QUAD/1: output-only card", header), std::string::npos) << listing;
}

}  // namespace
}  // namespace crumple::test
