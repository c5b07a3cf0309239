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
// The frames' contents: sim/trajectory_observer.hpp.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "../trajectory_observer.hpp"
#include "output.hpp"

namespace hypergas::cli {

namespace fs = std::filesystem;

namespace {

/// The file written as the run goes (OutputKind::partial).
constexpr std::string_view trajectory_partial = "trajectory.h5.partial";

class TrajectoryOutput final : public Output {
 public:
  explicit TrajectoryOutput(const RunSetup& s)
      : stride_(sampling_stride(s.plan, s.options.trajectory_every)),
        every_(static_cast<double>(stride_) * s.plan.sampling.every()),
        traj_(fs::path(s.options.out) / trajectory_partial, stride_,
              !(s.engine == registry::EngineKind::dsmc &&
                s.options.scheme == dsmc::Scheme::lanes),
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
    return {{"engine", std::string(registry::name(o.engine))},
            {"dim", std::to_string(o.dim)},
            {"n", std::to_string(o.n)},
            {"seed", std::to_string(o.seed)},
            {"model", o.model},
            {"scheme", std::string(registry::name(o.scheme))},
            {"init", std::string(registry::name(o.init))}};
  }
  std::uint64_t stride_;
  double every_;
  mutable TrajectoryObserver traj_;
};

}  // namespace

namespace outputs {
constexpr std::string_view trajectory_files[] = {"trajectory.h5"};
extern const OutputKind trajectory{
    .name = "trajectory",
    .wanted = [](const RunOptions& o, registry::EngineKind) { return o.trajectory_every > 0.0; },
    .make = make_output<TrajectoryOutput>,
    .files = trajectory_files,
    .partial = trajectory_partial};
}

}  // namespace hypergas::cli
