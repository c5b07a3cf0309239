// hypergas/analysis/vacf_recorder.hpp -- an Observer that stores velocity (and unwrapped
// position) frames for the VACF and the MSD.
//
// Snapshots must come at equal time spacing (the engine's sampling interval). The recorder
// keeps the first `max_particles` particles (memory: frames * max_particles * D doubles per
// array); the VACF averages over them and over time origins (see vacf.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::analysis {

class VacfRecorder final : public Observer {
 public:
  /// Records at most `max_particles` particles (>= 1) per frame.
  explicit VacfRecorder(std::size_t max_particles = 1000);

  /// Stores one frame. Throws InvalidInput if the dimension or particle count changes,
  /// positions appear or disappear, or the time spacing differs from the first one by
  /// more than 1e-6 relative.
  void observe(const Snapshot& s) override;

  std::size_t frames() const { return frames_; }
  std::size_t particles() const { return n_; }
  bool has_positions() const { return !positions_.empty(); }
  /// Frame spacing, time units (0 with fewer than two frames).
  double dt() const { return dt_; }

  /// <v(0) . v(lag dt)> for lags 0..max_lag (default frames / 2), velocity^2.
  std::vector<double> vacf(std::size_t max_lag = 0) const;
  /// <|r(lag dt) - r(0)|^2> for lags 0..max_lag (default frames / 2), length^2; needs positions.
  std::vector<double> msd(std::size_t max_lag = 0) const;
  /// Green–Kubo self-diffusion coefficient from the VACF up to max_lag, length^2/time.
  double green_kubo(std::size_t max_lag = 0) const;

  /// Writes vacf.csv with columns `lag,vacf,time,msd` (msd only with positions; time =
  /// lag dt) for lags 0..max_lag (default frames / 2). Throws with fewer than two frames.
  void write_csv(const std::string& path, std::size_t max_lag = 0) const;

 private:
  std::size_t default_lag(std::size_t max_lag) const;
  std::size_t max_particles_;
  std::size_t n_ = 0, frames_ = 0;
  int dim_ = 0;
  double t0_ = 0.0, t_last_ = 0.0, dt_ = 0.0;
  std::vector<double> velocities_, positions_;
};

}  // namespace hypergas::analysis
