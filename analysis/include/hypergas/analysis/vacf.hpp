// hypergas/analysis/vacf.hpp -- velocity autocorrelation, mean squared displacement, and the
// self-diffusion coefficient from each (Green–Kubo and Einstein).
//
// Input is a time series of `frames` equally spaced frames of n particles in D dimensions,
// frame f, particle i, component k at data[(f * n + i) * dim + k]. Averages run over all
// particles and all time origins t0 = 0 .. frames-1-lag:
//   vacf(lag) = < v(t0) . v(t0 + lag) >,   msd(lag) = < |r(t0 + lag) - r(t0)|^2 >.
// By FFT (FFTW, real-to-complex, zero-padded to >= 2 frames so that the circular
// correlation equals the linear one; Wiener–Khinchin): O(n D L log L). The tests check them
// against the direct double sums (tests/support/correlation.hpp). All are thread-safe.
#pragma once

#include <cstddef>
#include <vector>

#include "hypergas/analysis/moments.hpp"

namespace hypergas::analysis {

/// VACF for lags 0 .. max_lag (max_lag < frames), by FFT. velocity^2.
std::vector<double> vacf(const std::vector<double>& velocities, std::size_t frames, std::size_t n,
                         int dim, std::size_t max_lag);

/// MSD for lags 0 .. max_lag from unwrapped positions, by FFT. length^2.
std::vector<double> msd(const std::vector<double>& positions, std::size_t frames, std::size_t n,
                        int dim, std::size_t max_lag);

/// Green–Kubo self-diffusion coefficient (1/D) integral_0^(max_lag dt) vacf(t) dt by the
/// trapezoid rule; dt is the frame spacing (time). length^2 / time.
double green_kubo_diffusion(const std::vector<double>& vacf, double dt, int dim,
                            std::size_t max_lag);

/// Einstein self-diffusion coefficient slope / (2 D) of an unweighted least-squares line
/// through msd(lag dt) for lag_lo <= lag <= lag_hi (gsl_fit_linear), with the line's
/// standard error (which ignores the correlation between lags). length^2 / time.
Estimate msd_diffusion(const std::vector<double>& msd, double dt, int dim, std::size_t lag_lo,
                       std::size_t lag_hi);

}  // namespace hypergas::analysis
