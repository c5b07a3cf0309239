// h5md/src/datasets.cpp -- the writer's HDF5 pieces (datasets.hpp): groups, attributes,
// fixed and growing datasets, rows, and the step/time/value elements of H5MD.
#include "datasets.hpp"

#include <cstring>
#include <vector>

namespace hypergas::h5md::detail {

/// Group and dataset creation without time stamps (identical runs, identical datasets).
Id group_props() {
  Id p = checked(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "h5md: property list");
  check(H5Pset_obj_track_times(p.get(), false), "h5md: property list");
  return p;
}

Id make_group(hid_t parent, const char* name) {
  const Id p = group_props();
  return checked(H5Gcreate2(parent, name, H5P_DEFAULT, p.get(), H5P_DEFAULT), H5Gclose,
                 std::string("h5md: cannot create group ") + name);
}

void attr_string(hid_t obj, const char* name, const std::string& value) {
  const Id type = checked(H5Tcopy(H5T_C_S1), H5Tclose, "h5md: string type");
  check(H5Tset_size(type.get(), std::max<std::size_t>(1, value.size())), "h5md: string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "h5md: string type");
  const Id space = checked(H5Screate(H5S_SCALAR), H5Sclose, "h5md: dataspace");
  const Id a = checked(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Aclose, std::string("h5md: cannot write attribute ") + name);
  check(H5Awrite(a.get(), type.get(), value.c_str()), "h5md: attribute write");
}

void attr_strings(hid_t obj, const char* name, const std::vector<std::string>& values) {
  std::size_t w = 1;
  for (const auto& v : values) w = std::max(w, v.size());
  std::vector<char> buf(w * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k)
    std::memcpy(buf.data() + k * w, values[k].data(), values[k].size());
  const Id type = checked(H5Tcopy(H5T_C_S1), H5Tclose, "h5md: string type");
  check(H5Tset_size(type.get(), w), "h5md: string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "h5md: string type");
  const hsize_t dims[1] = {values.size()};
  const Id space = checked(H5Screate_simple(1, dims, nullptr), H5Sclose, "h5md: dataspace");
  const Id a = checked(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Aclose, std::string("h5md: cannot write attribute ") + name);
  check(H5Awrite(a.get(), type.get(), buf.data()), "h5md: attribute write");
}

void attr_ints(hid_t obj, const char* name, const std::vector<int>& values, bool scalar) {
  const hsize_t dims[1] = {values.size()};
  const Id space = checked(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr),
                           H5Sclose, "h5md: dataspace");
  const Id a = checked(
      H5Acreate2(obj, name, H5T_NATIVE_INT, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
      std::string("h5md: cannot write attribute ") + name);
  check(H5Awrite(a.get(), H5T_NATIVE_INT, values.data()), "h5md: attribute write");
}

/// A fixed dataset [n] of `mem` values stored as `file` type.
void fixed_dataset(hid_t parent, const char* name, hid_t file, hid_t mem, std::size_t n,
                   const void* data) {
  const hsize_t dims[1] = {n};
  const Id space = checked(H5Screate_simple(1, dims, nullptr), H5Sclose, "h5md: dataspace");
  const Id dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "h5md: property list");
  check(H5Pset_obj_track_times(dcpl.get(), false), "h5md: property list");
  const Id d = checked(H5Dcreate2(parent, name, file, space.get(), H5P_DEFAULT, dcpl.get(),
                                  H5P_DEFAULT),
                       H5Dclose, std::string("h5md: cannot create dataset ") + name);
  check(H5Dwrite(d.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "h5md: write failed");
}

/// A growing dataset [0, tail...] chunked one frame (or up to ~1 MiB of it) at a time.
Id growing_dataset(hid_t parent, const char* name, hid_t type, const std::vector<hsize_t>& tail) {
  const int rank = 1 + static_cast<int>(tail.size());
  std::vector<hsize_t> dims(std::size_t(rank), 0), max(std::size_t(rank), H5S_UNLIMITED),
      chunk(std::size_t(rank), 1);
  for (std::size_t k = 0; k < tail.size(); ++k) dims[k + 1] = max[k + 1] = chunk[k + 1] = tail[k];
  if (tail.empty()) chunk[0] = 1024;  // scalars per frame: 1024 frames a chunk
  // a frame [n, D] is cut along n into chunks of at most 2^17 doubles (1 MiB)
  if (tail.size() == 2) chunk[1] = std::max<hsize_t>(1, std::min<hsize_t>(tail[0], (1u << 17) / tail[1]));
  const Id space = checked(H5Screate_simple(rank, dims.data(), max.data()), H5Sclose,
                           "h5md: dataspace");
  const Id dcpl = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "h5md: property list");
  check(H5Pset_chunk(dcpl.get(), rank, chunk.data()), "h5md: chunking");
  check(H5Pset_obj_track_times(dcpl.get(), false), "h5md: property list");
  return checked(H5Dcreate2(parent, name, type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                 H5Dclose, std::string("h5md: cannot create dataset ") + name);
}

/// Sets the first dimension of dataset d to `frames`.
void set_frames(hid_t d, std::uint64_t frames) {
  const Id space = checked(H5Dget_space(d), H5Sclose, "h5md: dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > 3) fail("h5md: unexpected dataset rank");
  hsize_t dims[3];
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  dims[0] = frames;
  check(H5Dset_extent(d, dims), "h5md: cannot resize a dataset");
}

/// Writes one frame (row `frame`) of dataset d from `data` of memory type `mem`.
void write_row(hid_t d, hid_t mem, std::uint64_t frame, const void* data) {
  set_frames(d, frame + 1);
  const Id file = checked(H5Dget_space(d), H5Sclose, "h5md: dataspace");
  const int rank = H5Sget_simple_extent_ndims(file.get());
  hsize_t dims[3], start[3] = {frame, 0, 0}, count[3];
  H5Sget_simple_extent_dims(file.get(), dims, nullptr);
  count[0] = 1;
  for (int k = 1; k < rank; ++k) count[k] = dims[k];
  check(H5Sselect_hyperslab(file.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "h5md: selection");
  const Id memspace = checked(H5Screate_simple(rank, count, nullptr), H5Sclose, "h5md: dataspace");
  check(H5Dwrite(d, mem, memspace.get(), file.get(), H5P_DEFAULT, data), "h5md: write failed");
}


std::uint64_t extent0(hid_t d) {
  const Id space = checked(H5Dget_space(d), H5Sclose, "h5md: dataspace");
  hsize_t dims[4] = {0, 0, 0, 0};
  if (H5Sget_simple_extent_ndims(space.get()) < 1) return 0;
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  return dims[0];
}

}  // namespace hypergas::h5md::detail
