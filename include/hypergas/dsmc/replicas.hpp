// hypergas/dsmc/replicas.hpp -- independent replicas on several cores.
//
// The Kac process is sequential: one collision changes the state every later candidate
// sees, so a single run cannot be split across cores without changing its statistics. The
// second core is used for independent replicas instead: each has its own seed derived
// from (cfg.seed, replica index), so the result does not depend on the thread count or on
// scheduling, and the spread between replicas gives honest error bars.
#pragma once

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::dsmc {

/// Seed of replica r of a run with seed `seed` (replica 0 keeps `seed`).
inline std::uint64_t replica_seed(std::uint64_t seed, int r) {
  return r == 0 ? seed : hypergas::detail::mix64(seed ^ hypergas::detail::mix64(std::uint64_t(r)));
}

/// Constructs `replicas` engines of type EngineT from `cfg` (seed replaced by
/// replica_seed(cfg.seed, r)) and calls body(r, engine) for each, on up to `threads`
/// threads (replica r runs on thread r mod threads). `body` must only write to storage
/// indexed by r. Exceptions thrown by a replica are rethrown here (the first one).
template <class EngineT, class Body>
void run_replicas(const Config& cfg, int replicas, int threads, Body&& body) {
  threads = std::max(1, std::min(threads, replicas));
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](int t) {
    try {
      for (int r = t; r < replicas; r += threads) {
        Config c = cfg;
        c.seed = replica_seed(cfg.seed, r);
        EngineT e(c);
        body(r, e);
      }
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace hypergas::dsmc
