#include "crumple/output/results_reader.hpp"

#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "hdf5_support.hpp"

namespace crumple {

static_assert(std::is_same_v<hid_t, std::int64_t>, "ResultsReader keeps the file's hid_t as std::int64_t");

ResultsReader::ResultsReader(const std::filesystem::path& path) : path_(path) {
  hdf5::QuietErrors quiet;
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) fail("cannot open");
}

ResultsReader::~ResultsReader() {
  if (file_ >= 0) H5Fclose(file_);
}

void ResultsReader::fail(const std::string& what) const {
  const std::string detail = hdf5::last_error();
  throw std::runtime_error("results file " + path_.string() + ": " + what + (detail.empty() ? "" : ": " + detail));
}

bool ResultsReader::exists(const std::string& object) const {
  hdf5::QuietErrors quiet;
  // H5Lexists checks one link at a time: walk the path from the root.
  std::string prefix;
  std::stringstream parts(object);
  for (std::string part; std::getline(parts, part, '/');) {
    if (part.empty()) continue;
    prefix += "/" + part;
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

std::vector<std::size_t> ResultsReader::shape(const std::string& dataset) const {
  hdf5::QuietErrors quiet;
  const hdf5::Handle set(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail("no dataset " + dataset);
  const hdf5::Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0) fail("cannot read the shape of " + dataset);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

template <class T>
std::vector<T> ResultsReader::values(const std::string& dataset) const {
  std::size_t count = 1;
  for (std::size_t d : shape(dataset)) count *= d;
  hdf5::QuietErrors quiet;
  std::vector<T> out(count);
  const hdf5::Handle set(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (count > 0 && H5Dread(set.get(), hdf5::H5Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail("cannot read " + dataset);
  return out;
}

std::vector<double> ResultsReader::doubles(const std::string& dataset) const { return values<double>(dataset); }
std::vector<std::int32_t> ResultsReader::ints(const std::string& dataset) const {
  return values<std::int32_t>(dataset);
}
std::vector<std::int64_t> ResultsReader::longs(const std::string& dataset) const {
  return values<std::int64_t>(dataset);
}
std::vector<std::uint8_t> ResultsReader::bytes(const std::string& dataset) const {
  return values<std::uint8_t>(dataset);
}

template <class T>
T ResultsReader::attribute(const std::string& object, const std::string& name) const {
  hdf5::QuietErrors quiet;
  T value{};
  const hdf5::Handle attr(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) fail("no attribute " + name + " on " + object);
  if (H5Aread(attr.get(), hdf5::H5Types<T>::memory(), &value) < 0) fail("cannot read attribute " + name);
  return value;
}

template double ResultsReader::attribute<double>(const std::string&, const std::string&) const;
template std::int32_t ResultsReader::attribute<std::int32_t>(const std::string&, const std::string&) const;
template std::int64_t ResultsReader::attribute<std::int64_t>(const std::string&, const std::string&) const;

}  // namespace crumple
