// hypergas/studies/throughput.hpp -- engine throughput, the code of `hypergas bench`,
// bench_dsmc and bench_edmd. Both print one JSON object per line on `out`.
//
// DSMC: for each D and N, a gas of the chosen model relaxing from the delta shell (after a
// warm-up of 0.5 mean collision times) is run for at least `min_collisions` accepted
// collisions, `reps` times; the median collisions/s is reported with the acceptance ratio,
// the bytes per particle and the ratio to a memory-bound probe run in the same process:
// random pair updates (load two records of the same stride, average-and-swap their
// components, store) over an array of the same size, with the same prefetching as the
// engine. With a list of thread counts each point is timed for every count (alternating
// within each repeat) and each line adds the speed-up over the first count, the parallel
// efficiency, the ceiling (that many independent one-thread engines started together, each
// on its own gas: their summed rate over one engine alone, what the machine allows any
// schedule of one system) and the speed-up over the ceiling, and the block schedule's
// per-thread phase ticks (dsmc/detail/phase_clock.hpp). Rates are per wall second; with `cpu_clock`, per CPU second of the thread for
// paired A/B runs of one thread on a shared machine. The JSON says which ("clock").
//
// EDMD: one case is a dimension, N, packing fraction and neighbour scan:
//   {"bench":"edmd","queue":"calendar","scan":"horizon","dim":3,"n":32000,"packing":0.26,
//    "repeat":0,"collisions":...,"wall_s":...,"cpu_s":...,"collisions_per_s":...,
//    "bytes_per_particle":...,"cells_per_side":...,"Z":...,"crossings_per_collision":...,
//    "stale_per_collision":...,"pairs_per_collision":...,"scans_per_collision":...}
// per repeat and, after the repeats, a line with "stat":"median". Setup (lattice,
// compression, equilibration of `warmup` collisions per particle) is not timed; the timed
// part is `collisions` collision events on one core. collisions_per_s is per CPU second of
// the running thread (wall_s is also printed; on a shared machine it is larger).
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/models.hpp"

namespace hypergas::studies {

/// What the DSMC throughput study measures.
struct DsmcBenchOptions {
  std::vector<int> dims = {1, 2, 3, 4, 5, 6};
  std::vector<std::size_t> ns = {10000, 1000000, 10000000};
  int reps = 3;                 ///< runs per point; the median is reported
  double min_collisions = 5e6;  ///< accepted collisions per timed run
  std::string model{dsmc::HardSpheres::name};  ///< collision model (registry::model_names())
  std::uint64_t seed = 1;
  std::vector<int> threads = {1};  ///< thread counts of the one system, each timed (1..256)
  std::vector<std::string> schemes = {"exact"};  ///< time schemes (registry::schemes), in turn
  std::uint32_t lane_size = 0;  ///< lanes scheme: particles per lane (0: the default)
  double epoch = dsmc::Config{}.epoch;  ///< lanes scheme: time between deals
  bool cpu_clock = false;  ///< rates per CPU second of the thread instead of per wall second
};

/// Runs the DSMC throughput study and prints one JSON line per (D, N, scheme, thread count)
/// to `out`. Fields: model, dim, n, reps, scheme (with lanes: lanes, lane_size, epoch),
/// vs_exact (the rate over the exact scheme's at that thread count, when it is timed), collisions_per_s (median accepted collisions per
/// second), candidates_per_s, acceptance, bytes_per_particle, probe_pair_updates_per_s,
/// probe_ratio (one core), threads, speedup (against the scheme's first thread count, scaled
/// by it), efficiency (speedup / threads), ceiling (summed rate of `threads` one-thread
/// engines of the scheme run at once over one alone), of_ceiling (speedup / ceiling), ticks_per_s (the phase
/// clock's rate), clock, and with a team "schedule": per thread, the ticks of each phase per
/// candidate of the system and the fraction of its candidates it deferred. Throws InvalidInput for an unknown model, a
/// dimension outside 1..6 or a thread count outside 1..256.
void run_dsmc_bench(std::ostream& out, const DsmcBenchOptions& o = {});

/// One EDMD throughput case: dimension, N, packing fraction, timed collisions, repeats.
struct EdmdCase {
  int dim = 3;
  std::size_t n = 32000;
  double packing = 0.26;
  double start_packing = 0.0;  ///< lattice start packing, compressed to `packing` (0: none)
  std::uint64_t collisions = 2000000;
  int repeats = 3;
  /// Collisions per particle before timing; < 0: edmd_warmup(dim, packing).
  double warmup = -1.0;
  std::uint64_t seed = 1;
  std::string scan = "auto";  ///< neighbour scan, a name of edmd_scan_names()
};

/// Collisions per particle that take the lattice start to the fluid before a timing: 2
/// below half the jamming packing of D (3D eta = 0.2618: Z from a window of 5 collisions
/// per particle is within its noise of the final value after 2), 100 above it (3D eta =
/// 0.45: Z = 8.03, 8.36, 8.58, 8.75, 8.99, 9.21, 9.41 after 1, 2, 5, 10, 20, 40, 80; the
/// lattice melts slowly near freezing).
double edmd_warmup(int dim, double packing);
/// The neighbour-scan choices of an EDMD case: "auto" (the engine's default for D), then the
/// names of the scan policies (edmd/engine.hpp).
std::vector<std::string_view> edmd_scan_names();

/// Runs one case and prints its JSON lines to `out`. Throws InvalidInput for a dimension
/// outside 1..6 or an unknown scan.
void run_edmd_bench(const EdmdCase& c, std::ostream& out);

/// The default cases: 3D at eta = 0.26 for N = 4000, 32000, 256000 (the sizes of the DynamO
/// anchors, docs/benchmarks.md) and 6D at N = 32000, eta = 0.05 (6D jams at 0.20; at
/// eta = 0.1 the D_6 lattice of 32000 sites is too tight and needs the slow
/// Lubachevsky-Stillinger compression first), 2e5 timed collisions.
std::vector<EdmdCase> default_edmd_cases();

}  // namespace hypergas::studies
