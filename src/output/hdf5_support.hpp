#pragma once
// The output layer's HDF5 plumbing, shared by the results file's writer and its reader (results_file.cpp,
// results_reader.cpp): owned identifiers, quiet error stacks turned into messages, and the types written.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace crumple::hdf5 {

// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, -1);
      closer_ = other.closer_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns false when HDF5 reported an error.
  bool reset() {
    herr_t status = 0;
    if (id_ >= 0 && closer_ != nullptr) status = closer_(id_);
    id_ = -1;
    return status >= 0;
  }

 private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

// Turns HDF5's automatic printing of error stacks off for the scope of a public call: failures become
// exceptions that carry the most specific message of the stack instead.
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

// The most specific description on the current HDF5 error stack ("No such file or directory" rather than
// "unable to create file"), or an empty string. Clears the stack.
std::string last_error();

// Reading back what a results file holds (the history reader, and the writer continuing a file).
bool has_attribute(hid_t object, const char* name);
Handle open_attribute(hid_t object, const char* name);
std::size_t attribute_size(const Handle& attr);  // its number of values
// A numeric attribute's values (scalar or 1-D) read as `memory_type`; empty when the object has none.
template <class T>
std::vector<T> numbers(hid_t object, const char* name, hid_t memory_type) {
  if (!has_attribute(object, name)) return {};
  const Handle attr = open_attribute(object, name);
  std::vector<T> out(attribute_size(attr));
  if (!out.empty() && H5Aread(attr.get(), memory_type, out.data()) < 0) return {};
  return out;
}
// The names of a group's members, in creation order when the file tracks it, else by name.
std::vector<std::string> members(hid_t group);
// The dimensions of a dataset, slowest first.
std::vector<hsize_t> shape(hid_t set);

// Memory and file types of the element types written.
template <class T>
struct H5Types;
template <>
struct H5Types<double> {
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
  static hid_t file() { return H5T_IEEE_F64LE; }
  static constexpr const char* xdmf = R"(NumberType="Float" Precision="8")";
};
template <>
struct H5Types<float> {  // the integration points' state of the mixed build (core/precision.hpp)
  static hid_t memory() { return H5T_NATIVE_FLOAT; }
  static hid_t file() { return H5T_IEEE_F32LE; }
  static constexpr const char* xdmf = R"(NumberType="Float" Precision="4")";
};
template <>
struct H5Types<std::int32_t> {
  static hid_t memory() { return H5T_NATIVE_INT32; }
  static hid_t file() { return H5T_STD_I32LE; }
  static constexpr const char* xdmf = R"(NumberType="Int" Precision="4")";
};
template <>
struct H5Types<std::int64_t> {
  static hid_t memory() { return H5T_NATIVE_INT64; }
  static hid_t file() { return H5T_STD_I64LE; }
  static constexpr const char* xdmf = R"(NumberType="Int" Precision="8")";
};
template <>
struct H5Types<std::uint8_t> {
  static hid_t memory() { return H5T_NATIVE_UINT8; }
  static hid_t file() { return H5T_STD_U8LE; }
  static constexpr const char* xdmf = R"(NumberType="UChar" Precision="1")";
};
template <>
struct H5Types<long long> {  // a type of its own beside std::int64_t (long) on LP64
  static hid_t memory() { return H5T_NATIVE_LLONG; }
  static hid_t file() { return H5T_STD_I64LE; }
  static constexpr const char* xdmf = R"(NumberType="Int" Precision="8")";
};

}  // namespace crumple::hdf5
