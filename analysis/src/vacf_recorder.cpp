// VacfRecorder: feeds frames to multiple-tau correlators, reports VACF / MSD, writes vacf.csv.
#include "hypergas/analysis/vacf_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/error.hpp"

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
    velocity_ = MultiTauCorrelator(MultiTauCorrelator::Kind::correlation, n, s.dim, p, m, levels);
    if (positions)
      position_ =
          MultiTauCorrelator(MultiTauCorrelator::Kind::displacement, n, s.dim, p, m, levels);
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
