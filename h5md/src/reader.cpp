// h5md/src/reader.cpp -- the state of one frame and the observables of an H5MD file, read
// in this process (reader.hpp): the particle group, the dimension from the box, the
// elements' values with their shapes checked, every number finite.
#include "reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hypergas::h5md {

namespace detail {

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

}  // namespace detail

std::vector<std::pair<double, double>> read_observable(const std::string& path,
                                                       const std::string& name) {
  detail::Reader r = detail::open_file(path);
  std::vector<std::pair<double, double>> out;
  const std::string g = "observables/" + name;
  if (!r.exists(r.file.get(), "observables") || !r.exists(r.file.get(), g)) return out;
  const detail::Id grp = detail::checked(H5Gopen2(r.file.get(), g.c_str(), H5P_DEFAULT), H5Gclose, path);
  const detail::Id d = r.dataset(grp.get(), "value");
  const hsize_t F = r.shape(d.get()).at(0);
  if (F == 0) return out;
  const auto t = r.rows<double>(r.dataset(grp.get(), "time"), g + "/time", 0, F, H5T_NATIVE_DOUBLE);
  const auto v = r.rows<double>(d, g + "/value", 0, F, H5T_NATIVE_DOUBLE);
  for (hsize_t k = 0; k < F; ++k) out.emplace_back(t[k], v[k]);
  return out;
}

}  // namespace hypergas::h5md
