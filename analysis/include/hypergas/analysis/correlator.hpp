// hypergas/analysis/correlator.hpp -- time autocorrelations of many series at every lag up to
// a maximum, averaged over all time origins, by FFT in blocks, with block statistics.
//
// Frames arrive at equal spacing; each holds one value of every series. The series are
// grouped (stress components, heat-flux components, tagged velocities): a group's result is
// the autocorrelation averaged over its series and over all time origins,
//   C_g(k) = sum_{s in g} sum_{n : n + k < F} x_s(n) x_s(n + k) / (|g| (F - k)),
// for lags k = 0 .. K - 1 (K = `lags`), with F the frames received. Unlike the multiple-tau
// correlator (multi_tau.hpp), every lag uses every time origin and no block average smooths
// it, which a Green-Kubo integral over a fine grid needs.
//
// Method. The frames are cut into blocks of K. Block b is correlated with itself and the
// next block by one real FFT of length 2K of each ([block b, zeros] and [block b, block b+1]):
// the circular correlation of the two is the linear one for lags below K, because
// n + k < 2K for n, k < K. Spectra are summed over a group's series before the one inverse
// transform per group and block. Cost per frame and series: two real FFTs of length 2K per K
// frames, O(log K); memory: two blocks of every series, plus K numbers per group per error
// block.
//
// Errors. The origins are split into `error_blocks` consecutive stretches of equal length
// (in blocks of K); each stretch keeps its own sums, so a statistic computed from each
// stretch gives its standard error from their spread (the stretches are long compared to
// the correlation time when the run is).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace hypergas::analysis {

class BlockCorrelator {
 public:
  /// `group[s]`: the group (0 .. groups - 1) of series s; `lags` K >= 2; `planned_frames`:
  /// the frames the run will give (fixes the error stretches; fewer may arrive);
  /// `error_blocks` >= 2 stretches (fewer if the run has fewer blocks of K).
  BlockCorrelator(std::vector<int> group, std::size_t lags, std::uint64_t planned_frames,
                  int error_blocks = 32);
  ~BlockCorrelator();
  BlockCorrelator(BlockCorrelator&&) noexcept;
  BlockCorrelator& operator=(BlockCorrelator&&) noexcept;

  int series() const { return static_cast<int>(group_.size()); }
  int groups() const { return groups_; }
  std::size_t lags() const { return lags_; }
  /// Frames received so far.
  std::uint64_t frames() const { return frames_; }
  /// Error stretches that received origins (after finish()).
  int stretches() const;

  /// One frame: x[s] for every series s.
  void push(const double* x);
  /// Correlates the frames still buffered; call once, after the last push.
  void finish();

  /// C_g(k), k = 0 .. lags - 1, over all origins (after finish()).
  std::vector<double> mean(int g) const;
  /// The same over the origins of stretch j only.
  std::vector<double> stretch_mean(int g, int j) const;

 private:
  void correlate(std::size_t first_frame, std::size_t n_a, std::size_t n_c);

  std::vector<int> group_;
  std::vector<int> members_;
  int groups_ = 0;
  std::size_t lags_ = 0;
  std::uint64_t planned_ = 0, frames_ = 0;
  int stretches_ = 0;
  std::uint64_t blocks_per_stretch_ = 1;
  std::vector<double> prev_, cur_;  // series-major blocks of K frames
  std::size_t in_cur_ = 0;
  bool have_prev_ = false, finished_ = false;
  // sums[(j * groups + g) * K + k]; origin blocks as (stretch, first frame, frames)
  std::vector<double> sums_;
  struct Origins {
    int stretch;
    std::uint64_t first, count;
  };
  std::vector<Origins> origins_;
  struct Fft;
  std::unique_ptr<Fft> fft_;
};

}  // namespace hypergas::analysis
