// MomentsRecorder: moments, distances and tests per snapshot in streaming passes (the passes
// themselves in moments_passes.cpp); moments.csv and the final speed histogram.
#include "hypergas/analysis/moments_recorder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/error.hpp"
#include "hypergas/granular/theory.hpp"

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
// After the per-species columns: the Sonine cumulants and the true temperature and time of
// a granular gas whose engine stores scaled velocities (Snapshot::log_velocity_scale).
constexpr const char* trailing_columns[] = {"a2", "a3", "T", "real_time"};
constexpr std::size_t n_trailing_columns = std::size(trailing_columns);
}  // namespace

MomentsRecorder::MomentsRecorder(std::size_t bins, std::size_t ks_cap, std::uint64_t ks_seed)
    : bins_(bins), ks_cap_(ks_cap), ks_rng_(ks_seed, ks_stream) {
  if (bins < 1) throw InvalidInput("MomentsRecorder: need at least one histogram bin");
}

namespace {

/// Whether the snapshot's species masses are those of the layout.
bool same_masses(const Snapshot& s, const tally::Layout& L) {
  if (!s.species) return true;
  for (int k = 0; k < s.n_species; ++k)
    if (s.species_inv_mass[k] != L.inv_mass[std::size_t(k)]) return false;
  return true;
}

/// A kT that moved by more than this (relative) since the configuring snapshot configures
/// again.
constexpr double kT_tolerance = 1e-9;
/// Fine bins in all at most, and per sqrt(n).
constexpr std::size_t max_fine = 32768;
constexpr double fine_per_sqrt_n = 32.0;

/// 2^k with 2^k >= x > 2^(k-1), for x > 0: the power of two at or just above x.
double pow2_above(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
  return std::ldexp(1.0, m == 0.5 ? e - 1 : e);
}

/// P(D/2, z), the CDF of the MB speed at z = m s^2 / (2 kT), in closed form: the sum of the
/// Poisson terms for even D, erf and the recursion P(a + 1) = P(a) - z^a e^-z / Gamma(a + 1)
/// for odd D. Absolute error ~1e-15 (what the binned KS needs); one exp and one erf.
double speed_cdf(int dim, double z) {
  if (!(z > 0.0)) return 0.0;
  const double ez = std::exp(-z);
  double p;
  if (dim % 2 == 0) {
    double term = 1.0, sum = 1.0;
    for (int j = 1; j < dim / 2; ++j) sum += term *= z / j;
    p = 1.0 - ez * sum;
  } else {
    p = std::erf(std::sqrt(z));
    double term = 2.0 * std::sqrt(z / M_PI) * ez;  // z^(1/2) e^-z / Gamma(3/2)
    for (int k = 1; k <= (dim - 1) / 2; ++k) {
      p -= term;
      term *= z / (k + 0.5);
    }
  }
  return std::clamp(p, 0.0, 1.0);
}

/// Mean of a term under MB at kT for particles of the given masses (counts per species),
/// in scaled units: theta_k = kT c^2 / m_k.
struct Expect {
  int dim;
  double kT_c2;  // kT c^2
  double m_mean;
  std::vector<std::pair<double, double>> species;  // (fraction, mass)
  /// <|u|^2k> over the species.
  double u(int k) const {
    double e = 0.0;
    for (const auto& [frac, m] : species) {
      double x = 1.0;
      for (int i = 0; i < k; ++i) x *= (dim + 2.0 * i) * kT_c2 / m;
      e += frac * x;
    }
    return e;
  }
  /// <|w|^2k> (mass-weighted: every species at m_mean).
  double w(int k) const {
    double x = 1.0;
    for (int i = 0; i < k; ++i) x *= (dim + 2.0 * i) * kT_c2 / m_mean;
    return x;
  }
  /// <w_x^2k> = (2k - 1)!! theta^k.
  double x(int k) const {
    double v = 1.0;
    for (int i = 0; i < k; ++i) v *= (2.0 * i + 1.0) * kT_c2 / m_mean;
    return v;
  }
};

/// The fixed-point unit for terms of typical size `mean`: a typical term is ~2^40 units.
double unit_for(double mean) { return std::ldexp(1.0, 40) / pow2_above(mean); }

}  // namespace

void MomentsRecorder::configure(const Snapshot& s, int ns) {
  const std::size_t chunks = (s.n + chunk_size - 1) / chunk_size;
  std::vector<std::optional<SnapshotTotals>> part(chunks);
  for_chunks(chunks, [&](int, std::size_t c) {
    part[c].emplace(s, c * chunk_size, std::min(s.n, (c + 1) * chunk_size));
  });
  SnapshotTotals totals = std::move(*part[0]);
  for (std::size_t c = 1; c < chunks; ++c) totals.merge(*part[c]);
  const double m_mean = totals.mean_mass(-1), kT = totals.temperature(-1);
  const MaxwellReference ref{Quantity::speed, s.dim, kT, m_mean};
  ref.validate();

  Config c;
  c.set = true;
  c.kT = kT;
  tally::Layout& L = c.layout;
  L.dim = s.dim;
  L.n_species = ns;
  L.weighted = s.species != nullptr || s.inv_mass != nullptr;
  L.m_mean = m_mean;
  if (s.species)
    for (int k = 0; k < s.n_species; ++k) L.inv_mass[std::size_t(k)] = s.species_inv_mass[k];
  const double inv_c = pow2_above(std::sqrt(kT / m_mean));  // kT c^2 / m_mean in (1/4, 1]
  c.scale = inv_c;
  L.c2 = 1.0 / (inv_c * inv_c);
  Expect ex{s.dim, kT * L.c2, m_mean, {}};
  const double n = static_cast<double>(totals.count(-1));
  if (s.species) {
    for (int k = 0; k < ns; ++k)
      if (totals.count(k) > 0)
        ex.species.emplace_back(static_cast<double>(totals.count(k)) / n, totals.mean_mass(k));
  } else {
    ex.species.emplace_back(1.0, m_mean);
  }
  L.unit[tally::u2] = unit_for(ex.u(1));
  L.unit[tally::u4] = unit_for(ex.u(2));
  L.unit[tally::u6] = unit_for(ex.u(3));
  L.unit[tally::u8] = unit_for(ex.u(4));
  L.unit[tally::u12] = unit_for(ex.u(6));
  L.unit[tally::w4] = unit_for(ex.w(2));
  L.unit[tally::w8] = unit_for(ex.w(4));
  L.unit[tally::x2] = unit_for(ex.x(1));
  L.unit[tally::x4] = unit_for(ex.x(2));
  L.unit[tally::x6] = unit_for(ex.x(3));
  L.unit[tally::x8] = unit_for(ex.x(4));
  L.energy_unit = unit_for(s.dim * kT * L.c2);
  const std::size_t per_bin = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil(fine_per_sqrt_n * std::sqrt(n) / bins_)), 1,
      std::max<std::size_t>(1, max_fine / bins_));
  L.fine = static_cast<std::uint32_t>(per_bin * bins_);
  // the histograms: pooled at m_mean, then each species at its mass (the pooled mass for a
  // species without particles)
  for (int h = 0; h < L.histograms(); ++h) {
    MaxwellReference r = ref;
    if (h > 0 && totals.count(h - 1) > 0) r.mass = totals.mean_mass(h - 1);
    r.validate();
    const Histogram e = make_histogram(r, bins_);
    const auto k = static_cast<std::size_t>(h);
    c.lo[k] = e.lower(0);
    c.hi[k] = e.upper(bins_ - 1);
    c.mass[k] = r.mass;
    L.lo[k] = c.lo[k] / inv_c;
    L.inv_h[k] = static_cast<double>(L.fine) / ((c.hi[k] - c.lo[k]) / inv_c);
  }
  cfg_ = c;
  derive_tables();
}

void MomentsRecorder::derive_tables() {
  empty_.clear();
  probs_.clear();
  fine_cdf_.clear();
  if (!cfg_.set) return;
  const tally::Layout& L = cfg_.layout;
  for (int h = 0; h < L.histograms(); ++h) {
    const auto k = static_cast<std::size_t>(h);
    const MaxwellReference r{Quantity::speed, L.dim, cfg_.kT, cfg_.mass[k]};
    empty_.emplace_back(cfg_.lo[k], cfg_.hi[k], bins_);
    probs_.push_back(reference_probabilities(empty_.back(), r));
  }
  fine_cdf_.resize(std::size_t(L.fine) + 1);
  const double lo = cfg_.lo[0], width = (cfg_.hi[0] - cfg_.lo[0]) / L.fine;
  const double z_per_s2 = cfg_.mass[0] / (2.0 * cfg_.kT);
  for (std::size_t k = 0; k <= L.fine; ++k) {
    const double e = lo + width * static_cast<double>(k);
    fine_cdf_[k] = speed_cdf(L.dim, z_per_s2 * e * e);
  }
}

void MomentsRecorder::observe(const Snapshot& s) {
  ask_ = false;  // a request not taken by the engine is for an old snapshot: never sent
  pending_.reset();
  validate(s);
  if (s.n < 2) throw InvalidInput("MomentsRecorder: need at least 2 particles");
  const int ns = s.species ? s.n_species : 1;
  if (!columns_.empty() && (ns != n_species_ || s.dim != dim_))
    throw InvalidInput("MomentsRecorder: snapshot dimension or species count changed");
  if (ns > max_species)
    throw InvalidInput("MomentsRecorder: at most " + std::to_string(max_species) + " species");
  // the engine's tally if it fits the layout, else one pass with the layout, else
  // configure from this snapshot and pass
  // whether the engine's tally pays for itself (tally_limit): by the last interval's count
  const bool keep = !have_last_ || static_cast<double>(s.collisions - last_collisions_) <=
                                       tally_limit * static_cast<double>(s.n);
  last_collisions_ = s.collisions;
  have_last_ = true;
  const tally::Tally* kept = s.tally && s.tally->tally ? s.tally->tally.get() : nullptr;
  const bool fits = cfg_.set && cfg_.layout.dim == s.dim && cfg_.layout.n_species == ns &&
                    cfg_.layout.weighted == (s.species != nullptr || s.inv_mass != nullptr) &&
                    s.inv_mass == nullptr && same_masses(s, cfg_.layout);
  if (fits && kept && kept->layout() == cfg_.layout &&
      kept->count(-1) == static_cast<std::int64_t>(s.n) && record(s, *kept)) {
    if (!keep) ask(std::nullopt);
    return;
  }
  if (fits) {
    tally::Tally t = pass(s);
    ++passes_;
    if (record(s, t)) {
      if (s.tally) ask(keep ? std::optional(std::move(t)) : std::nullopt);
      return;
    }
  }
  configure(s, ns);
  tally::Tally t = pass(s);
  ++passes_;
  if (!record(s, t))
    throw InvalidInput("MomentsRecorder: the snapshot's temperature is not reproducible");
  if (s.tally) ask(keep ? std::optional(std::move(t)) : std::nullopt);
}

void MomentsRecorder::ask(std::optional<tally::Tally> t) {
  ask_ = true;
  pending_ = std::move(t);
}

void MomentsRecorder::request(tally::Requests& r) {
  if (!ask_) return;
  r.set_tally(pending_ ? std::make_unique<tally::Tally>(std::move(*pending_)) : nullptr);
  ask_ = false;
  pending_.reset();
}

bool MomentsRecorder::record(const Snapshot& s, const tally::Tally& t) {
  const tally::Layout& L = cfg_.layout;
  const int ns = L.n_species;
  const double n = static_cast<double>(t.count(-1));
  const double scale2 = cfg_.scale * cfg_.scale;
  const double kT = t.energy(-1) / (s.dim * n) * scale2;
  if (!(std::abs(kT - cfg_.kT) <= kT_tolerance * cfg_.kT)) return false;
  // mean mass of the species counts (the layout's when the counts are those it was made of)
  double m_mean = L.m_mean;
  if (s.species) {
    double mass = 0.0;
    for (int k = 0; k < ns; ++k)
      if (t.count(k) > 0) mass += static_cast<double>(t.count(k)) / s.species_inv_mass[k];
    if (std::abs(mass / n - m_mean) > 1e-12 * m_mean) return false;
  }
  using tally::Term;
  PowerSums p;
  p.n = n;
  p.s2 = t.term(Term::u2), p.s4 = t.term(Term::u4), p.s6 = t.term(Term::u6);
  p.s8 = t.term(Term::u8), p.s12 = t.term(Term::u12);
  p.w4 = t.term(Term::w4), p.w8 = t.term(Term::w8);
  p.x2 = t.term(Term::x2), p.x4 = t.term(Term::x4), p.x6 = t.term(Term::x6);
  p.x8 = t.term(Term::x8);
  p.twice_e = t.energy(-1);
  const Moments m = moments_from_sums(s.dim, m_mean, p, cfg_.scale);

  // the coarse histograms from the fine ones; references at this snapshot's kT
  const std::size_t per_bin = L.fine / bins_;
  std::vector<Histogram> hists;
  std::vector<MaxwellReference> refs;
  BinnedCounts pooled;
  for (int h = 0; h < L.histograms(); ++h) {
    const auto k = static_cast<std::size_t>(h);
    const std::int64_t* fine = t.counts(h);
    std::vector<double> coarse(bins_, 0.0);
    for (std::size_t i = 0; i < bins_; ++i) {
      std::int64_t c = 0;
      for (std::size_t f = 1 + i * per_bin; f < 1 + (i + 1) * per_bin; ++f) c += fine[f];
      coarse[i] = static_cast<double>(c);
    }
    const auto under = static_cast<double>(fine[0]);
    const auto over = static_cast<double>(fine[L.fine + 1]);
    if (h == 0) {
      pooled.counts.reserve(bins_ + 2);
      pooled.counts.push_back(under);
      pooled.counts.insert(pooled.counts.end(), coarse.begin(), coarse.end());
      pooled.counts.push_back(over);
      pooled.probs = probs_[0];
      pooled.total = n;
    }
    hists.push_back(empty_[k]);
    hists.back().set_counts(coarse, under, over);
    refs.push_back(MaxwellReference{Quantity::speed, s.dim, kT, cfg_.mass[k]});
  }
  const double ks_p = ks_cap_ == 0
                          ? ks_test_binned(t.counts(0), fine_cdf_.data(), L.fine).p_value
                          : ks_test(ks_sample(s, m_mean, rows_.size()), refs[0]).p_value;
  // kT comes from the same sample: one fitted parameter for the chi-square test. A gas too
  // small for it (fewer than three groups of 5 expected counts: N below about 20) has no
  // chi-square p-value: NaN, an empty field of moments.csv.
  double chi2_p = std::numeric_limits<double>::quiet_NaN();
  if (chi_square_possible(pooled, 1)) chi2_p = chi_square_test(pooled, 1).p_value;
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
                             l1_distance(pooled),
                             kl_divergence(pooled),
                             ks_p,
                             chi2_p};
  if (ns > 1)
    for (int k = 0; k < ns; ++k) {
      const auto nk = static_cast<double>(t.count(k));
      row.push_back(nk > 0 ? t.energy(k) / (s.dim * nk) * scale2 : NAN);
    }
  // trailing_columns: a2 and a3 of the pooled speeds (granular/theory.hpp), T, real_time
  row.push_back(granular::a2_from_moments(m.m2.value, m.m4.value, s.dim));
  row.push_back(granular::a3_from_moments(m.m2.value, m.m4.value, m.m6.value, s.dim));
  row.push_back(m.kT * std::exp(2.0 * s.log_velocity_scale));
  row.push_back(std::isnan(s.real_time) ? s.time : s.real_time);

  if (columns_.empty()) {
    n_species_ = ns;
    dim_ = s.dim;
    columns_.assign(std::begin(common_columns), std::end(common_columns));
    if (ns > 1)
      for (int k = 0; k < ns; ++k) columns_.push_back("kT_" + std::to_string(k));
    columns_.insert(columns_.end(), std::begin(trailing_columns), std::end(trailing_columns));
  }
  rows_.push_back(std::move(row));
  last_histograms_ = std::move(hists);
  last_refs_ = std::move(refs);
  return true;
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
  // the first Sonine form with the last row's a2 of the pooled speeds (one species: the
  // scaled HCS or driven state of a granular gas against its Sonine form)
  const double a2 = n_species_ == 1 ? rows_.back()[n_common_columns] : NAN;
  write_histogram_csv(path, last_histograms_[k], last_refs_[k], a2);
}

void MomentsRecorder::check_restored() const {
  const auto bad = [](const std::string& what) {
    throw InvalidInput("MomentsRecorder: restored state is inconsistent: " + what);
  };
  if (bins_ < 1) bad("no histogram bin");
  const bool empty = columns_.empty();
  if (empty != rows_.empty() || empty != last_histograms_.empty())
    bad("columns, rows and histograms disagree on whether anything was observed");
  if (last_histograms_.size() != last_refs_.size())
    bad("histograms and references differ in number");
  if (empty) return;
  if (n_species_ < 1 || dim_ < 1) bad("no species or no dimension");
  const std::size_t per_species = n_species_ > 1 ? static_cast<std::size_t>(n_species_) : 0;
  if (columns_.size() != n_common_columns + per_species + n_trailing_columns ||
      last_histograms_.size() != 1 + per_species)
    bad("the number of columns or histograms does not fit the species count");
  for (const auto& r : rows_)
    if (r.size() != columns_.size()) bad("a row of another length than the columns");
  for (const auto& h : last_histograms_)
    if (h.bins() != bins_) bad("a histogram of another bin count");
  if (!cfg_.set) bad("no tally layout after a snapshot");
  const tally::Layout& L = cfg_.layout;
  if (L.dim != dim_ || L.n_species != n_species_ || L.fine < bins_ || L.fine % bins_ != 0 ||
      L.fine > max_fine + bins_ || !(cfg_.kT > 0.0) || !(cfg_.scale > 0.0) || !(L.m_mean > 0.0))
    bad("a tally layout that does not fit the rows");
  for (int h = 0; h < L.histograms(); ++h) {
    const auto k = static_cast<std::size_t>(h);
    if (!(cfg_.lo[k] < cfg_.hi[k]) || !std::isfinite(cfg_.hi[k]) || !(cfg_.mass[k] > 0.0))
      bad("a tally histogram without a range or a mass");
  }
}

}  // namespace hypergas::analysis
