// sim/run_summary.hpp -- summary.json of a run: the keys every engine run has, written in
// one place, and how the commands read keys back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hypergas/analysis/output.hpp"
#include "options.hpp"
#include "run_driver.hpp"

namespace hypergas::cli {

/// What every engine run reports besides its options.
struct RunFacts {
  int dim = 0;
  std::string model;                ///< the collision model ("hs" for EDMD)
  std::int64_t collisions = 0;      ///< all replicas together
  double wall_s = 0.0;              ///< wall time of the run, set-up included
  double collisions_per_s = 0.0;    ///< per second in the engine (replicas: summed)
  double energy_rel_drift = 0.0;    ///< NaN for a granular gas (no energy to conserve)
  double momentum_drift = 0.0;
  double time = 0.0;                ///< engine time at the end
  double every = 0.0;               ///< the sampling interval
  double fraction = 0.0;            ///< fraction of species 2 (0: one species)
  double engine_bytes_per_particle = 0.0;
  double setup_s = 0.0;             ///< wall time before the first collision (start, set-up)
};

/// The summary of a run: the contract's keys (dim, engine, model, n, seed, collisions,
/// wall_s, collisions_per_s, energy_rel_drift, momentum_drift), the run's description
/// (init: "file" for a run from --init-file, which adds init_file, init_frame and
/// init_checksum; time, every, mass_ratio, fraction), the engine's own keys `engine_keys`, the
/// process measures of `st` (engine_s, analysis_s, engine_bytes_per_particle,
/// peak_rss_bytes_per_particle, checkpoints, resumes). The outputs' keys follow.
analysis::JsonObject run_summary(const RunOptions& o, const RunFacts& f,
                                 const analysis::JsonObject& engine_keys, const DriverState& st);

/// The value of `key` in `o` as text (doubles with 4 significant digits); "-" if absent.
std::string summary_field(const analysis::JsonObject& o, const std::string& key);
/// The value of `key` in `o` as a double (NaN if absent or not a number).
double summary_number(const analysis::JsonObject& o, const std::string& key);

}  // namespace hypergas::cli
