#pragma once
// Reads a results file NAME.h5 back (layout: docs/output-format.md): the regression comparison's histories and
// the tests' checks of the writer. Every failure (no such file, dataset or attribute) throws std::runtime_error
// naming the file and the object.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace crumple {

class ResultsReader {
 public:
  explicit ResultsReader(const std::filesystem::path& path);
  ~ResultsReader();
  ResultsReader(const ResultsReader&) = delete;
  ResultsReader& operator=(const ResultsReader&) = delete;

  // Whether every group of `object` ("/frames/0001/displacement") exists.
  bool exists(const std::string& object) const;
  // The dimensions of a dataset, slowest first.
  std::vector<std::size_t> shape(const std::string& dataset) const;
  // A dataset's values in row-major order, converted to the type asked for.
  std::vector<double> doubles(const std::string& dataset) const;
  std::vector<std::int32_t> ints(const std::string& dataset) const;
  std::vector<std::int64_t> longs(const std::string& dataset) const;
  std::vector<std::uint8_t> bytes(const std::string& dataset) const;
  // A scalar attribute of a group or dataset; T is double, std::int32_t or std::int64_t.
  template <class T>
  T attribute(const std::string& object, const std::string& name) const;

 private:
  template <class T>
  std::vector<T> values(const std::string& dataset) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path path_;
  std::int64_t file_ = -1;  // the HDF5 file identifier (hid_t)
};

}  // namespace crumple
