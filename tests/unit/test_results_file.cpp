// NAME.h5 / NAME.xdmf (docs/output-format.md): written through ResultsFile, read back with ResultsReader.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "crumple/elements/shell4.hpp"
#include "crumple/output/results_file.hpp"
#include "crumple/output/history_reader.hpp"
#include "crumple/output/results_reader.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_results_file {

using namespace crumple;
using test::I;
using test::R;

namespace {

constexpr double kTol = 1e-15;

// Shell state of one kind sized for the model: `points` through-thickness points per element, zero stresses.
void size_shells(ShellState& st, const Model& m, ElementKind kind, int points) {
  const std::size_t shells = m.elements[static_cast<int>(kind)].size();
  st.point_offset.assign(m.element_groups.size(), 0);
  st.points.assign(m.element_groups.size(), 0);
  std::size_t total = 0;
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != kind) continue;
    st.point_offset[g] = total;
    st.points[g] = points;
    total += static_cast<std::size_t>(group.end - group.begin) * static_cast<std::size_t>(points);
  }
  st.sxx.assign(total, 0.0), st.syy.assign(total, 0.0), st.sxy.assign(total, 0.0), st.eps_p.assign(total, 0.0);
  st.thickness.assign(shells, 0.001);
  st.deleted.assign(shells, 0);
  st.qx.assign(shells, 0.0), st.qy.assign(shells, 0.0);
}

// The plate of test::write_deck (6 nodes, 2 shells in one group) with a hand-made state: `points`
// through-thickness points per shell, at rest in the initial position.
SolverState plate_state(const Model& m, int points) {
  SolverState s;
  const std::size_t n = m.nodes.size();
  s.nodes.resize(n);
  s.x0 = m.nodes.x, s.y0 = m.nodes.y, s.z0 = m.nodes.z;
  for (std::size_t i = 0; i < n; ++i) {
    s.nodes.x[i] = m.nodes.x[i], s.nodes.y[i] = m.nodes.y[i], s.nodes.z[i] = m.nodes.z[i];
  }
  size_shells(s.shells, m, ElementKind::Shell4, points);
  size_shells(s.shells3, m, ElementKind::Shell3, points);
  return s;
}

// Moves the state by `scale`: displacements and velocities that differ per node, stresses per shell4 point.
void advance(SolverState& s, const Model& m, double scale) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const double k = static_cast<double>(i + 1);
    s.nodes.x[i] = m.nodes.x[i] + scale * 1e-4 * k;
    s.nodes.y[i] = m.nodes.y[i] - scale * 2e-4 * k;
    s.nodes.z[i] = m.nodes.z[i] + scale * 3e-4;
    s.nodes.vx[i] = scale * k, s.nodes.vy[i] = -scale, s.nodes.vz[i] = 0.5 * scale;
  }
  for (std::size_t p = 0; p < s.shells.sxx.size(); ++p) {
    const double k = static_cast<double>(p + 1);
    s.shells.sxx[p] = scale * 1e6 * k, s.shells.syy[p] = -scale * 2e6 * k, s.shells.sxy[p] = scale * 3e5;
    s.shells.eps_p[p] = scale * 0.01 * k;
  }
  for (std::size_t e = 0; e < s.shells.thickness.size(); ++e) s.shells.thickness[e] = 0.001 - scale * 1e-5;
}

HistoryRow history_row(int k) {
  HistoryRow r;
  r.time = 1e-4 * k, r.dt = 1e-7 * (k + 1);
  r.internal = 10.0 * k, r.kinetic_translational = 100.0 - k, r.kinetic_rotational = 0.5 * k, r.hourglass = 0.01 * k;
  r.contact = 0.0, r.external_work = 2.0 * k, r.total = 100.0 + 8.5 * k;
  r.rigid_wall_force = {1.0 * k, 2.0 * k, 3.0 * k};
  r.node_values = {0.1 * k, 0.2 * k, 0.3 * k, 1.0, 2.0, 3.0 + k};
  return r;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Writes the standard file of these tests: 2 frames (t = 0 and 5e-4) and 3 history rows; 2 points per shell.
std::filesystem::path write_standard(const test::TempDir& dir, const Model& m) {
  const auto path = dir.path() / "TEST.h5";
  ResultsFile file(path, m);
  SolverState s = plate_state(m, 2);
  file.write_history(history_row(0));
  file.write_frame(0.0, 0, m, s);
  file.write_history(history_row(1));
  advance(s, m, 1.0);
  s.shells.deleted[1] = 1;
  file.write_history(history_row(2));
  file.write_frame(5e-4, 100, m, s);
  EXPECT_EQ(file.frames(), 2u);
  file.close();
  file.close();  // idempotent
  return path;
}

// What a frame holds for a shell4 element of local stress `local` (sxx syy sxy): the tensor in the global axes at
// the frame's positions (shell_stress_in_global_axes, checked on its own in test_frame_fields.cpp).
std::array<double, 6> global_stress(const ResultsReader& h5, const std::string& frame, std::size_t element,
                                    const double (&local)[3]) {
  const auto x = h5.doubles(frame + "/coordinates");
  const auto connectivity = h5.ints("/mesh/shell4/connectivity");
  Vec3 corners[4];
  for (std::size_t a = 0; a < 4; ++a) {
    const auto i = static_cast<std::size_t>(connectivity[4 * element + a]);
    corners[a] = Vec3{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
  }
  return shell_stress_in_global_axes(corners, 4, local);
}

void expect_stress(const ResultsReader& h5, const std::string& frame, std::size_t element, const double (&local)[3]) {
  const auto written = h5.doubles(frame + "/shell4/stress");
  const std::array<double, 6> expected = global_stress(h5, frame, element, local);
  for (std::size_t d = 0; d < 6; ++d)
    EXPECT_NEAR(written[6 * element + d], expected[d], 1e-9 * 1e7) << frame << " element " << element << " " << d;
}

}  // namespace

TEST(ResultsFile, WritesMeshFramesAndHistories) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  const auto path = write_standard(dir, m);

  const ResultsReader h5(path);
  // Mesh: initial coordinates, user ids, 0-based connectivity (deck: 1 2 5 4 and 2 3 6 5).
  EXPECT_EQ(h5.shape("/mesh/coordinates"), (std::vector<std::size_t>{6, 3}));
  const auto xyz = h5.doubles("/mesh/coordinates");
  EXPECT_DOUBLE_EQ(xyz[3 * 2 + 0], 0.02);
  EXPECT_DOUBLE_EQ(xyz[3 * 4 + 1], 0.01);
  EXPECT_EQ(h5.longs("/mesh/node_ids"), (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(h5.shape("/mesh/shell4/connectivity"), (std::vector<std::size_t>{2, 4}));
  EXPECT_EQ(h5.ints("/mesh/shell4/connectivity"), (std::vector<std::int32_t>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(h5.longs("/mesh/shell4/ids"), (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(h5.ints("/mesh/shell4/part"), (std::vector<std::int32_t>{0, 0}));
  EXPECT_EQ(h5.longs("/mesh/shell4/part_id"), (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(h5.longs("/mesh/parts/ids"), (std::vector<std::int64_t>{1}));
  EXPECT_FALSE(h5.exists("/mesh/shell3"));
  EXPECT_FALSE(h5.exists("/mesh/brick8"));
  EXPECT_EQ(h5.attribute<std::int32_t>("/", "format_version"), 1);

  // Frames: time and cycle attributes, nodal and shell fields.
  EXPECT_TRUE(h5.exists("/frames/0000/displacement"));
  EXPECT_FALSE(h5.exists("/frames/0002"));
  EXPECT_DOUBLE_EQ(h5.attribute<double>("/frames/0001", "time"), 5e-4);
  EXPECT_EQ(h5.attribute<std::int64_t>("/frames/0001", "cycle"), 100);
  EXPECT_EQ(h5.attribute<std::int64_t>("/frames/0000", "cycle"), 0);
  for (const char* name : {"displacement", "velocity"}) {
    EXPECT_EQ(h5.shape(std::string("/frames/0001/") + name), (std::vector<std::size_t>{6, 3})) << name;
  }
  for (double u : h5.doubles("/frames/0000/displacement")) EXPECT_EQ(u, 0.0);
  const auto u = h5.doubles("/frames/0001/displacement");
  EXPECT_NEAR(u[3 * 5 + 0], 6e-4, kTol);   // node 6: +1e-4 * 6
  EXPECT_NEAR(u[3 * 5 + 1], -1.2e-3, kTol);
  EXPECT_NEAR(u[3 * 0 + 2], 3e-4, kTol);
  const auto v = h5.doubles("/frames/0001/velocity");
  EXPECT_DOUBLE_EQ(v[3 * 3 + 0], 4.0);
  EXPECT_DOUBLE_EQ(v[3 * 3 + 1], -1.0);
  EXPECT_DOUBLE_EQ(v[3 * 3 + 2], 0.5);

  // The deformed positions: the initial ones plus the displacement.
  const auto x1 = h5.doubles("/frames/0001/coordinates");
  ASSERT_EQ(x1.size(), xyz.size());
  for (std::size_t k = 0; k < x1.size(); ++k) EXPECT_NEAR(x1[k], xyz[k] + u[k], 1e-15) << k;

  EXPECT_EQ(h5.shape("/frames/0001/shell4/stress"), (std::vector<std::size_t>{2, 6}));
  // Element 2 owns points 3 and 4 (sxx 3e6, 4e6): mean 3.5e6; written as a tensor in the global axes.
  expect_stress(h5, "/frames/0001", 0, {1.5e6, -3e6, 3e5});
  expect_stress(h5, "/frames/0001", 1, {3.5e6, -7e6, 3e5});
  const auto stress = h5.doubles("/frames/0001/shell4/stress");
  EXPECT_NEAR(stress[6] + stress[7] + stress[8], 3.5e6 - 7e6, 1e-3);  // the trace does not depend on the axes
  const auto eps = h5.doubles("/frames/0001/shell4/plastic_strain");
  ASSERT_EQ(eps.size(), 2u);
  EXPECT_DOUBLE_EQ(eps[0], 0.02);  // max of points 1 and 2
  EXPECT_DOUBLE_EQ(eps[1], 0.04);
  EXPECT_DOUBLE_EQ(h5.doubles("/frames/0001/shell4/thickness")[0], 0.001 - 1e-5);
  EXPECT_DOUBLE_EQ(h5.doubles("/frames/0000/shell4/thickness")[1], 0.001);
  EXPECT_EQ(h5.bytes("/frames/0001/shell4/deleted"), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(h5.bytes("/frames/0000/shell4/deleted"), (std::vector<std::uint8_t>{0, 0}));

  // Histories: 3 rows.
  for (const char* name : {"time", "dt", "internal", "kinetic_translational", "kinetic_rotational", "hourglass",
                           "contact", "external_work", "total"})
    EXPECT_EQ(h5.shape(std::string("/history/") + name), (std::vector<std::size_t>{3})) << name;
  EXPECT_EQ(h5.doubles("/history/time"), (std::vector<double>{0.0, 1e-4, 2e-4}));
  EXPECT_EQ(h5.doubles("/history/kinetic_translational"), (std::vector<double>{100.0, 99.0, 98.0}));
  EXPECT_EQ(h5.doubles("/history/total"), (std::vector<double>{100.0, 108.5, 117.0}));
  EXPECT_EQ(h5.shape("/history/rigid_wall_force"), (std::vector<std::size_t>{3, 3}));
  EXPECT_EQ(h5.doubles("/history/rigid_wall_force"), (std::vector<double>{0, 0, 0, 1, 2, 3, 2, 4, 6}));
  EXPECT_EQ(h5.shape("/history/node_values"), (std::vector<std::size_t>{3, 6}));
  EXPECT_DOUBLE_EQ(h5.doubles("/history/node_values")[6 * 2 + 5], 5.0);
  EXPECT_EQ(h5.shape("/history/rigid_body_values"), (std::vector<std::size_t>{3, 0}));
}

TEST(ResultsFile, XdmfBesideTheFileHasATemporalCollectionOverTheFrames) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  write_standard(dir, d.model);
  const auto xdmf = dir.path() / "TEST.xdmf";
  ASSERT_TRUE(std::filesystem::exists(xdmf));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "TEST.xdmf.tmp"));
  const std::string text = read_text(xdmf);
  EXPECT_NE(text.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_EQ(occurrences(text, "<Time "), 2u);
  EXPECT_NE(text.find("<Time Value=\"0.00050000000000000001\"/>"), std::string::npos) << text;
  EXPECT_EQ(occurrences(text, "TopologyType=\"Quadrilateral\" NumberOfElements=\"2\""), 2u);
  EXPECT_NE(text.find("TEST.h5:/mesh/shell4/connectivity"), std::string::npos);
  EXPECT_EQ(text.find("TEST.h5:/mesh/coordinates"), std::string::npos);  // each frame its deformed positions
  for (const char* ref : {"TEST.h5:/frames/0000/coordinates", "TEST.h5:/frames/0001/coordinates",
                          "TEST.h5:/frames/0000/displacement", "TEST.h5:/frames/0001/displacement",
                          "TEST.h5:/frames/0001/velocity", "TEST.h5:/frames/0001/shell4/stress",
                          "TEST.h5:/frames/0001/shell4/plastic_strain", "TEST.h5:/frames/0001/shell4/thickness",
                          "TEST.h5:/frames/0001/shell4/deleted"})
    EXPECT_NE(text.find(ref), std::string::npos) << ref;
  EXPECT_NE(text.find("Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"plastic_strain\" AttributeType=\"Scalar\" Center=\"Cell\""), std::string::npos);
  EXPECT_EQ(text.find("/frames/0002"), std::string::npos);
}

TEST(ResultsFile, XdmfIsUpdatedAtEveryFrameAndShowsTheMeshBeforeTheFirst) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  const auto xdmf = dir.path() / "TEST.xdmf";
  ResultsFile file(dir.path() / "TEST.h5", m);
  std::string text = read_text(xdmf);
  EXPECT_NE(text.find("TopologyType=\"Quadrilateral\""), std::string::npos);
  EXPECT_EQ(text.find("Temporal"), std::string::npos);
  SolverState s = plate_state(m, 1);
  file.write_frame(0.0, 0, m, s);
  text = read_text(xdmf);
  EXPECT_NE(text.find("TEST.h5:/frames/0000/velocity"), std::string::npos);
  file.write_frame(1e-4, 10, m, s);
  EXPECT_NE(read_text(xdmf).find("TEST.h5:/frames/0001/velocity"), std::string::npos);
}

TEST(ResultsFile, CannotCreateFileNamesThePath) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const auto path = dir.path() / "no-such-folder" / "TEST.h5";
  try {
    ResultsFile file(path, d.model);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(ResultsReader, FailuresNameTheFileAndTheObject) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const auto path = write_standard(dir, d.model);
  const ResultsReader h5(path);
  const auto message = [&](auto&& read) {
    try {
      read();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { h5.doubles("/history/no_such"); }).find(path.string() + ": no dataset /history/no_such"),
            std::string::npos);
  EXPECT_NE(message([&] { h5.attribute<double>("/", "no_such"); }).find("no attribute no_such on /"),
            std::string::npos);
  const auto missing = dir.path() / "missing.h5";
  EXPECT_NE(message([&] { ResultsReader r(missing); }).find("results file " + missing.string() + ": cannot open"),
            std::string::npos);
}

TEST(ResultsFile, WritingAfterCloseThrowsAndTheDestructorCloses) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  const SolverState s = plate_state(m, 1);
  {
    ResultsFile file(dir.path() / "A.h5", m);
    file.close();
    EXPECT_THROW(file.write_frame(0.0, 0, m, s), std::runtime_error);
    EXPECT_THROW(file.write_history(history_row(0)), std::runtime_error);
    EXPECT_EQ(file.frames(), 0u);
  }
  {
    ResultsFile file(dir.path() / "B.h5", m);
    file.write_frame(0.0, 0, m, s);
    file.write_history(history_row(0));
  }  // no close(): the destructor closes
  const ResultsReader h5(dir.path() / "B.h5");
  EXPECT_EQ(h5.shape("/history/time"), (std::vector<std::size_t>{1}));
  EXPECT_EQ(h5.shape("/history/rigid_wall_force"), (std::vector<std::size_t>{1, 3}));
  EXPECT_TRUE(h5.exists("/frames/0000/shell4/stress"));
  const ResultsReader a(dir.path() / "A.h5");  // no rows, no frames: every history dataset is there, empty
  EXPECT_EQ(a.shape("/history/time"), (std::vector<std::size_t>{0}));
  EXPECT_EQ(a.shape("/history/node_values"), (std::vector<std::size_t>{0, 0}));
  EXPECT_EQ(a.shape("/mesh/shell4/connectivity"), (std::vector<std::size_t>{2, 4}));
}

TEST(ResultsFile, ManyHistoryRowsAreAllAppended) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const auto path = dir.path() / "TEST.h5";
  constexpr int rows = 1000;  // several flushes of the row buffer, several chunks
  {
    ResultsFile file(path, d.model);
    for (int k = 0; k < rows; ++k) {
      file.write_history(history_row(k));
      if (k == 300) file.write_frame(0.03, 300, d.model, plate_state(d.model, 1));
    }
  }
  const ResultsReader h5(path);
  const auto time = h5.doubles("/history/time");
  ASSERT_EQ(time.size(), static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k) EXPECT_DOUBLE_EQ(time[static_cast<std::size_t>(k)], 1e-4 * k);
  const auto force = h5.doubles("/history/rigid_wall_force");
  ASSERT_EQ(force.size(), 3u * rows);
  EXPECT_DOUBLE_EQ(force[3 * 999 + 2], 3.0 * 999);
  EXPECT_DOUBLE_EQ(h5.doubles("/history/node_values")[6 * 777 + 5], 3.0 + 777);
}

TEST(ResultsFile, HistoryRowsKeepTheWidthOfTheFirst) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  ResultsFile file(dir.path() / "TEST.h5", d.model);
  file.write_history(history_row(0));
  HistoryRow row = history_row(1);
  row.rigid_wall_force.resize(6);
  try {
    file.write_history(row);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rigid_wall_force"), std::string::npos) << e.what();
  }
}

// Two /TH datasets laid out by hand, the second with 5000 columns: its labels are far above the 64 KiB that the
// earliest HDF5 object format allows for attributes. Written, then read back through HistoryFile.
std::vector<HistoryDataset> th_layout() {
  HistoryDataset node{"NODE_2", "NODE", "/TH/NODE/2", 2, "nodes", {}};
  node.columns = {{6, "corner", "DX", "L", 1e-3, "NODE_2/6/DX"}, {6, "corner", "VX", "L/T", 1.0, "NODE_2/6/VX"},
                  {7, "", "DX", "L", 1e-3, "NODE_2/7/DX"}};
  HistoryDataset wide{"SHEL_3", "SHEL", "/TH/SHELL/3", 3, "shells", {}};
  for (int e = 1; e <= 5000; ++e)
    wide.columns.push_back({e, "a rather long element name " + std::to_string(e), "F1", "F/L", 1.0,
                            "SHEL_3/" + std::to_string(e) + "/F1"});
  return {node, wide};
}

HistoryRow th_row(int k) {
  HistoryRow r = history_row(k);
  r.th = {{0.1 * k, 1.0 * k, -0.2 * k}, std::vector<double>(5000, 0.5 * k)};
  r.th[1][4999] = 7.0 + k;
  return r;
}

TEST(ResultsFile, ThDatasetsCarryTheirColumnsAndReadBack) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const auto path = dir.path() / "TEST.h5";
  {
    ResultsFile file(path, d.model, th_layout());
    for (int k = 0; k < 3; ++k) file.write_history(th_row(k));
    file.close();
  }
  const ResultsReader h5(path);
  EXPECT_EQ(h5.shape("/history/th/NODE_2"), (std::vector<std::size_t>{3, 3}));
  EXPECT_EQ(h5.doubles("/history/th/NODE_2"), (std::vector<double>{0, 0, 0, 0.1, 1, -0.2, 0.2, 2, -0.4}));
  EXPECT_EQ(h5.attribute<std::int64_t>("/history/th/NODE_2", "id"), 2);
  EXPECT_EQ(h5.shape("/history/th/SHEL_3"), (std::vector<std::size_t>{3, 5000}));
  EXPECT_EQ(h5.doubles("/history/th/SHEL_3")[2 * 5000 + 4999], 9.0);

  const HistoryFile file(path);
  EXPECT_EQ(file.rows(), 3u);
  const auto& series = file.series();
  ASSERT_GE(series.size(), 3u);
  EXPECT_EQ(series[0].path, "/history/time");
  EXPECT_EQ(series[0].columns.at(0).unit, "T");
  const auto internal = std::find_if(series.begin(), series.end(),
                                     [](const HistorySeries& s) { return s.path == "/history/internal"; });
  ASSERT_NE(internal, series.end());
  EXPECT_EQ(internal->kind, "global");
  EXPECT_EQ(internal->columns.at(0).unit, "E");
  EXPECT_EQ(internal->columns.at(0).label, "internal");
  // The /TH datasets come last, in the order of the layout.
  const HistorySeries& node = series[series.size() - 2];
  const HistorySeries& shells = series.back();
  EXPECT_EQ(node.path, "/history/th/NODE_2");
  EXPECT_EQ(node.kind, "NODE");
  EXPECT_EQ(node.keyword, "/TH/NODE/2");
  EXPECT_EQ(node.id, 2);
  EXPECT_EQ(node.title, "nodes");
  ASSERT_EQ(node.columns.size(), 3u);
  EXPECT_EQ(node.columns[1].label, "NODE_2/6/VX");
  EXPECT_EQ(node.columns[1].unit, "L/T");
  EXPECT_EQ(node.columns[1].object_title, "corner");
  EXPECT_EQ(node.columns[2].object_id, 7);
  EXPECT_EQ(node.columns[0].si_scale, 1e-3);
  EXPECT_EQ(file.values(series.size() - 2), h5.doubles("/history/th/NODE_2"));
  ASSERT_EQ(shells.columns.size(), 5000u);
  EXPECT_EQ(shells.columns[4999].label, "SHEL_3/5000/F1");
  EXPECT_EQ(shells.columns[4999].object_title, "a rather long element name 5000");
}

TEST(ResultsFile, ThRowsMustFitTheLayout) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  ResultsFile file(dir.path() / "TEST.h5", d.model, th_layout());
  HistoryRow row = th_row(1);
  row.th[0].pop_back();
  try {
    file.write_history(row);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/history/th/NODE_2, which has 3 columns"), std::string::npos) << e.what();
  }
  row.th.pop_back();
  EXPECT_THROW(file.write_history(row), std::runtime_error);
}

TEST(ResultsFile, HistoryFileRefusesOtherFiles) {
  test::TempDir dir;
  const auto text = dir.write("notes.h5", "not HDF5");
  try {
    const HistoryFile file(text);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("notes.h5: cannot open as an HDF5 file"), std::string::npos) << e.what();
  }
  const auto other = dir.path() / "other.h5";
  H5Fclose(H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  try {
    const HistoryFile file(other);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a Crumple results file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(HistoryFile(dir.path() / "missing.h5"), std::runtime_error);
}

TEST(ResultsFile, StateThatDoesNotMatchTheMeshIsRejected) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  ResultsFile file(dir.path() / "TEST.h5", m);
  SolverState s = plate_state(m, 1);
  s.nodes.resize(5);
  EXPECT_THROW(file.write_frame(0.0, 0, m, s), std::runtime_error);
  s = plate_state(m, 2);
  s.shells.sxx.resize(3);  // 2 shells x 2 points need 4
  EXPECT_THROW(file.write_frame(0.0, 0, m, s), std::runtime_error);
  s = plate_state(m, 1);
  s.shells.thickness.clear();
  EXPECT_THROW(file.write_frame(0.0, 0, m, s), std::runtime_error);
  EXPECT_EQ(file.frames(), 0u);
  file.write_frame(0.0, 0, m, plate_state(m, 1));
  EXPECT_EQ(file.frames(), 1u);
}

TEST(ResultsFile, MidSurfaceStressIsWeightedByTheIntegrationRuleWhenTheStateHasIt) {
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const Model& m = d.model;
  const auto path = dir.path() / "TEST.h5";
  {
    ResultsFile file(path, m);
    SolverState s = plate_state(m, 2);
    advance(s, m, 1.0);  // element 1: sxx 1e6, 2e6
    s.shell_groups.assign(m.element_groups.size(), ShellGroupParameters{});
    const double weight[2] = {0.25, 0.75};
    s.shell_groups[0].points = 2;
    s.shell_groups[0].membrane_weight = weight;
    file.write_frame(1e-4, 1, m, s);
  }
  const ResultsReader h5(path);
  // The points' sxx 1e6, 2e6 and syy -2e6, -4e6 weighted 1/4, 3/4; sxy 3e5 at both.
  expect_stress(h5, "/frames/0000", 0, {0.25 * 1e6 + 0.75 * 2e6, -(0.25 * 2e6 + 0.75 * 4e6), 3e5});
}

TEST(ResultsFile, ShellsOfBothKindsAreWrittenAndGiveASpatialCollectionPerFrame) {
  test::TempDir dir;
  const std::string extra = "/NODE\n" + I(7) + R(0.03) + R(0.0) + R(0.0) + "\n/SH3N/1\n" + I(9) + I(3) + I(7) +
                            I(6) + "\n";
  const Deck d = read_deck(test::write_deck(dir, extra));
  const Model& m = d.model;
  ASSERT_EQ(m.elements[static_cast<int>(ElementKind::Shell3)].size(), 1u);
  const auto path = dir.path() / "TEST.h5";
  {
    ResultsFile file(path, m);
    SolverState s = plate_state(m, 2);
    SolverState missing_triangles = s;
    missing_triangles.shells3 = ShellState{};
    EXPECT_THROW(file.write_frame(0.0, 0, m, missing_triangles), std::runtime_error);
    s.shells3.sxx = {4e6, 6e6};
    s.shells3.eps_p = {0.3, 0.1};
    s.shells3.deleted[0] = 1;
    file.write_frame(0.0, 0, m, s);
  }
  const ResultsReader h5(path);
  EXPECT_EQ(h5.shape("/mesh/shell3/connectivity"), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(h5.ints("/mesh/shell3/connectivity"), (std::vector<std::int32_t>{2, 6, 5}));
  EXPECT_EQ(h5.longs("/mesh/shell3/ids"), (std::vector<std::int64_t>{9}));
  EXPECT_EQ(h5.shape("/frames/0000/shell3/stress"), (std::vector<std::size_t>{1, 6}));
  EXPECT_DOUBLE_EQ(h5.doubles("/frames/0000/shell3/stress")[0], 5e6);
  EXPECT_DOUBLE_EQ(h5.doubles("/frames/0000/shell3/plastic_strain")[0], 0.3);
  EXPECT_EQ(h5.bytes("/frames/0000/shell3/deleted"), (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(h5.shape("/frames/0000/shell4/stress"), (std::vector<std::size_t>{2, 6}));
  const std::string text = read_text(dir.path() / "TEST.xdmf");
  EXPECT_NE(text.find("CollectionType=\"Spatial\""), std::string::npos);
  EXPECT_NE(text.find("TopologyType=\"Triangle\" NumberOfElements=\"1\""), std::string::npos);
  EXPECT_NE(text.find("TEST.h5:/mesh/shell3/connectivity"), std::string::npos);
  EXPECT_NE(text.find("TEST.h5:/frames/0000/shell3/plastic_strain"), std::string::npos);
  EXPECT_NE(text.find("TEST.h5:/frames/0000/shell4/plastic_strain"), std::string::npos);
}

// Optional: the layout as a Python user sees it, when an interpreter with h5py is there.
TEST(ResultsFile, H5pyReadsTheFile) {
  std::string python;
  for (const char* candidate : {"/usr/bin/python3", "python3"})
    if (std::system((std::string(candidate) + " -c \"import h5py\" >/dev/null 2>&1").c_str()) == 0) {
      python = candidate;
      break;
    }
  if (python.empty()) GTEST_SKIP() << "no python3 with h5py";
  test::TempDir dir;
  const Deck d = read_deck(test::write_deck(dir));
  const auto path = write_standard(dir, d.model);
  const auto script = dir.write("check.py", R"(import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    assert f["mesh/coordinates"].shape == (6, 3)
    assert f["mesh/shell4/connectivity"][0].tolist() == [0, 1, 4, 3]
    assert f["mesh/parts/ids"][f["mesh/shell4/part"][1]] == 1
    frames = sorted(f["frames"], key=int)
    assert frames == ["0000", "0001"], frames
    last = f["frames"][frames[-1]]
    assert abs(last.attrs["time"] - 5e-4) < 1e-18 and last.attrs["cycle"] == 100
    assert np.allclose(last["displacement"][5], [6e-4, -1.2e-3, 3e-4], rtol=0, atol=1e-15)
    assert last["shell4/deleted"][:].tolist() == [0, 1]
    assert f["history/time"].shape == (3,)
    assert f["history/rigid_wall_force"][2].tolist() == [2.0, 4.0, 6.0]
    assert f.attrs["format"] == "crumple results", f.attrs["format"]
print("ok")
)");
  const std::string command = python + " " + script.string() + " " + path.string() + " > " +
                              (dir.path() / "out.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << read_text(dir.path() / "out.txt");
}

}  // namespace test_results_file
