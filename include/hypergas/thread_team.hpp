// hypergas/thread_team.hpp -- a fixed team of threads that run one function together and meet
// at barriers.
//
//   ThreadTeam team(4);            // the caller plus 3 workers
//   team.run([&](int t) {          // t = 0 (the caller), 1, 2, 3
//     ... phase 1 on thread t's share ...
//     team.sync();                 // every thread arrives before any goes on
//     ... phase 2 ...
//   });                            // returns when all four have returned
//
// A barrier spins for at most 50 microseconds, because waking a sleeping thread costs
// about as long as a phase of the DSMC engine (docs/benchmarks.md, "One system on T
// threads"), and then sleeps in std::atomic::wait; with more threads than cores it sleeps at
// once. Between runs the workers sleep. The function must not throw.
#pragma once

#include <atomic>
#include <barrier>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "hypergas/error.hpp"

namespace hypergas {

class ThreadTeam {
 public:
  /// A team of `threads` >= 1 (the calling thread counts as thread 0).
  explicit ThreadTeam(int threads)
      : n_(threads), start_(threads), end_(threads) {
    if (threads < 1) throw InvalidInput("thread team: need at least one thread");
    left_ = threads;
    const unsigned cores = std::thread::hardware_concurrency();
    spin_ = cores == 0 || unsigned(threads) <= cores;
    workers_.reserve(static_cast<std::size_t>(threads - 1));
    for (int t = 1; t < threads; ++t)
      workers_.emplace_back([this, t] {
        for (;;) {
          start_.arrive_and_wait();
          if (quit_) return;
          (*job_)(t);
          end_.arrive_and_wait();
        }
      });
  }
  ~ThreadTeam() {
    quit_ = true;
    start_.arrive_and_wait();
    for (auto& w : workers_) w.join();
  }
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return n_; }
  /// Runs f(t) on threads t = 0 .. size() - 1 and returns when all have finished.
  void run(const std::function<void(int)>& f) {
    job_ = &f;
    start_.arrive_and_wait();
    f(0);
    end_.arrive_and_wait();
    job_ = nullptr;
  }
  /// Inside run(): waits until every thread of the team has called sync(). Writes made
  /// before it are visible to all threads after it.
  void sync() {
    if (n_ == 1) return;
    const std::uint32_t gen = generation_.load(std::memory_order_acquire);
    if (left_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      left_.store(n_, std::memory_order_relaxed);
      generation_.fetch_add(1, std::memory_order_seq_cst);
      if (sleepers_.load(std::memory_order_seq_cst) > 0) generation_.notify_all();
      return;
    }
    if (spin_) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
      for (int s = 1;; ++s) {
        if (generation_.load(std::memory_order_acquire) != gen) return;
        pause();
        if (s % 64 == 0 && std::chrono::steady_clock::now() > until) break;
      }
    }
    sleepers_.fetch_add(1, std::memory_order_seq_cst);
    while (generation_.load(std::memory_order_seq_cst) == gen)
      generation_.wait(gen, std::memory_order_acquire);
    sleepers_.fetch_sub(1, std::memory_order_relaxed);
  }

 private:
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  int n_;
  bool spin_ = false;
  std::barrier<> start_, end_;
  alignas(64) std::atomic<int> left_{0};
  alignas(64) std::atomic<std::uint32_t> generation_{0};
  alignas(64) std::atomic<int> sleepers_{0};
  const std::function<void(int)>* job_ = nullptr;
  bool quit_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace hypergas
