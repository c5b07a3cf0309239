// Block FFT autocorrelations (correlator.hpp).
#include "hypergas/analysis/correlator.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <new>
#include <string>

#include "fftw_planner.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

/// FFTW buffers and plans of length 2K (real to half-complex and back).
struct BlockCorrelator::Fft {
  std::size_t len;
  double* in = nullptr;
  fftw_complex* out = nullptr;
  fftw_complex* spec_a = nullptr;
  std::vector<fftw_complex*> acc;  // per group: summed cross spectra
  fftw_plan forward = nullptr, backward = nullptr;

  Fft(std::size_t n, int groups) : len(n) {
    const std::size_t h = n / 2 + 1;
    in = static_cast<double*>(fftw_malloc(sizeof(double) * n));
    out = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * h));
    spec_a = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * h));
    for (int g = 0; g < groups; ++g)
      acc.push_back(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * h)));
    bool ok = in && out && spec_a;
    for (auto* a : acc) ok = ok && a;
    if (ok) {
      std::lock_guard lock(detail::fftw_planner_mutex());
      forward = fftw_plan_dft_r2c_1d(static_cast<int>(n), in, out, FFTW_ESTIMATE);
      backward = fftw_plan_dft_c2r_1d(static_cast<int>(n), out, in, FFTW_ESTIMATE);
    }
    if (!ok || !forward || !backward) {
      release();
      throw std::bad_alloc();
    }
  }
  ~Fft() { release(); }
  Fft(const Fft&) = delete;
  Fft& operator=(const Fft&) = delete;
  void release() {
    {
      std::lock_guard lock(detail::fftw_planner_mutex());
      if (forward) fftw_destroy_plan(forward);
      if (backward) fftw_destroy_plan(backward);
      forward = backward = nullptr;
    }
    fftw_free(in);
    fftw_free(out);
    fftw_free(spec_a);
    for (auto* a : acc) fftw_free(a);
    in = nullptr, out = spec_a = nullptr;
    acc.clear();
  }
};

BlockCorrelator::BlockCorrelator(std::vector<int> group, std::size_t lags,
                                 std::uint64_t planned_frames, int error_blocks)
    : group_(std::move(group)), lags_(lags), planned_(planned_frames) {
  if (group_.empty()) throw InvalidInput("correlator: no series");
  if (lags_ < 2 || lags_ > (std::size_t{1} << 24))
    throw InvalidInput("correlator: lags must be in 2..2^24, got " + std::to_string(lags_));
  if (error_blocks < 2) throw InvalidInput("correlator: need at least 2 error blocks");
  for (int g : group_) {
    if (g < 0) throw InvalidInput("correlator: negative group");
    groups_ = std::max(groups_, g + 1);
  }
  members_.assign(std::size_t(groups_), 0);
  for (int g : group_) ++members_[std::size_t(g)];
  const std::uint64_t blocks = std::max<std::uint64_t>(1, (planned_ + lags_ - 1) / lags_);
  stretches_ = static_cast<int>(std::min<std::uint64_t>(std::uint64_t(error_blocks), blocks));
  blocks_per_stretch_ = blocks / std::uint64_t(stretches_);
  const std::size_t s = group_.size();
  prev_.assign(s * lags_, 0.0);
  cur_.assign(s * lags_, 0.0);
  sums_.assign(std::size_t(stretches_) * std::size_t(groups_) * lags_, 0.0);
  fft_ = std::make_unique<Fft>(2 * lags_, groups_);
}

BlockCorrelator::~BlockCorrelator() = default;
BlockCorrelator::BlockCorrelator(BlockCorrelator&&) noexcept = default;
BlockCorrelator& BlockCorrelator::operator=(BlockCorrelator&&) noexcept = default;

void BlockCorrelator::push(const double* x) {
  if (finished_) throw InvalidInput("correlator: push after finish");
  const std::size_t s = group_.size();
  for (std::size_t c = 0; c < s; ++c) cur_[c * lags_ + in_cur_] = x[c];
  ++in_cur_;
  ++frames_;
  if (in_cur_ == lags_) {
    if (have_prev_) correlate(frames_ - 2 * lags_, lags_, lags_);
    std::swap(prev_, cur_);
    have_prev_ = true;
    in_cur_ = 0;
  }
}

void BlockCorrelator::finish() {
  if (finished_) return;
  finished_ = true;
  if (have_prev_) correlate(frames_ - in_cur_ - lags_, lags_, in_cur_);
  if (in_cur_ > 0) {
    std::swap(prev_, cur_);
    correlate(frames_ - in_cur_, in_cur_, 0);
  }
}

// Correlates prev_ (n_a frames from first_frame on) with [prev_, cur_ (n_c frames)].
void BlockCorrelator::correlate(std::size_t first_frame, std::size_t n_a, std::size_t n_c) {
  Fft& f = *fft_;
  const std::size_t K = lags_, L = f.len, h = L / 2 + 1;
  for (auto* a : f.acc) std::memset(a, 0, sizeof(fftw_complex) * h);
  for (std::size_t c = 0; c < group_.size(); ++c) {
    const double* a = prev_.data() + c * K;
    const double* b = cur_.data() + c * K;
    std::fill(f.in, f.in + L, 0.0);
    std::copy(a, a + n_a, f.in);
    fftw_execute(f.forward);
    std::memcpy(f.spec_a, f.out, sizeof(fftw_complex) * h);
    std::copy(b, b + n_c, f.in + K);  // [a, b, zeros]
    fftw_execute(f.forward);
    fftw_complex* acc = f.acc[std::size_t(group_[c])];
    for (std::size_t k = 0; k < h; ++k) {  // conj(A) C
      const double ar = f.spec_a[k][0], ai = f.spec_a[k][1];
      const double cr = f.out[k][0], ci = f.out[k][1];
      acc[k][0] += ar * cr + ai * ci;
      acc[k][1] += ar * ci - ai * cr;
    }
  }
  const std::uint64_t block = first_frame / K;
  const int j = static_cast<int>(
      std::min<std::uint64_t>(block / blocks_per_stretch_, std::uint64_t(stretches_ - 1)));
  const double inv = 1.0 / static_cast<double>(L);
  for (int g = 0; g < groups_; ++g) {
    std::memcpy(f.out, f.acc[std::size_t(g)], sizeof(fftw_complex) * h);
    fftw_execute(f.backward);
    double* s = sums_.data() + (std::size_t(j) * std::size_t(groups_) + std::size_t(g)) * K;
    for (std::size_t k = 0; k < K; ++k) s[k] += f.in[k] * inv;
  }
  origins_.push_back({j, first_frame, n_a});
}

int BlockCorrelator::stretches() const {
  int used = 0;
  for (const auto& o : origins_) used = std::max(used, o.stretch + 1);
  return used;
}

std::vector<double> BlockCorrelator::stretch_mean(int g, int j) const {
  if (!finished_) throw InvalidInput("correlator: results before finish()");
  std::vector<double> c(lags_, 0.0), count(lags_, 0.0);
  for (const auto& o : origins_) {
    if (j >= 0 && o.stretch != j) continue;
    for (std::size_t k = 0; k < lags_; ++k) {  // origins n with n + k < frames
      const std::uint64_t end = frames_ > k ? frames_ - k : 0;
      const std::uint64_t hi = std::min(o.first + o.count, end);
      if (hi > o.first) count[k] += static_cast<double>(hi - o.first);
    }
  }
  for (int jj = 0; jj < stretches_; ++jj) {
    if (j >= 0 && jj != j) continue;
    const double* s = sums_.data() + (std::size_t(jj) * std::size_t(groups_) + std::size_t(g)) * lags_;
    for (std::size_t k = 0; k < lags_; ++k) c[k] += s[k];
  }
  const double m = members_[std::size_t(g)];
  for (std::size_t k = 0; k < lags_; ++k) c[k] = count[k] > 0 ? c[k] / (count[k] * m) : 0.0;
  return c;
}

std::vector<double> BlockCorrelator::mean(int g) const { return stretch_mean(g, -1); }

}  // namespace hypergas::analysis
