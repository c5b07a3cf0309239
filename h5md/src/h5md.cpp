// h5md/src/h5md.cpp -- the H5MD writer and reader on HDF5's C interface
// (hypergas/h5md/h5md.hpp has the layout).
#include "hypergas/h5md/h5md.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/error.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <stdexcept>

namespace hypergas::h5md {

namespace {

[[noreturn]] void fail(const std::string& what) { throw InvalidInput(what); }

/// HDF5 prints its error stack on stderr by default; every failure here becomes one line.
void quiet() {
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

Id checked(hid_t id, herr_t (*close)(hid_t), const std::string& what) {
  if (id < 0) fail(what);
  return Id(id, close);
}
void check(herr_t r, const std::string& what) {
  if (r < 0) fail(what);
}

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

std::uint64_t extent0(hid_t d) {
  const Id space = checked(H5Dget_space(d), H5Sclose, "h5md: dataspace");
  hsize_t dims[4] = {0, 0, 0, 0};
  if (H5Sget_simple_extent_ndims(space.get()) < 1) return 0;
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  return dims[0];
}

}  // namespace

struct Writer::Impl {
  Layout layout;
  Id file, particles, box, observables_group;
  Element edges, position, image, velocity;
  std::vector<Element> observables;
  std::uint64_t frames = 0;

  void open_elements(bool create) {
    const hid_t f = file.get();
    if (create) {
      const Id h5md = make_group(f, "h5md");
      attr_ints(h5md.get(), "version", {1, 1}, false);
      const Id author = make_group(h5md.get(), "author");
      attr_string(author.get(), "name", "hypergas user");
      const Id creator = make_group(h5md.get(), "creator");
      attr_string(creator.get(), "name", "hypergas");
      attr_string(creator.get(), "version", layout.creator_version);
      const Id ps = make_group(f, "particles");
      particles = make_group(ps.get(), "all");
      box = make_group(particles.get(), "box");
      attr_ints(box.get(), "dimension", {layout.dim}, true);
      attr_strings(box.get(), "boundary",
                   std::vector<std::string>(std::size_t(layout.dim),
                                            layout.positions ? "periodic" : "none"));
      const hsize_t n = layout.n, d = hsize_t(layout.dim);
      if (layout.positions) {
        // the D x D matrix form of the edges (diagonal here): MDAnalysis reads that one
        edges.create(box.get(), "edges", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {d, d});
        position.create(particles.get(), "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n, d});
        image.create(particles.get(), "image", H5T_STD_I32LE, H5T_NATIVE_INT32, {n, d});
      }
      velocity.create(particles.get(), "velocity", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n, d});
      std::vector<std::int32_t> species = layout.species;
      if (species.empty()) species.assign(layout.n, 0);
      std::vector<double> mass = layout.mass;
      if (mass.empty()) mass.assign(layout.n, 1.0);
      fixed_dataset(particles.get(), "species", H5T_STD_I32LE, H5T_NATIVE_INT32, layout.n,
                    species.data());
      fixed_dataset(particles.get(), "mass", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, layout.n,
                    mass.data());
      if (layout.ids) {
        std::vector<std::int64_t> id(layout.n);
        for (std::size_t i = 0; i < layout.n; ++i) id[i] = static_cast<std::int64_t>(i);
        fixed_dataset(particles.get(), "id", H5T_STD_I64LE, H5T_NATIVE_INT64, layout.n, id.data());
      }
      observables_group = make_group(f, "observables");
      for (const auto& name : layout.observables) {
        observables.emplace_back();
        observables.back().create(observables_group.get(), name.c_str(), H5T_IEEE_F64LE,
                                  H5T_NATIVE_DOUBLE, {});
      }
      const Id params = make_group(f, "parameters");
      const Id mine = make_group(params.get(), "hypergas");
      for (const auto& [k, v] : layout.parameters) attr_string(mine.get(), k.c_str(), v);
    } else {
      particles = checked(H5Gopen2(f, "particles/all", H5P_DEFAULT), H5Gclose,
                          "h5md: the trajectory has no /particles/all");
      box = checked(H5Gopen2(particles.get(), "box", H5P_DEFAULT), H5Gclose,
                    "h5md: the trajectory has no box");
      if (layout.positions) {
        edges.open(box.get(), "edges", H5T_NATIVE_DOUBLE);
        position.open(particles.get(), "position", H5T_NATIVE_DOUBLE);
        image.open(particles.get(), "image", H5T_NATIVE_INT32);
      }
      velocity.open(particles.get(), "velocity", H5T_NATIVE_DOUBLE);
      observables_group = checked(H5Gopen2(f, "observables", H5P_DEFAULT), H5Gclose,
                                  "h5md: the trajectory has no /observables");
      for (const auto& name : layout.observables) {
        observables.emplace_back();
        observables.back().open(observables_group.get(), name.c_str(), H5T_NATIVE_DOUBLE);
      }
    }
  }
};

Writer::Writer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Writer::Writer(const std::string& path, const Layout& layout) {
  quiet();
  if (layout.dim < 1 || layout.dim > 6 || layout.n == 0)
    fail("h5md: a trajectory needs D in 1..6 and N >= 1");
  impl_ = std::make_unique<Impl>();
  impl_->layout = layout;
  const Id fcpl = checked(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "h5md: property list");
  check(H5Pset_obj_track_times(fcpl.get(), false), "h5md: property list");
  impl_->file = checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose,
                        "cannot create the trajectory file " + path);
  impl_->open_elements(true);
  flush();
}

Writer Writer::resume(const std::string& path, const Layout& layout, std::uint64_t frames) {
  quiet();
  auto impl = std::make_unique<Impl>();
  impl->layout = layout;
  impl->file = checked(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose,
                       "cannot reopen the trajectory file " + path +
                           " (missing or damaged: the run cannot continue it)");
  impl->open_elements(false);
  if (extent0(impl->velocity.value.get()) < frames)
    fail("the trajectory file " + path + " has fewer frames than its checkpoint says");
  impl->frames = frames;
  std::vector<Element*> all{&impl->velocity};
  if (layout.positions) all.insert(all.end(), {&impl->edges, &impl->position, &impl->image});
  for (Element& e : impl->observables) all.push_back(&e);
  for (Element* e : all) e->truncate(frames);
  Writer w(std::move(impl));
  w.flush();
  return w;
}

Writer::~Writer() = default;
Writer::Writer(Writer&&) noexcept = default;
Writer& Writer::operator=(Writer&&) noexcept = default;

void Writer::append(const FrameData& f) {
  if (!impl_ || !impl_->file.valid()) fail("h5md: append to a closed trajectory");
  Impl& m = *impl_;
  const std::uint64_t k = m.frames;
  if (m.layout.positions) {
    const std::size_t D = std::size_t(m.layout.dim);
    std::vector<double> e(D * D, 0.0);
    for (std::size_t k = 0; k < D; ++k) e[k * D + k] = f.box;
    m.edges.append(k, f.step, f.time, e.data());
    m.position.append(k, f.step, f.time, f.positions);
    m.image.append(k, f.step, f.time, f.images);
  }
  m.velocity.append(k, f.step, f.time, f.velocities);
  for (std::size_t o = 0; o < m.observables.size(); ++o)
    m.observables[o].append(k, f.step, f.time, f.observables + o);
  ++m.frames;
}

void Writer::flush() {
  if (impl_ && impl_->file.valid())
    check(H5Fflush(impl_->file.get(), H5F_SCOPE_GLOBAL), "h5md: flush failed");
}

std::uint64_t Writer::frames() const { return impl_ ? impl_->frames : 0; }

void Writer::close() {
  if (!impl_) return;
  flush();
  impl_.reset();
}

// ---------------------------------------------------------------------------------------
// Reading

namespace {

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

void require_finite(const Reader& r, const std::vector<double>& v, const std::string& what) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k])) r.bad(what + " holds a value that is not finite (element " +
                                    std::to_string(k) + ")");
}

Reader open_file(const std::string& path) {
  quiet();
  Reader r;
  r.path = path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path + ": no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0)
    fail(path + ": not an HDF5 file (or a truncated one)");
  r.file = checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                   path + ": not a readable HDF5 file (truncated or damaged?)");
  if (!r.exists(r.file.get(), "h5md") || !r.exists(r.file.get(), "particles"))
    r.bad("not an H5MD file (no /h5md or /particles group)");
  return r;
}

/// The particle group: /particles/all, else the only group in /particles.
std::string particle_group(const Reader& r) {
  if (r.exists(r.file.get(), "particles/all")) return "particles/all";
  const Id g = checked(H5Gopen2(r.file.get(), "particles", H5P_DEFAULT), H5Gclose,
                       r.path + ": cannot open /particles");
  H5G_info_t info;
  if (H5Gget_info(g.get(), &info) < 0 || info.nlinks != 1)
    r.bad("/particles holds no group 'all' and not exactly one particle group");
  char name[256] = {0};
  if (H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, 0, name, sizeof name,
                         H5P_DEFAULT) < 0)
    r.bad("unreadable /particles");
  return std::string("particles/") + name;
}

int read_dimension(const Reader& r, hid_t box) {
  if (H5Aexists(box, "dimension") <= 0) r.bad("the box has no 'dimension' attribute");
  const Id a = checked(H5Aopen(box, "dimension", H5P_DEFAULT), H5Aclose, r.path + ": box");
  const Id space = checked(H5Aget_space(a.get()), H5Sclose, r.path + ": box");
  if (H5Sget_simple_extent_npoints(space.get()) != 1) r.bad("the box dimension is not a scalar");
  int d = 0;
  if (H5Aread(a.get(), H5T_NATIVE_INT, &d) < 0) r.bad("unreadable box dimension");
  if (d < 1 || d > 6) r.bad("box dimension " + std::to_string(d) + " is outside 1..6");
  return d;
}

/// Reads an element's frame k as doubles (time-dependent group) or the whole dataset
/// (time-independent); `time`/`step` set from a group.
std::vector<double> element(const Reader& r, hid_t parent, const std::string& name,
                            std::int64_t k, std::uint64_t* frames, double* time,
                            std::int64_t* step) {
  if (r.is_group(parent, name)) {
    const Id g = checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose,
                         r.path + ": cannot open " + name);
    if (!r.exists(g.get(), "value")) r.bad(name + " has no value dataset");
    const Id d = r.dataset(g.get(), "value");
    const std::vector<hsize_t> dims = r.shape(d.get());
    const std::uint64_t F = dims.empty() ? 0 : dims[0];
    if (frames) *frames = F;
    const std::int64_t idx = k < 0 ? static_cast<std::int64_t>(F) + k : k;
    if (F == 0 || idx < 0 || static_cast<std::uint64_t>(idx) >= F)
      r.bad("frame " + std::to_string(k) + " does not exist: " + name + " has " +
            std::to_string(F) + " frame(s)");
    if (time && r.exists(g.get(), "time"))
      *time = r.rows<double>(r.dataset(g.get(), "time"), name + "/time", hsize_t(idx), 1,
                             H5T_NATIVE_DOUBLE).at(0);
    if (step && r.exists(g.get(), "step"))
      *step = r.rows<std::int64_t>(r.dataset(g.get(), "step"), name + "/step", hsize_t(idx), 1,
                                   H5T_NATIVE_INT64).at(0);
    return r.rows<double>(d, name + "/value", hsize_t(idx), 1, H5T_NATIVE_DOUBLE);
  }
  const Id d = r.dataset(parent, name);
  const auto dims = r.shape(d.get());
  return r.rows<double>(d, name, 0, dims.empty() ? 1 : dims[0], H5T_NATIVE_DOUBLE);
}

std::vector<hsize_t> value_shape(const Reader& r, hid_t parent, const std::string& name) {
  const bool per_frame = r.is_group(parent, name);
  auto s = r.shape(r.dataset(parent, per_frame ? name + "/value" : name).get());
  if (per_frame && !s.empty()) s.erase(s.begin());
  return s;
}

}  // namespace

State read_state_here(const std::string& path, std::int64_t frame) {
  Reader r = open_file(path);
  const std::string pg = particle_group(r);
  const Id g = checked(H5Gopen2(r.file.get(), pg.c_str(), H5P_DEFAULT), H5Gclose,
                       path + ": cannot open /" + pg);
  if (!r.exists(g.get(), "box")) r.bad("/" + pg + " has no box (H5MD requires one)");
  const Id box = checked(H5Gopen2(g.get(), "box", H5P_DEFAULT), H5Gclose, path + ": box");
  State s;
  s.dim = read_dimension(r, box.get());
  if (!r.exists(g.get(), "velocity")) r.bad("/" + pg + " has no velocity");
  const auto vs = value_shape(r, g.get(), "velocity");
  if (vs.size() != 2 || vs[1] != hsize_t(s.dim))
    r.bad("velocity has not the shape [N, " + std::to_string(s.dim) + "] of the box's dimension");
  s.n = std::size_t(vs[0]);
  if (s.n == 0) r.bad("velocity holds no particles");
  s.velocities = element(r, g.get(), "velocity", frame, &s.frames, &s.time, &s.step);
  s.frame = frame < 0 ? s.frames + std::uint64_t(frame) : std::uint64_t(frame);
  require_finite(r, s.velocities, "velocity");
  if (r.exists(g.get(), "position")) {
    const auto ps = value_shape(r, g.get(), "position");
    if (ps.size() != 2 || ps[0] != vs[0] || ps[1] != vs[1])
      r.bad("position and velocity have different shapes");
    std::uint64_t pf = 0;
    s.positions = element(r, g.get(), "position", frame, &pf, nullptr, nullptr);
    require_finite(r, s.positions, "position");
    if (!r.exists(box.get(), "edges")) r.bad("the box has positions but no edges");
    std::vector<double> e = element(r, box.get(), "edges", frame, nullptr, nullptr, nullptr);
    require_finite(r, e, "box edges");
    if (e.size() == std::size_t(s.dim * s.dim)) {  // a D x D matrix: diagonal only
      std::vector<double> diag(std::size_t(s.dim));
      for (int a = 0; a < s.dim; ++a)
        for (int b = 0; b < s.dim; ++b) {
          const double x = e[std::size_t(a * s.dim + b)];
          if (a == b) diag[std::size_t(a)] = x;
          else if (x != 0.0) r.bad("the box is not rectangular (off-diagonal edges)");
        }
      e = diag;
    }
    if (e.size() != std::size_t(s.dim)) r.bad("the box edges have not D values");
    for (double x : e)
      if (!(x > 0.0) || x != e[0]) r.bad("the box is not a cube of positive side");
    s.box = e[0];
    // positions into [0, box): an H5MD file may hold unwrapped ones
    for (double& x : s.positions) {
      x -= s.box * std::floor(x / s.box);
      if (x >= s.box) x = 0.0;
    }
  }
  if (r.exists(g.get(), "species")) {
    const auto v = element(r, g.get(), "species", frame, nullptr, nullptr, nullptr);
    if (v.size() != s.n) r.bad("species has not N values");
    for (double x : v) {
      if (!(x >= 0.0 && x < 256.0 && x == std::floor(x))) r.bad("species must be integers in 0..255");
      s.species.push_back(static_cast<std::int32_t>(x));
    }
  }
  if (r.exists(g.get(), "mass")) {
    s.mass = element(r, g.get(), "mass", frame, nullptr, nullptr, nullptr);
    if (s.mass.size() != s.n) r.bad("mass has not N values");
    for (double m : s.mass)
      if (!(m > 0.0 && std::isfinite(m))) r.bad("masses must be finite and > 0");
  }
  return s;
}

namespace {

// The reading runs in a child process: the HDF5 library reads past its buffers on some
// damaged files (heap overflows inside H5Dread, found by tests/unit/test_h5md.cpp's byte
// flips), and what a damaged file does to the library must not become a crash, nor
// memory corruption, of the command. The child sends the state (or the error's one line)
// through a pipe and exits; a child that dies says the file is damaged.

void put(std::string& out, const void* p, std::size_t n) {
  out.append(static_cast<const char*>(p), n);
}
template <class T>
void put_vector(std::string& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  put(out, &n, sizeof n);
  put(out, v.data(), n * sizeof(T));
}

struct Cursor {
  const std::string& in;
  std::size_t at = 0;
  void get(void* p, std::size_t n) {
    if (at + n > in.size()) throw std::out_of_range("short message");
    std::memcpy(p, in.data() + at, n);
    at += n;
  }
  template <class T>
  void get_vector(std::vector<T>& v) {
    std::uint64_t n = 0;
    get(&n, sizeof n);
    if (n > (in.size() - at) / sizeof(T)) throw std::out_of_range("short message");
    v.resize(n);
    get(v.data(), n * sizeof(T));
  }
};

std::string encode(const State& s) {
  std::string out(1, 'S');
  put(out, &s.dim, sizeof s.dim);
  const std::uint64_t n = s.n;
  put(out, &n, sizeof n);
  put(out, &s.frames, sizeof s.frames);
  put(out, &s.frame, sizeof s.frame);
  put(out, &s.step, sizeof s.step);
  put(out, &s.time, sizeof s.time);
  put(out, &s.box, sizeof s.box);
  put_vector(out, s.velocities);
  put_vector(out, s.positions);
  put_vector(out, s.species);
  put_vector(out, s.mass);
  return out;
}

State decode(const std::string& in) {
  State s;
  Cursor c{in, 1};
  std::uint64_t n = 0;
  c.get(&s.dim, sizeof s.dim);
  c.get(&n, sizeof n);
  s.n = static_cast<std::size_t>(n);
  c.get(&s.frames, sizeof s.frames);
  c.get(&s.frame, sizeof s.frame);
  c.get(&s.step, sizeof s.step);
  c.get(&s.time, sizeof s.time);
  c.get(&s.box, sizeof s.box);
  c.get_vector(s.velocities);
  c.get_vector(s.positions);
  c.get_vector(s.species);
  c.get_vector(s.mass);
  if (c.at != in.size()) throw std::out_of_range("long message");
  return s;
}

bool write_all(int fd, const std::string& m) {
  std::size_t done = 0;
  while (done < m.size()) {
    const ssize_t k = ::write(fd, m.data() + done, m.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    done += std::size_t(k);
  }
  return true;
}

}  // namespace

State read_state(const std::string& path, std::int64_t frame) {
  int fds[2];
  if (::pipe(fds) != 0) return read_state_here(path, frame);  // no pipe: read here
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    return read_state_here(path, frame);
  }
  if (pid == 0) {  // the child: read, send, leave without running the parent's exit code
    ::close(fds[0]);
    std::string m;
    try {
      m = encode(read_state_here(path, frame));
    } catch (const std::exception& e) {
      m = std::string("E") + e.what();
    }
    ::_exit(write_all(fds[1], m) ? 0 : 1);
  }
  ::close(fds[1]);
  std::string m;
  char buf[1 << 16];
  for (;;) {
    const ssize_t k = ::read(fds[0], buf, sizeof buf);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    m.append(buf, std::size_t(k));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (clean && !m.empty() && m[0] == 'E') fail(m.substr(1));
  if (clean && !m.empty() && m[0] == 'S') {
    try {
      return decode(m);
    } catch (const std::out_of_range&) {
    }
  }
  fail(path + ": a damaged HDF5 file (reading it failed inside the HDF5 library)");
}

std::vector<std::pair<double, double>> read_observable(const std::string& path,
                                                       const std::string& name) {
  Reader r = open_file(path);
  std::vector<std::pair<double, double>> out;
  const std::string g = "observables/" + name;
  if (!r.exists(r.file.get(), "observables") || !r.exists(r.file.get(), g)) return out;
  const Id grp = checked(H5Gopen2(r.file.get(), g.c_str(), H5P_DEFAULT), H5Gclose, path);
  const Id d = r.dataset(grp.get(), "value");
  const hsize_t F = r.shape(d.get()).at(0);
  if (F == 0) return out;
  const auto t = r.rows<double>(r.dataset(grp.get(), "time"), g + "/time", 0, F, H5T_NATIVE_DOUBLE);
  const auto v = r.rows<double>(d, g + "/value", 0, F, H5T_NATIVE_DOUBLE);
  for (hsize_t k = 0; k < F; ++k) out.emplace_back(t[k], v[k]);
  return out;
}

}  // namespace hypergas::h5md
