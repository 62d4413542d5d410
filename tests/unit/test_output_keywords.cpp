// Output requests: /TH/... (variable lines, object lines, names, resolution to dense indices) and /SECT (every
// line, including the blank file-name line), with the errors for malformed cards.
#include <gtest/gtest.h>

#include "crumple/model/cut_sections.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_output_keywords {

using namespace crumple;
using test::blank;
using test::I;
using test::R;

namespace {

bool warned(const Deck& d, const std::string& text) {
  for (const auto& w : d.report.warnings)
    if (w.text().find(text) != std::string::npos) return true;
  return false;
}

std::string all_warnings(const Deck& d) {
  std::string out;
  for (const auto& w : d.report.warnings) out += w.text() + "\n";
  return out;
}

std::string vec(double x, double y, double z) { return R(x) + R(y) + R(z) + "\n"; }

// Objects for the requests to refer to, on top of the plate (nodes 1-6, shells 1-2, part 1): node 7, node groups
// 10 (plate) and 14 (nodes 3, 6), shell group 6, surface 20, subset 30, rigid wall 1, rigid body 7, interface 5.
std::string references() {
  std::string s = "/NODE\n" + I(7) + R(0.05) + R(0.0) + R(0.1) + "\n";
  s += "/GRNOD/NODE/10\nplate\n" + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + "\n";
  s += "/GRNOD/NODE/14\nedge\n" + I(3) + I(6) + "\n";
  s += "/GRSHEL/SHEL/6\nshells\n" + I(1) + I(2) + "\n";
  s += "/SURF/PART/20\nsurface\n" + I(1) + "\n";
  s += "/SUBSET/30\nsubset\n";
  s += "/RWALL/PLANE/1\nwall\n" + I(0) + I(0) + I(10) + I(0) + "\n" + vec(0, 0, 0) + vec(0, 0, -1) + vec(0, 0, 0);
  s += "/RBODY/7\nbody\n" + I(7) + I(0) + I(0) + I(0) + R(3.0) + I(14) + I(0) + I(0) + I(0) + "\n" + vec(0, 0, 0) +
       vec(0, 0, 0) + I(0) + I(0) + "\n";
  s += "/INTER/TYPE7/5\ncontact\n" + I(10) + I(20) + "\n\n\n\n" + "       000\n\n";
  return s;
}

// A section cut through the plate, as in the QA deck box_crush (blank file-name line).
std::string section(long long id, const std::string& groups_line = I(0) + I(0) + I(6) + I(0) + I(0) + I(0) + I(0) +
                                                                       I(0) + I(0) + I(1),
                    const std::string& frame_line = I(1) + I(2) + I(4) + I(10) + I(0) + I(0) + R(0.0) + R(0.0)) {
  return "/SECT/" + std::to_string(id) + "\nsection_" + std::to_string(id) + "\n" + frame_line + "\n" + blank(100) +
         "\n" + groups_line + "\n";
}

std::filesystem::path starter(const test::TempDir& dir, const std::string& cards) {
  return dir.write("T_0000.rad", test::begin_card() + test::plate_cards() + references() + cards + "/END\n");
}

Deck read(const std::string& cards) {
  test::TempDir dir;
  return read_deck(starter(dir, cards));
}

std::string error_of(const std::string& cards) {
  test::TempDir dir;
  return test::first_error(starter(dir, cards));
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string th(const std::string& keyword, const std::string& variables, const std::string& objects) {
  return keyword + "\ngroup title\n" + variables + "\n" + objects;
}

std::string var(const std::string& name) { return name + blank(10 - static_cast<int>(name.size())); }

}  // namespace

TEST(OutputKeywords, NodeHistoryOneObjectPerLineWithName) {
  const std::string objects = I(6) + I(0) + blank(20) + "corner" + "\n" + I(1) + I(0) + blank(80) + "\n";
  const Deck d = read(th("/TH/NODE/2", var("DEF") + var("ax") + var("REACX"), objects));
  ASSERT_EQ(d.model.histories.size(), 1u);
  const TimeHistoryRequest& h = d.model.histories[0];
  EXPECT_EQ(h.keyword, "/TH/NODE/2");
  EXPECT_EQ(h.user_id, 2);
  EXPECT_EQ(h.title, "group title");
  EXPECT_EQ(h.object, HistoryObject::Node);
  EXPECT_EQ(h.variables, (std::vector<std::string>{"DEF", "AX", "REACX"}));
  EXPECT_EQ(h.object_ids, (std::vector<std::int64_t>{6, 1}));
  EXPECT_EQ(h.object_names, (std::vector<std::string>{"corner", ""}));
  EXPECT_EQ(h.objects, (std::vector<std::int32_t>{5, 0}));
}

TEST(OutputKeywords, ListHistoriesReadTenIdsPerLineOverSeveralLines) {
  const std::string cards = th("/TH/PART/1", var("DEF"), I(1) + "\n") +
                            th("/TH/RWALL/3", var("FNX") + var("FNY"), I(1) + "\n") +
                            th("/TH/RBODY/4", var("DEF") + var("F"), I(7) + "\n") +
                            th("/TH/INTER/5", var("DEF") + var("|FNX|") + var("CE_ELAST"), I(5) + "\n") +
                            th("/TH/SUBS/8", var("IE"), I(30) + "\n") + section(11) + section(12) +
                            th("/TH/SECTIO/6", var("DEF") + "\n" + var("WORK"),
                               I(11) + "\n" + blank(10) + I(12) + "\n");
  const Deck d = read(cards);
  const auto& h = d.model.histories;
  ASSERT_EQ(h.size(), 6u);
  EXPECT_EQ(h[0].object, HistoryObject::Part);
  EXPECT_EQ(h[1].object, HistoryObject::RigidWall);
  EXPECT_EQ(h[1].objects, (std::vector<std::int32_t>{0}));
  EXPECT_EQ(h[2].object, HistoryObject::RigidBody);
  EXPECT_EQ(h[2].objects, (std::vector<std::int32_t>{0}));
  EXPECT_EQ(h[3].object, HistoryObject::Interface);
  EXPECT_EQ(h[3].variables, (std::vector<std::string>{"DEF", "|FNX|", "CE_ELAST"}));
  EXPECT_EQ(h[4].object, HistoryObject::Subset);
  EXPECT_EQ(h[5].object, HistoryObject::Section);
  EXPECT_EQ(h[5].variables, (std::vector<std::string>{"DEF", "WORK"}));  // two variable lines
  EXPECT_EQ(h[5].object_ids, (std::vector<std::int64_t>{11, 12}));
  EXPECT_EQ(h[5].objects, (std::vector<std::int32_t>{0, 1}));
  EXPECT_TRUE(h[0].object_names.empty());
}

// /TH/SHELL is the spelling HyperCrash writes (QA box_crush); it reads as /TH/SHEL and keeps its keyword text.
TEST(OutputKeywords, ShellHistoryAcceptsBothSpellings) {
  const std::string objects = I(2) + I(0) + blank(20) + "mid" + "\n";
  const Deck d = read(th("/TH/SHELL/3", var("DEF"), objects) + th("/TH/SHEL/4", var("STRESS") + var("EMAX"), objects));
  const auto& h = d.model.histories;
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(h[0].keyword, "/TH/SHELL/3");
  EXPECT_EQ(h[0].object, HistoryObject::Shell);
  EXPECT_EQ(h[1].object, HistoryObject::Shell);
  EXPECT_EQ(h[0].objects, (std::vector<std::int32_t>{1}));
  EXPECT_EQ(h[1].object_names, (std::vector<std::string>{"mid"}));
}

TEST(OutputKeywords, ElementHistoriesLookInTheirOwnElementTable) {
  // Shell 1 exists, but no 3-node shell or brick does: each request resolves against its own element kind.
  const std::string sh3n = error_of(th("/TH/SH3N/3", var("DEF"), I(1) + I(0) + "\n"));
  EXPECT_TRUE(contains(sh3n, "3-node shell 1 not defined")) << sh3n;
  const std::string bric = error_of(th("/TH/BRIC/3", var("DEF") + var("SX"), I(1) + blank(10) + "solid\n"));
  EXPECT_TRUE(contains(bric, "brick 1 not defined")) << bric;
  const std::string bric_columns = error_of(th("/TH/BRIC/3", var("DEF"), I(1) + I(5) + "\n"));
  EXPECT_TRUE(contains(bric_columns, "columns 11-20")) << bric_columns;
}

TEST(OutputKeywords, DuplicateObjectIsKeptOnceWithAWarning) {
  const Deck d = read(th("/TH/PART/1", var("DEF"), I(1) + I(1) + "\n"));
  EXPECT_EQ(d.model.histories[0].object_ids, (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(warned(d, "listed twice"));
}

TEST(OutputKeywords, MalformedHistoriesAreErrorsNamingTheField) {
  const std::string no_variables = error_of("/TH/PART/1\ntitle\n" + I(1) + "\n");
  EXPECT_TRUE(contains(no_variables, "var_ID1")) << no_variables;
  const std::string nothing = error_of("/TH/PART/1\ntitle\n");
  EXPECT_TRUE(contains(nothing, "var_ID1")) << nothing;
  const std::string negative = error_of(th("/TH/PART/1", var("DEF"), I(-1) + "\n"));
  EXPECT_TRUE(contains(negative, "Obj_ID")) << negative;
  const std::string late_variable = error_of(th("/TH/PART/1", var("DEF"), I(1) + "\n" + var("IE") + "\n"));
  EXPECT_TRUE(contains(late_variable, "Obj_ID")) << late_variable;
  const std::string skew = error_of(th("/TH/NODE/2", var("DEF"), I(1) + I(3) + "\n"));
  EXPECT_TRUE(contains(skew, "skew_ID")) << skew;
  const std::string missing = error_of(th("/TH/NODE/2", var("DEF"), I(99) + "\n"));
  EXPECT_TRUE(contains(missing, "node 99 not defined")) << missing;
  const std::string no_id = error_of(th("/TH/NODE", var("DEF"), I(1) + "\n"));
  EXPECT_TRUE(contains(no_id, "an id in the keyword line")) << no_id;
  const std::string past_100 = error_of(th("/TH/PART/1", var("DEF"), I(1) + blank(90) + "7\n"));
  EXPECT_TRUE(contains(past_100, "column 100")) << past_100;
}

TEST(OutputKeywords, HistoryWithoutObjectsIsAWarning) {
  const Deck d = read(th("/TH/PART/1", var("DEF"), ""));
  ASSERT_EQ(d.model.histories.size(), 1u);
  EXPECT_TRUE(d.model.histories[0].object_ids.empty());
  EXPECT_TRUE(warned(d, "no objects"));
}

// Output requests Crumple does not write are warnings naming the card and exactly what is missing, never errors:
// a name that is no variable of the kind, the variables Crumple does not compute (groups expanded), and a kind of
// object whose history it does not record. What NAME.h5 records draws no warning.
TEST(OutputKeywords, HistoriesCrumpleDoesNotWriteAreNamedWarnings) {
  auto skipped = [](const Deck& d) {
    std::vector<std::string> texts;
    for (const auto& option : d.report.skipped_options) {
      EXPECT_EQ(option.kind, SkipKind::OutputOnly);
      texts.push_back(option.keyword + ": " + option.what);
    }
    return texts;
  };
  const Deck unknown = read(th("/TH/NODE/2", var("DEF") + var("TEMP"), I(1) + "\n"));
  EXPECT_EQ(skipped(unknown), (std::vector<std::string>{
                                  "/TH/NODE/2: output-only: TEMP not among the variables of /TH/NODE/2 in the manual "
                                  "that Crumple computes"}));
  // DEF of a shell names the membrane and bending energies, which Crumple does not split.
  const Deck shell = read(th("/TH/SHEL/3", var("DEF") + var("THIC"), I(1) + I(0) + "\n"));
  EXPECT_EQ(skipped(shell), (std::vector<std::string>{"/TH/SHEL/3: output-only: variables IEM IEB not written "
                                                      "(NAME.h5 records the others)"}));
  const Deck inertia = read(th("/TH/PART/1", var("IXX") + var("XXMOM") + var("FOO"), I(1) + "\n"));
  EXPECT_EQ(skipped(inertia), (std::vector<std::string>{
                                  "/TH/PART/1: output-only: time history not written by Crumple; variables IXX XXMOM "
                                  "not written; FOO not among the variables of /TH/PART/1 in the manual that Crumple "
                                  "computes"}));
  // An interface's moments: the manual does not say about which point.
  const Deck moments = read(th("/TH/INTER/5", var("|FNX|") + var("MX"), I(5) + "\n"));
  EXPECT_EQ(skipped(moments), (std::vector<std::string>{"/TH/INTER/5: output-only: variables MX not written (NAME.h5 "
                                                        "records the others)"}));
  // Sections: WORKR (the manual does not say what it is) and the errors of imposed sections are not written.
  const Deck sections = read(section(11) + th("/TH/SECTIO/6", var("DEF") + var("WORKR") + var("DFX"), I(11) + "\n"));
  EXPECT_EQ(skipped(sections), (std::vector<std::string>{"/TH/SECTIO/6: output-only: variables WORKR DFX not written "
                                                         "(NAME.h5 records the others)"}));
  // Everything these ask for is in NAME.h5.
  const std::string all_written = th("/TH/PART/1", var("DEF") + var("XCG") + var("RKE"), I(1) + "\n") +
                                  th("/TH/SUBS/8", var("DEF"), I(30) + "\n") +
                                  th("/TH/RWALL/3", var("DEF"), I(1) + "\n") +
                                  th("/TH/RBODY/4", var("DEF"), I(7) + "\n") +
                                  th("/TH/INTER/5", var("DEF") + var("CE_ELAST") + var("CE_FRIC") + var("CE_DAMP") +
                                                        var("|FN|") + var("|F|") + var("FN") + var("FT"),
                                     I(5) + "\n") +
                                  th("/TH/NODE/2", var("XYZ") + var("A") + var("VR") + var("AR") + var("REACX") +
                                                       var("DRX") + var("DRZ"),
                                     I(1) + "\n") +
                                  th("/TH/SHELL/3", var("STRESS") + var("PLAS") + var("OFF") + var("EPSD"),
                                     I(1) + I(0) + "\n") +
                                  section(11) +
                                  th("/TH/SECTIO/6", var("DEF") + var("CENTER") + var("GLOBAL") + var("LOCAL") +
                                                         var("WORK"),
                                     I(11) + "\n");
  EXPECT_TRUE(skipped(read(all_written)).empty()) << all_warnings(read(all_written));
}

// /ACCEL (docs/cards/loads-output-engine.md §6.3): node_ID 1-10, skew_ID 11-20 (0), Fcut 31-50 (blank: 0, no
// filter); /TH/ACCEL names accelerometers by their ids and draws no warning.
TEST(OutputKeywords, AccelerometersAndTheirHistory) {
  const std::string cards = "/ACCEL/4\nhead\n" + I(5) + I(0) + blank(10) + R(1650.0) + "\n" + "/ACCEL/9\n\n" + I(7) +
                            "\n" + th("/TH/ACCEL/3", var("DEF") + var("W"), I(9) + I(4) + "\n");
  const Deck d = read(cards);
  ASSERT_EQ(d.model.accelerometers.size(), 2u);
  const Accelerometer& head = d.model.accelerometers[0];
  EXPECT_EQ(head.user_id, 4);
  EXPECT_EQ(head.title, "head");
  EXPECT_EQ(head.node_id, 5);
  EXPECT_EQ(head.node, d.model.index.nodes.at(5));
  EXPECT_EQ(head.cutoff, 1650.0);
  EXPECT_EQ(d.model.accelerometers[1].node, d.model.index.nodes.at(7));
  EXPECT_EQ(d.model.accelerometers[1].cutoff, 0.0);
  ASSERT_EQ(d.model.histories.size(), 1u);
  const TimeHistoryRequest& h = d.model.histories[0];
  EXPECT_EQ(h.object, HistoryObject::Accelerometer);
  EXPECT_EQ(h.objects, (std::vector<std::int32_t>{1, 0}));
  EXPECT_TRUE(d.report.warnings.empty()) << all_warnings(d);
  EXPECT_TRUE(d.report.skipped_options.empty());
}

TEST(OutputKeywords, MalformedAccelerometersAreErrorsNamingTheField) {
  const std::string skew = error_of("/ACCEL/4\nhead\n" + I(5) + I(2) + "\n");
  EXPECT_TRUE(contains(skew, "/ACCEL/4: field skew_ID")) << skew;
  EXPECT_TRUE(contains(skew, "expected an existing skew, found skew 2 not defined")) << skew;
  const std::string negative = error_of("/ACCEL/4\nhead\n" + I(5) + I(0) + blank(10) + R(-1.0) + "\n");
  EXPECT_TRUE(contains(negative, "field Fcut")) << negative;
  EXPECT_TRUE(contains(negative, "non-negative cutoff frequency")) << negative;
  const std::string no_node = error_of("/ACCEL/4\nhead\n" + I(0) + "\n");
  EXPECT_TRUE(contains(no_node, "field node_ID")) << no_node;
  const std::string missing = error_of("/ACCEL/4\nhead\n" + I(99) + "\n");
  EXPECT_TRUE(contains(missing, "node 99 not defined")) << missing;
  const std::string unit = error_of("/ACCEL/4/2\nhead\n" + I(5) + "\n");
  EXPECT_TRUE(contains(unit, "unit_ID")) << unit;
  const std::string unread = error_of("/ACCEL/4\nhead\n" + I(5) + I(0) + I(7) + "\n");  // columns 21-30 are blank
  EXPECT_TRUE(contains(unread, "columns 30-30")) << unread;
  const std::string unknown = error_of("/ACCEL/4\nhead\n" + I(5) + "\n" + th("/TH/ACCEL/3", var("DEF"), I(8) + "\n"));
  EXPECT_TRUE(contains(unknown, "accelerometer 8 not defined")) << unknown;
  const std::string twice = error_of("/ACCEL/4\nhead\n" + I(5) + "\n/ACCEL/4\nagain\n" + I(6) + "\n");
  EXPECT_TRUE(contains(twice, "/ACCEL/4")) << twice;
}

// QA box_crush layout: the all-blank file-name line is a data line; without it the group line would be misread.
TEST(OutputKeywords, SectionReadsEveryLine) {
  const std::string frame = I(1) + I(2) + I(4) + I(10) + I(0) + I(0) + R(1e-4) + R(0.5);
  const Deck d = read(section(8, I(0) + I(0) + I(6) + I(0) + I(0) + I(0) + I(0) + I(1) + I(0) + I(12), frame) +
                      I(5) + "\n");
  ASSERT_EQ(d.model.sections.size(), 1u);
  const Section& s = d.model.sections[0];
  EXPECT_EQ(s.user_id, 8);
  EXPECT_EQ(s.title, "section_8");
  EXPECT_EQ(s.node_ids[0], 1);
  EXPECT_EQ(s.node_ids[1], 2);
  EXPECT_EQ(s.node_ids[2], 4);
  EXPECT_EQ(s.node_group_id, 10);
  EXPECT_DOUBLE_EQ(s.dt, 1e-4);
  EXPECT_DOUBLE_EQ(s.alpha, 0.5);
  EXPECT_EQ(s.file_name, "");
  EXPECT_EQ(s.shell_group_id, 6);
  EXPECT_EQ(s.ninter, 1);
  EXPECT_EQ(s.iframe, 12);
  EXPECT_EQ(s.interface_ids, (std::vector<std::int64_t>{5}));
  EXPECT_EQ(s.interfaces, (std::vector<std::int32_t>{0}));
  EXPECT_EQ(s.node_group, 0);
  EXPECT_EQ(s.shell_group, 0);
}

TEST(OutputKeywords, MalformedSectionsAreErrorsNamingTheField) {
  const std::string group_line = I(0) + I(0) + I(6);
  auto frame = [](long long isave, long long frame_id) {
    return I(1) + I(2) + I(4) + I(10) + I(isave) + I(frame_id) + R(0.0) + R(0.0);
  };
  EXPECT_TRUE(contains(error_of(section(1, group_line, frame(1, 0))), "field ISAVE"));
  EXPECT_TRUE(contains(error_of(section(1, group_line, frame(0, 3))), "field frame_ID"));
  EXPECT_TRUE(contains(error_of(section(1, I(4) + I(0) + I(6))), "field grbric_ID"));
  EXPECT_TRUE(contains(error_of(section(1, I(0) + I(0) + I(6) + I(0) + I(0) + I(0) + I(2))), "field grtria_ID"));
  EXPECT_TRUE(contains(error_of(section(1, group_line + blank(40) + I(11))), "field Ninter"));
  EXPECT_TRUE(contains(error_of(section(1, group_line + blank(60) + I(5))), "field Iframe"));
  // Ninter = 2 but one id only.
  const std::string ids = error_of(section(1, group_line + blank(40) + I(2)) + I(5) + "\n");
  EXPECT_TRUE(contains(ids, "int_ID2")) << ids;
  // Without the blank file-name line the card is one line short.
  const std::string truncated = error_of("/SECT/1\ncut\n" + frame(0, 0) + "\n" + group_line + "\n");
  EXPECT_TRUE(contains(truncated, "truncated")) << truncated;
  const std::string paral = error_of("/SECT/PARAL/1\ncut\n");
  EXPECT_TRUE(contains(paral, "/SECT/PARAL form is not supported")) << paral;
  const std::string unit = error_of(section(1) + "" + "/SECT/2/7\ncut\n");
  EXPECT_TRUE(contains(unit, "unit_ID")) << unit;
  const std::string group = error_of(section(1, I(0) + I(0) + I(66)));
  EXPECT_TRUE(contains(group, "shell group 66 not defined")) << group;
  const std::string interface = error_of(section(1, group_line + blank(40) + I(1)) + I(55) + "\n");
  EXPECT_TRUE(contains(interface, "interface 55 not defined")) << interface;
}

TEST(OutputKeywords, EmptySectionIsAWarning) {
  const Deck d = read(section(1, I(0), I(1) + I(2) + I(4)));
  std::string all;
  for (const auto& w : d.report.warnings) all += w.text() + "\n";
  EXPECT_TRUE(contains(all, "no node group")) << all;
  EXPECT_TRUE(contains(all, "records nothing")) << all;
}

// /GRSH3N and /GRBRIC (docs/deck-format.md): element groups of 3-node shells and bricks, by ids or by parts, for
// the sections' grtria_ID and grbric_ID; a member of another kind is not found.
TEST(OutputKeywords, SectionsTakeTriangleAndBrickGroups) {
  std::string cards = "/NODE\n";
  for (int k = 0; k < 8; ++k)
    cards += I(101 + k) + R(0.1 + 0.01 * (k % 2)) + R(0.01 * ((k / 2) % 2)) + R(0.01 * (k / 4)) + "\n";
  cards += "/SH3N/2\n" + I(5) + I(1) + I(2) + I(4) + "\n" + I(6) + I(2) + I(5) + I(4) + "\n";
  cards += "/PART/2\ntriangles\n" + I(1) + I(1) + "\n";
  cards += "/BRICK/3\n" + I(9) + I(101) + I(102) + I(104) + I(103) + I(105) + I(106) + I(108) + I(107) + "\n";
  cards += "/PART/3\nbrick\n" + I(3) + I(1) + "\n/PROP/SOLID/3\nsolid\n" + I(1) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
  cards += "/GRSH3N/SH3N/7\ntriangles\n" + I(6) + "\n/GRSH3N/PART/8\nby part\n" + I(2) + "\n";
  cards += "/GRBRIC/BRIC/9\nbrick\n" + I(9) + "\n/GRBRIC/PART/10\nby part\n" + I(3) + "\n";
  const std::string groups = I(9) + I(0) + I(6) + I(0) + I(0) + I(0) + I(7) + I(0) + I(0) + I(1);
  const Deck d = read(cards + section(1, groups) + th("/TH/SECTIO/6", var("DEF"), I(1) + "\n"));
  const Model& m = d.model;
  ASSERT_EQ(m.sh3n_groups.size(), 2u);
  ASSERT_EQ(m.brick_groups.size(), 2u);
  const auto sh3n = static_cast<std::int32_t>(m.index.elements[static_cast<int>(ElementKind::Shell3)].at(6));
  EXPECT_EQ(m.sh3n_groups[0].elements, (std::vector<std::int32_t>{sh3n}));
  EXPECT_EQ(m.sh3n_groups[1].elements.size(), 2u);
  EXPECT_EQ(m.brick_groups[0].elements, (std::vector<std::int32_t>{0}));
  EXPECT_EQ(m.brick_groups[1].elements, (std::vector<std::int32_t>{0}));
  const Section& s = m.sections[0];
  EXPECT_EQ(s.brick_group, 0);
  EXPECT_EQ(s.shell_group, 0);
  EXPECT_EQ(s.sh3n_group, 0);
  EXPECT_EQ(s.nodes[0], m.index.nodes.at(1));
  EXPECT_EQ(s.nodes[2], m.index.nodes.at(4));
  const auto elements = section_elements(m, s);
  EXPECT_EQ(elements[0].size(), 2u);  // shells 1, 2
  EXPECT_EQ(elements[1], (std::vector<std::int32_t>{sh3n}));
  EXPECT_EQ(elements[2], (std::vector<std::int32_t>{0}));
  EXPECT_TRUE(d.report.warnings.empty()) << all_warnings(d);
  const std::string other = error_of(cards + "/GRSH3N/SH3N/11\nwrong kind\n" + I(1) + "\n");
  EXPECT_TRUE(contains(other, "/GRSH3N/SH3N/11: field sh3n_ID")) << other;
  EXPECT_TRUE(contains(other, "3-node shell 1 not defined")) << other;
  const std::string brick = error_of(cards + section(1, I(99)));
  EXPECT_TRUE(contains(brick, "field grbric_ID")) << brick;
  EXPECT_TRUE(contains(brick, "brick group 99 not defined")) << brick;
}

// What a section sums (include/crumple/model/cut_sections.hpp): the slots of its elements at its nodes, in model
// order. Nodes 3 and 6 are the plate's edge x = 0.02, which only shell 2 (nodes 2 3 6 5) touches.
TEST(OutputKeywords, SectionTermsAreTheElementsNodesOnTheCut) {
  const std::string groups = I(0) + I(0) + I(6) + I(0) + I(0) + I(0) + I(0) + I(0) + I(0) + I(1);
  const std::string frame = I(3) + I(6) + I(7) + I(14) + I(0) + I(0) + R(0.0) + R(0.0);
  const Deck d = read(section(1, groups, frame) + th("/TH/SECTIO/6", var("DEF"), I(1) + "\n"));
  const Model& m = d.model;
  const std::vector<SectionTerm> terms = section_terms(m, m.sections[0]);
  ASSERT_EQ(terms.size(), 2u);
  const auto shell2 = m.index.elements[static_cast<int>(ElementKind::Shell4)].at(2);
  EXPECT_EQ(terms[0].kind, ElementKind::Shell4);
  EXPECT_EQ(terms[0].element, shell2);
  EXPECT_EQ(terms[0].slot, 1);
  EXPECT_EQ(terms[0].node, m.index.nodes.at(3));
  EXPECT_EQ(terms[1].slot, 2);
  EXPECT_EQ(terms[1].node, m.index.nodes.at(6));
}

// A section that /TH/SECTIO writes needs its frame (three nodes off one line) and no interfaces across the cut
// (their forces are not in the sums); a section no request writes is only read.
TEST(OutputKeywords, WrittenSectionsNeedAFrameAndNoInterfaces) {
  const std::string groups = I(0) + I(0) + I(6);
  auto written = [&](const std::string& card) { return card + th("/TH/SECTIO/6", var("DEF"), I(1) + "\n"); };
  const std::string interfaces = written(section(1, groups + blank(40) + I(1)) + I(5) + "\n");
  EXPECT_TRUE(contains(error_of(interfaces), "/SECT/1: field Ninter")) << error_of(interfaces);
  EXPECT_TRUE(contains(error_of(interfaces), "not supported by Crumple")) << error_of(interfaces);
  EXPECT_TRUE(error_of(section(1, groups + blank(40) + I(1)) + I(5) + "\n").empty());  // not written: read only
  const std::string blank_node = written(section(1, groups, I(1) + I(2) + I(0) + I(10)));
  EXPECT_TRUE(contains(error_of(blank_node), "field node_ID3")) << error_of(blank_node);
  const std::string in_line = written(section(1, groups, I(1) + I(2) + I(3) + I(10)));  // nodes 1 2 3 on y = 0
  EXPECT_TRUE(contains(error_of(in_line), "a node off the line N1N2")) << error_of(in_line);
  const std::string same_place = written(section(1, groups, I(1) + I(1) + I(3) + I(10)));
  EXPECT_TRUE(contains(error_of(same_place), "field node_ID2")) << error_of(same_place);
  // Nodes 1, 4 (x = 0) are not nodes of shell 2 (group 6 holds shells 1 and 2; shell 1 has them): a group of shell 2
  // alone and a cut at x = 0 do not meet.
  const std::string apart = "/GRSHEL/SHEL/16\nright\n" + I(2) + "\n/GRNOD/NODE/17\nleft edge\n" + I(1) + I(4) + "\n" +
                            written(section(1, I(0) + I(0) + I(16), I(1) + I(2) + I(4) + I(17)));
  EXPECT_TRUE(warned(read(apart), "no element of the section's groups has a node of its cut")) << all_warnings(read(apart));
  EXPECT_FALSE(warned(read(written(section(1))), "has a node of its cut"));
  test::TempDir dir;
  ReadOptions skip;
  skip.skip_unknown = true;
  const Deck skipped = read_deck(starter(dir, interfaces), skip);
  EXPECT_EQ(skipped.model.sections[0].ninter, 0);
  EXPECT_TRUE(skipped.model.sections[0].interfaces.empty());
  EXPECT_FALSE(skipped.report.skipped_options.empty());
}

}  // namespace test_output_keywords
