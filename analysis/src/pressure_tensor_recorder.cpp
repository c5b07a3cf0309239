// analysis/src/pressure_tensor_recorder.cpp -- see pressure_tensor_recorder.hpp.
#include "hypergas/analysis/pressure_tensor_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
constexpr const char* axes = "xyzuvw";
}

PressureTensorRecorder::PressureTensorRecorder(int dim, double shear_rate, double exponent)
    : dim_(dim), rate_(shear_rate), exponent_(exponent) {
  if (dim < 2 || dim > 6)
    throw InvalidInput("pressure tensor: dim must be in 2..6, got " + std::to_string(dim));
  if (!(std::isfinite(shear_rate) && shear_rate >= 0.0))
    throw InvalidInput("pressure tensor: shear_rate must be finite and >= 0");
  if (!(exponent >= 0.0 && exponent <= 1.0))
    throw InvalidInput("pressure tensor: the rate exponent must be in [0, 1]");
}

void PressureTensorRecorder::observe(const Snapshot& s) {
  const int D = s.dim;
  if (D != dim_)
    throw InvalidInput("pressure tensor: a snapshot of D = " + std::to_string(D) +
                       " for a recorder of D = " + std::to_string(dim_));
  if (s.stress_integral) {
    observe_integral(s);
    return;
  }
  const std::size_t n = s.n;
  std::vector<double> sum(D * D, 0.0), sq(D * D, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = s.velocities + i * s.stride;
    const double m = 1.0 / s.inverse_mass(i);
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) {
        const double x = m * v[a] * v[b];
        sum[a * D + b] += x;
        sq[a * D + b] += x * x;
      }
  }
  double tr = 0.0;
  for (int a = 0; a < D; ++a) tr += sum[a * D + a];
  const double nm1 = static_cast<double>(n) - 1.0;
  const double kT = tr / (D * nm1);  // of the stored velocities
  const double ln_t = std::log(kT) + 2.0 * s.log_velocity_scale;
  if (!have_t0_) {
    ln_t0_ = ln_t;
    have_t0_ = true;
  }
  const double t_ratio = std::exp(ln_t - ln_t0_);
  std::vector<double> row = row_head(s, t_ratio);
  const double nn = static_cast<double>(n);
  for (int a = 0; a < D; ++a)
    for (int b = a; b < D; ++b) {
      const double mean = sum[a * D + b] / nn;
      const double var = std::max(0.0, sq[a * D + b] / nn - mean * mean);
      row.push_back(sum[a * D + b] / nm1 / kT);
      row.push_back(std::sqrt(var * nn) / nm1 / kT);
    }
  rows_.push_back(std::move(row));
}

std::vector<double> PressureTensorRecorder::row_head(const Snapshot& s, double t_ratio) const {
  return {s.time, std::isnan(s.real_time) ? s.time : s.real_time, t_ratio,
          rate_ * std::pow(t_ratio, -0.5 * exponent_)};
}

void PressureTensorRecorder::observe_integral(const Snapshot& s) {
  const int D = dim_;
  const std::size_t dd = static_cast<std::size_t>(D * D);
  std::vector<double> P(dd);
  // prev_: the stress integral, then the kinetic integral, at the previous snapshot
  std::vector<double> S(s.stress_integral, s.stress_integral + dd);
  S.insert(S.end(), s.kinetic_integral, s.kinetic_integral + dd);
  const bool interval = have_prev_ && s.time > prev_time_;
  const double dt = s.time - prev_time_;
  for (std::size_t q = 0; q < dd; ++q)
    P[q] = interval ? (S[q] - prev_[q]) / dt : s.kinetic_stress[q];
  double trk = 0.0;  // the kinetic temperature: mean over the interval, or at the instant
  for (int a = 0; a < D; ++a) {
    const std::size_t q = static_cast<std::size_t>(a * D + a);
    trk += interval ? (S[dd + q] - prev_[dd + q]) / dt : s.kinetic_stress[q];
  }
  prev_ = std::move(S);
  prev_time_ = s.time;
  have_prev_ = true;
  const double kT = trk / (D * static_cast<double>(s.n));
  if (!have_t0_) {
    ln_t0_ = std::log(std::isfinite(s.shear_kT0) ? s.shear_kT0 : kT);
    have_t0_ = true;
  }
  const double t_ratio = std::exp(std::log(kT) - ln_t0_);
  std::vector<double> row = row_head(s, t_ratio);
  double tr = 0.0;
  for (int a = 0; a < D; ++a) tr += P[a * D + a];
  const double p = tr / D;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (int a = 0; a < D; ++a)
    for (int b = a; b < D; ++b) {
      row.push_back(0.5 * (P[a * D + b] + P[b * D + a]) / p);
      row.push_back(nan);
    }
  rows_.push_back(std::move(row));
}

std::vector<std::string> PressureTensorRecorder::columns() const {
  std::vector<std::string> c{"time", "real_time", "temperature_ratio", "reduced_shear_rate"};
  for (int a = 0; a < dim_; ++a)
    for (int b = a; b < dim_; ++b) {
      const std::string k = std::string("P_") + axes[a] + axes[b];
      c.push_back(k);
      c.push_back(k + "_err");
    }
  return c;
}

std::size_t PressureTensorRecorder::column(int a, int b) const {
  std::size_t c = 4;
  for (int i = 0; i < dim_; ++i)
    for (int j = i; j < dim_; ++j) {
      if (i == a && j == b) return c;
      c += 2;
    }
  throw InvalidInput("pressure tensor: no component (" + std::to_string(a) + ", " +
                     std::to_string(b) + ")");
}

}  // namespace hypergas::analysis
