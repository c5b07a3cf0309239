// MultiTauCorrelator: the blocking scheme of multi_tau.hpp.
#include "hypergas/analysis/multi_tau.hpp"

#include <limits>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
// The largest grid lag (p-1) m^(levels-1) must stay below this (no overflow in lag()).
constexpr std::uint64_t lag_limit = std::uint64_t{1} << 62;

// (p-1) m^(levels-1), or 0 if it exceeds lag_limit.
std::uint64_t grid_max_lag(std::uint64_t p, std::uint64_t m, std::uint64_t levels) {
  std::uint64_t lag = p - 1;
  for (std::uint64_t l = 1; l < levels; ++l) {
    if (lag > lag_limit / m) return 0;
    lag *= m;
  }
  return lag;
}
}  // namespace

MultiTauCorrelator::MultiTauCorrelator(Kind kind, std::size_t channels, int dim, std::size_t p,
                                       std::size_t m, std::size_t levels, std::size_t groups)
    : kind_(kind), channels_(channels), dim_(dim), p_(p), m_(m), levels_(levels),
      groups_(groups) {
  if (channels < 1 || dim < 1)
    throw InvalidInput("MultiTauCorrelator: need >= 1 channel and dimension >= 1");
  if (groups < 1 || groups > channels)
    throw InvalidInput("MultiTauCorrelator: need 1 <= groups <= channels (groups " +
                       std::to_string(groups) + ", channels " + std::to_string(channels) + ")");
  if (m < 2 || p < m || p % m != 0)
    throw InvalidInput("MultiTauCorrelator: need m >= 2 and p a multiple of m (p " +
                       std::to_string(p) + ", m " + std::to_string(m) + ")");
  if (levels == 0) {
    levels_ = 1;
    while (grid_max_lag(p_, m_, levels_) < auto_max_lag) ++levels_;
  } else if (grid_max_lag(p_, m_, levels_) == 0) {
    throw InvalidInput("MultiTauCorrelator: " + std::to_string(levels) +
                       " levels exceed the largest representable lag");
  }
  const auto nl = static_cast<std::size_t>(levels_);
  ring_.reserve(nl);
  if (kind_ == Kind::correlation) block_.reserve(nl);
  head_.assign(nl, 0);
  filled_.assign(nl, 0);
  block_count_.assign(nl, 0);
  sum_.assign(nl * p * groups, 0.0);
  count_.assign(nl * p, 0);
}

std::size_t MultiTauCorrelator::max_lag() const {
  return levels_ == 0 ? 0 : static_cast<std::size_t>(grid_max_lag(p_, m_, levels_));
}

void MultiTauCorrelator::add_level() {
  ring_.emplace_back(static_cast<std::size_t>(p_) * width(), 0.0);
  if (kind_ == Kind::correlation) block_.emplace_back(width(), 0.0);
}

void MultiTauCorrelator::add(const double* x, std::size_t stride) {
  if (channels_ == 0) throw InvalidInput("MultiTauCorrelator: add() on an empty correlator");
  if (stride < static_cast<std::size_t>(dim_))
    throw InvalidInput("MultiTauCorrelator: stride " + std::to_string(stride) + " < dimension " +
                       std::to_string(dim_));
  if (ring_.empty()) add_level();
  store(0, x, stride);
  ++samples_;
}

void MultiTauCorrelator::store(std::size_t level, const double* x, std::size_t stride) {
  const std::size_t w = width(), p = static_cast<std::size_t>(p_);
  const auto dim = static_cast<std::size_t>(dim_);
  const bool corr = kind_ == Kind::correlation;
  for (std::size_t l = level; l < static_cast<std::size_t>(levels_); ++l) {
    // The new value goes into the slot after the newest (the oldest when the ring is full).
    std::vector<double>& ring = ring_[l];
    const std::size_t head = filled_[l] == 0 ? 0 : (static_cast<std::size_t>(head_[l]) + 1) % p;
    double* a = ring.data() + head * w;
    for (std::size_t c = 0; c < channels_; ++c)
      for (std::size_t k = 0; k < dim; ++k) a[c * dim + k] = x[c * stride + k];
    head_[l] = head;
    if (filled_[l] < p_) ++filled_[l];

    // Pairs (a(t - j), a(t)): j from 0 on level 0, from p/m on coarser levels.
    const std::size_t j0 = l == 0 ? 0 : p / static_cast<std::size_t>(m_);
    const auto filled = static_cast<std::size_t>(filled_[l]);
    const auto G = static_cast<std::size_t>(groups_);
    for (std::size_t j = j0; j < filled; ++j) {
      const double* b = ring.data() + ((head + p - j) % p) * w;
      for (std::size_t g = 0; g < G; ++g) {
        const std::size_t i0 = group_begin(g) * dim, i1 = group_begin(g + 1) * dim;
        double s = 0.0;
        if (corr) {
          for (std::size_t i = i0; i < i1; ++i) s += a[i] * b[i];
        } else {
          for (std::size_t i = i0; i < i1; ++i) {
            const double d = a[i] - b[i];
            s += d * d;
          }
        }
        sum_[(l * p + j) * G + g] += s;
      }
      ++count_[l * p + j];
    }

    // Coarsening: a block of m values of level l becomes one value of level l+1.
    if (l + 1 == static_cast<std::size_t>(levels_)) return;
    if (corr) {
      double* blk = block_[l].data();
      if (block_count_[l] == 0)
        for (std::size_t i = 0; i < w; ++i) blk[i] = a[i];
      else
        for (std::size_t i = 0; i < w; ++i) blk[i] += a[i];
    }
    if (++block_count_[l] < m_) return;
    block_count_[l] = 0;
    if (l + 1 == ring_.size()) add_level();  // before taking pointers into level l's buffers
    if (corr) {
      double* blk = block_[l].data();  // the block's average; overwritten by the next block
      for (std::size_t i = 0; i < w; ++i) blk[i] /= static_cast<double>(m_);
      x = blk;
    } else {
      x = ring_[l].data() + head * w;  // the block's last value (decimation)
    }
    stride = dim;
  }
}

MultiTauCurve MultiTauCorrelator::curve(std::size_t max_lag) const {
  return values(max_lag, 0, static_cast<std::size_t>(groups_));
}

MultiTauCurve MultiTauCorrelator::group_curve(std::size_t g, std::size_t max_lag) const {
  if (g >= groups_) throw InvalidInput("MultiTauCorrelator: no group " + std::to_string(g));
  return values(max_lag, g, g + 1);
}

MultiTauCurve MultiTauCorrelator::values(std::size_t max_lag, std::size_t g0,
                                         std::size_t g1) const {
  MultiTauCurve out;
  const std::size_t p = static_cast<std::size_t>(p_);
  const auto G = static_cast<std::size_t>(groups_);
  const auto channels = static_cast<double>(group_begin(g1) - group_begin(g0));
  std::uint64_t scale = 1;  // m^l
  for (std::size_t l = 0; l < ring_.size(); ++l, scale *= m_) {
    for (std::size_t j = l == 0 ? 0 : p / static_cast<std::size_t>(m_); j < p; ++j) {
      const std::uint64_t lag = j * scale;
      if (lag > max_lag) return out;
      const std::uint64_t n = count_[l * p + j];
      if (n == 0) continue;
      out.lag.push_back(static_cast<std::size_t>(lag));
      out.origins.push_back(static_cast<std::size_t>(n));
      double s = 0.0;
      for (std::size_t g = g0; g < g1; ++g) s += sum_[(l * p + j) * G + g];
      out.value.push_back(s / (static_cast<double>(n) * channels));
    }
  }
  return out;
}

std::size_t MultiTauCorrelator::bytes() const {
  std::size_t b =
      (head_.capacity() + filled_.capacity() + block_count_.capacity() + count_.capacity()) *
          sizeof(std::uint64_t) +
      sum_.capacity() * sizeof(double);
  for (const auto& r : ring_) b += r.capacity() * sizeof(double);
  for (const auto& r : block_) b += r.capacity() * sizeof(double);
  return b;
}

std::size_t MultiTauCorrelator::max_bytes() const {
  const auto nl = static_cast<std::size_t>(levels_), p = static_cast<std::size_t>(p_);
  const std::size_t values = width() * (p + (kind_ == Kind::correlation ? 1 : 0));
  return nl * (values + (static_cast<std::size_t>(groups_) + 1) * p + 3) * sizeof(double);
}

void MultiTauCorrelator::check_state() const {
  const auto bad = [](const char* what) {
    throw InvalidInput(std::string("MultiTauCorrelator: inconsistent saved state (") + what + ")");
  };
  if (kind_ != Kind::correlation && kind_ != Kind::displacement) bad("kind");
  if (channels_ == 0) {
    if (levels_ != 0 || samples_ != 0 || !ring_.empty() || !block_.empty() || !head_.empty() ||
        !filled_.empty() || !block_count_.empty() || !sum_.empty() || !count_.empty())
      bad("empty correlator with data");
    return;
  }
  if (dim_ < 1 || m_ < 2 || p_ < m_ || p_ % m_ != 0 || levels_ < 1 ||
      grid_max_lag(p_, m_, levels_) == 0 ||
      channels_ > std::numeric_limits<std::size_t>::max() / static_cast<std::uint64_t>(dim_) / p_)
    bad("parameters");
  const auto nl = static_cast<std::size_t>(levels_), p = static_cast<std::size_t>(p_);
  if (ring_.size() > nl || block_.size() != (kind_ == Kind::correlation ? ring_.size() : 0))
    bad("levels");
  if (ring_.empty() && samples_ != 0) bad("levels");
  if (head_.size() != nl || filled_.size() != nl || block_count_.size() != nl ||
      groups_ < 1 || groups_ > channels_ || sum_.size() != nl * p * groups_ ||
      count_.size() != nl * p)
    bad("bookkeeping sizes");
  for (const auto& r : ring_)
    if (r.size() != p * width()) bad("ring size");
  for (const auto& b : block_)
    if (b.size() != width()) bad("block size");
  for (std::size_t l = 0; l < nl; ++l)
    if (head_[l] >= p_ || filled_[l] > p_ || block_count_[l] >= m_ ||
        (l >= ring_.size() && (filled_[l] != 0 || block_count_[l] != 0)))
      bad("ring positions");
}

}  // namespace hypergas::analysis
