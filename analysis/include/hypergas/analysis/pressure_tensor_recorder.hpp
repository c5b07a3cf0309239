// hypergas/analysis/pressure_tensor_recorder.hpp -- the pressure tensor of a sheared gas, one
// row per snapshot: the rows of the command's pressure_tensor.csv (sim/outputs/shear.cpp)
// and of Python's PressureTensorRecorder.
//
// Columns: time, real_time (the snapshot's, or time where the clock is not rescaled),
// temperature_ratio T/T0 (T0 that of the first snapshot; true temperatures, with the
// snapshot's velocity scale), reduced_shear_rate a (T/T0)^(-a_m/2) (a per mean collision
// time at T0, a_m the collision model's rate exponent), then P_ij / p for i <= j, each
// followed by its standard error over the particles (P_xx, P_xx_err, P_xy, P_xy_err, ...;
// axes x, y, z, u, v, w). P = sum m v v^T / (N - 1), p = tr P / D.
//
// A sheared EDMD gas (Snapshot::stress_integral set) gives the exact pressure tensor,
// kinetic and collisional, averaged over the interval since the previous snapshot (the
// first row: the kinetic part at that instant); its `_err` columns are NaN, written empty
// (the summary's block errors are the errors); T is the kinetic temperature averaged over
// the same interval and T0 the engine's Snapshot::shear_kT0.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hypergas/observer.hpp"

namespace hypergas::analysis {

class PressureTensorRecorder final : public Observer {
 public:
  /// For D = dim (2..6), shear rate a (0: a gas at rest) and rate exponent a_m (hard
  /// spheres 1, Maxwell molecules 0, VHS its exponent). Throws InvalidInput otherwise.
  PressureTensorRecorder(int dim, double shear_rate, double exponent);

  void observe(const Snapshot& s) override;

  std::vector<std::string> columns() const;
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// The column of P_ab / p (a <= b, axes 0 .. D - 1); its error is the next column.
  std::size_t column(int a, int b) const;
  int dim() const { return dim_; }

  template <class Archive>
  void io(Archive& ar) {
    ar.tag("pressure-tensor");
    ar(have_t0_, ln_t0_, rows_, have_prev_, prev_time_, prev_);
  }

 private:
  int dim_;
  double rate_, exponent_;
  void observe_integral(const Snapshot& s);
  /// A row's first four columns: time, real_time, temperature_ratio, reduced_shear_rate.
  std::vector<double> row_head(const Snapshot& s, double t_ratio) const;

  bool have_t0_ = false;
  bool have_prev_ = false;    // EDMD: the stress integral of the previous snapshot
  double prev_time_ = 0.0;
  std::vector<double> prev_;
  double ln_t0_ = 0.0;
  std::vector<std::vector<double>> rows_;
};

}  // namespace hypergas::analysis
