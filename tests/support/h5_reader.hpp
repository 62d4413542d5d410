#pragma once
// Test support: reading an HDF5 file back with the HDF5 C API (results files, docs/output-format.md).
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace crumple::test {

class H5Reader {
 public:
  explicit H5Reader(const std::filesystem::path& path) : file_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {
    if (file_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~H5Reader() { H5Fclose(file_); }
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;

  bool exists(const std::string& path) const {
    // H5Lexists checks one link at a time: walk the path from the root.
    std::string prefix;
    std::stringstream parts(path);
    std::string part;
    while (std::getline(parts, part, '/')) {
      if (part.empty()) continue;
      prefix += "/" + part;
      if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    return true;
  }

  std::vector<hsize_t> shape(const std::string& path) const {
    const hid_t set = open(path);
    const hid_t space = H5Dget_space(set);
    std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    H5Dclose(set);
    return dims;
  }

  template <class T>
  std::vector<T> read(const std::string& path, hid_t memory_type) const {
    std::size_t count = 1;
    for (hsize_t d : shape(path)) count *= d;
    std::vector<T> values(count);
    const hid_t set = open(path);
    if (count > 0) H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(set);
    return values;
  }
  std::vector<double> doubles(const std::string& path) const { return read<double>(path, H5T_NATIVE_DOUBLE); }
  std::vector<std::int32_t> ints(const std::string& path) const { return read<std::int32_t>(path, H5T_NATIVE_INT32); }
  std::vector<std::int64_t> longs(const std::string& path) const { return read<std::int64_t>(path, H5T_NATIVE_INT64); }
  std::vector<std::uint8_t> bytes(const std::string& path) const { return read<std::uint8_t>(path, H5T_NATIVE_UINT8); }

  template <class T>
  T attribute(const std::string& object, const std::string& name, hid_t memory_type) const {
    T value{};
    const hid_t attr = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    if (attr < 0) throw std::runtime_error("no attribute " + object + " " + name);
    H5Aread(attr, memory_type, &value);
    H5Aclose(attr);
    return value;
  }

 private:
  hid_t open(const std::string& path) const {
    const hid_t set = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + path);
    return set;
  }
  hid_t file_;
};

}  // namespace crumple::test
