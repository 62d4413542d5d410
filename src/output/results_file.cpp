// NAME.h5 and NAME.xdmf: mesh, field frames and time histories (layout: docs/output-format.md).
// Written with the HDF5 C API through a serial file driver: only the process that owns the file calls it.
#include "crumple/core/utf8.hpp"
#include "crumple/output/results_file.hpp"

#include "crumple/model/history_variables.hpp"
#include "crumple/output/restart_file.hpp"
#include "crumple/state/element_status.hpp"
#include "frame_fields.hpp"
#include "hdf5_support.hpp"
#include "xml_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "hdf5_support.hpp"

namespace crumple {
namespace {

using hdf5::H5Types;
using hdf5::Handle;
using hdf5::QuietErrors;

constexpr int kFormatVersion = 1;
constexpr hsize_t kHistoryChunkRows = 512;   // rows per chunk of the 1-D history datasets
constexpr std::size_t kHistoryBuffer = 256;  // history rows kept in memory before they are appended


// What NAME.xdmf says of a frame's field: its dataset and attribute name, where it lives, its width and type.
struct FieldEntry {
  std::string name;
  int kind = -1;  // element kind of a cell field, -1 for a nodal field
  std::size_t width = 1;
  bool is_bytes = false;
};

struct Frame {
  std::string name;  // group name under /frames
  double time = 0.0;
  long long cycle = 0;
  std::vector<FieldEntry> fields;
};

// An extendible history dataset: `rows` (1-D) or `rows x columns` (2-D; columns may be 0).
struct Series {
  std::string path;  // "/history/time", "/history/th/NODE_2"
  bool two_d = false;
  hsize_t columns = 0;
  Handle dataset;
};

// The global history series (docs/output-format.md, "/history"): 1-D ones with their unit, then the 2-D ones.
struct GlobalSeries {
  const char* name;
  const char* unit;  // 1-D: the dimension of the values; 2-D: "" (per column)
  Dimension dimension;
};
constexpr std::array<GlobalSeries, 13> kGlobalSeries{{{"time", "T", {0, 0, 1}},
                                                      {"dt", "T", {0, 0, 1}},
                                                      {"internal", "E", {1, 2, -2}},
                                                      {"kinetic_translational", "E", {1, 2, -2}},
                                                      {"kinetic_rotational", "E", {1, 2, -2}},
                                                      {"hourglass", "E", {1, 2, -2}},
                                                      {"contact", "E", {1, 2, -2}},
                                                      {"external_work", "E", {1, 2, -2}},
                                                      {"total", "E", {1, 2, -2}},
                                                      {"rigid_wall_force", "", {}},
                                                      {"node_values", "", {}},
                                                      {"rigid_body_values", "", {}},
                                                      {"interface_values", "", {}}}};

// The columns of one object in a global 2-D series: name, unit and dimension of each value.
struct GlobalColumn {
  const char* variable;
  const char* unit;
  Dimension dimension;
};
constexpr Dimension kForceDimension{1, 1, -2}, kEnergyDimension{1, 2, -2};
constexpr std::array<GlobalColumn, 3> kWallColumns{{{"FX", "F", kForceDimension},
                                                    {"FY", "F", kForceDimension},
                                                    {"FZ", "F", kForceDimension}}};
constexpr std::array<GlobalColumn, 9> kBodyColumns{{{"X", "L", {0, 1, 0}},
                                                    {"Y", "L", {0, 1, 0}},
                                                    {"Z", "L", {0, 1, 0}},
                                                    {"VX", "L/T", {0, 1, -1}},
                                                    {"VY", "L/T", {0, 1, -1}},
                                                    {"VZ", "L/T", {0, 1, -1}},
                                                    {"WX", "1/T", {0, 0, -1}},
                                                    {"WY", "1/T", {0, 0, -1}},
                                                    {"WZ", "1/T", {0, 0, -1}}}};
constexpr std::array<GlobalColumn, 10> kInterfaceColumns{{{"FNX", "F", kForceDimension},
                                                          {"FNY", "F", kForceDimension},
                                                          {"FNZ", "F", kForceDimension},
                                                          {"FTX", "F", kForceDimension},
                                                          {"FTY", "F", kForceDimension},
                                                          {"FTZ", "F", kForceDimension},
                                                          {"ELASTIC_ENERGY", "E", kEnergyDimension},
                                                          {"FRICTION_WORK", "E", kEnergyDimension},
                                                          {"ABSORBED", "E", kEnergyDimension},
                                                          {"ACTIVE_NODES", "-", {}}}};

// Labelled columns of a global 2-D series: `columns` per object, objects in model order.
template <class Object, std::size_t Count>
std::vector<HistoryColumn> global_columns(const char* series, const std::vector<Object>& objects,
                                          const std::array<GlobalColumn, Count>& columns, const double (&work)[3]) {
  std::vector<HistoryColumn> out;
  for (const Object& o : objects)
    for (const GlobalColumn& c : columns)
      out.push_back({o.user_id, o.title, c.variable, c.unit, si_factor(c.dimension, work),
                     fmt::format("{}/{}/{}", series, o.user_id, c.variable)});
  return out;
}

}  // namespace

// Texts for an HDF5 string of the UTF-8 type: each made valid (a title cut inside a character is not), and the
// pointers the C API takes.
struct Utf8Texts {
  std::vector<std::string> valid;
  std::vector<const char*> pointers;
  explicit Utf8Texts(const std::vector<std::string>& values) {
    for (const std::string& v : values) valid.push_back(valid_utf8(v));
    for (const std::string& v : valid) pointers.push_back(v.c_str());
  }
};

struct ResultsFile::Impl {
  std::filesystem::path path, xdmf_path;
  std::string h5_name;  // file name of the .h5 as the XDMF file refers to it (same folder)
  Handle file;
  bool open = false;

  std::size_t nodes = 0;
  std::array<std::size_t, kElementKinds> elements{};
  std::size_t element_groups = 0;
  std::vector<Frame> frames;
  std::vector<std::pair<std::int64_t, std::string>> part_table;  // deck id and title, for NAME.xdmf

  // Histories: 9 scalar series, then rigid_wall_force, node_values, rigid_body_values, interface_values, then one
  // series per /TH dataset (th, in the same order).
  static constexpr std::size_t kScalars = 9, kWide = 4, kGlobal = kScalars + kWide;
  std::vector<Series> series;
  std::vector<HistoryDataset> th;
  bool widths_known = false;
  std::array<std::size_t, kWide> widths{};        // values per row of the global 2-D series
  std::array<std::vector<HistoryColumn>, kWide> wide_columns;  // their labels, written when the first row fits them
  double work_si[3] = {1.0, 1.0, 1.0};             // SI size of the working units
  std::vector<std::vector<double>> pending;        // rows not yet appended, row-major, one per series
  // A continued file (a resumed run): the last history row it held; a row at or before it is not written again.
  double last_row_time = -std::numeric_limits<double>::infinity();
  bool continued = false;
  std::size_t pending_rows = 0;

  [[noreturn]] void fail(const std::string& what) const {
    const std::string detail = hdf5::last_error();
    throw std::runtime_error("results file " + path.string() + ": " + what + (detail.empty() ? "" : ": " + detail));
  }
  hid_t check(hid_t id, const std::string& what) const {
    if (id < 0) fail(what);
    return id;
  }
  void check_status(herr_t status, const std::string& what) const {
    if (status < 0) fail(what);
  }
  void require_open() const {
    if (!open) throw std::runtime_error("results file " + path.string() + " is closed");
  }

  Handle group(hid_t location, const std::string& name) const {
    return {check(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "cannot create " + name),
            H5Gclose};
  }
  // A group whose members a reader lists in the order they were written.
  Handle ordered_group(hid_t location, const std::string& name) const {
    Handle plist(check(H5Pcreate(H5P_GROUP_CREATE), "property list"), H5Pclose);
    check_status(H5Pset_link_creation_order(plist.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
                 "property list");
    return {check(H5Gcreate2(location, name.c_str(), H5P_DEFAULT, plist.get(), H5P_DEFAULT), "cannot create " + name),
            H5Gclose};
  }

  // A contiguous dataset of shape dims written from `data` (row-major).
  template <class T>
  void dataset(hid_t location, const std::string& name, const T* data, std::initializer_list<hsize_t> dims) const {
    const std::vector<hsize_t> shape(dims);
    Handle space(check(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), "dataspace " + name),
                 H5Sclose);
    Handle set(check(H5Dcreate2(location, name.c_str(), H5Types<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
                     "cannot create dataset " + name),
               H5Dclose);
    hsize_t count = 1;
    for (hsize_t d : shape) count *= d;
    if (count > 0)
      check_status(H5Dwrite(set.get(), H5Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                   "cannot write dataset " + name);
  }

  template <class T>
  void attribute(hid_t location, const char* name, const T& value) const {
    Handle space(check(H5Screate(H5S_SCALAR), "dataspace"), H5Sclose);
    Handle attr(check(H5Acreate2(location, name, H5Types<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      std::string("cannot create attribute ") + name),
                H5Aclose);
    check_status(H5Awrite(attr.get(), H5Types<T>::memory(), &value), std::string("cannot write attribute ") + name);
  }

  template <class T>
  void array_attribute(hid_t location, const char* name, const std::vector<T>& values) const {
    const hsize_t n = values.size();
    Handle space(check(H5Screate_simple(1, &n, nullptr), "dataspace"), H5Sclose);
    Handle attr(check(H5Acreate2(location, name, H5Types<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      std::string("cannot create attribute ") + name),
                H5Aclose);
    if (n > 0)
      check_status(H5Awrite(attr.get(), H5Types<T>::memory(), values.data()),
                   std::string("cannot write attribute ") + name);
  }

  Handle utf8_string_type() const {
    Handle type(check(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "string type");
    check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
    return type;
  }

  void string_attribute(hid_t location, const char* name, const std::string& value) const {
    Handle type = utf8_string_type();
    Handle space(check(H5Screate(H5S_SCALAR), "dataspace"), H5Sclose);
    Handle attr(check(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      std::string("cannot create attribute ") + name),
                H5Aclose);
    const std::string valid = valid_utf8(value);  // the type says UTF-8: a title cut inside a character is not
    const char* text = valid.c_str();
    check_status(H5Awrite(attr.get(), type.get(), &text), std::string("cannot write attribute ") + name);
  }

  void string_array_attribute(hid_t location, const char* name, const std::vector<std::string>& values) const {
    Handle type = utf8_string_type();
    const hsize_t n = values.size();
    Handle space(check(H5Screate_simple(1, &n, nullptr), "dataspace"), H5Sclose);
    Handle attr(check(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      std::string("cannot create attribute ") + name),
                H5Aclose);
    const Utf8Texts texts(values);
    if (n > 0)
      check_status(H5Awrite(attr.get(), type.get(), texts.pointers.data()), std::string("cannot write attribute ") + name);
  }

  void string_dataset(hid_t location, const std::string& name, const std::vector<std::string>& values) const {
    Handle type = utf8_string_type();
    const hsize_t n = values.size();
    Handle space(check(H5Screate_simple(1, &n, nullptr), "dataspace " + name), H5Sclose);
    Handle set(check(H5Dcreate2(location, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
                     "cannot create dataset " + name),
               H5Dclose);
    const Utf8Texts texts(values);
    if (n > 0)
      check_status(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.pointers.data()),
                   "cannot write dataset " + name);
  }

  void write_mesh(const Model& model) {
    Handle mesh = group(file.get(), "mesh");
    nodes = model.nodes.size();
    std::vector<double> xyz(3 * nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
      xyz[3 * i] = model.nodes.x[i], xyz[3 * i + 1] = model.nodes.y[i], xyz[3 * i + 2] = model.nodes.z[i];
    }
    dataset(mesh.get(), "coordinates", xyz.data(), {nodes, 3});
    dataset(mesh.get(), "node_ids", model.nodes.user_id.data(), {nodes});

    std::vector<std::int64_t> part_ids;
    std::vector<std::string> part_titles;
    for (const Part& p : model.parts) {
      part_ids.push_back(p.user_id), part_titles.push_back(p.title);
      part_table.emplace_back(p.user_id, p.title);
    }
    Handle parts = group(mesh.get(), "parts");
    dataset(parts.get(), "ids", part_ids.data(), {part_ids.size()});
    string_dataset(parts.get(), "titles", part_titles);

    for (const ElementKindDescription& k : kElementKindTable) {
      const ElementTable& table = model.elements[static_cast<std::size_t>(k.kind)];
      const std::size_t n = table.size();
      elements[static_cast<std::size_t>(k.kind)] = n;
      if (n == 0) continue;
      const auto npe = static_cast<hsize_t>(nodes_per_element(k.kind));
      Handle g = group(mesh.get(), std::string(k.mesh_group));
      dataset(g.get(), "connectivity", table.connectivity.data(), {n, npe});
      dataset(g.get(), "ids", table.user_id.data(), {n});
      dataset(g.get(), "part", table.part.data(), {n});
      std::vector<std::int64_t> part_user(n);
      for (std::size_t e = 0; e < n; ++e)
        part_user[e] = model.parts[static_cast<std::size_t>(table.part[e])].user_id;
      dataset(g.get(), "part_id", part_user.data(), {n});
    }
    element_groups = model.element_groups.size();
  }

  void create_history(const Model& model) {
    Handle history = ordered_group(file.get(), "history");
    for (int i = 0; i < 3; ++i) work_si[i] = model.units.work[i];
    series.resize(kGlobal + th.size());
    pending.resize(series.size());
    for (std::size_t s = 0; s < kGlobal; ++s) {
      series[s].path = std::string("/history/") + kGlobalSeries[s].name;
      series[s].two_d = s >= kScalars;
    }
    for (std::size_t s = 0; s < kScalars; ++s) {
      create_series(series[s]);
      const GlobalSeries& g = kGlobalSeries[s];
      string_attribute(series[s].dataset.get(), "unit", g.unit);
      string_attribute(series[s].dataset.get(), "unit_name", unit_name(g.unit, unit_names(work_si)));
      attribute(series[s].dataset.get(), "si_scale", si_factor(g.dimension, work_si));
      string_attribute(series[s].dataset.get(), "label", g.name);
    }
    wide_columns = {global_columns("rigid_wall_force", model.rigid_walls, kWallColumns, work_si), {},
                    global_columns("rigid_body_values", model.rigid_bodies, kBodyColumns, work_si),
                    global_columns("interface_values", model.type7_interfaces, kInterfaceColumns, work_si)};
    Handle th_group = ordered_group(history.get(), "th");
    for (std::size_t d = 0; d < th.size(); ++d) create_th_series(series[kGlobal + d], th[d]);
  }

  // /history/th/<name>: rows x columns, with the request and each column described in attributes.
  void create_th_series(Series& s, const HistoryDataset& d) {
    s.path = "/history/th/" + d.name;
    s.two_d = true;
    s.columns = d.columns.size();
    create_series(s);
    const hid_t set = s.dataset.get();
    string_attribute(set, "kind", d.kind);
    string_attribute(set, "keyword", d.keyword);
    attribute(set, "id", d.id);
    string_attribute(set, "title", d.title);
    column_attributes(set, d.columns);
  }

  // Per column: object_ids, object_titles, variables, units (dimension letters), unit_names (their names in the
  // working units), si_scale, labels.
  void column_attributes(hid_t set, const std::vector<HistoryColumn>& columns) const {
    std::vector<std::int64_t> ids;
    std::vector<std::string> titles, variables, units, names, labels;
    std::vector<double> scales;
    const UnitNames working = unit_names(work_si);
    for (const HistoryColumn& c : columns) {
      ids.push_back(c.object_id), titles.push_back(c.object_title), variables.push_back(c.variable);
      units.push_back(c.unit), labels.push_back(c.label), scales.push_back(c.si_scale);
      names.push_back(unit_name(c.unit, working));
    }
    array_attribute(set, "object_ids", ids);
    string_array_attribute(set, "object_titles", titles);
    string_array_attribute(set, "variables", variables);
    string_array_attribute(set, "units", units);
    string_array_attribute(set, "unit_names", names);
    array_attribute(set, "si_scale", scales);
    string_array_attribute(set, "labels", labels);
  }

  void create_series(Series& s) const {
    const int rank = s.two_d ? 2 : 1;
    const std::array<hsize_t, 2> dims{0, s.columns};
    const std::array<hsize_t, 2> max{H5S_UNLIMITED, H5S_UNLIMITED};
    const std::array<hsize_t, 2> chunk{
        s.two_d ? std::max<hsize_t>(1, std::min<hsize_t>(kHistoryChunkRows, 8192 / std::max<hsize_t>(1, s.columns)))
                : kHistoryChunkRows,
        std::max<hsize_t>(1, s.columns)};
    Handle space(check(H5Screate_simple(rank, dims.data(), max.data()), "dataspace " + s.path), H5Sclose);
    Handle plist(check(H5Pcreate(H5P_DATASET_CREATE), "property list"), H5Pclose);
    check_status(H5Pset_chunk(plist.get(), rank, chunk.data()), "chunks of " + s.path);
    s.dataset = Handle(check(H5Dcreate2(file.get(), s.path.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                        plist.get(), H5P_DEFAULT),
                             "cannot create " + s.path),
                       H5Dclose);
  }

  // Creates the 2-D series once their widths are known (first row, or close() with no row: width 0).
  // Their columns are labelled when the row has the model's walls, bodies and interfaces.
  void create_wide_series() {
    for (std::size_t w = 0; w < kWide; ++w) {
      Series& s = series[kScalars + w];
      s.columns = widths[w];
      create_series(s);
      if (widths[w] > 0 && widths[w] == wide_columns[w].size()) column_attributes(s.dataset.get(), wide_columns[w]);
    }
    widths_known = true;
  }

  void flush_history() {
    if (pending_rows == 0) return;
    for (std::size_t s = 0; s < series.size(); ++s) {
      Series& ser = series[s];
      const std::string what = "cannot append to " + ser.path;
      Handle file_space(check(H5Dget_space(ser.dataset.get()), what), H5Sclose);
      std::array<hsize_t, 2> dims{};
      check(H5Sget_simple_extent_dims(file_space.get(), dims.data(), nullptr), what);
      const hsize_t first = dims[0];
      dims[0] += pending_rows;
      check_status(H5Dset_extent(ser.dataset.get(), dims.data()), what);
      const hsize_t width = ser.two_d ? ser.columns : 1;
      if (width == 0) continue;
      file_space = Handle(check(H5Dget_space(ser.dataset.get()), what), H5Sclose);
      const std::array<hsize_t, 2> start{first, 0};
      const std::array<hsize_t, 2> count{pending_rows, width};
      check_status(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
                   what);
      Handle memory(check(H5Screate_simple(ser.two_d ? 2 : 1, count.data(), nullptr), what), H5Sclose);
      check_status(H5Dwrite(ser.dataset.get(), H5T_NATIVE_DOUBLE, memory.get(), file_space.get(), H5P_DEFAULT,
                            pending[s].data()),
                   what);
    }
    for (auto& p : pending) p.clear();
    pending_rows = 0;
  }

  void append_history(const HistoryRow& row) {
    if (row.time <= last_row_time) return;  // a continued file holds it already
    const std::array<const std::vector<double>*, kWide> wide{&row.rigid_wall_force, &row.node_values,
                                                             &row.rigid_body_values, &row.interface_values};
    if (!widths_known) {
      for (std::size_t w = 0; w < kWide; ++w) widths[w] = wide[w]->size();
      create_wide_series();
    }
    for (std::size_t w = 0; w < kWide; ++w)
      if (wide[w]->size() != widths[w])
        throw std::runtime_error(fmt::format("results file {}: history row at time {} has {} {} values, the first row "
                                             "had {}",
                                             path.string(), row.time, wide[w]->size(), series[kScalars + w].path,
                                             widths[w]));
    if (row.th.size() != th.size())
      throw std::runtime_error(fmt::format("results file {}: history row at time {} has {} /TH datasets, the file {}",
                                           path.string(), row.time, row.th.size(), th.size()));
    for (std::size_t d = 0; d < th.size(); ++d)
      if (row.th[d].size() != th[d].columns.size())
        throw std::runtime_error(fmt::format("results file {}: history row at time {} has {} values for {}, which has "
                                             "{} columns",
                                             path.string(), row.time, row.th[d].size(), series[kGlobal + d].path,
                                             th[d].columns.size()));
    const std::array<double, kScalars> scalars{row.time,    row.dt,      row.internal,      row.kinetic_translational,
                                               row.kinetic_rotational, row.hourglass, row.contact,
                                               row.external_work,      row.total};
    for (std::size_t s = 0; s < kScalars; ++s) pending[s].push_back(scalars[s]);
    for (std::size_t w = 0; w < kWide; ++w)
      pending[kScalars + w].insert(pending[kScalars + w].end(), wide[w]->begin(), wide[w]->end());
    for (std::size_t d = 0; d < th.size(); ++d)
      pending[kGlobal + d].insert(pending[kGlobal + d].end(), row.th[d].begin(), row.th[d].end());
    ++pending_rows;
    if (pending_rows >= kHistoryBuffer) flush_history();
  }

  // The counts the mesh was written with; the arrays of the state are checked with the frame's fields.
  void check_state(const Model& model) const {
    const auto mismatch = [&](const std::string& what) {
      throw std::runtime_error("results file " + path.string() + ": the solver state does not match the mesh: " + what);
    };
    if (model.nodes.size() != nodes)
      mismatch(fmt::format("the model has {} nodes, the mesh {}", model.nodes.size(), nodes));
    for (const ElementKindDescription& k : kElementKindTable)
      if (model.elements[static_cast<std::size_t>(k.kind)].size() != elements[static_cast<std::size_t>(k.kind)])
        mismatch(fmt::format("the model has {} {} elements, the mesh {}",
                             model.elements[static_cast<std::size_t>(k.kind)].size(), k.mesh_group,
                             elements[static_cast<std::size_t>(k.kind)]));
    if (model.element_groups.size() != element_groups)
      mismatch(fmt::format("the model has {} element groups, the mesh {}", model.element_groups.size(),
                           element_groups));
  }

  // /frames/NNNN: the nodal fields in the group, the cell fields in a subgroup per element kind
  // (docs/output-format.md). Each field is written as soon as it is made, so that a frame holds one field's buffers
  // at a time; a state that does not fit the mesh leaves no frame (the group written so far is removed).
  void write_frame(double time, long long cycle, const Model& model, const SolverState& state) {
    check_state(model);
    if (continued && !frames.empty() && time <= frames.back().time) return;  // held already
    Frame f{fmt::format("{:04}", frames.size()), time, cycle, {}};
    Handle frames_group(check(H5Gopen2(file.get(), "frames", H5P_DEFAULT), "cannot open /frames"), H5Gclose);
    {
      Handle frame = group(frames_group.get(), f.name);
      attribute(frame.get(), "time", time);
      attribute(frame.get(), "cycle", static_cast<std::int64_t>(cycle));
      struct Writer final : FieldSink {
        Impl& file;
        hid_t frame;
        Frame& entry;
        std::array<Handle, kElementKinds> kind_groups;
        Writer(Impl& i, hid_t g, Frame& e) : file(i), frame(g), entry(e) {}
        void push_back(FrameField&& field) override {
          hid_t at = frame;
          std::size_t rows = file.nodes;
          if (field.kind >= 0) {
            const auto k = static_cast<std::size_t>(field.kind);
            if (!kind_groups[k].valid())
              kind_groups[k] = file.group(frame, std::string(kElementKindTable[k].mesh_group));
            at = kind_groups[k].get(), rows = file.elements[k];
          }
          if (field.is_bytes) file.dataset(at, field.name, field.bytes.data(), {rows});
          else if (field.width == 1) file.dataset(at, field.name, field.values.data(), {rows});
          else file.dataset(at, field.name, field.values.data(), {rows, field.width});
          entry.fields.push_back({field.name, field.kind, field.width, field.is_bytes});
        }
      } writer(*this, frame.get(), f);
      try {
        frame_fields(model, state, writer);
      } catch (const std::runtime_error& e) {
        for (Handle& g : writer.kind_groups) g = Handle();
        frame = Handle();
        H5Ldelete(frames_group.get(), f.name.c_str(), H5P_DEFAULT);
        throw std::runtime_error("results file " + path.string() + ": the solver state does not match the mesh: " +
                                 e.what());
      }
    }
    frames.push_back(std::move(f));

    flush_history();
    check_status(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), "cannot flush");
    write_xdmf();
  }

  // ---- continuing a file: a run resumed from a restart appends to the results it continues ----
  // (docs/output-format.md, "Restart"). What the file holds up to the resumed state's time `from` stays; a frame or
  // a history row at or before the last one held is not written again.

  [[noreturn]] void cannot_continue(const std::string& why) const {
    throw RestartError(fmt::format("cannot continue the results file {}: {}. Write the resumed run to another folder "
                                   "(-o), or pass --overwrite to replace the file",
                                   path.string(), why));
  }

  // The rows of dataset `at`, or -1 when there is none.
  long long rows_of(const std::string& at) const {
    if (H5Lexists(file.get(), at.c_str(), H5P_DEFAULT) <= 0) return -1;
    Handle set(H5Dopen2(file.get(), at.c_str(), H5P_DEFAULT), H5Dclose);
    const std::vector<hsize_t> dims = set.valid() ? hdf5::shape(set.get()) : std::vector<hsize_t>{};
    return dims.empty() ? -1 : static_cast<long long>(dims[0]);
  }

  void check_same_mesh(const Model& model) {
    if (!hdf5::has_attribute(file.get(), "format")) cannot_continue("it is not a Crumple results file");
    nodes = model.nodes.size();
    if (rows_of("/mesh/node_ids") != static_cast<long long>(nodes))
      cannot_continue(fmt::format("its mesh has {} nodes, the model {}", rows_of("/mesh/node_ids"), nodes));
    for (const ElementKindDescription& k : kElementKindTable) {
      const std::size_t n = model.elements[static_cast<std::size_t>(k.kind)].size();
      const long long held = std::max(0LL, rows_of("/mesh/" + std::string(k.mesh_group) + "/ids"));
      if (held != static_cast<long long>(n))
        cannot_continue(fmt::format("its mesh has {} {} elements, the model {}", held, k.mesh_group, n));
      elements[static_cast<std::size_t>(k.kind)] = n;
    }
    element_groups = model.element_groups.size();
    for (const Part& p : model.parts) part_table.emplace_back(p.user_id, p.title);
  }

  // The fields of a frame group as written (nodal datasets, then per kind its subgroup's), the ghost flags last.
  std::vector<FieldEntry> fields_held(hid_t frame) const {
    std::vector<FieldEntry> nodal, cells;
    const auto add = [](std::vector<FieldEntry>& to, hid_t location, const std::string& name, int kind) {
      Handle set(H5Dopen2(location, name.c_str(), H5P_DEFAULT), H5Dclose);
      if (!set.valid()) return;
      const std::vector<hsize_t> dims = hdf5::shape(set.get());
      Handle type(H5Dget_type(set.get()), H5Tclose);
      to.push_back({name, kind, dims.size() == 2 ? static_cast<std::size_t>(dims[1]) : 1,
                    H5Tget_size(type.get()) == 1});
    };
    for (const std::string& name : hdf5::members(frame)) {
      const ElementKindDescription* k = nullptr;
      for (const ElementKindDescription& d : kElementKindTable)
        if (name == d.mesh_group) k = &d;
      if (k == nullptr) {
        add(nodal, frame, name, -1);
        continue;
      }
      Handle group(H5Gopen2(frame, name.c_str(), H5P_DEFAULT), H5Gclose);
      std::vector<FieldEntry> kind_fields;
      for (const std::string& field : hdf5::members(group.get()))
        add(kind_fields, group.get(), field, static_cast<int>(k->kind));
      std::stable_partition(kind_fields.begin(), kind_fields.end(),
                            [](const FieldEntry& f) { return f.name != "vtkGhostType"; });
      cells.insert(cells.end(), kind_fields.begin(), kind_fields.end());
    }
    nodal.insert(nodal.end(), cells.begin(), cells.end());
    return nodal;
  }

  void read_frames_held(double from) {
    Handle frames_group(H5Gopen2(file.get(), "frames", H5P_DEFAULT), H5Gclose);
    if (!frames_group.valid()) cannot_continue("it has no /frames");
    std::vector<std::string> names = hdf5::members(frames_group.get());
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
      return a.size() != b.size() ? a.size() < b.size() : a < b;  // 0000 ... 9999, 10000: as integers
    });
    for (const std::string& name : names) {
      Handle frame(H5Gopen2(frames_group.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
      const auto time = hdf5::numbers<double>(frame.get(), "time", H5T_NATIVE_DOUBLE);
      const auto cycle = hdf5::numbers<std::int64_t>(frame.get(), "cycle", H5T_NATIVE_INT64);
      if (time.size() != 1 || cycle.size() != 1) cannot_continue("frame " + name + " has no time or cycle");
      if (time[0] > from)
        cannot_continue(fmt::format("it holds a frame at t = {:.6g}, past the restart's t = {:.6g}", time[0], from));
      frames.push_back({name, time[0], static_cast<long long>(cycle[0]), fields_held(frame.get())});
    }
  }

  // Opens the history datasets as create_history makes them; the rows held end at or before `from`.
  void open_history_held(const Model& model, double from) {
    for (int i = 0; i < 3; ++i) work_si[i] = model.units.work[i];
    series.resize(kGlobal + th.size());
    pending.resize(series.size());
    for (std::size_t s = 0; s < series.size(); ++s) {
      Series& ser = series[s];
      ser.path = s < kGlobal ? std::string("/history/") + kGlobalSeries[s].name : "/history/th/" + th[s - kGlobal].name;
      ser.two_d = s >= kScalars;
      if (rows_of(ser.path) < 0) cannot_continue("it has no " + ser.path + " as the deck's histories need");
      ser.dataset = Handle(H5Dopen2(file.get(), ser.path.c_str(), H5P_DEFAULT), H5Dclose);
      const std::vector<hsize_t> dims = hdf5::shape(ser.dataset.get());
      ser.columns = ser.two_d && dims.size() == 2 ? dims[1] : 0;
      if (s >= kGlobal && ser.columns != th[s - kGlobal].columns.size())
        cannot_continue(fmt::format("its {} has {} columns, the deck's {}", ser.path, ser.columns,
                                    th[s - kGlobal].columns.size()));
    }
    for (std::size_t w = 0; w < kWide; ++w) widths[w] = series[kScalars + w].columns;
    widths_known = true;  // created by the run that wrote the file, at its first row or at its close
    wide_columns = {global_columns("rigid_wall_force", model.rigid_walls, kWallColumns, work_si), {},
                    global_columns("rigid_body_values", model.rigid_bodies, kBodyColumns, work_si),
                    global_columns("interface_values", model.type7_interfaces, kInterfaceColumns, work_si)};
    const std::vector<double> times = read_column("/history/time");
    if (!times.empty()) last_row_time = times.back();
    if (last_row_time > from)
      cannot_continue(fmt::format("its histories run to t = {:.6g}, past the restart's t = {:.6g}", last_row_time, from));
  }

  std::vector<double> read_column(const std::string& at) const {
    Handle set(H5Dopen2(file.get(), at.c_str(), H5P_DEFAULT), H5Dclose);
    std::vector<double> out(static_cast<std::size_t>(std::max(0LL, rows_of(at))));
    if (!out.empty())
      check_status(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "cannot read " + at);
    return out;
  }

  // ---- XDMF ----
  template <class T>
  std::string item(const std::string& dims, const std::string& h5_path) const {
    return fmt::format(R"(<DataItem Dimensions="{}" {} Format="HDF">{}:{}</DataItem>)", dims, H5Types<T>::xdmf,
                       xml_escaped(h5_name), h5_path);
  }

  // 3 values are a vector (shell stresses sxx syy sxy too); 6 stay six components (sxx syy szz sxy syz szx, VTK's
  // order of a symmetric tensor): XDMF's Tensor6 is read in another order by each of ParaView's readers.
  static const char* attribute_type(std::size_t width) {
    return width == 1 ? "Scalar" : width == 3 ? "Vector" : "Matrix";
  }

  // The nodes' positions of an instant: the frame's deformed ones, so that ParaView shows the deformed shape with
  // no filter (the mesh's initial ones without a frame, or in a file written before frames held them).
  std::string xdmf_geometry(const Frame* frame, const std::string& in) const {
    std::string at = "/mesh/coordinates";
    if (frame != nullptr)
      for (const FieldEntry& field : frame->fields)
        if (field.name == kFrameCoordinates) at = "/frames/" + frame->name + "/" + field.name;
    return fmt::format("{}<Geometry GeometryType=\"XYZ\">\n{}  {}\n{}</Geometry>\n", in, in,
                       item<double>(fmt::format("{} 3", nodes), at), in);
  }

  static void attribute_xml(std::string& x, const std::string& in, const std::string& name, const char* type,
                            const char* center, const std::string& data) {
    x += fmt::format("{}<Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"{}\">\n{}  {}\n{}</Attribute>\n", in,
                     name, type, center, in, data, in);
  }

  // The frame's nodal fields and, for the grid of element kind `kind` (nullptr: the cloud of points), its cell
  // fields, in the order written (the kind's vtkGhostType last: ParaView's XDMF reader takes the first scalar of
  // a grid as its active one).
  void xdmf_fields(std::string& x, const Frame& frame, const ElementKindDescription* kind,
                   const std::string& in) const {
    for (const FieldEntry& field : frame.fields) {
      if (field.name == kFrameCoordinates) continue;  // the geometry (xdmf_geometry)
      const bool cell = field.kind >= 0;
      if (cell && (kind == nullptr || field.kind != static_cast<int>(kind->kind))) continue;
      const std::string at =
          "/frames/" + frame.name + (cell ? std::string("/") + std::string(kind->mesh_group) : std::string()) + "/" +
          field.name;
      const std::size_t rows = cell ? elements[static_cast<std::size_t>(field.kind)] : nodes;
      const std::string dims = field.width == 1 ? std::to_string(rows) : fmt::format("{} {}", rows, field.width);
      attribute_xml(x, in, field.name, attribute_type(field.width), cell ? "Cell" : "Node",
                    field.is_bytes ? item<std::uint8_t>(dims, at) : item<double>(dims, at));
    }
  }

  void xdmf_grid(std::string& x, const ElementKindDescription& k, const Frame* frame, const std::string& indent) const {
    const std::size_t n = elements[static_cast<std::size_t>(k.kind)];
    const int npe = nodes_per_element(k.kind);
    const std::string mesh = std::string("/mesh/") + std::string(k.mesh_group);
    const std::string in = indent + "  ";
    x += fmt::format("{}<Grid Name=\"{}\" GridType=\"Uniform\">\n", indent, k.mesh_group);
    if (frame != nullptr) x += fmt::format("{}<Time Value=\"{:.17g}\"/>\n", in, frame->time);
    x += fmt::format("{}<Topology TopologyType=\"{}\" NumberOfElements=\"{}\" NodesPerElement=\"{}\">\n{}  {}\n{}"
                     "</Topology>\n",
                     in, k.xdmf_topology, n, npe, in,
                     item<std::int32_t>(fmt::format("{} {}", n, npe), mesh + "/connectivity"), in);
    x += xdmf_geometry(frame, in);
    attribute_xml(x, in, "node_id", "Scalar", "Node", item<std::int64_t>(std::to_string(nodes), "/mesh/node_ids"));
    attribute_xml(x, in, "element_id", "Scalar", "Cell", item<std::int64_t>(std::to_string(n), mesh + "/ids"));
    attribute_xml(x, in, "part_id", "Scalar", "Cell", item<std::int64_t>(std::to_string(n), mesh + "/part_id"));
    if (frame != nullptr) xdmf_fields(x, *frame, &k, in);
    x += indent + "</Grid>\n";
  }

  // A model without elements is shown as a cloud of points.
  void xdmf_points(std::string& x, const Frame* frame, const std::string& indent) const {
    const std::string in = indent + "  ";
    x += indent + "<Grid Name=\"nodes\" GridType=\"Uniform\">\n";
    if (frame != nullptr) x += fmt::format("{}<Time Value=\"{:.17g}\"/>\n", in, frame->time);
    x += fmt::format("{}<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" NodesPerElement=\"1\"/>\n", in,
                     nodes);
    x += xdmf_geometry(frame, in);
    if (frame != nullptr) xdmf_fields(x, *frame, nullptr, in);
    x += indent + "</Grid>\n";
  }

  // The grids of one instant: one uniform grid per element kind present, in a spatial collection when there
  // are several.
  void xdmf_instant(std::string& x, const Frame* frame, const std::string& indent, const std::string& name) const {
    std::vector<const ElementKindDescription*> kinds;
    for (const ElementKindDescription& k : kElementKindTable)
      if (elements[static_cast<std::size_t>(k.kind)] > 0) kinds.push_back(&k);
    if (kinds.empty()) return xdmf_points(x, frame, indent);
    if (kinds.size() == 1) return xdmf_grid(x, *kinds.front(), frame, indent);
    x += fmt::format("{}<Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Spatial\">\n", indent, name);
    if (frame != nullptr) x += fmt::format("{}  <Time Value=\"{:.17g}\"/>\n", indent, frame->time);
    for (const ElementKindDescription* k : kinds) xdmf_grid(x, *k, frame, indent + "  ");
    x += indent + "</Grid>\n";
  }

  std::string xdmf_text() const {
    std::string x = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n"
                    "  <Domain>\n";
    // The part table for readers of the XML; ParaView ignores Information and colours by the cell data part_id.
    for (const auto& [id, title] : part_table)
      x += fmt::format("    <Information Name=\"part {}\" Value=\"{}\"/>\n", id, xml_escaped(title));
    if (frames.empty()) {
      xdmf_instant(x, nullptr, "    ", "mesh");
    } else {
      x += "    <Grid Name=\"frames\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const Frame& f : frames) {
        x += fmt::format("      <!-- frame {} cycle {} -->\n", f.name, f.cycle);
        xdmf_instant(x, &f, "      ", "frame " + f.name);
      }
      x += "    </Grid>\n";
    }
    x += "  </Domain>\n</Xdmf>\n";
    return x;
  }

  // Written beside the .h5 through a temporary file, so that a reader never sees half of it.
  void write_xdmf() const {
    const std::string text = xdmf_text();
    std::filesystem::path temporary = xdmf_path;
    temporary += ".tmp";
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      out << text;
      out.close();
      if (!out) throw std::runtime_error("cannot write " + temporary.string());
    }
    std::error_code ec;
    std::filesystem::rename(temporary, xdmf_path, ec);
    if (ec) {
      std::filesystem::remove(temporary, ec);
      throw std::runtime_error("cannot write " + xdmf_path.string());
    }
  }

  void close() {
    if (!open) return;
    open = false;  // whatever happens below, the file is released and close() is not tried again
    try {
      if (!widths_known) create_wide_series();
      flush_history();
    } catch (...) {
      for (Series& s : series) s.dataset.reset();
      file.reset();
      throw;
    }
    for (Series& s : series) s.dataset.reset();
    const bool closed = file.reset();
    if (!closed) fail("cannot close");
    write_xdmf();
  }
};

ResultsFile::ResultsFile(const std::filesystem::path& path, const Model& model, std::vector<HistoryDataset> histories,
                         std::optional<double> continue_from)
    : impl_(std::make_unique<Impl>()) {
  QuietErrors quiet;
  Impl& d = *impl_;
  d.path = path;
  d.xdmf_path = path;
  d.xdmf_path.replace_extension(".xdmf");
  d.h5_name = path.filename().string();
  Handle fapl(d.check(H5Pcreate(H5P_FILE_ACCESS), "property list"), H5Pclose);
  // Strong close: H5Fclose closes every object still open, so the file is complete when close() returns.
  d.check_status(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), "property list");
  // The 1.8 object format stores large attributes densely: the column labels of a history with many columns do not
  // fit the 64 KiB object header of the earliest format.
  d.check_status(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), "property list");
  d.th = std::move(histories);
  if (continue_from && std::filesystem::exists(path)) {
    d.file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get()), H5Fclose);
    if (!d.file.valid()) d.cannot_continue("it cannot be opened for writing (" + hdf5::last_error() + ")");
    d.open = true;
    d.continued = true;
    d.check_same_mesh(model);
    d.read_frames_held(*continue_from);
    d.open_history_held(model, *continue_from);
    d.write_xdmf();
    return;
  }
  d.file = Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  if (!d.file.valid()) {
    const std::string detail = hdf5::last_error();
    throw std::runtime_error("cannot create results file " + path.string() + (detail.empty() ? "" : ": " + detail));
  }
  d.open = true;
  const hid_t root = d.file.get();
  d.string_attribute(root, "format", "crumple results");
  d.attribute(root, "format_version", static_cast<std::int32_t>(kFormatVersion));
  d.string_attribute(root, "run_name", model.run_name);
  d.string_attribute(root, "title", model.title);
  d.array_attribute(root, "working_units_si",
                    std::vector<double>{model.units.work[0], model.units.work[1], model.units.work[2]});
  const UnitNames names = unit_names(model.units.work);
  d.string_array_attribute(root, "working_unit_names",
                           {names.mass, names.length, names.time, names.force, names.energy, names.stress});
  d.write_mesh(model);
  d.group(root, "frames");
  d.create_history(model);
  d.check_status(H5Fflush(root, H5F_SCOPE_GLOBAL), "cannot flush");
  d.write_xdmf();
}

ResultsFile::~ResultsFile() {
  try {
    close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "warning: %s\n", e.what());
  } catch (...) {
  }
}

void ResultsFile::write_frame(double time, long long cycle, const Model& model, const SolverState& state) {
  QuietErrors quiet;
  impl_->require_open();
  impl_->write_frame(time, cycle, model, state);
}

void ResultsFile::write_history(const HistoryRow& row) {
  QuietErrors quiet;
  impl_->require_open();
  impl_->append_history(row);
}

std::size_t ResultsFile::frames() const { return impl_->frames.size(); }

void ResultsFile::close() {
  QuietErrors quiet;
  impl_->close();
}

}  // namespace crumple
