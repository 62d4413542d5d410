// NAME.rst (docs/output-format.md, "Restart file"): one dataset per field of the snapshot (solver/snapshot.hpp),
// under /state, and the model's counts as attributes of the root to refuse a file written for another deck.
#include "crumple/output/restart_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "crumple/core/precision.hpp"
#include "crumple/output/build_info.hpp"
#include "crumple/state/element_status.hpp"
#include "hdf5_support.hpp"

namespace crumple {
namespace {

using hdf5::Handle;
using hdf5::H5Types;

// 2: marks/deleted_inverted and marks/step_drop_warned; 3: shells' hardening_term; 4: springs and /DAMP's alpha;
// 6: trusses and beams; 8: six hourglass stresses per 4-node shell (kShellHourglassModes, docs/theory/shell4.md S-13a)
constexpr int kRestartFormat = 8;

// The counts a snapshot's arrays are sized by; a restart file is read only by a model with the same counts.
std::array<long long, 9> model_counts(const Model& m, const SolverState& s) {
  return {static_cast<long long>(m.nodes.size()),       static_cast<long long>(m.elements[0].size()),
          static_cast<long long>(m.elements[1].size()), static_cast<long long>(m.elements[2].size()),
          static_cast<long long>(m.elements[3].size()), static_cast<long long>(m.elements[4].size()),
          static_cast<long long>(m.elements[5].size()), static_cast<long long>(s.bodies.size()),
          static_cast<long long>(s.contact.interfaces.size())};
}
constexpr std::array<const char*, 9> kCountNames{"nodes",   "shells4", "shells3", "bricks",    "springs",
                                                 "trusses", "beams",   "rigid_bodies", "interfaces"};

template <class T>
using Stored = std::conditional_t<std::is_same_v<T, bool>, std::uint8_t, T>;

class Writer {
 public:
  explicit Writer(hid_t root) : root_(root), links_(H5Pcreate(H5P_LINK_CREATE), H5Pclose) {
    H5Pset_create_intermediate_group(links_.get(), 1);
  }
  template <class T>
  void operator()(const std::string& name, std::vector<T>& values) {
    write(name, values.data(), values.size());
  }
  // Element statuses: their conditions only, as one process has them; a domain of a run of several marks the
  // elements it does not compute when it reads them back (parallel runs, docs/parallel.md).
  void operator()(const std::string& name, std::vector<std::uint8_t>& values) {
    if (!name.ends_with("/deleted")) return write(name, values.data(), values.size());
    conditions_.resize(values.size());
    for (std::size_t e = 0; e < values.size(); ++e) conditions_[e] = element_condition(values[e]);
    write(name, conditions_.data(), conditions_.size());
  }
  template <class T, std::size_t N>
  void operator()(const std::string& name, std::array<T, N>& values) {
    write(name, values.data(), N);
  }
  void operator()(const std::string& name, Vec3& v) {  // as three doubles x y z
    const double xyz[3] = {v.x, v.y, v.z};
    write(name, xyz, 3);
  }
  template <class T>
  void operator()(const std::string& name, T& value) {
    const Stored<T> stored = static_cast<Stored<T>>(value);
    write(name, &stored, 1);
  }

 private:
  template <class T>
  void write(const std::string& name, const T* data, std::size_t size) {
    const hsize_t dims[1] = {static_cast<hsize_t>(size)};
    Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
    Handle set(H5Dcreate2(root_, name.c_str(), H5Types<T>::file(), space.get(), links_.get(), H5P_DEFAULT,
                          H5P_DEFAULT), H5Dclose);
    if (!set.valid() || (size > 0 && H5Dwrite(set.get(), H5Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                               data) < 0))
      throw std::runtime_error(fmt::format("cannot write {} into the restart file: {}", name, hdf5::last_error()));
  }
  hid_t root_;
  Handle links_;
  std::vector<std::uint8_t> conditions_;
};

class Reader {
 public:
  Reader(hid_t root, std::string file) : root_(root), file_(std::move(file)) {}
  template <class T>
  void operator()(const std::string& name, std::vector<T>& values) {
    values.resize(size_of(name));
    read(name, values.data(), values.size());
  }
  template <class T, std::size_t N>
  void operator()(const std::string& name, std::array<T, N>& values) {
    if (size_of(name) != N) fail(name, fmt::format("{} values expected, {} found", N, size_of(name)));
    read(name, values.data(), N);
  }
  void operator()(const std::string& name, Vec3& v) {
    std::array<double, 3> xyz{};
    (*this)(name, xyz);
    v = {xyz[0], xyz[1], xyz[2]};
  }
  template <class T>
  void operator()(const std::string& name, T& value) {
    if (size_of(name) != 1) fail(name, "one value expected");
    Stored<T> stored{};
    read(name, &stored, 1);
    value = static_cast<T>(stored);
  }

 private:
  [[noreturn]] void fail(const std::string& name, const std::string& why) const {
    throw RestartError(fmt::format("restart file {}: {}: {}", file_, name, why));
  }
  std::size_t size_of(const std::string& name) {
    Handle set(H5Dopen2(root_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) fail(name, "missing (not a restart file of this Crumple version)");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    hsize_t dims[1] = {0};
    if (H5Sget_simple_extent_ndims(space.get()) != 1 || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0)
      fail(name, "not a one-dimensional dataset");
    return static_cast<std::size_t>(dims[0]);
  }
  template <class T>
  void read(const std::string& name, T* data, std::size_t size) {
    if (size == 0) return;
    Handle set(H5Dopen2(root_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (H5Dread(set.get(), H5Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
      fail(name, "cannot be read: " + hdf5::last_error());
  }
  hid_t root_;
  std::string file_;
};

void write_count(hid_t file, const char* name, long long value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(file, name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_LLONG, &value) < 0)
    throw std::runtime_error(fmt::format("cannot write the attribute {} of the restart file", name));
}

long long read_count(hid_t file, const char* name, const std::string& path) {
  long long value = -1;
  Handle attribute(H5Aopen(file, name, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Aread(attribute.get(), H5T_NATIVE_LLONG, &value) < 0)
    throw RestartError(fmt::format("restart file {}: no attribute {} (not a Crumple restart file)", path, name));
  return value;
}

}  // namespace

void write_restart(const std::filesystem::path& file, const Model& model, SolverState& state, ResumeMarks& marks) {
  hdf5::QuietErrors quiet;
  const std::filesystem::path partial = file.string() + ".partial";
  {
    Handle h5(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!h5.valid())
      throw std::runtime_error(fmt::format("cannot create the restart file {}: {}", partial.string(), hdf5::last_error()));
    write_count(h5.get(), "format", kRestartFormat);
    const auto counts = model_counts(model, state);
    for (std::size_t k = 0; k < counts.size(); ++k) write_count(h5.get(), kCountNames[k], counts[k]);
    write_count(h5.get(), "point_bytes", static_cast<long long>(sizeof(point_real)));
    Handle root(H5Gcreate2(h5.get(), "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    Writer writer(root.get());
    visit_state(writer, state, marks);
    root.reset();
    if (!h5.reset()) throw std::runtime_error("cannot close the restart file " + partial.string());
  }
  std::filesystem::rename(partial, file);
}

ResumeMarks read_restart(const std::filesystem::path& file, const Model& model, SolverState& state) {
  hdf5::QuietErrors quiet;
  const std::string path = file.string();
  if (!std::filesystem::is_regular_file(file)) throw RestartError(fmt::format("restart file {}: no such file", path));
  Handle h5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) throw RestartError(fmt::format("restart file {}: not an HDF5 file ({})", path, hdf5::last_error()));
  if (const long long format = read_count(h5.get(), "format", path); format != kRestartFormat)
    throw RestartError(fmt::format("restart file {}: format {}, this Crumple reads format {}", path, format,
                                   kRestartFormat));
  const auto counts = model_counts(model, state);
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (const long long found = read_count(h5.get(), kCountNames[k], path); found != counts[k])
      throw RestartError(fmt::format("restart file {} was written for another model: {} {} in the file, {} in the "
                                     "deck", path, found, kCountNames[k], counts[k]));
  // The integration points' state as the build that wrote the file stored it (core/precision.hpp): a run goes on
  // in the precision it started in. A file without the attribute comes from a double build.
  const long long point_bytes = H5Aexists(h5.get(), "point_bytes") > 0 ? read_count(h5.get(), "point_bytes", path) : 8;
  if (point_bytes != static_cast<long long>(sizeof(point_real)))
    throw RestartError(fmt::format("restart file {} was written by the {} build of Crumple, and this is the {} build: "
                                   "resume it with the build that wrote it (docs/theory/precision.md)",
                                   path, point_bytes == 4 ? "mixed" : "double", kPrecision));
  Handle root(H5Gopen2(h5.get(), "state", H5P_DEFAULT), H5Gclose);
  if (!root.valid()) throw RestartError(fmt::format("restart file {}: no /state group", path));
  ResumeMarks marks;
  Reader reader(root.get(), path);
  visit_state(reader, state, marks);
  return marks;
}

}  // namespace crumple
