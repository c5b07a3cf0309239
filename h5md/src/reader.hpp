// h5md/src/reader.hpp -- reading an H5MD file in this process: an open file with its
// checked dataset reads (Reader), and read_state_here, which the isolated reader
// (isolated_reader.cpp) runs in a child process. Private to h5md/src.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hdf5.hpp"
#include "hypergas/h5md/h5md.hpp"

namespace hypergas::h5md::detail {

struct Reader {
  std::string path;
  Id file;

  [[noreturn]] void bad(const std::string& what) const { fail(path + ": " + what); }

  std::vector<hsize_t> shape(hid_t d) const {
    const Id space = checked(H5Dget_space(d), H5Sclose, path + ": unreadable dataspace");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0 || rank > 8) bad("unreadable dataspace");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return dims;
  }

  bool exists(hid_t parent, const std::string& name) const {
    return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0;
  }
  bool is_group(hid_t parent, const std::string& name) const {
    if (!exists(parent, name)) return false;
    const hid_t g = H5Gopen2(parent, name.c_str(), H5P_DEFAULT);  // fails on a dataset
    if (g < 0) return false;
    H5Gclose(g);
    return true;
  }

  Id dataset(hid_t parent, const std::string& name) const {
    return checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose,
                   path + ": cannot open " + name);
  }

  /// Reads `count` rows from `first` of the open dataset d (rank >= 1, called `name` in
  /// messages) as doubles or ints.
  template <class T>
  std::vector<T> rows(const Id& d, const std::string& name, hsize_t first, hsize_t count,
                      hid_t mem) const {
    const std::vector<hsize_t> dims = shape(d.get());
    if (dims.empty()) bad(name + " is a scalar, expected an array");
    std::vector<hsize_t> start(dims.size(), 0), cnt = dims;
    start[0] = first, cnt[0] = count;
    std::size_t total = 1;
    for (hsize_t c : cnt) total *= std::size_t(c);
    std::vector<T> out(total);
    const Id file_space = checked(H5Dget_space(d.get()), H5Sclose, path + ": dataspace");
    if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, cnt.data(),
                            nullptr) < 0)
      bad("cannot select rows of " + name);
    const Id mem_space = checked(H5Screate_simple(int(cnt.size()), cnt.data(), nullptr),
                                 H5Sclose, path + ": dataspace");
    if (H5Dread(d.get(), mem, mem_space.get(), file_space.get(), H5P_DEFAULT, out.data()) < 0)
      bad("cannot read " + name + " (truncated or damaged file?)");
    return out;
  }
};

/// Opens `path` as an H5MD file (a regular file, HDF5, with /h5md and /particles), or throws
/// InvalidInput with one line.
Reader open_file(const std::string& path);

/// read_state (h5md.hpp) in the calling process, without the isolation.
State read_state_here(const std::string& path, std::int64_t frame);

}  // namespace hypergas::h5md::detail
