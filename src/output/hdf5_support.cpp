#include "hdf5_support.hpp"

#include <string_view>

namespace crumple::hdf5 {
namespace {

herr_t innermost_error(unsigned, const H5E_error2_t* error, void* client) {
  if (error != nullptr && error->desc != nullptr) *static_cast<std::string*>(client) = error->desc;
  return 0;
}

}  // namespace

std::string last_error() {
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
