// sim/granular_summary.hpp -- the summary keys of a granular run (restitution < 1): the
// cumulants of the scaled state, the cooling rate per collision and Haff's t0, each beside
// its first Sonine value (granular/theory.hpp).
#pragma once

#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"

namespace hypergas::cli {

/// What the granular keys need to know of the run.
struct GranularRun {
  int dim = 3;
  double restitution = 1.0;
  bool driven = false;     ///< DSMC white-noise drive (a steady state)
  bool hard_spheres = true;  ///< the Sonine values are those of hard spheres
};

/// Appends the granular keys to `summary` from the rows of `m` (columns a2, a3, T,
/// real_time, collisions_per_particle). The averages use the second half of the rows (the
/// scaled state has relaxed there) in 8 consecutive blocks; errors are the standard errors
/// of the block values. Keys (NaN, written null, where fewer than 16 rows exist):
///   restitution, temperature_ratio (last T / first T),
///   a2_mean, a2_error, a3_mean, a3_error, a2_sonine (HCS or driven, hard spheres),
///   cooling_per_collision(_error): -d ln T / d(collisions per particle), and its Sonine
///     value cooling_per_collision_sonine (zeta / collision frequency, at a2_sonine);
///   HCS only: haff_t0(_error): 1 / (sqrt(T_first) d T^(-1/2) / d real_time), real_time's
///     unit, and (DSMC) haff_t0_sonine = 2 / zeta(T_first);
///   driven only: temperature_ratio_mean(_error): <T> / T_first over the second half.
///   tail_slope: A of ln(f(c) / c^(D-1)) = b - A c fitted over the last speed histogram's
///     bins with c = v / v_T >= 2 and at least 20 counts (an exponential tail exp(-A c) has
///     a constant A), and tail_slope_maxwell: the same fit to the Maxwellian on those bins
///     (its A grows with c as c + ...: a smaller measured A is an overpopulated tail).
void add_granular_summary(analysis::JsonObject& summary, const analysis::MomentsRecorder& m,
                          const GranularRun& run, bool dsmc_time_unit);

}  // namespace hypergas::cli
