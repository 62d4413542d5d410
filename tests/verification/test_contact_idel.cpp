// Idel (type7.md §2): segments of deleted elements leave the main surface; secondary nodes none of whose elements
// is left leave the secondary set; with Idel 0 nothing leaves.
#include "contact_cards.hpp"
#include "crumple/contact/contact.hpp"
#include "crumple/solver/solver.hpp"  // initial_state (the start state of a run)

namespace crumple::verification::test_contact_idel {
namespace {

// Plate of two shells (part 2, main surface) and a block of two shells (part 1) sharing node 102, above it.
SolverState start(int idel, Model& model) {
  const std::vector<NodeRow> nodes{{1, 0.0, 0.0, 0.0},   {2, 0.1, 0.0, 0.0},   {3, 0.2, 0.0, 0.0},
                                   {4, 0.0, 0.1, 0.0},   {5, 0.1, 0.1, 0.0},   {6, 0.2, 0.1, 0.0},
                                   {101, 0.05, 0.02, 0.01}, {102, 0.1, 0.02, 0.01}, {103, 0.15, 0.02, 0.01},
                                   {104, 0.05, 0.08, 0.01}, {105, 0.1, 0.08, 0.01}, {106, 0.15, 0.08, 0.01}};
  Type7Options o;
  o.gapmin = 1e-3, o.idel = idel;
  const std::string starter = node_cards(nodes) + shell_cards(1, {{1, 101, 102, 105, 104}, {2, 102, 103, 106, 105}}) +
                              shell_cards(2, {{3, 1, 2, 5, 4}, {4, 2, 3, 6, 5}}) + part_card(1) + part_card(2) +
                              shell_property(0.002, 1) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, {101, 102, 103, 104, 105, 106}) + surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  test::TempDir dir;
  model = read_deck(dir.write("I_0000.rad", test::begin_card("I") + starter + "/END\n")).model;
  std::vector<std::string> notes;
  return initial_state(model, notes);
}

std::size_t active(const std::vector<std::uint8_t>& flags) {
  std::size_t n = 0;
  for (std::uint8_t f : flags) n += f != 0;
  return n;
}

void remove(SolverState& s) {
  contact::remove_deleted_elements(s.contact, {&s.shells.deleted, &s.shells3.deleted, &s.bricks.deleted});
}

TEST(ContactIdel, DeletedElementsLeaveTheInterface) {
  Model model;
  SolverState s = start(2, model);
  const ContactInterface& in = s.contact.interfaces.at(0);
  ASSERT_EQ(active(in.node_active), 6u);
  ASSERT_EQ(active(in.segment_active), 2u);
  const auto shell = [&](long long id) { return static_cast<std::size_t>(model.index.elements[0].at(id)); };
  // Block shell 1 fails: its own nodes 101 and 104 leave; 102 and 105 keep shell 2.
  s.shells.deleted[shell(1)] = 1;
  remove(s);
  EXPECT_EQ(active(in.node_active), 4u);
  for (std::size_t i = 0; i < in.secondary_nodes.size(); ++i) {
    const long long id = model.nodes.user_id[static_cast<std::size_t>(in.secondary_nodes[i])];
    EXPECT_EQ(in.node_active[i] != 0, id != 101 && id != 104) << "node " << id;
  }
  // Plate shell 3 fails: its segment leaves the main surface.
  s.shells.deleted[shell(3)] = 1;
  remove(s);
  EXPECT_EQ(active(in.segment_active), 1u);
}

TEST(ContactIdel, IdelZeroKeepsEverything) {
  Model model;
  SolverState s = start(0, model);
  for (std::uint8_t& d : s.shells.deleted) d = 1;
  remove(s);
  EXPECT_EQ(active(s.contact.interfaces.at(0).node_active), 6u);
  EXPECT_EQ(active(s.contact.interfaces.at(0).segment_active), 2u);
}

// Elements deleted by the /DT/SHELL/DEL criterion leave the interface like failed ones: a plate of small shells
// (main surface, step ~ 0.9 h / c = 1.4e-6 s) under a block of large ones (secondary, 1.4e-5 s); with a minimum
// step of 5e-6 s every plate shell is deleted at the first cycle and its segment must leave the main surface.
TEST(ContactIdel, ElementsDeletedBelowTheirMinimumStepLeaveTheInterface) {
  std::vector<NodeRow> nodes;
  const std::vector<ShellRow> plate = shell_grid(10, 10, 0.01, 0.01, 0.0, 0.0, 0.0, 1, 1, nodes);
  const std::vector<ShellRow> block = shell_grid(1, 1, 0.1, 0.1, 0.0, 0.0, 0.01, 1001, 1001, nodes);
  Type7Options o;
  o.gapmin = 1e-3, o.idel = 2;
  std::vector<long long> secondary;
  for (long long id = 1001; id <= 1004; ++id) secondary.push_back(id);
  const std::string starter = node_cards(nodes) + shell_cards(1, block) + shell_cards(2, plate) + part_card(1) +
                              part_card(2) + shell_property(0.002, 1) + elastic_material(7800.0, 2.1e11, 0.3) +
                              node_group(1, secondary) + surface_of_part(2, 2) + type7_card(1, 1, 2, o);
  test::TempDir dir;
  std::size_t segments_after_first_cycle = 999, deleted = 0;
  const RunResult r = run_deck(dir, starter, 2e-5, 1e-9, [&](const Model&, const SolverState& s) {
    if (s.cycle != 1) return;
    segments_after_first_cycle = active(s.contact.interfaces.at(0).segment_active);
    deleted = active(s.shells.deleted);
  }, "/DT/SHELL/DEL\n0.9 5e-6\n");
  ASSERT_EQ(r.summary.status, RunStatus::Normal) << r.summary.message;
  EXPECT_EQ(deleted, 100u);
  EXPECT_EQ(segments_after_first_cycle, 0u);
}

}  // namespace
}  // namespace crumple::verification::test_contact_idel
