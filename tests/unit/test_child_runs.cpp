// Child processes of `crumple regress` (src/app/child_runs.hpp): exit codes, signals and time limits, each run
// on its own, a few at a time. /bin/sh stands in for crumple.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "app/child_runs.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_child_runs {

using namespace crumple::app;

namespace {

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ChildRuns, ExitCodesSignalsAndTimeLimitsAreEachChildsOwn) {
  crumple::test::TempDir dir;
  const auto console = [&](int i) { return dir.path() / ("console" + std::to_string(i) + ".txt"); };
  const std::vector<ChildCommand> commands{
      {{"-c", "echo out; echo err >&2; exit 0"}, console(0)},
      {{"-c", "exit 3"}, console(1)},
      {{"-c", "kill -SEGV $$"}, console(2)},
      {{"-c", "sleep 30"}, console(3)},
  };
  std::vector<std::size_t> order;
  const auto results = run_children("/bin/sh", commands, 2, 0.5, [&](std::size_t i, const ChildResult&) {
    order.push_back(i);
  });
  ASSERT_EQ(results.size(), 4u);
  EXPECT_EQ(results[0].end, ChildResult::End::Exited);
  EXPECT_EQ(results[0].code, 0);
  EXPECT_EQ(text_of(console(0)), "out\nerr\n");
  EXPECT_EQ(results[1].end, ChildResult::End::Exited);
  EXPECT_EQ(results[1].code, 3);
  EXPECT_EQ(results[2].end, ChildResult::End::Signalled);
  EXPECT_EQ(results[2].code, SIGSEGV);
  EXPECT_EQ(results[3].end, ChildResult::End::TimedOut);
  EXPECT_GE(results[3].seconds, 0.5);
  EXPECT_LT(results[3].seconds, 10.0);
  EXPECT_EQ(order.size(), 4u);
  EXPECT_EQ(order.back(), 3u);  // the one killed at its limit ends last
  EXPECT_EQ(describe(results[1], 0.5), "exit code 3");
  EXPECT_EQ(describe(results[2], 0.5), "killed by signal 11 (Segmentation fault)");
  EXPECT_EQ(describe(results[3], 0.5), "timed out after 0.5 s");
}

TEST(ChildRuns, AProgramThatCannotStartIsReported) {
  crumple::test::TempDir dir;
  const auto results = run_children(dir.path() / "no-such-program", {{{}, dir.path() / "console.txt"}}, 1, 10.0,
                                    [](std::size_t, const ChildResult&) {});
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].end, ChildResult::End::NotStarted);
  EXPECT_EQ(describe(results[0], 10.0), "could not start: No such file or directory");
}

}  // namespace

}  // namespace test_child_runs
