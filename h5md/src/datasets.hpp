// h5md/src/datasets.hpp -- the writer's HDF5 pieces: groups and datasets created without
// time stamps (identical runs, identical files), attributes, growing datasets of frames and
// the step/time/value element of H5MD (datasets.cpp). Private to h5md/src.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hdf5.hpp"

namespace hypergas::h5md::detail {

/// Group and dataset creation without time stamps (identical runs, identical datasets).
Id group_props();

Id make_group(hid_t parent, const char* name);

void attr_string(hid_t obj, const char* name, const std::string& value);

void attr_strings(hid_t obj, const char* name, const std::vector<std::string>& values);

void attr_ints(hid_t obj, const char* name, const std::vector<int>& values, bool scalar);

/// A fixed dataset [n] of `mem` values stored as `file` type.
void fixed_dataset(hid_t parent, const char* name, hid_t file, hid_t mem, std::size_t n,
                   const void* data);

/// A growing dataset [0, tail...] chunked one frame (or up to ~1 MiB of it) at a time.
Id growing_dataset(hid_t parent, const char* name, hid_t type, const std::vector<hsize_t>& tail);

/// Sets the first dimension of dataset d to `frames`.
void set_frames(hid_t d, std::uint64_t frames);

/// Writes one frame (row `frame`) of dataset d from `data` of memory type `mem`.
void write_row(hid_t d, hid_t mem, std::uint64_t frame, const void* data);

/// The first dimension of dataset d (0 for a scalar).
std::uint64_t extent0(hid_t d);

/// A time-dependent element: the group with step, time and value.
struct Element {
  Id group, step, time, value;
  hid_t mem = H5T_NATIVE_DOUBLE;
  void create(hid_t parent, const char* name, hid_t file_type, hid_t mem_type,
              const std::vector<hsize_t>& tail) {
    group = make_group(parent, name);
    step = growing_dataset(group.get(), "step", H5T_STD_I64LE, {});
    time = growing_dataset(group.get(), "time", H5T_IEEE_F64LE, {});
    value = growing_dataset(group.get(), "value", file_type, tail);
    mem = mem_type;
  }
  void open(hid_t parent, const char* name, hid_t mem_type) {
    group = checked(H5Gopen2(parent, name, H5P_DEFAULT), H5Gclose,
                    std::string("h5md: the file has no ") + name);
    step = checked(H5Dopen2(group.get(), "step", H5P_DEFAULT), H5Dclose, "h5md: no step");
    time = checked(H5Dopen2(group.get(), "time", H5P_DEFAULT), H5Dclose, "h5md: no time");
    value = checked(H5Dopen2(group.get(), "value", H5P_DEFAULT), H5Dclose, "h5md: no value");
    mem = mem_type;
  }
  void append(std::uint64_t frame, std::int64_t s, double t, const void* data) {
    write_row(step.get(), H5T_NATIVE_INT64, frame, &s);
    write_row(time.get(), H5T_NATIVE_DOUBLE, frame, &t);
    write_row(value.get(), mem, frame, data);
  }
  void truncate(std::uint64_t frames) {
    for (const Id* d : {&step, &time, &value}) set_frames(d->get(), frames);
  }
};

}  // namespace hypergas::h5md::detail
