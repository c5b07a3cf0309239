// analysis/src/pressure_tensor_recorder.cpp -- see pressure_tensor_recorder.hpp.
#include "hypergas/analysis/pressure_tensor_recorder.hpp"

#include <algorithm>
#include <cmath>
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
  std::vector<double> row{s.time, std::isnan(s.real_time) ? s.time : s.real_time, t_ratio,
                          rate_ * std::pow(t_ratio, -0.5 * exponent_)};
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
