// VacfRecorder: stores frames, computes VACF / MSD with vacf.hpp, writes vacf.csv.
#include "hypergas/analysis/vacf_recorder.hpp"

#include <cmath>

#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

VacfRecorder::VacfRecorder(std::size_t max_particles) : max_particles_(max_particles) {
  if (max_particles < 1) throw InvalidInput("VacfRecorder: max_particles must be >= 1");
}

void VacfRecorder::observe(const Snapshot& s) {
  validate(s);
  const std::size_t n = std::min(s.n, max_particles_);
  if (frames_ == 0) {
    if (n == 0) throw InvalidInput("VacfRecorder: snapshot without particles");
    n_ = n;
    dim_ = s.dim;
    t0_ = s.time;
  } else {
    if (n != n_ || s.dim != dim_ || (s.positions != nullptr) != has_positions())
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
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < s.dim; ++k) {
      velocities_.push_back(s.velocities[i * stride + k]);
      if (s.positions) positions_.push_back(s.positions[i * stride + k]);
    }
  ++frames_;
}

std::size_t VacfRecorder::default_lag(std::size_t max_lag) const {
  if (frames_ < 2) throw InvalidInput("VacfRecorder: need at least two frames");
  if (max_lag == 0) return frames_ / 2;
  if (max_lag >= frames_)
    throw InvalidInput("VacfRecorder: max_lag " + std::to_string(max_lag) + " >= frames " +
                       std::to_string(frames_));
  return max_lag;
}

std::vector<double> VacfRecorder::vacf(std::size_t max_lag) const {
  return analysis::vacf(velocities_, frames_, n_, dim_, default_lag(max_lag));
}

std::vector<double> VacfRecorder::msd(std::size_t max_lag) const {
  if (!has_positions()) throw InvalidInput("VacfRecorder: no positions were recorded");
  return analysis::msd(positions_, frames_, n_, dim_, default_lag(max_lag));
}

double VacfRecorder::green_kubo(std::size_t max_lag) const {
  const std::size_t lag = default_lag(max_lag);
  return green_kubo_diffusion(vacf(lag), dt_, dim_, lag);
}

void VacfRecorder::write_csv(const std::string& path, std::size_t max_lag) const {
  const std::size_t lag = default_lag(max_lag);
  const std::vector<double> c = vacf(lag);
  const std::vector<double> m = has_positions() ? msd(lag) : std::vector<double>{};
  std::vector<std::vector<double>> rows;
  rows.reserve(lag + 1);
  for (std::size_t l = 0; l <= lag; ++l) {
    std::vector<double> row = {static_cast<double>(l), c[l], static_cast<double>(l) * dt_};
    if (!m.empty()) row.push_back(m[l]);
    rows.push_back(std::move(row));
  }
  std::vector<std::string> columns = {"lag", "vacf", "time"};
  if (!m.empty()) columns.push_back("msd");
  analysis::write_csv(path, columns, rows);
}

}  // namespace hypergas::analysis
