#pragma once
// A JUnit XML report (the format CI servers read): one <testsuite> of test cases, each passed or failed.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace crumple {

struct JunitCase {
  std::string name;
  double seconds = 0.0;
  bool failed = false;
  std::string failure_type;     // "mismatch", "timeout", "run failed", ... (the failure's type attribute)
  std::string failure_message;  // one line with the numbers
  std::string failure_text;     // details: the element's text (console lines of the run)
};

struct JunitSuite {
  std::string name;
  double seconds = 0.0;
  std::vector<JunitCase> cases;
};

// The report as XML 1.0 text; every name and message is escaped.
void write_junit(std::ostream& out, const JunitSuite& suite);
// Writes the report to `file`; throws std::runtime_error when it cannot.
void write_junit(const std::filesystem::path& file, const JunitSuite& suite);

}  // namespace crumple
