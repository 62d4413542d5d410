// The /TH variable tables (include/crumple/model/history_variables.hpp): groups expand to variables of their own
// kind, in the request's order, each once; the SI factor of a dimension.
#include <gtest/gtest.h>

#include <set>

#include "crumple/model/history_variables.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_history_variables {

using namespace crumple;

namespace {

constexpr HistoryObject kAll[] = {HistoryObject::Node,  HistoryObject::Part,      HistoryObject::RigidWall,
                                  HistoryObject::Interface, HistoryObject::Shell, HistoryObject::Sh3n,
                                  HistoryObject::Brick, HistoryObject::Subset,    HistoryObject::Section,
                                  HistoryObject::RigidBody};

std::vector<std::string> names(const HistorySelection& s) {
  std::vector<std::string> out;
  for (const HistoryVariable* v : s.variables) out.emplace_back(v->name);
  return out;
}

}  // namespace

TEST(HistoryVariables, EveryGroupExpandsToVariablesOfItsKindAndNamesAreUnique) {
  for (HistoryObject object : kAll) {
    const HistoryKind& kind = history_kind(object);
    std::set<std::string_view> seen;
    for (const HistoryVariable& v : kind.variables) {
      EXPECT_TRUE(seen.insert(v.name).second) << kind.name << " " << v.name;
      EXPECT_FALSE(v.unit.empty()) << kind.name << " " << v.name;
    }
    for (const HistoryGroup& g : kind.groups) {
      EXPECT_FALSE(seen.count(g.name)) << kind.name << ": group " << g.name << " is also a variable";
      const HistorySelection s = select_history_variables(object, {std::string(g.name)});
      EXPECT_TRUE(s.unknown.empty()) << kind.name << " " << g.name;
      EXPECT_EQ(s.variables.size(), g.members.size()) << kind.name << " " << g.name;
      for (const HistoryVariable* v : s.variables) EXPECT_NE(v, nullptr) << kind.name << " " << g.name;
    }
  }
}

TEST(HistoryVariables, SelectionKeepsTheRequestOrderAndEachVariableOnce) {
  const HistorySelection s = select_history_variables(HistoryObject::Node, {"X", "DEF", "DX", "V", "TEMP", "A"});
  EXPECT_EQ(names(s), (std::vector<std::string>{"X", "DX", "DY", "DZ", "VX", "VY", "VZ", "AX", "AY", "AZ"}));
  EXPECT_EQ(s.unknown, (std::vector<std::string>{"TEMP"}));
  EXPECT_EQ(names(select_history_variables(HistoryObject::Shell, {"DEF"})),
            (std::vector<std::string>{"F1", "F2", "F12", "M1", "M2", "M12", "IEM", "IEB", "OFF", "EMIN", "EMAX"}));
  EXPECT_EQ(names(select_history_variables(HistoryObject::Brick, {"DEF"})),
            (std::vector<std::string>{"OFF", "SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "IE", "DENS", "PLAS"}));
  EXPECT_EQ(names(select_history_variables(HistoryObject::RigidBody, {"M", "F"})),
            (std::vector<std::string>{"MX", "MY", "MZ", "FX", "FY", "FZ"}));
}

TEST(HistoryVariables, SiFactorIsTheProductOfTheUnitSizes) {
  const double kg_mm_ms[3] = {1.0, 0.001, 0.001};
  EXPECT_DOUBLE_EQ(si_factor({1, 1, -2}, kg_mm_ms), 1000.0);  // a force of 1 kg mm / ms^2 is 1 kN
  EXPECT_DOUBLE_EQ(si_factor({0, 1, -1}, kg_mm_ms), 1.0);     // 1 mm/ms = 1 m/s
  EXPECT_DOUBLE_EQ(si_factor({1, -1, -2}, kg_mm_ms), 1e9);    // 1 kg/(mm ms^2) = 1 GPa
  EXPECT_DOUBLE_EQ(si_factor({1, 2, -2}, kg_mm_ms), 1.0);     // 1 kg mm^2 / ms^2 = 1 J
  EXPECT_DOUBLE_EQ(si_factor({0, 0, 0}, kg_mm_ms), 1.0);
}

// /TH/SECTIO (docs/output-format.md, "SECTIO"): the manual's groups; WORKR and the imposed-section errors are named
// but not written.
TEST(HistoryVariables, SectionGroupsAndWhatIsWritten) {
  EXPECT_EQ(names(select_history_variables(HistoryObject::Section, {"DEF"})),
            (std::vector<std::string>{"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "M1", "M2", "M3"}));
  EXPECT_EQ(names(select_history_variables(HistoryObject::Section, {"CENTER", "LOCAL", "GLOBAL", "WORK"})),
            (std::vector<std::string>{"CX", "CY", "CZ", "F1", "F2", "F3", "M1", "M2", "M3", "FNX", "FNY", "FNZ", "FTX",
                                      "FTY", "FTZ", "MX", "MY", "MZ", "WORK"}));
  for (const HistoryVariable& v : history_kind(HistoryObject::Section).variables)
    EXPECT_EQ(v.written, v.name != "WORKR" && !v.name.starts_with("DF") && !v.name.starts_with("DM")) << v.name;
}

}  // namespace test_history_variables
