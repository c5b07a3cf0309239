// VacfRecorder: feeds frames to multiple-tau correlators, reports VACF / MSD, writes vacf.csv.
#include "hypergas/analysis/vacf_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/error.hpp"
#include "integrals.hpp"

namespace hypergas::analysis {

VacfRecorder::VacfRecorder(std::size_t max_particles, std::size_t p, std::size_t m,
                           std::size_t levels)
    : max_particles_(max_particles), p_(p), m_(m), levels_(levels) {
  if (max_particles < 1) throw InvalidInput("VacfRecorder: max_particles must be >= 1");
  // Checks p, m and levels now rather than at the first frame.
  (void)MultiTauCorrelator(MultiTauCorrelator::Kind::correlation, 1, 1, p, m, levels);
}

void VacfRecorder::observe(const Snapshot& s) {
  validate(s);
  const std::size_t n = std::min<std::size_t>(s.n, max_particles_);
  const bool positions = s.positions != nullptr;
  if (frames_ == 0) {
    if (n == 0) throw InvalidInput("VacfRecorder: snapshot without particles");
    const auto p = static_cast<std::size_t>(p_), m = static_cast<std::size_t>(m_),
               levels = static_cast<std::size_t>(levels_);
    const std::size_t g = std::min(groups, n);
    velocity_ =
        MultiTauCorrelator(MultiTauCorrelator::Kind::correlation, n, s.dim, p, m, levels, g);
    if (positions)
      position_ =
          MultiTauCorrelator(MultiTauCorrelator::Kind::displacement, n, s.dim, p, m, levels, g);
    n_ = n;
    dim_ = s.dim;
    has_positions_ = positions;
    t0_ = s.time;
  } else {
    if (n != n_ || s.dim != dim_ || positions != has_positions_)
      throw InvalidInput("VacfRecorder: the particles, dimension or positions changed");
    const double step = s.time - t_last_;
    if (frames_ == 1) {
      if (!(step > 0.0)) throw InvalidInput("VacfRecorder: snapshot times must increase");
      dt_ = step;
    } else if (std::abs(step - dt_) > 1e-6 * dt_) {
      throw InvalidInput("VacfRecorder: snapshots must be equally spaced in time (spacing " +
                         std::to_string(step) + " after " + std::to_string(dt_) + ")");
    }
  }
  t_last_ = s.time;
  const auto stride = static_cast<std::size_t>(s.stride);
  velocity_.add(s.velocities, stride);
  if (positions) position_.add(s.positions, stride);
  ++frames_;
}

std::size_t VacfRecorder::default_lag(std::size_t max_lag) const {
  if (frames_ < 2) throw InvalidInput("VacfRecorder: need at least two frames");
  if (max_lag == 0) return static_cast<std::size_t>(frames_ / 2);
  if (max_lag >= frames_)
    throw InvalidInput("VacfRecorder: max_lag " + std::to_string(max_lag) + " >= frames " +
                       std::to_string(frames_));
  return max_lag;
}

MultiTauCurve VacfRecorder::curve(const MultiTauCorrelator& c, std::size_t max_lag) const {
  return c.curve(default_lag(max_lag));
}

std::vector<std::size_t> VacfRecorder::lags(std::size_t max_lag) const {
  return curve(velocity_, max_lag).lag;
}

std::vector<std::size_t> VacfRecorder::origins(std::size_t max_lag) const {
  return curve(velocity_, max_lag).origins;
}

std::vector<double> VacfRecorder::vacf(std::size_t max_lag) const {
  return curve(velocity_, max_lag).value;
}

std::vector<double> VacfRecorder::msd(std::size_t max_lag) const {
  if (!has_positions_) throw InvalidInput("VacfRecorder: no positions were recorded");
  return curve(position_, max_lag).value;
}

double VacfRecorder::green_kubo(std::size_t max_lag) const {
  const MultiTauCurve c = curve(velocity_, max_lag);
  double s = 0.0;
  for (std::size_t i = 1; i < c.lag.size(); ++i)
    s += 0.5 * (c.value[i - 1] + c.value[i]) * static_cast<double>(c.lag[i] - c.lag[i - 1]);
  return s * dt_ / dim_;
}

namespace {
/// A multiple-tau curve on the uniform grid of lags 0 .. last, linear between its lags.
std::vector<double> uniform(const MultiTauCurve& c) {
  std::vector<double> u(c.lag.back() + 1);
  for (std::size_t i = 0; i + 1 < c.lag.size(); ++i) {
    const std::size_t a = c.lag[i], b = c.lag[i + 1];
    for (std::size_t k = a; k < b; ++k)
      u[k] = c.value[i] + (c.value[i + 1] - c.value[i]) * static_cast<double>(k - a) /
                              static_cast<double>(b - a);
  }
  u.back() = c.value.back();
  return u;
}
}  // namespace

VacfRecorder::Diffusion VacfRecorder::diffusion(double mean_free_time) const {
  if (frames_ < 8) throw InvalidInput("VacfRecorder: diffusion() needs at least 8 frames");
  if (!has_positions_) throw InvalidInput("VacfRecorder: diffusion() needs positions");
  if (!(mean_free_time > 0.0 && std::isfinite(mean_free_time)))
    throw InvalidInput("VacfRecorder: diffusion() needs a finite mean free time > 0");
  const std::size_t L = default_lag(0);
  const double h = dt_;
  const double per_dim = 1.0 / static_cast<double>(dim_);
  // running integrals over D, the whole set and each group
  const auto over_dim = [&](std::vector<double> I) {
    for (double& x : I) x *= per_dim;
    return I;
  };
  const auto integral = [&](const std::vector<double>& c) {
    return over_dim(detail::running_integral(c, h));
  };
  const std::vector<double> c = uniform(velocity_.curve(L));
  const std::vector<double> I_time = detail::running_integral(c, h);  // int C dt
  const std::vector<double> I = over_dim(I_time);
  std::vector<std::vector<double>> Ij;
  std::vector<std::vector<double>> msd_j;
  for (std::size_t g = 0; g < velocity_.groups(); ++g) {
    Ij.push_back(integral(uniform(velocity_.group_curve(g, L))));
    msd_j.push_back(uniform(position_.group_curve(g, L)));
  }
  const std::size_t K = c.size() - 1;
  const auto k_least =
      static_cast<std::size_t>(std::max(1.0, std::round(5.0 * mean_free_time / h)));
  const std::size_t k0 =
      std::max(k_least, detail::auto_cut(c, I_time, h, 3.0));
  const detail::Plateau P = detail::plateau(I, Ij, k0, 2 * K / 3, dim_);
  Diffusion d;
  d.green_kubo = P.value;
  d.statistical_error = P.statistical_error;
  d.truncation_error = P.truncation_error;
  d.error = P.error;
  d.cut_time = static_cast<double>(P.cut) * h;
  d.reached = P.reached;
  // Einstein: the slope around the cut, each group's, with the Green-Kubo remainder
  const std::size_t a = std::max<std::size_t>(1, P.cut / 2), b = std::min(3 * P.cut / 2, K);
  if (b >= a + 2) {
    std::vector<double> e;
    for (const auto& m : msd_j) e.push_back(msd_diffusion(m, h, dim_, a, b).value + P.remainder);
    const MeanSe all = mean_se(e);
    d.einstein = msd_diffusion(uniform(position_.curve(L)), h, dim_, a, b).value + P.remainder;
    d.einstein_error = std::hypot(all.se, P.truncation_error);
  }
  return d;
}

void VacfRecorder::write_csv(const std::string& path, std::size_t max_lag) const {
  const MultiTauCurve c = curve(velocity_, max_lag);
  const std::vector<double> m = has_positions_ ? msd(max_lag) : std::vector<double>{};
  std::vector<std::vector<double>> rows;
  rows.reserve(c.lag.size());
  for (std::size_t i = 0; i < c.lag.size(); ++i) {
    const auto lag = static_cast<double>(c.lag[i]);
    std::vector<double> row = {lag, c.value[i], lag * dt_};
    if (!m.empty()) row.push_back(m[i]);
    rows.push_back(std::move(row));
  }
  std::vector<std::string> columns = {"lag", "vacf", "time"};
  if (!m.empty()) columns.push_back("msd");
  analysis::write_csv(path, columns, rows);
}

void VacfRecorder::check_state() const {
  const bool ok = max_particles_ >= 1 && (frames_ == 0 ? n_ == 0 && !has_positions_ : n_ >= 1) &&
                  n_ <= max_particles_ && velocity_.samples() == frames_ &&
                  position_.samples() == (has_positions_ ? frames_ : 0) &&
                  (frames_ == 0 ||
                   (velocity_.channels() == n_ && velocity_.dim() == dim_ &&
                    velocity_.points() == p_ && velocity_.factor() == m_ &&
                    (!has_positions_ || (position_.channels() == n_ && position_.dim() == dim_))));
  if (!ok) throw InvalidInput("VacfRecorder: inconsistent saved state");
}

}  // namespace hypergas::analysis
