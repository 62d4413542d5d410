#include "hdf5_support.hpp"

#include <algorithm>
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

bool has_attribute(hid_t object, const char* name) { return H5Aexists(object, name) > 0; }

Handle open_attribute(hid_t object, const char* name) { return {H5Aopen(object, name, H5P_DEFAULT), H5Aclose}; }

std::size_t attribute_size(const Handle& attr) {
  Handle space(H5Aget_space(attr.get()), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

std::vector<std::string> members(hid_t group) {
  H5G_info_t info;
  if (H5Gget_info(group, &info) < 0) return {};
  for (H5_index_t index : {H5_INDEX_CRT_ORDER, H5_INDEX_NAME}) {
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      const ssize_t size = H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
      if (size < 0) break;
      std::string name(static_cast<std::size_t>(size) + 1, '\0');
      H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
      name.resize(static_cast<std::size_t>(size));
      names.push_back(std::move(name));
    }
    if (names.size() == info.nlinks) return names;
    H5Eclear2(H5E_DEFAULT);
  }
  return {};
}

std::vector<hsize_t> shape(hid_t set) {
  Handle space(H5Dget_space(set), H5Sclose);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(space.get()))));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

}  // namespace crumple::hdf5
