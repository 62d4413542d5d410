// The JUnit XML report of `crumple regress` (crumple/output/junit_report.hpp): the exact text, escaped.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "crumple/output/junit_report.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_junit_report {

using namespace crumple;

namespace {

JunitSuite two_cases() {
  JunitSuite suite{"crumple regress", 12.5, {}};
  suite.cases.push_back({"box_crush", 2.25, false, "", "", ""});
  suite.cases.push_back({"a<b>&\"c'", 10.0, true, "mismatch", "kinetic energy 1 against 2: 10 % > 5 %",
                         "line 1\nbell \a here\n<tag> & 'q'"});
  return suite;
}

TEST(JunitReport, OneTestcasePerCaseWithTheFailuresEscaped) {
  std::ostringstream out;
  write_junit(out, two_cases());
  EXPECT_EQ(out.str(),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<testsuites name=\"crumple regress\" tests=\"2\" failures=\"1\" errors=\"0\" time=\"12.500\">\n"
            "  <testsuite name=\"crumple regress\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\" "
            "time=\"12.500\">\n"
            "    <testcase classname=\"crumple regress\" name=\"box_crush\" time=\"2.250\"/>\n"
            "    <testcase classname=\"crumple regress\" name=\"a&lt;b&gt;&amp;&quot;c&apos;\" time=\"10.000\">\n"
            "      <failure type=\"mismatch\" message=\"kinetic energy 1 against 2: 10 % &gt; 5 %\">line 1\n"
            "bell ? here\n&lt;tag&gt; &amp; &apos;q&apos;</failure>\n"
            "    </testcase>\n"
            "  </testsuite>\n"
            "</testsuites>\n");
}

TEST(JunitReport, AnEmptySuiteIsWellFormed) {
  std::ostringstream out;
  write_junit(out, JunitSuite{"s", 0.0, {}});
  EXPECT_NE(out.str().find("<testsuite name=\"s\" tests=\"0\" failures=\"0\" errors=\"0\" skipped=\"0\" "
                           "time=\"0.000\">\n  </testsuite>\n</testsuites>\n"),
            std::string::npos);
}

TEST(JunitReport, WritesTheFileOrSaysWhyNot) {
  test::TempDir dir;
  const auto file = dir.path() / "report.xml";
  write_junit(file, two_cases());
  std::ifstream in(file);
  std::ostringstream text, expected;
  text << in.rdbuf();
  write_junit(expected, two_cases());
  EXPECT_EQ(text.str(), expected.str());
  const auto nowhere = dir.path() / "no" / "such" / "report.xml";
  try {
    write_junit(nowhere, two_cases());
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write the JUnit report " + nowhere.string());
  }
}

}  // namespace

}  // namespace test_junit_report
