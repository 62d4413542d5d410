// Reading the histories of NAME.h5 back (include/crumple/output/results_reader.hpp; layout: docs/output-format.md).
#include "crumple/output/history_reader.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "crumple/core/units.hpp"
#include "hdf5_support.hpp"

namespace crumple {
namespace {

using hdf5::attribute_size;
using hdf5::Handle;
using hdf5::has_attribute;
using hdf5::members;
using hdf5::numbers;
using hdf5::open_attribute;
using hdf5::QuietErrors;
using hdf5::shape;

Handle string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

// A variable-length string attribute, scalar or 1-D; empty when the object has none.
std::vector<std::string> strings(hid_t object, const char* name) {
  if (!has_attribute(object, name)) return {};
  const Handle attr = open_attribute(object, name);
  const Handle type = string_type();
  std::vector<char*> texts(attribute_size(attr), nullptr);
  if (texts.empty() || H5Aread(attr.get(), type.get(), texts.data()) < 0) return {};
  std::vector<std::string> out;
  for (char* t : texts) {
    out.emplace_back(t != nullptr ? t : "");
    H5free_memory(t);
  }
  return out;
}

std::string string_of(hid_t object, const char* name) {
  const std::vector<std::string> s = strings(object, name);
  return s.empty() ? std::string() : s.front();
}

// The columns of a dataset from its attributes; a file without them gets labels made from the dataset's name.
std::vector<HistoryColumn> columns_of(hid_t set, const std::string& name, const std::vector<hsize_t>& dims) {
  if (dims.size() == 1) {
    const std::vector<double> scale = numbers<double>(set, "si_scale", H5T_NATIVE_DOUBLE);
    return {{0, "", name, string_of(set, "unit"), scale.empty() ? 1.0 : scale.front(), name}};
  }
  const std::size_t count = dims.size() == 2 ? static_cast<std::size_t>(dims[1]) : 0;
  const auto ids = numbers<std::int64_t>(set, "object_ids", H5T_NATIVE_INT64);
  const auto scales = numbers<double>(set, "si_scale", H5T_NATIVE_DOUBLE);
  const auto titles = strings(set, "object_titles"), variables = strings(set, "variables");
  const auto units = strings(set, "units"), labels = strings(set, "labels");
  std::vector<HistoryColumn> out(count);
  for (std::size_t c = 0; c < count; ++c) {
    HistoryColumn& col = out[c];
    col.object_id = c < ids.size() ? ids[c] : 0;
    col.object_title = c < titles.size() ? titles[c] : "";
    col.variable = c < variables.size() ? variables[c] : "";
    col.unit = c < units.size() ? units[c] : "";
    col.si_scale = c < scales.size() ? scales[c] : 1.0;
    col.label = c < labels.size() ? labels[c] : fmt::format("{}/{}", name, c);
  }
  return out;
}

}  // namespace

struct HistoryFile::Impl {
  std::filesystem::path path;
  Handle file;
  std::size_t rows = 0;
  std::vector<HistorySeries> series;
  std::optional<UnitNames> units;

  [[noreturn]] void fail(const std::string& what) const {
    const std::string detail = hdf5::last_error();
    throw std::runtime_error(fmt::format("{}: {}{}", path.string(), what, detail.empty() ? "" : ": " + detail));
  }

  Handle open_group(const char* name) const {
    Handle g(H5Gopen2(file.get(), name, H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail(fmt::format("no group {}", name));
    return g;
  }

  // The dataset `name` of `group` (at `at`) as a series of `kind`, when it has at least one column.
  void add(hid_t group, const std::string& name, const std::string& at, const std::string& kind) {
    Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) {  // a group or a link to something else: not a history
      H5Eclear2(H5E_DEFAULT);
      return;
    }
    const std::vector<hsize_t> dims = shape(set.get());
    HistorySeries s{at, kind, string_of(set.get(), "keyword"), 0, string_of(set.get(), "title"),
                    columns_of(set.get(), name, dims)};
    const auto id = numbers<std::int64_t>(set.get(), "id", H5T_NATIVE_INT64);
    if (!id.empty()) s.id = id.front();
    if (dims.empty() || static_cast<std::size_t>(dims[0]) != rows)
      fail(fmt::format("{} has {} rows, /history/time {}", at, dims.empty() ? 0 : dims[0], rows));
    if (!s.columns.empty()) series.push_back(std::move(s));
  }

  void read_layout() {
    if (string_of(file.get(), "format") != "crumple results") fail("not a Crumple results file");
    Handle history = open_group("/history");
    Handle time(H5Dopen2(history.get(), "time", H5P_DEFAULT), H5Dclose);
    if (!time.valid()) fail("no dataset /history/time");
    rows = static_cast<std::size_t>(shape(time.get()).at(0));
    add(history.get(), "time", "/history/time", "global");
    for (const std::string& name : members(history.get()))
      if (name != "time" && name != "th") add(history.get(), name, "/history/" + name, "global");
    if (H5Lexists(history.get(), "th", H5P_DEFAULT) > 0) {
      Handle th = open_group("/history/th");
      for (const std::string& name : members(th.get())) {
        Handle set(H5Dopen2(th.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
        add(th.get(), name, "/history/th/" + name, set.valid() ? string_of(set.get(), "kind") : "");
      }
    }
    const auto si = numbers<double>(file.get(), "working_units_si", H5T_NATIVE_DOUBLE);
    if (si.size() == 3) {
      const double work[3] = {si[0], si[1], si[2]};
      units = unit_names(work);
    }
  }
};

HistoryFile::HistoryFile(const std::filesystem::path& path) : impl_(std::make_unique<Impl>()) {
  QuietErrors quiet;
  impl_->path = path;
  if (!std::filesystem::exists(path)) throw std::runtime_error(path.string() + ": no such file");
  impl_->file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!impl_->file.valid()) impl_->fail("cannot open as an HDF5 file");
  impl_->read_layout();
}

HistoryFile::~HistoryFile() = default;

std::size_t HistoryFile::rows() const { return impl_->rows; }

std::string HistoryFile::unit_of(const HistoryColumn& column) const {
  return impl_->units ? unit_name(column.unit, *impl_->units) : column.unit;
}

const std::vector<HistorySeries>& HistoryFile::series() const { return impl_->series; }

std::vector<double> HistoryFile::values(std::size_t s) const {
  QuietErrors quiet;
  const HistorySeries& series = impl_->series.at(s);
  Handle set(H5Dopen2(impl_->file.get(), series.path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) impl_->fail("cannot open " + series.path);
  std::vector<double> out(impl_->rows * series.columns.size());
  if (!out.empty() && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    impl_->fail("cannot read " + series.path);
  return out;
}

}  // namespace crumple
