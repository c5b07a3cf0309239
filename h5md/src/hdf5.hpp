// h5md/src/hdf5.hpp -- what every part of hypergas_h5md uses of HDF5's C interface: its
// error stack silenced (a failure becomes one InvalidInput line), and identifiers that
// close themselves. Private to h5md/src: no HDF5 type reaches hypergas/h5md/h5md.hpp.
#pragma once

#include <hdf5.h>

#include <string>
#include <utility>

#include "hypergas/error.hpp"

namespace hypergas::h5md::detail {

[[noreturn]] inline void fail(const std::string& what) { throw InvalidInput(what); }

/// HDF5 prints its error stack on stderr by default; every failure here becomes one line.
inline void quiet() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

/// An HDF5 identifier, closed with its own function.
class Id {
 public:
  Id() = default;
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id(Id&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  Id& operator=(Id&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      close_ = o.close_;
    }
    return *this;
  }
  ~Id() { reset(); }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

inline Id checked(hid_t id, herr_t (*close)(hid_t), const std::string& what) {
  if (id < 0) fail(what);
  return Id(id, close);
}
inline void check(herr_t r, const std::string& what) {
  if (r < 0) fail(what);
}


}  // namespace hypergas::h5md::detail
