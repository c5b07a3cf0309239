// MomentsRecorder: moments, distances and tests per snapshot in streaming passes; moments.csv
// and the final speed histogram.
#include "hypergas/analysis/moments_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <optional>
#include <utility>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
// The columns of every row, in order; mixtures add kT_0, kT_1, ...
constexpr const char* common_columns[] = {"time",        "collisions_per_particle",
                                          "m2",          "m4",
                                          "kurtosis_x",  "m6",
                                          "m2_err",      "m4_err",
                                          "m6_err",      "kurtosis_x_err",
                                          "m4_ratio",    "m4_ratio_err",
                                          "kT",          "l1_speed",
                                          "kl_speed",    "ks_p_speed",
                                          "chi2_p_speed"};
constexpr std::size_t n_common_columns = std::size(common_columns);
}  // namespace

MomentsRecorder::MomentsRecorder(std::size_t bins, std::size_t ks_cap, std::uint64_t ks_seed)
    : bins_(bins), ks_cap_(ks_cap), ks_rng_(ks_seed, ks_stream) {
  if (bins < 1) throw InvalidInput("MomentsRecorder: need at least one histogram bin");
  if (ks_cap < 1) throw InvalidInput("MomentsRecorder: the KS sample cap must be >= 1");
}

namespace {

/// Adds particles [begin, end) of `s`: moments into `sums`, speeds into the histograms
/// (pooled, then per species for mixtures), the speeds `pick(i)` selects into `ks`. Pooled
/// speeds are mass-weighted, |v| sqrt(m_i / m_mean); species speeds are plain |v|.
template <class Pick>
void add_particles(const Snapshot& s, std::size_t begin, std::size_t end, double m_mean,
                   int ns, MomentSums& sums, std::vector<Histogram>& hists,
                   std::vector<double>& ks, Pick&& pick) {
  const auto stride = static_cast<std::size_t>(s.stride);
  if (!s.species && !s.inv_mass) {
    // Unit masses: the loop below with w = 1, its divisions and one square root hoisted
    // (the same values bit for bit; a unit-mass gas is the common case).
    const double f = 1.0 / std::sqrt(1.0 * m_mean);
    for (std::size_t i = begin; i < end; ++i) {
      const double speed = f * std::sqrt(sums.add_unit_mass(s.velocities + i * stride));
      hists[0].add(speed);
      if (pick(i)) ks.push_back(speed);
    }
  } else {
    for (std::size_t i = begin; i < end; ++i) {
      const double w = s.inverse_mass(i);
      const double vv = sums.add(s.velocities + i * stride, w);
      const double f = 1.0 / std::sqrt(w * m_mean);
      const double speed = f * std::sqrt(vv);
      hists[0].add(speed);
      if (ns > 1) hists[1 + s.species[i]].add(std::sqrt(vv));
      if (pick(i)) ks.push_back(speed);
    }
  }
}

}  // namespace

void MomentsRecorder::set_threads(int threads) {
  if (threads < 1 || threads > 256)
    throw InvalidInput("MomentsRecorder: threads must be in 1..256, got " + std::to_string(threads));
  if (threads == 1)
    team_.p.reset();
  else if (!team_ || team_->size() != threads)
    team_.p = std::make_unique<ThreadTeam>(threads);
}

int MomentsRecorder::threads() const { return team_ ? team_->size() : 1; }

void MomentsRecorder::for_chunks(std::size_t chunks,
                                 const std::function<void(int, std::size_t)>& f) const {
  if (!team_) {
    for (std::size_t c = 0; c < chunks; ++c) f(0, c);
    return;
  }
  const int T = team_->size();
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(T));
  team_->run([&](int t) {
    try {
      for (std::size_t c = static_cast<std::size_t>(t); c < chunks; c += static_cast<std::size_t>(T))
        f(t, c);
    } catch (...) {
      failed[static_cast<std::size_t>(t)] = std::current_exception();
    }
  });
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
}

void MomentsRecorder::observe(const Snapshot& s) {
  validate(s);
  if (s.n < 2) throw InvalidInput("MomentsRecorder: need at least 2 particles");
  const int ns = s.species ? s.n_species : 1;
  if (!columns_.empty() && (ns != n_species_ || s.dim != dim_))
    throw InvalidInput("MomentsRecorder: snapshot dimension or species count changed");
  // Above the KS cap the passes run over fixed chunks, on the recorder's threads, and the
  // chunks' sums are added in chunk order: the same numbers for every thread count.
  const bool chunked = s.n > ks_cap_;
  const Summation how = chunked ? Summation::compensated : Summation::plain;
  const std::size_t chunks = chunked ? (s.n + chunk_size - 1) / chunk_size : 1;
  const auto range = [&](std::size_t c) {
    return std::pair{c * chunk_size, std::min(s.n, (c + 1) * chunk_size)};
  };

  // Pass 1: counts, masses and kinetic energies, per species and of all particles.
  std::optional<SnapshotTotals> totals;
  if (!chunked) {
    totals.emplace(s);
  } else {
    std::vector<std::optional<SnapshotTotals>> part(chunks);
    for_chunks(chunks, [&](int, std::size_t c) {
      const auto [b, e] = range(c);
      part[c].emplace(s, b, e);
    });
    totals = std::move(part[0]);
    for (std::size_t c = 1; c < chunks; ++c) totals->merge(*part[c]);
  }
  const double m_mean = totals->mean_mass(-1, how);
  // The references: MB at the common kT, of the mean mass (pooled) or of each species'
  // mass; a species with no particle gets the pooled one (and an empty histogram).
  const MaxwellReference ref{Quantity::speed, s.dim, totals->temperature(-1, how), m_mean};
  ref.validate();
  std::vector<MaxwellReference> refs{ref};
  std::vector<Histogram> hists{make_histogram(ref, bins_)};
  if (ns > 1) {
    for (int k = 0; k < ns; ++k) {
      MaxwellReference rk = ref;
      if (totals->count(k) > 0) rk.mass = totals->mean_mass(k, how);
      rk.validate();
      refs.push_back(rk);
      hists.push_back(make_histogram(rk, bins_));
    }
  }

  // Pass 2: power sums, histograms and the KS sample.
  MomentSums sums(s.dim, m_mean);
  std::vector<double> ks_sample;
  ks_sample.reserve(std::min(s.n, ks_cap_));
  const Rng stream = ks_rng_.split(rows_.size());
  if (!chunked) {
    SequentialSample pick(s.n, ks_cap_, stream);
    add_particles(s, 0, s.n, m_mean, ns, sums, hists, ks_sample,
                  [&](std::size_t) { return pick.take(); });
  } else {
    const int T = threads();
    std::vector<MomentSums> part(chunks, MomentSums(s.dim, m_mean));
    std::vector<std::vector<Histogram>> thread_hists(static_cast<std::size_t>(T), hists);
    std::vector<std::vector<double>> ks_part(chunks);
    for_chunks(chunks, [&](int t, std::size_t c) {
      const auto [b, e] = range(c);
      // Chunk c's share of the KS sample: floor(k e / n) - floor(k b / n) particles,
      // drawn without replacement (Floyd's algorithm) from its own stream.
      __extension__ using u128 = unsigned __int128;  // k e may exceed 2^64
      const u128 k = ks_cap_, n = s.n;
      const auto want = static_cast<std::size_t>(k * e / n - k * b / n);
      std::vector<bool> chosen(e - b, false);
      Rng r = stream.split(c);
      for (std::size_t j = e - b - want; j < e - b; ++j) {
        const std::size_t x = static_cast<std::size_t>(r.below(j + 1));
        chosen[chosen[x] ? j : x] = true;
      }
      ks_part[c].reserve(want);
      add_particles(s, b, e, m_mean, ns, part[c], thread_hists[static_cast<std::size_t>(t)],
                    ks_part[c], [&](std::size_t i) { return chosen[i - b]; });
    });
    for (std::size_t c = 0; c < chunks; ++c) {
      sums.merge(part[c]);
      ks_sample.insert(ks_sample.end(), ks_part[c].begin(), ks_part[c].end());
    }
    for (const auto& th : thread_hists)
      for (std::size_t h = 0; h < hists.size(); ++h) hists[h].merge(th[h]);
  }
  const Moments m = sums.result(how);
  const double ks_p = ks_test(std::move(ks_sample), ref).p_value;
  // kT comes from the same sample: one fitted parameter for the chi-square test.
  const double chi2_p = chi_square_test(hists[0], ref, 1).p_value;
  std::vector<double> row = {s.time,
                             s.collisions_per_particle,
                             m.m2.value,
                             m.m4.value,
                             m.kurtosis_x.value,
                             m.m6.value,
                             m.m2.error,
                             m.m4.error,
                             m.m6.error,
                             m.kurtosis_x.error,
                             m.m4_ratio.value,
                             m.m4_ratio.error,
                             m.kT,
                             l1_distance(hists[0], ref),
                             kl_divergence(hists[0], ref),
                             ks_p,
                             chi2_p};
  if (ns > 1)
    for (int k = 0; k < ns; ++k)
      row.push_back(totals->count(k) > 0 ? totals->temperature(k, how) : NAN);

  if (columns_.empty()) {
    n_species_ = ns;
    dim_ = s.dim;
    columns_.assign(std::begin(common_columns), std::end(common_columns));
    if (ns > 1)
      for (int k = 0; k < ns; ++k) columns_.push_back("kT_" + std::to_string(k));
  }
  rows_.push_back(std::move(row));
  last_histograms_ = std::move(hists);
  last_refs_ = std::move(refs);
}

std::vector<double> MomentsRecorder::column(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) throw InvalidInput("MomentsRecorder: no column '" + name + "'");
  const auto c = static_cast<std::size_t>(it - columns_.begin());
  std::vector<double> out;
  out.reserve(rows_.size());
  for (const auto& r : rows_) out.push_back(r[c]);
  return out;
}

void MomentsRecorder::write_moments_csv(const std::string& path) const {
  if (rows_.empty()) throw InvalidInput("MomentsRecorder: nothing observed, no " + path);
  write_csv(path, columns_, rows_);
}

std::size_t MomentsRecorder::histogram_index(int species, const std::string& what) const {
  if (last_histograms_.empty()) throw InvalidInput("MomentsRecorder: nothing observed, no " + what);
  const auto k = static_cast<std::size_t>(species + 1);
  if (species < -1 || k >= last_histograms_.size())
    throw InvalidInput("MomentsRecorder: no species " + std::to_string(species) + " for " + what);
  return k;
}

const Histogram& MomentsRecorder::last_histogram(int species) const {
  return last_histograms_[histogram_index(species, "speed histogram")];
}

const MaxwellReference& MomentsRecorder::last_reference(int species) const {
  return last_refs_[histogram_index(species, "speed histogram")];
}

void MomentsRecorder::write_speed_histogram_csv(const std::string& path, int species) const {
  const std::size_t k = histogram_index(species, path);
  write_histogram_csv(path, last_histograms_[k], last_refs_[k]);
}

void MomentsRecorder::check_restored() const {
  const auto bad = [](const std::string& what) {
    throw InvalidInput("MomentsRecorder: restored state is inconsistent: " + what);
  };
  if (bins_ < 1 || ks_cap_ < 1) bad("no histogram bin or a KS cap of 0");
  const bool empty = columns_.empty();
  if (empty != rows_.empty() || empty != last_histograms_.empty())
    bad("columns, rows and histograms disagree on whether anything was observed");
  if (last_histograms_.size() != last_refs_.size())
    bad("histograms and references differ in number");
  if (empty) return;
  if (n_species_ < 1 || dim_ < 1) bad("no species or no dimension");
  const std::size_t per_species = n_species_ > 1 ? static_cast<std::size_t>(n_species_) : 0;
  if (columns_.size() != n_common_columns + per_species ||
      last_histograms_.size() != 1 + per_species)
    bad("the number of columns or histograms does not fit the species count");
  for (const auto& r : rows_)
    if (r.size() != columns_.size()) bad("a row of another length than the columns");
  for (const auto& h : last_histograms_)
    if (h.bins() != bins_) bad("a histogram of another bin count");
}

}  // namespace hypergas::analysis
