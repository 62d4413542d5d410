// NAME.summary.json (docs/output-format.md, "Run summary"): what built the run, when, from which deck files.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "crumple/output/build_info.hpp"
#include "crumple/output/run_summary.hpp"
#include "deck_files.hpp"

namespace crumple::test_run_summary {
namespace {

TEST(RunSummary, DeckFileChecksumIsTheStandardCrc32) {
  test::TempDir dir;
  const auto file = dir.path() / "check.rad";
  std::ofstream(file) << "123456789";  // the CRC-32 check value of this string is cbf43926
  const std::vector<DeckFile> files = describe_deck_files({file.string()});
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].bytes, 9u);
  EXPECT_EQ(files[0].crc32, 0xcbf43926u);
  EXPECT_THROW(describe_deck_files({(dir.path() / "gone.rad").string()}), std::runtime_error);
}

TEST(RunSummary, JsonCarriesBuildDateDeckFilesAndDeletions) {
  RunSummary s;
  s.name = "TUBE";
  s.crumple_version = build::version();
  s.commit = build::commit();
  s.date = utc_now_iso8601();
  s.deck_files = {{"a/TUBE_0000.rad", 12, 0xcbf43926u}};
  s.deleted_elements = 7;
  const std::string json = to_json(s);
  EXPECT_NE(json.find(fmt::format("\"crumple_version\": \"{}\"", CRUMPLE_TEST_VERSION)), std::string::npos) << json;
  EXPECT_TRUE(std::regex_search(json, std::regex(R"re("commit": "([0-9a-f]{12}(-modified)?|unknown)")re"))) << json;
  EXPECT_TRUE(std::regex_search(json, std::regex(R"re("date": "20[0-9]{2}-[01][0-9]-[0-3][0-9]T[0-9]{2}:[0-9]{2}:[0-9]{2}Z")re")));
  EXPECT_NE(json.find(R"({"path": "a/TUBE_0000.rad", "bytes": 12, "crc32": "cbf43926"})"), std::string::npos) << json;
  EXPECT_NE(json.find("\"deleted_elements\": 7"), std::string::npos);
}

}  // namespace
}  // namespace crumple::test_run_summary
