// `crumple th` (src/app/th.cpp) on a results file written by hand: the listing and the CSV, exactly.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/exit_codes.hpp"
#include "app/th.hpp"
#include "crumple/output/results_file.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_th_command {

using namespace crumple;

namespace {

// The plate of test::write_deck with one /TH/NODE dataset of two columns and three rows.
std::filesystem::path write_file(const test::TempDir& dir) {
  const Deck d = read_deck(test::write_deck(dir));
  HistoryDataset node{"NODE_2", "NODE", "/TH/NODE/2", 2, "nodes", {}};
  node.columns = {{6, "corner", "DX", "L", 1.0, "NODE_2/6/DX"}, {6, "corner", "VX", "L/T", 1.0, "NODE_2/6/VX"}};
  const auto path = dir.path() / "TEST.h5";
  ResultsFile file(path, d.model, {node});
  for (int k = 0; k < 3; ++k) {
    HistoryRow row;
    row.time = 1e-4 * k, row.dt = 1e-4, row.internal = 0.1 * k, row.total = 1.0 / 3.0 * k;
    row.th = {{0.5 * row.time, k == 2 ? -1.25 : 0.5}};
    file.write_history(row);
  }
  file.close();
  return path;
}

struct Output {
  int code;
  std::string out, err;
};

Output run(const app::ThOptions& options) {
  std::ostringstream out, err;
  const int code = app::run_th(options, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace

TEST(ThCommand, ListsTheHistoriesWithTheirColumns) {
  test::TempDir dir;
  app::ThOptions options;
  options.file = write_file(dir);
  options.select = {"NODE_2/*", "internal"};
  const Output o = run(options);
  EXPECT_EQ(o.code, app::kExitNormal) << o.err;
  EXPECT_EQ(o.out,
            "TEST.h5: 3 history rows, time 0 to 0.0002 s\n"
            "/history/internal  global  1 column\n"
            "  internal [J]\n"
            "/history/th/NODE_2  NODE 2  \"nodes\"  /TH/NODE/2  2 columns\n"
            "  NODE_2/6/DX [m]  (corner)\n"
            "  NODE_2/6/VX [m/s]  (corner)\n");
  options.select.clear();
  const Output all = run(options);
  EXPECT_NE(all.out.find("/history/dt  global  1 column\n  dt [s]\n"), std::string::npos) << all.out;
  EXPECT_NE(all.out.find("/history/total  global  1 column\n  total [J]\n"), std::string::npos) << all.out;
  EXPECT_EQ(all.out.find("node_values"), std::string::npos) << all.out;  // no columns: not listed
}

// Time first, the columns in the file's order, the header their labels with units, every value as the shortest
// decimal that reads back to the same double.
TEST(ThCommand, WritesTheSelectedColumnsAsCsv) {
  test::TempDir dir;
  app::ThOptions options;
  options.file = write_file(dir);
  options.csv = true;
  options.select = {"NODE_2/6/?X", "total"};
  const Output o = run(options);
  EXPECT_EQ(o.code, app::kExitNormal) << o.err;
  EXPECT_EQ(o.out,
            "time [s],total [J],NODE_2/6/DX [m],NODE_2/6/VX [m/s]\n"
            "0,0,0,0.5\n"
            "0.0001,0.3333333333333333,5e-05,0.5\n"
            "0.0002,0.6666666666666666,0.0001,-1.25\n");
  options.output = dir.path() / "out.csv";
  const Output to_file = run(options);
  EXPECT_EQ(to_file.code, app::kExitNormal);
  EXPECT_TRUE(to_file.out.empty());
  std::ifstream in(options.output);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), o.out);
}

TEST(ThCommand, BadSelectionsAndFilesAreBadInput) {
  test::TempDir dir;
  app::ThOptions options;
  options.file = write_file(dir);
  options.select = {"NODE_2/*", "NODE_3/*"};
  const Output none = run(options);
  EXPECT_EQ(none.code, app::kExitBadInput);
  EXPECT_EQ(none.err, "crumple: --select NODE_3/*: no history column matches\n");
  options.select.clear();
  options.file = dir.path() / "missing.h5";
  const Output missing = run(options);
  EXPECT_EQ(missing.code, app::kExitBadInput);
  EXPECT_NE(missing.err.find("missing.h5: no such file"), std::string::npos) << missing.err;
  options.file = write_file(dir);
  options.csv = true;
  options.output = dir.path() / "no-such-folder" / "out.csv";
  EXPECT_EQ(run(options).code, app::kExitRunFailed);
}

}  // namespace test_th_command
