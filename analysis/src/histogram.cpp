// Histogram: a thin owner of a gsl_histogram plus underflow / overflow counts.
#include "hypergas/analysis/histogram.hpp"

#include <gsl/gsl_histogram.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <string>

#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

struct Histogram::Impl {
  gsl_histogram* h = nullptr;
  double under = 0.0, over = 0.0;
  Impl() = default;
  Impl(const Impl& o) : h(gsl_histogram_clone(o.h)), under(o.under), over(o.over) {}
  ~Impl() {
    if (h) gsl_histogram_free(h);
  }
  Impl& operator=(const Impl&) = delete;
};

Histogram::Histogram(double lo, double hi, std::size_t bins) : impl_(std::make_unique<Impl>()) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
    throw InvalidInput("Histogram: need finite lo < hi, got [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + ")");
  if (bins < 1) throw InvalidInput("Histogram: need at least one bin");
  impl_->h = gsl_histogram_alloc(bins);
  if (!impl_->h) throw std::bad_alloc();
  gsl_histogram_set_ranges_uniform(impl_->h, lo, hi);
}

Histogram::Histogram() : Histogram(0.0, 1.0, 1) {}

Histogram::~Histogram() = default;
Histogram::Histogram(const Histogram& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Histogram& Histogram::operator=(const Histogram& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}
Histogram::Histogram(Histogram&&) noexcept = default;
Histogram& Histogram::operator=(Histogram&&) noexcept = default;

void Histogram::add(double x) {
  if (!std::isfinite(x)) throw InvalidInput("Histogram::add: non-finite value");
  gsl_histogram* h = impl_->h;
  if (x < h->range[0]) {
    impl_->under += 1.0;
  } else if (x >= h->range[h->n]) {
    impl_->over += 1.0;
  } else {
    // The bin GSL's gsl_histogram_increment finds, found here without its call and checks
    // (a tenth of a snapshot's analysis at N = 1e7): the linear guess for equal bins, then
    // the unique i with range[i] <= x < range[i + 1].
    const std::size_t n = h->n;
    const double* r = h->range;
    auto i = static_cast<std::size_t>((x - r[0]) / (r[n] - r[0]) * static_cast<double>(n));
    if (!(i < n && x >= r[i] && x < r[i + 1]))
      i = static_cast<std::size_t>(std::upper_bound(r, r + n + 1, x) - r) - 1;
    h->bin[i] += 1.0;
  }
}

void Histogram::add(const std::vector<double>& xs) {
  for (double x : xs) add(x);
}

void Histogram::merge(const Histogram& o) {
  if (gsl_histogram_equal_bins_p(impl_->h, o.impl_->h) != 1)
    throw InvalidInput("Histogram::merge: different bins");
  for (std::size_t i = 0; i < impl_->h->n; ++i) impl_->h->bin[i] += o.impl_->h->bin[i];
  impl_->under += o.impl_->under;
  impl_->over += o.impl_->over;
}

std::size_t Histogram::bins() const {
  return impl_->h->n;
}
double Histogram::lower(std::size_t i) const {
  return impl_->h->range[i];
}
double Histogram::upper(std::size_t i) const {
  return impl_->h->range[i + 1];
}
double Histogram::count(std::size_t i) const {
  return impl_->h->bin[i];
}
double Histogram::underflow() const {
  return impl_->under;
}
double Histogram::overflow() const {
  return impl_->over;
}
double Histogram::total() const {
  return gsl_histogram_sum(impl_->h) + impl_->under + impl_->over;
}

double Histogram::density(std::size_t i) const {
  const double t = total();
  return t > 0.0 ? count(i) / (t * (upper(i) - lower(i))) : 0.0;
}

void Histogram::restore(const std::vector<double>& edges, const std::vector<double>& counts,
                        double under, double over) {
  const auto bad = [](const std::string& what) {
    throw InvalidInput("Histogram: cannot restore a histogram with " + what);
  };
  if (counts.empty() || edges.size() != counts.size() + 1)
    bad(std::to_string(edges.size()) + " edges for " + std::to_string(counts.size()) + " bins");
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (!std::isfinite(edges[i]) || (i > 0 && !(edges[i - 1] < edges[i])))
      bad("bin edges that are not finite and increasing");
  const auto is_count = [](double c) { return c >= 0.0 && c == std::floor(c) && c < 0x1p53; };
  for (double c : counts)
    if (!is_count(c)) bad("a bin count that is not a whole number >= 0");
  if (!is_count(under) || !is_count(over)) bad("an underflow or overflow that is not a count");
  auto fresh = std::make_unique<Impl>();
  fresh->h = gsl_histogram_alloc(counts.size());
  if (!fresh->h) throw std::bad_alloc();
  gsl_histogram_set_ranges(fresh->h, edges.data(), edges.size());
  std::copy(counts.begin(), counts.end(), fresh->h->bin);
  fresh->under = under;
  fresh->over = over;
  impl_ = std::move(fresh);
}

void Histogram::set_counts(const std::vector<double>& counts, double under, double over) {
  if (counts.size() != bins())
    throw InvalidInput("Histogram::set_counts: " + std::to_string(counts.size()) +
                       " counts for " + std::to_string(bins()) + " bins");
  std::vector<double> edges;
  edges.reserve(bins() + 1);
  for (std::size_t i = 0; i < bins(); ++i) edges.push_back(lower(i));
  edges.push_back(upper(bins() - 1));
  restore(edges, counts, under, over);
}

Histogram make_histogram(const MaxwellReference& ref, std::size_t bins) {
  ref.validate();
  constexpr double tail = 1e-7;
  const double hi = ref.quantile(1.0 - tail);
  const double lo = ref.quantity == Quantity::component ? ref.quantile(tail) : 0.0;
  return Histogram(lo, hi, bins);
}

Histogram make_histogram(const std::vector<double>& xs, const MaxwellReference& ref,
                         std::size_t bins) {
  Histogram h = make_histogram(ref, bins);
  h.add(xs);
  return h;
}

double bin_density(const MaxwellReference& ref, double lo, double hi) {
  // Exact bin probability over the width; the upper tails keep it accurate far out.
  const double p =
      ref.cdf(lo) < 0.5 ? ref.cdf(hi) - ref.cdf(lo) : ref.upper_tail(lo) - ref.upper_tail(hi);
  return p / (hi - lo);
}

double sonine_bin_density(const MaxwellReference& ref, double a2, double lo, double hi) {
  // Simpson's rule on 32 intervals of the bin: the density is smooth on a bin
  const int m = 32;
  const double h = (hi - lo) / m;
  const double d = ref.dim;
  double s = 0.0;
  for (int k = 0; k <= m; ++k) {
    const double v = lo + h * k;
    const double x = 0.5 * ref.mass * v * v / ref.kT;  // c^2 = v^2 / v_T^2
    const double s2 = 0.5 * x * x - 0.5 * (d + 2.0) * x + d * (d + 2.0) / 8.0;
    const double f = ref.pdf(v) * (1.0 + a2 * s2);
    s += f * (k == 0 || k == m ? 1.0 : (k % 2 ? 4.0 : 2.0));
  }
  return s * h / 3.0 / (hi - lo);
}

void write_histogram_csv(const std::string& path, const Histogram& h, const MaxwellReference& ref,
                         double a2) {
  ref.validate();
  const bool sonine = std::isfinite(a2) && ref.quantity == Quantity::speed;
  std::vector<std::vector<double>> rows;
  rows.reserve(h.bins());
  for (std::size_t i = 0; i < h.bins(); ++i) {
    const double lo = h.lower(i), hi = h.upper(i);
    rows.push_back({lo, hi, h.count(i), h.density(i), bin_density(ref, lo, hi)});
    if (sonine) rows.back().push_back(sonine_bin_density(ref, a2, lo, hi));
  }
  std::vector<std::string> cols = {"lo", "hi", "count", "density", "maxwell_density"};
  if (sonine) cols.push_back("sonine_density");
  write_csv(path, cols, rows);
}

}  // namespace hypergas::analysis
