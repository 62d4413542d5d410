#include "crumple/output/junit_report.hpp"

#include <fmt/ostream.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "xml_text.hpp"

namespace crumple {

void write_junit(std::ostream& out, const JunitSuite& suite) {
  const auto failures = std::count_if(suite.cases.begin(), suite.cases.end(), [](const JunitCase& c) { return c.failed; });
  const std::string name = xml_escaped(suite.name);
  fmt::print(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  fmt::print(out, "<testsuites name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n", name,
             suite.cases.size(), failures, suite.seconds);
  fmt::print(out, "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\" time=\"{:.3f}\">\n",
             name, suite.cases.size(), failures, suite.seconds);
  for (const JunitCase& c : suite.cases) {
    fmt::print(out, "    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\"", name, xml_escaped(c.name), c.seconds);
    if (!c.failed) {
      fmt::print(out, "/>\n");
      continue;
    }
    fmt::print(out, ">\n      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>\n",
               xml_escaped(c.failure_type), xml_escaped(c.failure_message), xml_escaped(c.failure_text));
  }
  fmt::print(out, "  </testsuite>\n</testsuites>\n");
}

void write_junit(const std::filesystem::path& file, const JunitSuite& suite) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write the JUnit report " + file.string());
  write_junit(out, suite);
  out.close();
  if (!out) throw std::runtime_error("cannot write the JUnit report " + file.string());
}

}  // namespace crumple
