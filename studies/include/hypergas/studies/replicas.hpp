// hypergas/studies/replicas.hpp -- independent replicas on several cores.
//
// The Kac process is sequential: one collision changes the state every later candidate
// sees, so a single run cannot be split across cores without changing its statistics. The
// second core is used for independent replicas instead: each has its own seed derived
// from (seed, replica index), so the result does not depend on the thread count or on
// scheduling, and the spread between replicas gives honest error bars.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace hypergas::studies {

/// Where replicas run when several processes share one study (the MPI ranks of `mpirun
/// hypergas report` or `run --replicas`): the program installs one (set_replica_spread);
/// without one, replicas run on threads of this process.
class ReplicaSpread {
 public:
  virtual ~ReplicaSpread() = default;
  /// Calls body(r) for r = 0 .. replicas-1, each once, on one of the processes; replica 0
  /// on this process if it is the root. Afterwards every process holds (*results[j])[r] for
  /// every j and r, as the process that ran replica r wrote it (the arrays are sized by the
  /// caller beforehand).
  virtual void run(int replicas, const std::function<void(int)>& body,
                   std::span<std::vector<double>* const> results) = 0;
  /// Whether this process is the one that writes the study's files and prints (rank 0).
  virtual bool root() const = 0;
};
/// Installs `s` (nullptr: none) for for_each_replica; the caller keeps it alive.
void set_replica_spread(ReplicaSpread* s);
/// Whether this process writes and prints: true without a spread.
bool replica_root();

/// Seed of replica r of a run with seed `seed`: replica 0 keeps `seed`, replica r > 0 gets
/// mix64(seed ^ mix64(r)) (rng.hpp).
std::uint64_t replica_seed(std::uint64_t seed, int r);

/// Calls body(r) for r = 0 .. replicas-1 on up to `threads` threads (replica r runs on
/// thread r mod threads; thread 0 is the caller's). `body` must only write to storage
/// indexed by r. After all threads finish, the first exception (lowest thread) thrown by a
/// replica is rethrown here; a thread stops at its first exception.
/// With a ReplicaSpread installed and `results` given (every array that body writes at
/// [r]), the replicas run over its processes instead and the results reach every process;
/// without `results` they run here.
void for_each_replica(int replicas, int threads, const std::function<void(int)>& body,
                      const std::vector<std::vector<double>*>& results = {});

/// Constructs `replicas` engines of type EngineT from `cfg` (seed replaced by
/// replica_seed(cfg.seed, r)) and calls body(r, engine) for each, through
/// for_each_replica (same threads, same exceptions).
template <class EngineT, class Config, class Body>
void run_replicas(const Config& cfg, int replicas, int threads, Body&& body,
                  const std::vector<std::vector<double>*>& results = {}) {
  for_each_replica(
      replicas, threads,
      [&](int r) {
        Config c = cfg;
        c.seed = replica_seed(cfg.seed, r);
        EngineT e(c);
        body(r, e);
      },
      results);
}

}  // namespace hypergas::studies
