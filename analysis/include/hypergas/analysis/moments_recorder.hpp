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
// Pooled speeds are mass-weighted (see sample.hpp). The recorder keeps the speed histograms
// of the last snapshot (pooled and, for mixtures, per species) for speed_histogram.csv.
//
// Cost per snapshot of n particles: three streaming passes over the snapshot's arrays
// (validation; counts, masses and energies; moments, histograms and the KS sample), O(n)
// time and, besides the KS sample, O(bins + species) memory: no per-particle copy. The
// target is n ~ 1e7 in a process whose velocities are most of its memory.
//
// The KS test needs its sample sorted, so it is the one statistic that keeps values:
// min(n, ks_cap) doubles.
//  - n <= ks_cap: all n speeds, as before.
//  - n > ks_cap: a stratified random subsample of exactly k = ks_cap particles: chunk c
//    (particles [b, e), 65536 per chunk) gives floor(k e / n) - floor(k b / n) of its
//    particles, drawn without replacement by Floyd's algorithm. Snapshot number j (0, 1,
//    ... in order of observation) draws chunk c's share from the stream
//    Rng(ks_seed, ks_stream).split(j).split(c), so the subsample is reproducible,
//    independent of the engine's random numbers, of the thread count and of the sizes of
//    earlier snapshots. Which particles are taken does not depend on their speeds, so
//    under the null hypothesis the subsample is k independent MB speeds, as a uniform
//    subsample would be. ks_p_speed is then the p-value of the same null hypothesis
//    (the speeds are MB at the snapshot's kT) tested with ks_cap samples: under it, it is
//    uniform as before; its power is that of ks_cap samples, not of n (the smallest
//    deviation of the speed CDF it resolves is ~1.36 / sqrt(ks_cap), the 5% critical value
//    of the KS statistic: 1.4e-3 for the default cap); and it varies with the subsample, so
//    another seed gives another p.
//    Because kT comes mostly from particles outside the subsample, the test is then close
//    to exact rather than conservative.
// Histograms, distances, the chi-square test and the moments always use every particle.
//
// Sums over particles (moments, kT, mean masses): for n <= ks_cap they are read as plain
// left-to-right double sums, which reproduce the files of earlier versions bit for bit;
// for n > ks_cap they are compensated (sample.hpp), accurate to a few eps for any n. The
// two differ by the rounding error of the plain sum, ~sqrt(n) eps relative.
//
// Threads (set_threads): for n > ks_cap both passes run over the chunks, chunk c on thread
// c mod T; each chunk keeps its own sums, which are then added in chunk order
// (RunningSum::merge), and the histograms' integer counts are added per thread. The rows
// are therefore the same for every T. For n <= ks_cap the passes run on one thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/thread_team.hpp"

namespace hypergas::analysis {

class MomentsRecorder final : public Observer {
 public:
  /// Default largest KS sample (doubles kept per snapshot: 8 MB).
  static constexpr std::size_t default_ks_cap = 1'000'000;
  /// Default seed of the KS subsample stream.
  static constexpr std::uint64_t default_ks_seed = 0x6b735f63617073ULL;
  /// Stream number of the KS subsample (with the seed above): one no engine uses.
  static constexpr std::uint64_t ks_stream = 0x4d6f6d656e74734bULL;

  /// `bins` bins for the speed histograms (>= 1); a KS test on at most `ks_cap` speeds
  /// (>= 1; a uniform subsample above it) drawn with seed `ks_seed`. Throws InvalidInput
  /// for bins or ks_cap < 1.
  explicit MomentsRecorder(std::size_t bins = 50, std::size_t ks_cap = default_ks_cap,
                           std::uint64_t ks_seed = default_ks_seed);

  /// Runs the passes over a snapshot above the KS cap on `threads` threads (1..256; the
  /// rows are the same for every count). Not state: neither a checkpoint nor a copy of the
  /// recorder keeps it.
  void set_threads(int threads);
  int threads() const;

  /// Records one row; throws InvalidInput for an unreadable snapshot or one whose number of
  /// species differs from the first (nothing is recorded then).
  void observe(const Snapshot& s) override;

  /// Column names, fixed by the first snapshot (the per-species columns need it).
  const std::vector<std::string>& columns() const { return columns_; }
  /// One row per observed snapshot, in column order.
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// The values of one column over time; throws InvalidInput for an unknown name.
  std::vector<double> column(const std::string& name) const;
  /// Largest KS sample (particles).
  std::size_t ks_cap() const { return ks_cap_; }

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
    if constexpr (!Archive::saving) check_restored();
  }

 private:
  static_assert(std::is_trivially_copyable_v<Rng>, "io() saves the KS stream as raw bytes");
  static_assert(std::is_trivially_copyable_v<MaxwellReference>);

  void check_restored() const;
  /// Particles per chunk of the passes above the KS cap.
  static constexpr std::size_t chunk_size = std::size_t{1} << 16;
  /// f(thread, chunk) for chunks 0..chunks-1, chunk c on thread c mod T; rethrows the
  /// first exception of a thread.
  void for_chunks(std::size_t chunks, const std::function<void(int, std::size_t)>& f) const;
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
