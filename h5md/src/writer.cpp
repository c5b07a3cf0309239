// h5md/src/writer.cpp -- h5md::Writer: creates an H5MD 1.1 file (or reopens one to resume
// at a frame count) and appends frames of positions, images, velocities, the box and
// observables (hypergas/h5md/h5md.hpp has the layout).
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "datasets.hpp"
#include "hypergas/h5md/h5md.hpp"

namespace hypergas::h5md {

using namespace detail;

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

}  // namespace hypergas::h5md
