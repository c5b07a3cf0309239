// hypergas/analysis/moments_recorder.hpp -- an Observer that records the relaxation to MB.
//
// Per snapshot it records one row of moments.csv (the file contract of docs/design.md).
// Columns, in order:
//   time                     engine time (engine units)
//   collisions_per_particle  2 * collisions / n
//   m2, m4                   <|v|^2>, <|v|^4> over all particles (velocity^2, velocity^4)
//   kurtosis_x               <w_x^4> / <w_x^2>^2 (mass-weighted x component; MB: 3)
//   m6                       <|v|^6> (velocity^6)
//   m2_err, m4_err, m6_err, kurtosis_x_err   standard errors of the above
//   m4_ratio, m4_ratio_err   <w^4> / (D(D+2)(kT/m_mean)^2) and its error (MB: 1)
//   kT                       2 E_kin / (D n), energy units: the reference temperature
//   l1_speed, kl_speed       L1 distance and KL divergence (nats) of the speed histogram
//   ks_p_speed               KS p-value of the speeds against MB at kT (see below)
//   chi2_p_speed             chi-square p-value of the speed histogram (1 fitted parameter)
//   kT_0, kT_1, ...          per-species temperature, energy units (mixtures only)
//   a2, a3                   Sonine cumulants of the pooled speeds (0 for MB):
//                            a2 = D/(D+2) m4/m2^2 - 1,
//                            a3 = 1 + 3 a2 - D^2/((D+2)(D+4)) m6/m2^3
//   T                        kT of the true velocities: kT exp(2 log_velocity_scale) (a
//                            cooling granular gas stores scaled ones; else T = kT)
//   real_time                Snapshot::real_time, or time where it is NaN
// Pooled speeds are mass-weighted (see sample.hpp). The recorder keeps the speed histograms
// of the last snapshot (pooled and, for mixtures, per species) for speed_histogram.csv.
//
// Where the numbers come from: a tally (hypergas/tally/tally.hpp) of the power sums and of
// fine speed histograms, exact fixed-point sums that do not depend on the order of the
// particles. An engine that keeps a tally (Snapshot::tally: DSMC) updates it at every
// collision, so a row costs O(bins + fine bins): the recorder builds it once from the
// first snapshot and hands it to the engine. Without one (EDMD, arrays from Python) each
// row builds it in one pass over the snapshot. Either way a row is the same bit for bit,
// for every thread count.
//
// The layout of the tally, fixed by the first snapshot (the configuring one): velocities
// scaled by a power of two near sqrt(m_mean / kT); the histogram range of make_histogram
// at that kT, `bins` bins of `r` fine bins each, r = ceil(32 sqrt(n) / bins) (at most
// 32768 fine bins in all); MB references, bin probabilities and the fine bins' CDF at that
// kT. A later snapshot whose kT differs from it by more than 1e-9 relative (any engine
// conserves energy to ~1e-13), or whose mean mass, dimension or species differ, configures
// again. The moments are exact sums of rounded terms: they differ from plain double sums in
// the last bits (~2^-41 / sqrt(n) relative, see tally.hpp).
//
// ks_p_speed. With ks_sample = 0 (the default), the KS test of all n pooled speeds against
// MB at kT, on the fine bins: the statistic max |F_n - F| over the fine bin edges, which is
// at most the exact KS statistic of the speeds and at least that minus the largest MB
// probability of one fine bin (~4 / (32 sqrt(n)), an eighth of the 5% critical value
// 1.36 / sqrt(n); at most 1.3e-4 with 32768 fine bins, for n > 1e6); p from the
// Kolmogorov distribution of n. It is conservative (a true MB fails no more often than the
// exact test) and resolves a deviation of the speed CDF of ~1.5 / sqrt(n) + that bin
// probability. With ks_sample = k > 0, the exact KS test of the speeds themselves:
//  - n <= k: all n speeds (sorted: O(n log n) per row);
//  - n > k: a stratified random subsample of exactly k particles: chunk c (particles
//    [b, e), 65536 per chunk) gives floor(k e / n) - floor(k b / n) of its particles,
//    drawn without replacement by Floyd's algorithm. Snapshot number j (0, 1, ... in order
//    of observation) draws chunk c's share from the stream
//    Rng(ks_seed, ks_stream).split(j).split(c), so the subsample is reproducible,
//    independent of the engine's random numbers and of the thread count. Which particles
//    are taken does not depend on their speeds, so under the null hypothesis it is k
//    independent MB speeds; its power is that of k samples.
// Histograms, distances, the chi-square test and the moments always use every particle.
//
// Threads (set_threads): the passes over a snapshot run over chunks of 65536 particles,
// chunk c on thread c mod T, each thread with its own tally; tallies are integers, so they
// add to the same numbers for every T.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/tally/tally.hpp"
#include "hypergas/thread_team.hpp"

namespace hypergas::analysis {

class MomentsRecorder final : public Observer {
 public:
  /// Default KS sample: 0, the binned test of all speeds (see the file comment).
  static constexpr std::size_t default_ks_cap = 0;
  /// Default seed of the KS subsample stream.
  static constexpr std::uint64_t default_ks_seed = 0x6b735f63617073ULL;
  /// Stream number of the KS subsample (with the seed above): one no engine uses.
  static constexpr std::uint64_t ks_stream = 0x4d6f6d656e74734bULL;

  /// `bins` bins for the speed histograms (>= 1); the KS test binned on all speeds
  /// (ks_cap = 0) or exact on at most `ks_cap` speeds (a stratified subsample above it,
  /// drawn with seed `ks_seed`). Throws InvalidInput for bins < 1.
  explicit MomentsRecorder(std::size_t bins = 50, std::size_t ks_cap = default_ks_cap,
                           std::uint64_t ks_seed = default_ks_seed);

  /// Runs the passes over a snapshot on `threads` threads (1..256; the
  /// rows are the same for every count). Not state: neither a checkpoint nor a copy of the
  /// recorder keeps it.
  void set_threads(int threads);
  int threads() const;

  /// Records one row; throws InvalidInput for an unreadable snapshot or one whose number of
  /// species differs from the first (nothing is recorded then).
  void observe(const Snapshot& s) override;
  /// Asks the engine to keep the tally of the last snapshot, or to drop its tally, as
  /// observe decided (tally_limit); asks nothing when the engine's tally stays as it is.
  void request(tally::Requests& r) override;

  /// Column names, fixed by the first snapshot (the per-species columns need it).
  const std::vector<std::string>& columns() const { return columns_; }
  /// One row per observed snapshot, in column order.
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// The values of one column over time; throws InvalidInput for an unknown name.
  std::vector<double> column(const std::string& name) const;
  /// KS sample: 0 for the binned test of all speeds, else the largest exact sample.
  std::size_t ks_cap() const { return ks_cap_; }
  /// Rows that read every particle (configuring, or an engine without a tally); the other
  /// rows came from the engine's tally in O(bins). Not state.
  ///
  /// The engine keeps the tally only while it pays: a collision costs it about as much as
  /// a pass costs per particle (docs/benchmarks.md), so when the previous interval between
  /// rows held more than tally_limit * n collisions, the recorder takes the tally out of
  /// the engine and makes each row by one pass (same numbers, bit for bit).
  std::uint64_t passes() const { return passes_; }
  static constexpr double tally_limit = 2.0;
  /// Fine bins of the tally's histograms (0 before the first snapshot).
  std::size_t fine_bins() const { return cfg_.layout.fine; }

  /// Writes moments.csv (atomically). Throws InvalidInput if nothing was observed.
  void write_moments_csv(const std::string& path) const;
  /// Writes the last snapshot's speed histogram `lo,hi,count,density,maxwell_density`
  /// (speed in velocity units, densities in 1/velocity; MB at that snapshot's kT) of all
  /// particles (species = -1, mass-weighted) or of one species (mixtures).
  void write_speed_histogram_csv(const std::string& path, int species = -1) const;

  /// The last snapshot's speed histogram and its Maxwell-Boltzmann reference (what
  /// write_speed_histogram_csv writes) of all particles (species = -1) or of one species.
  /// Throws InvalidInput if nothing was observed or there is no such species.
  const Histogram& last_histogram(int species = -1) const;
  const MaxwellReference& last_reference(int species = -1) const;

  /// Saves or restores every data member through a checkpoint archive
  /// (hypergas/checkpoint.hpp): a restored recorder continues exactly as the saved one
  /// would, KS subsamples included. The saved bins and KS cap and seed replace the
  /// constructor's. Restoring throws InvalidInput for an inconsistent state.
  template <class Archive>
  void io(Archive& a) {
    a.tag("moments-recorder");
    a(bins_, ks_cap_, ks_rng_, n_species_, dim_, columns_, rows_, last_histograms_, last_refs_);
    a(cfg_);
    if constexpr (!Archive::saving) {
      check_restored();
      derive_tables();
    }
  }

 private:
  static_assert(std::is_trivially_copyable_v<Rng>, "io() saves the KS stream as raw bytes");
  static_assert(std::is_trivially_copyable_v<MaxwellReference>);

  /// What the configuring snapshot fixed (saved in checkpoints; the tables below follow
  /// from it).
  struct Config {
    bool set = false;
    double kT = 0.0;      // energy units
    double scale = 1.0;   // 1 / c: a scaled velocity of 1 in velocity units
    std::array<double, 1 + max_species> lo{}, hi{}, mass{};  // per histogram (velocity, mass)
    tally::Layout layout;
  };
  static_assert(std::is_trivially_copyable_v<Config>);

  void check_restored() const;
  /// Chooses the layout from a snapshot (a pass for its temperature) and derives the tables.
  void configure(const Snapshot& s, int ns);
  /// The references, empty histograms, bin probabilities and fine CDF of cfg_.
  void derive_tables();
  /// A tally of cfg_'s layout from one pass over s (on the recorder's threads).
  tally::Tally pass(const Snapshot& s) const;
  /// The row of a tally that fits cfg_, or false if its kT is too far from cfg_'s.
  bool record(const Snapshot& s, const tally::Tally& t);
  /// The exact KS sample (ks_cap_ > 0) of snapshot number `row`.
  std::vector<double> ks_sample(const Snapshot& s, double m_mean, std::size_t row) const;
  /// Particles per chunk of the passes.
  static constexpr std::size_t chunk_size = std::size_t{1} << 16;
  /// f(thread, chunk) for chunks 0..chunks-1, chunk c on thread c mod T; rethrows the
  /// first exception of a thread.
  void for_chunks(std::size_t chunks, const std::function<void(int, std::size_t)>& f) const;
  /// Sets what request() asks the engine for: the tally `t`, or none.
  void ask(std::optional<tally::Tally> t);
  /// Index into last_histograms_ of `species`; throws InvalidInput naming `what`.
  std::size_t histogram_index(int species, const std::string& what) const;

  std::size_t bins_;
  std::size_t ks_cap_;
  Rng ks_rng_;  // root of the KS subsample streams; snapshot j uses ks_rng_.split(j)
  int n_species_ = 0;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  std::vector<Histogram> last_histograms_;  // pooled, then species 0, 1, ... (mixtures)
  std::vector<MaxwellReference> last_refs_;
  int dim_ = 0;
  Config cfg_;
  // derived from cfg_ (derive_tables)
  std::vector<Histogram> empty_;                 // the histograms' edges, no counts
  std::vector<std::vector<double>> probs_;       // their MB bin probabilities at cfg_.kT
  std::vector<double> fine_cdf_;                 // MB CDF of the pooled speed at fine edges
  std::uint64_t passes_ = 0;
  // collisions at the previous row (keep_tally); not state: a restored recorder installs
  // the tally again, and the rows are the same either way
  std::uint64_t last_collisions_ = 0;
  bool have_last_ = false;
  // what observe decided the engine should keep (request): ask_ set, pending_ the tally
  // (empty: none); not state
  bool ask_ = false;
  std::optional<tally::Tally> pending_;
  /// The thread team of set_threads; a copy of the recorder gets none (one thread), so
  /// that two recorders never drive one team.
  struct Team {
    std::unique_ptr<ThreadTeam> p;
    Team() = default;
    Team(const Team&) {}
    Team& operator=(const Team&) {
      p.reset();
      return *this;
    }
    Team(Team&&) noexcept = default;
    Team& operator=(Team&&) noexcept = default;
    ThreadTeam* operator->() const { return p.get(); }
    explicit operator bool() const { return p != nullptr; }
  };
  Team team_;
};

}  // namespace hypergas::analysis
