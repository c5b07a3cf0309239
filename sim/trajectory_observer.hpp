// sim/trajectory_observer.hpp -- the observer that appends H5MD frames
// (hypergas/h5md/h5md.hpp): the trajectory output of `hypergas run --trajectory-every`
// (sim/outputs/trajectory.cpp) and Python's engine.run(..., trajectory=PATH). Needs HDF5
// (HYPERGAS_H5MD).
//
// Frame contents: velocities (the true ones: a cooling DSMC gas's stored velocities times
// its scale; time is then the real time at the initial temperature), EDMD positions
// wrapped into [0, L) with their integer images, species and masses; observables
// temperature = sum m|v|^2 / (D N), a2 = D/(D+2) N sum|v|^4 / (sum|v|^2)^2 - 1 and
// collisions_per_particle = 2 collisions / N. Step is the observation's index.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/error.hpp"
#include "hypergas/h5md/h5md.hpp"
#include "hypergas/observer.hpp"
#include "version.hpp"

namespace hypergas::cli {

/// Writes every `stride`-th snapshot it sees as a frame of the H5MD file `path` (created at
/// the first frame; with load(), continued after the checkpoint's frames).
class TrajectoryObserver final : public Observer {
 public:
  /// `ids`: write the id dataset (not for the lanes scheme); `params`: /parameters/hypergas.
  TrajectoryObserver(std::filesystem::path partial, std::uint64_t stride, bool ids,
                     std::vector<std::pair<std::string, std::string>> params)
      : partial_(std::move(partial)), stride_(stride), ids_(ids), params_(std::move(params)) {}

  void observe(const Snapshot& s) override {
    const std::uint64_t index = seen_++;
    if (index % stride_ != 0) return;
    if (!writer_) open(s);
    const std::size_t n = s.n, D = std::size_t(s.dim), st = std::size_t(s.stride);
    const double scale = std::exp(s.log_velocity_scale);
    vel_.resize(n * D);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t a = 0; a < D; ++a) vel_[i * D + a] = s.velocities[i * st + a] * scale;
    h5md::FrameData f;
    f.step = static_cast<std::int64_t>(index);
    f.time = std::isfinite(s.real_time) ? s.real_time : s.time;
    f.velocities = vel_.data();
    if (s.positions) {
      pos_.resize(n * D);
      img_.resize(n * D);
      const double L = s.box;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t a = 0; a < D; ++a) {
          const double x = s.positions[i * st + a];
          double k = std::floor(x / L);
          double w = x - k * L;
          if (w >= L) w -= L, k += 1.0;  // rounding at the upper face
          if (w < 0.0) w = 0.0;
          pos_[i * D + a] = w;
          img_[i * D + a] = static_cast<std::int32_t>(k);
        }
      f.positions = pos_.data();
      f.images = img_.data();
      f.box = L;
    }
    // the moments of moments.csv (the stored velocities: kT scales with their scale^2)
    const analysis::Moments m = analysis::compute_moments(s);
    const double d = static_cast<double>(s.dim);
    const double obs[3] = {m.kT * scale * scale,
                           d / (d + 2.0) * m.m4.value / (m.m2.value * m.m2.value) - 1.0,
                           2.0 * static_cast<double>(s.collisions) / static_cast<double>(n)};
    f.observables = obs;
    writer_->append(f);
  }

  void save(checkpoint::Writer& w) const {
    if (writer_) writer_->flush();
    const std::uint64_t frames = writer_ ? writer_->frames() : resume_frames_;
    w.tag("trajectory");
    w(seen_, frames);
  }
  void load(checkpoint::Reader& r) {
    r.tag("trajectory");
    r(seen_, resume_frames_);
    resuming_ = true;
  }
  /// Closes the file and returns its path.
  const std::filesystem::path& close() {
    if (!writer_) throw InvalidInput("--trajectory-every: the run wrote no frame");
    writer_->close();
    return partial_;
  }
  std::uint64_t frames() const { return writer_ ? writer_->frames() : resume_frames_; }

 private:
  void open(const Snapshot& s) {
    h5md::Layout l;
    l.dim = s.dim;
    l.n = s.n;
    l.positions = s.positions != nullptr;
    l.ids = ids_;
    if (s.species || s.inv_mass) {
      l.species.resize(s.n);
      l.mass.resize(s.n);
      for (std::size_t i = 0; i < s.n; ++i) {
        l.species[i] = s.species ? s.species[i] : 0;
        l.mass[i] = 1.0 / s.inverse_mass(i);
      }
    }
    l.observables = {"temperature", "a2", "collisions_per_particle"};
    l.creator_version = std::string(version());
    l.parameters = params_;
    // a checkpoint before the first frame (EDMD's equilibration) leaves no file to continue
    if (resuming_ && resume_frames_ > 0)
      writer_.emplace(h5md::Writer::resume(partial_.string(), l, resume_frames_));
    else writer_.emplace(partial_.string(), l);
  }

  std::filesystem::path partial_;
  std::uint64_t stride_;
  bool ids_;
  std::vector<std::pair<std::string, std::string>> params_;
  std::uint64_t seen_ = 0;
  std::uint64_t resume_frames_ = 0;
  bool resuming_ = false;
  mutable std::optional<h5md::Writer> writer_;  // save() flushes it
  std::vector<double> vel_, pos_;
  std::vector<std::int32_t> img_;
};

}  // namespace hypergas::cli
