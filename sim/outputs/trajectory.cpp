// sim/outputs/trajectory.cpp -- trajectory.h5 with --trajectory-every T: H5MD frames of the
// gas (hypergas/h5md/h5md.hpp, docs/h5md.md) at every m-th sampling instant from the
// first, m = max(1, round(T / sampling interval)).
//
// The file is written as the run goes, frame by frame, into OUT/trajectory.h5.partial (the
// run's own file, like its checkpoint: memory holds one frame), and moved to
// OUT/trajectory.h5 with the run's other files when the run ends. A checkpoint flushes it
// and records its frame count; `hypergas resume` reopens it, drops the frames written after
// the checkpoint and appends from there, so a run killed and resumed writes the datasets of
// the uninterrupted run.
//
// Frame contents: velocities (the true ones: a cooling DSMC gas's stored velocities times
// its scale; time is then the real time at the initial temperature), EDMD positions
// wrapped into [0, L) with their integer images, species and masses; observables
// temperature = sum m|v|^2 / (D N), a2 = D/(D+2) N sum|v|^4 / (sum|v|^2)^2 - 1 and
// collisions_per_particle = 2 collisions / N. Step is the sampling instant's index.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "../version.hpp"
#include "hypergas/h5md/h5md.hpp"
#include "output.hpp"

namespace hypergas::cli {

namespace fs = std::filesystem;

namespace {

class Trajectory final : public Observer {
 public:
  Trajectory(fs::path partial, std::uint64_t stride, bool ids,
             std::vector<std::pair<std::string, std::string>> params)
      : partial_(std::move(partial)), stride_(stride), ids_(ids), params_(std::move(params)) {}

  void observe(const Snapshot& s) override {
    const std::uint64_t index = seen_++;
    if (index % stride_ != 0) return;
    if (!writer_) open(s);
    const std::size_t n = s.n, D = std::size_t(s.dim), st = std::size_t(s.stride);
    const double scale = std::exp(s.log_velocity_scale);
    vel_.resize(n * D);
    double e2 = 0.0, e4 = 0.0, ke = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double v2 = 0.0;
      for (std::size_t a = 0; a < D; ++a) {
        const double v = s.velocities[i * st + a] * scale;
        vel_[i * D + a] = v;
        v2 += v * v;
      }
      e2 += v2, e4 += v2 * v2;
      ke += v2 / s.inverse_mass(i);
    }
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
    const double N = static_cast<double>(n), d = static_cast<double>(s.dim);
    const double obs[3] = {ke / (d * N), d / (d + 2.0) * N * e4 / (e2 * e2) - 1.0,
                           2.0 * static_cast<double>(s.collisions) / N};
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
  const fs::path& close() {
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

  fs::path partial_;
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

class TrajectoryOutput final : public Output {
 public:
  explicit TrajectoryOutput(const RunSetup& s)
      : stride_(static_cast<std::uint64_t>(
            std::max(1.0, std::round(s.options.trajectory_every / s.plan.sampling.every())))),
        every_(static_cast<double>(stride_) * s.plan.sampling.every()),
        traj_(fs::path(s.options.out) / OutputDir::trajectory_partial, stride_,
              !(s.engine == registry::EngineKind::dsmc &&
                registry::scheme(s.options.scheme) == dsmc::Scheme::lanes),
              parameters(s)) {}

  Observer* sampler() override { return &traj_; }
  void save(checkpoint::Writer& w) const override { traj_.save(w); }
  void load(checkpoint::Reader& r) override { traj_.load(r); }
  void write(OutputDir& out) const override {
    fs::rename(traj_.close(), out.staged("trajectory.h5"));
  }
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("trajectory_frames", static_cast<std::int64_t>(traj_.frames()));
    s.emplace_back("trajectory_dt", every_);
  }

 private:
  static std::vector<std::pair<std::string, std::string>> parameters(const RunSetup& s) {
    const RunOptions& o = s.options;
    return {{"engine", o.engine},
            {"dim", std::to_string(o.dim)},
            {"n", std::to_string(o.n)},
            {"seed", std::to_string(o.seed)},
            {"model", o.model},
            {"scheme", o.scheme},
            {"init", o.init}};
  }
  std::uint64_t stride_;
  double every_;
  mutable Trajectory traj_;
};

}  // namespace

namespace outputs {
extern const OutputKind trajectory{
    "trajectory",
    [](const RunOptions& o, registry::EngineKind) { return o.trajectory_every > 0.0; },
    make_output<TrajectoryOutput>};
}

}  // namespace hypergas::cli
