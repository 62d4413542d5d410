#pragma once
// Internal to the output library: the HDF5 C API with its identifiers owned and its errors turned into messages
// (results_file.cpp writes NAME.h5, results_reader.cpp reads it back).
#include <hdf5.h>

#include <string>
#include <string_view>
#include <utility>

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

inline herr_t innermost_error(unsigned, const H5E_error2_t* error, void* client) {
  if (error != nullptr && error->desc != nullptr) *static_cast<std::string*>(client) = error->desc;
  return 0;
}

// The most specific description on the current HDF5 error stack ("No such file or directory" rather than
// "unable to create file"), or an empty string.
inline std::string hdf5_error() {
  std::string desc;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, innermost_error, &desc);
  H5Eclear2(H5E_DEFAULT);
  constexpr std::string_view marker = "error message = '";
  if (const auto at = desc.find(marker); at != std::string::npos) {
    const auto begin = at + marker.size();
    const auto end = desc.find('\'', begin);
    if (end != std::string::npos) return desc.substr(begin, end - begin);
  }
  return desc;
}

}  // namespace crumple::hdf5
