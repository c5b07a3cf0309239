// The replica seed rule and the replica thread pool.
#include "hypergas/studies/replicas.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

#include "hypergas/rng.hpp"

namespace hypergas::studies {

std::uint64_t replica_seed(std::uint64_t seed, int r) {
  return r == 0 ? seed
                : hypergas::detail::mix64(seed ^ hypergas::detail::mix64(std::uint64_t(r)));
}

namespace {
ReplicaSpread* spread = nullptr;
}

void set_replica_spread(ReplicaSpread* s) { spread = s; }
bool replica_root() { return !spread || spread->root(); }

void for_each_replica(int replicas, int threads, const std::function<void(int)>& body,
                      const std::vector<std::vector<double>*>& results) {
  if (spread && !results.empty()) {
    spread->run(replicas, body, results);
    return;
  }
  threads = std::max(1, std::min(threads, replicas));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  auto work = [&](int t) {
    try {
      for (int r = t; r < replicas; r += threads) body(r);
    } catch (...) {
      errors[static_cast<std::size_t>(t)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace hypergas::studies
