// VACF and MSD by FFT (Wiener–Khinchin); diffusion coefficients.
#include "hypergas/analysis/vacf.hpp"

#include <fftw3.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <string>

#include "fftw_planner.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
void check_series(const std::vector<double>& data, std::size_t frames, std::size_t n, int dim,
                  std::size_t max_lag, const char* who) {
  if (dim < 1) throw InvalidInput(std::string(who) + ": dimension must be >= 1");
  if (frames < 1 || n < 1) throw InvalidInput(std::string(who) + ": need >= 1 frame and particle");
  if (data.size() != frames * n * static_cast<std::size_t>(dim))
    throw InvalidInput(std::string(who) + ": data has " + std::to_string(data.size()) +
                       " values, expected frames * n * dim = " +
                       std::to_string(frames * n * static_cast<std::size_t>(dim)));
  if (max_lag >= frames)
    throw InvalidInput(std::string(who) + ": max_lag " + std::to_string(max_lag) +
                       " must be < frames " + std::to_string(frames));
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

// R(lag) = sum over channels of sum_t0 x_c(t0) x_c(t0 + lag), lags 0..max_lag, by FFT.
class Correlator {
 public:
  explicit Correlator(std::size_t frames) : frames_(frames) {
    // A length >= 2 frames - 1 avoids wrap-around; a power of two is fast for FFTW.
    len_ = 1;
    while (len_ < 2 * frames) len_ *= 2;
    in_.reset(static_cast<double*>(fftw_malloc(sizeof(double) * len_)));
    out_.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * (len_ / 2 + 1))));
    if (!in_ || !out_) throw std::bad_alloc();
    const int nn = static_cast<int>(len_);
    std::lock_guard lock(planner_mutex());  // FFTW's planner is not thread-safe
    forward_ = fftw_plan_dft_r2c_1d(nn, in_.get(), out_.get(), FFTW_ESTIMATE);
    backward_ = fftw_plan_dft_c2r_1d(nn, out_.get(), in_.get(), FFTW_ESTIMATE);
    if (!forward_ || !backward_) throw std::bad_alloc();
  }
  ~Correlator() {
    std::lock_guard lock(planner_mutex());
    if (forward_) fftw_destroy_plan(forward_);
    if (backward_) fftw_destroy_plan(backward_);
  }
  Correlator(const Correlator&) = delete;
  Correlator& operator=(const Correlator&) = delete;

  // Adds the autocorrelation sums of x (length frames) to acc[0..max_lag].
  void accumulate(const double* x, std::vector<double>& acc) {
    double* in = in_.get();
    for (std::size_t t = 0; t < frames_; ++t) in[t] = x[t];
    for (std::size_t t = frames_; t < len_; ++t) in[t] = 0.0;
    fftw_execute(forward_);
    fftw_complex* o = out_.get();
    for (std::size_t k = 0; k <= len_ / 2; ++k) {  // |X_k|^2 (Wiener–Khinchin)
      o[k][0] = o[k][0] * o[k][0] + o[k][1] * o[k][1];
      o[k][1] = 0.0;
    }
    fftw_execute(backward_);  // unnormalised: multiply by 1/len
    const double inv = 1.0 / static_cast<double>(len_);
    for (std::size_t lag = 0; lag < acc.size(); ++lag) acc[lag] += in[lag] * inv;
  }

 private:
  std::size_t frames_, len_;
  std::unique_ptr<double, FftwFree> in_;
  std::unique_ptr<fftw_complex, FftwFree> out_;
  fftw_plan forward_ = nullptr, backward_ = nullptr;
  static std::mutex& planner_mutex() { return detail::fftw_planner_mutex(); }
};

// Channel c = i * dim + k of the series, gathered into a contiguous array.
void gather(const std::vector<double>& data, std::size_t frames, std::size_t channels,
            std::size_t c, std::vector<double>& x) {
  for (std::size_t t = 0; t < frames; ++t) x[t] = data[t * channels + c];
}
}  // namespace

std::vector<double> vacf(const std::vector<double>& v, std::size_t frames, std::size_t n, int dim,
                         std::size_t max_lag) {
  check_series(v, frames, n, dim, max_lag, "vacf");
  const std::size_t channels = n * static_cast<std::size_t>(dim);
  std::vector<double> acc(max_lag + 1, 0.0), x(frames);
  Correlator corr(frames);
  for (std::size_t c = 0; c < channels; ++c) {
    gather(v, frames, channels, c, x);
    corr.accumulate(x.data(), acc);
  }
  for (std::size_t lag = 0; lag <= max_lag; ++lag)
    acc[lag] /= static_cast<double>(n) * static_cast<double>(frames - lag);
  return acc;
}

std::vector<double> msd(const std::vector<double>& r, std::size_t frames, std::size_t n, int dim,
                        std::size_t max_lag) {
  check_series(r, frames, n, dim, max_lag, "msd");
  // sum_t0 (x(t0+m) - x(t0))^2 = S(m) - 2 R(m) with S(m) = sum_{t<L-m} x(t)^2 +
  // sum_{t>=m} x(t)^2 (prefix sums) and R the autocorrelation sum. Each channel is shifted
  // by its mean first (MSD is shift-invariant) so that the subtraction loses little.
  const std::size_t channels = n * static_cast<std::size_t>(dim);
  std::vector<double> acc(max_lag + 1, 0.0), corr_acc(max_lag + 1), x(frames), pre(frames + 1);
  Correlator corr(frames);
  for (std::size_t c = 0; c < channels; ++c) {
    gather(r, frames, channels, c, x);
    double mean = 0.0;
    for (double xi : x) mean += xi;
    mean /= static_cast<double>(frames);
    for (double& xi : x) xi -= mean;
    pre[0] = 0.0;
    for (std::size_t t = 0; t < frames; ++t) pre[t + 1] = pre[t] + x[t] * x[t];
    std::fill(corr_acc.begin(), corr_acc.end(), 0.0);
    corr.accumulate(x.data(), corr_acc);
    for (std::size_t m = 0; m <= max_lag; ++m)
      acc[m] += pre[frames - m] + (pre[frames] - pre[m]) - 2.0 * corr_acc[m];
  }
  for (std::size_t m = 0; m <= max_lag; ++m)
    acc[m] = std::max(acc[m], 0.0) / (static_cast<double>(n) * static_cast<double>(frames - m));
  acc[0] = 0.0;
  return acc;
}

double green_kubo_diffusion(const std::vector<double>& c, double dt, int dim, std::size_t max_lag) {
  if (dim < 1 || !(dt > 0.0) || max_lag >= c.size())
    throw InvalidInput("green_kubo_diffusion: need dim >= 1, dt > 0 and max_lag < vacf size");
  double s = 0.5 * (c[0] + c[max_lag]);
  for (std::size_t i = 1; i < max_lag; ++i) s += c[i];
  return max_lag == 0 ? 0.0 : s * dt / dim;
}

Estimate msd_diffusion(const std::vector<double>& m, double dt, int dim, std::size_t lag_lo,
                       std::size_t lag_hi) {
  if (dim < 1 || !(dt > 0.0) || lag_hi >= m.size() || lag_hi < lag_lo + 2)
    throw InvalidInput("msd_diffusion: need dim >= 1, dt > 0, lag_lo + 2 <= lag_hi < msd size");
  const std::size_t k = lag_hi - lag_lo + 1;
  std::vector<double> t(k);
  for (std::size_t i = 0; i < k; ++i) t[i] = static_cast<double>(lag_lo + i) * dt;
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(t.data(), 1, m.data() + lag_lo, 1, k, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return {c1 / (2.0 * dim), std::sqrt(cov11) / (2.0 * dim)};
}

}  // namespace hypergas::analysis
