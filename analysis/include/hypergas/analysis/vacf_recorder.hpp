// hypergas/analysis/vacf_recorder.hpp -- an Observer that accumulates the VACF and the MSD
// of a run in memory independent of its length.
//
// Snapshots must come at equal time spacing (the engine's sampling interval). The recorder
// follows the first `max_particles` particles and feeds their velocities, and unwrapped
// positions when the snapshot has them, to multiple-tau correlators (multi_tau.hpp): the
// VACF <v(0) . v(t)> by block averaging, the MSD <|r(t) - r(0)|^2> by decimation (exact
// displacements). Both are averaged over the particles and over time origins, at the
// multiple-tau lags (in frames) 0 .. p-1 (exact, every origin), then j m^l for j = p/m .. p-1
// on levels l = 1, 2, ... (p = 16, m = 2: 0..15, 16, 18, ..., 30, 32, 36, ...). Memory:
// at most levels * (max_particles * D * (2p + 1) + 2 ((groups + 1) p + 3)) * 8 bytes
// (bytes()), whatever the number of frames; by default lags up to about 2e6 frames are
// reachable.
//
// The self-diffusion coefficient, diffusion(): the particles are followed in `groups`
// groups (MultiTauCorrelator's groups; 8, or one per particle below 8), independent
// estimates whose spread is the statistical error. Green-Kubo: the running integral of the
// VACF over D, read at its plateau by the one rule of every EDMD transport coefficient
// (integrals.hpp, detail::plateau: the cut, the t^(-D/2) tail's remainder and the
// truncation error), on the uniform lag grid of the frames: the VACF between two multiple-tau
// lags is taken linear, exact on level 0 and within the coarse levels' own smoothing
// (multi_tau.hpp) beyond. Einstein: the MSD's slope over [k_c / 2, 3 k_c / 2] around the same
// cut, over 2D, with the same remainder (helfand_recorder.cpp does the same).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hypergas/analysis/multi_tau.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::analysis {

class VacfRecorder final : public Observer {
 public:
  /// Records at most `max_particles` particles (>= 1) per frame; p, m and levels as in
  /// MultiTauCorrelator (0 levels: automatic). Throws InvalidInput for invalid values.
  explicit VacfRecorder(std::size_t max_particles = 1000, std::size_t p = 16, std::size_t m = 2,
                        std::size_t levels = 0);

  /// Error groups of the followed particles (at most one per particle).
  static constexpr std::size_t groups = 8;

  /// Self-diffusion coefficient by two routes (see the file comment), length^2/time.
  /// NaN where not measured (a default Diffusion: none at all).
  struct Diffusion {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double green_kubo = nan;             ///< at the plateau, the remainder included
    double statistical_error = nan;      ///< of green_kubo, from the groups
    double truncation_error = nan;       ///< |remainder| of the cut
    double error = nan;                  ///< hypot of the two
    double cut_time = nan;               ///< the cut, time units
    double einstein = nan;               ///< MSD slope / 2D around the cut, with the remainder
    double einstein_error = nan;         ///< its statistical error (groups) and truncation
    bool reached = false;                ///< the remainder is within the statistical error
  };
  /// diffusion() of the run: the first candidate cut at 5 mean free times (`mean_free_time`,
  /// time units) and 3 integral times. Throws InvalidInput with fewer than 8 frames or
  /// without positions.
  Diffusion diffusion(double mean_free_time) const;

  /// Adds one frame. Throws InvalidInput if the dimension or particle count changes,
  /// positions appear or disappear, or the time spacing differs from the first one by
  /// more than 1e-6 relative.
  void observe(const Snapshot& s) override;
  /// The particles it follows: the first max_particles.
  std::size_t particles_read() const override { return max_particles_; }

  std::size_t frames() const { return static_cast<std::size_t>(frames_); }
  std::size_t particles() const { return static_cast<std::size_t>(n_); }
  bool has_positions() const { return has_positions_; }
  /// Frame spacing, time units (0 with fewer than two frames).
  double dt() const { return dt_; }

  /// The lags, in frames, at which vacf() and msd() are given: the multiple-tau lags
  /// <= max_lag (default frames / 2; max_lag < frames) that have at least one time origin.
  /// Throws InvalidInput with fewer than two frames.
  std::vector<std::size_t> lags(std::size_t max_lag = 0) const;
  /// The number of time origins averaged at each of lags(max_lag).
  std::vector<std::size_t> origins(std::size_t max_lag = 0) const;
  /// <v(0) . v(lag dt)> at lags(max_lag), velocity^2.
  std::vector<double> vacf(std::size_t max_lag = 0) const;
  /// <|r(lag dt) - r(0)|^2> at lags(max_lag), length^2; needs positions.
  std::vector<double> msd(std::size_t max_lag = 0) const;
  /// The running Green–Kubo integral (1/D) of the VACF from 0 to the last of lags(max_lag),
  /// trapezoid rule on the (non-uniform) lag grid, length^2/time: no cut rule, no error (the
  /// estimate is diffusion()).
  double green_kubo(std::size_t max_lag = 0) const;

  /// Writes vacf.csv with columns `lag,vacf,time,msd` (msd only with positions; time =
  /// lag dt), one row per lag of lags(max_lag). Throws with fewer than two frames.
  void write_csv(const std::string& path, std::size_t max_lag = 0) const;

  /// Bytes of the correlators' buffers now, and what they reach once every level is in use
  /// (fixed by the first frame; 0 before it). Neither depends on the number of frames.
  std::size_t bytes() const { return velocity_.bytes() + position_.bytes(); }
  std::size_t max_bytes() const { return velocity_.max_bytes() + position_.max_bytes(); }

  /// Saves or restores the complete state (hypergas/checkpoint.hpp); a restored recorder fed
  /// the same later frames gives bit-identical results.
  template <class Archive>
  void io(Archive& a) {
    a.tag("vacf-recorder");
    a(max_particles_, p_, m_, levels_, n_, frames_, dim_, has_positions_);
    a(t0_, t_last_, dt_, velocity_, position_);
    if constexpr (!Archive::saving) check_state();
  }

 private:
  std::size_t default_lag(std::size_t max_lag) const;
  MultiTauCurve curve(const MultiTauCorrelator& c, std::size_t max_lag) const;
  void check_state() const;

  std::uint64_t max_particles_, p_, m_, levels_;
  std::uint64_t n_ = 0, frames_ = 0;
  int dim_ = 0;
  bool has_positions_ = false;
  double t0_ = 0.0, t_last_ = 0.0, dt_ = 0.0;
  MultiTauCorrelator velocity_, position_;  // position_ stays empty without positions
};

}  // namespace hypergas::analysis
