// hypergas/analysis/multi_tau.hpp -- multiple-tau correlator: time correlations and mean
// squared displacements of many channels in memory independent of the length of the series.
//
// The blocking scheme of Ramírez, Sukumaran, Vorselaars and Likhtman, J. Chem. Phys. 133,
// 154103 (2010). Values arrive at equal time spacing (one "frame"); each is `channels`
// vectors of `dim` components (channel c, component k). Level 0 receives the frames, level
// l >= 1 receives one value per block of m values of level l-1, i.e. one per m^l frames.
// Every level keeps its last p values in a ring buffer and, when a value a(t) arrives,
// accumulates the statistic of the pairs (a(t - j), a(t)) for j = 0 .. p-1 on level 0 and
// j = p/m .. p-1 on level l >= 1 (smaller j on level l are the lags of level l-1). The lag
// grid, in frames, is therefore
//   0, 1, ..., p-1,   then   j m^l for j = p/m .. p-1 on each level l = 1, 2, ...
// (p = 16, m = 2: 0..15, 16, 18, ..., 30, 32, 36, ..., 60, 64, ...): about p (1 - 1/m) lags
// per factor m in time. Each lag carries its number of time origins (pairs accumulated).
//
// Two kinds, differing in the statistic and in how a block of m values is coarsened:
//   correlation   C(tau) = < a(t) . a(t + tau) >. A block is replaced by its average (the
//                 paper's scheme). Level 0 (tau < p) is the exact estimator with every time
//                 origin; on level l the value is the correlation of m^l-frame block means,
//                 i.e. C smoothed by a triangle of half-width B = m^l frames around
//                 tau >= (p/m) B. To second order the smoothing adds (B^2 - 1)/12 C''(tau)
//                 (for C = exp(-tau/T) a relative (B^2 - 1)/(12 T^2)): small where C varies
//                 slowly over one block, which the growth of the blocks with tau assumes.
//   displacement  M(tau) = < |a(t + tau) - a(t)|^2 > (the MSD of positions a). A block is
//                 replaced by its LAST value (decimation, not the average): level l then
//                 holds the exact positions at frames m^l - 1, 2 m^l - 1, ..., so every
//                 displacement it forms is exact and M(tau) is unbiased at every lag, only
//                 with fewer time origins (spaced m^l frames apart). The block average would
//                 bias it: the displacement of block means of a random walk has variance
//                 tau - (m^l - 1/m^l) / 3 per step variance, not tau.
// Results are averaged over channels and time origins, and summed over the `dim` components
// of a channel (so C(0) = <|a|^2> per channel). Each pair's terms are summed over channels
// and components first, then added to its lag's sum (double).
//
// Groups. The channels can be split into `groups` contiguous groups of nearly equal size
// (channel c in group floor(c G / channels)), each with its own sums: group_curve(g) is the
// statistic of group g's channels, and independent channels (particles of a fluid, whose
// cross-correlations are O(1/N)) make the groups independent estimates, whose spread is the
// statistical error of curve(). With one group the sums are those without groups, bit for
// bit.
//
// Memory. Level l is allocated when its first value arrives (after m^l frames), up to
// `levels` levels; the largest lag is (p-1) m^(levels-1) frames. Per level: a ring of
// p * channels * dim doubles, for `correlation` one block sum of channels * dim doubles, and
// (groups + 1) p + 3 numbers of bookkeeping. In all at most
//   levels * (channels * dim * (p + [correlation]) + (groups + 1) p + 3) * 8 bytes
// (bytes() reports the current value): O(channels * dim * levels * p), independent of the
// number of frames once all levels exist. Cost per frame: about m/(m-1) * p * channels * dim
// multiply-adds.
//
// State can be saved and restored with io() (hypergas/checkpoint.hpp); a restored correlator
// fed the same later values gives bit-identical results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hypergas::analysis {

/// One multiple-tau result: lags in frames (increasing), the number of time origins of each
/// lag, and the statistic at each lag. Only lags with at least one origin are listed.
struct MultiTauCurve {
  std::vector<std::size_t> lag;
  std::vector<std::size_t> origins;
  std::vector<double> value;
};

class MultiTauCorrelator {
 public:
  enum class Kind : std::uint8_t { correlation = 0, displacement = 1 };

  /// Lags up to at least this many frames are covered when `levels` is left automatic.
  static constexpr std::size_t auto_max_lag = std::size_t{1} << 20;

  /// An empty correlator (no channels) that accepts no values; a placeholder to assign or
  /// restore into.
  MultiTauCorrelator() = default;
  /// `channels` >= 1 vectors of `dim` >= 1 components; p points per level (p >= m, p a
  /// multiple of m), averaging factor m >= 2, `levels` >= 1 levels (0: the fewest levels
  /// whose largest lag (p-1) m^(levels-1) is >= auto_max_lag; p = 16, m = 2: 18 levels, up
  /// to 1966080 frames), `groups` in 1..channels (see the file comment). Throws
  /// InvalidInput for other values.
  MultiTauCorrelator(Kind kind, std::size_t channels, int dim, std::size_t p = 16,
                     std::size_t m = 2, std::size_t levels = 0, std::size_t groups = 1);

  /// Adds one frame: channel c, component k at x[c * stride + k] (stride >= dim). Throws
  /// InvalidInput on an empty correlator.
  void add(const double* x, std::size_t stride);

  Kind kind() const { return kind_; }
  std::size_t channels() const { return static_cast<std::size_t>(channels_); }
  int dim() const { return dim_; }
  std::size_t points() const { return static_cast<std::size_t>(p_); }
  std::size_t factor() const { return static_cast<std::size_t>(m_); }
  std::size_t levels() const { return static_cast<std::size_t>(levels_); }
  std::size_t groups() const { return static_cast<std::size_t>(groups_); }
  /// The channels of group g: [group_begin(g), group_begin(g + 1)).
  std::size_t group_begin(std::size_t g) const {
    return static_cast<std::size_t>((g * channels_ + groups_ - 1) / groups_);
  }
  /// Frames added so far.
  std::size_t samples() const { return static_cast<std::size_t>(samples_); }
  /// The largest lag of the grid, (p-1) m^(levels-1) frames.
  std::size_t max_lag() const;

  /// The statistic (correlation: <a(t) . a(t+lag)>, displacement: <|a(t+lag) - a(t)|^2>, in
  /// the units of a squared) at the grid lags <= max_lag that have at least one origin.
  MultiTauCurve curve(std::size_t max_lag) const;
  /// The same of group g's channels only, at the lags of curve(max_lag).
  MultiTauCurve group_curve(std::size_t g, std::size_t max_lag) const;

  /// Bytes of the buffers held now (their capacities; the few vector headers not counted).
  std::size_t bytes() const;
  /// What bytes() reaches once all levels exist (the formula above).
  std::size_t max_bytes() const;

  /// Saves or restores the complete state (hypergas/checkpoint.hpp). On restoring, throws
  /// InvalidInput if the state read is inconsistent.
  template <class Archive>
  void io(Archive& a) {
    a.tag("multi-tau");
    a(kind_, channels_, dim_, p_, m_, levels_, groups_, samples_);
    a(ring_, block_, head_, filled_, block_count_, sum_, count_);
    if constexpr (!Archive::saving) check_state();
  }

 private:
  // Stores a value in level l's ring, accumulates its pairs and coarsens it into level l+1.
  void store(std::size_t l, const double* x, std::size_t stride);
  void add_level();
  void check_state() const;
  // curve() of the channels of groups g0 .. g1 - 1
  MultiTauCurve values(std::size_t max_lag, std::size_t g0, std::size_t g1) const;
  std::size_t width() const {
    return static_cast<std::size_t>(channels_) * static_cast<std::size_t>(dim_);
  }

  Kind kind_ = Kind::correlation;
  std::uint64_t channels_ = 0;
  int dim_ = 0;
  std::uint64_t p_ = 0, m_ = 0, levels_ = 0, groups_ = 1;
  std::uint64_t samples_ = 0;
  // Per allocated level l (ring_.size() of them): the last p values, value slot s at
  // ring_[l][s * width() ...]; for `correlation` the running sum of the current block.
  std::vector<std::vector<double>> ring_, block_;
  // Per level (levels_ entries): the slot of the newest value, the number of values held
  // (<= p), the number of values in the current block (< m).
  std::vector<std::uint64_t> head_, filled_, block_count_;
  // Per level and j: sum over pairs and the channels of group g of the statistic (index
  // (l * p + j) * groups + g), and the number of pairs (time origins, index l * p + j).
  std::vector<double> sum_;
  std::vector<std::uint64_t> count_;
};

}  // namespace hypergas::analysis
