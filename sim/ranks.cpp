// sim/ranks.cpp -- MPI session, dynamic task distribution, replicas over ranks (ranks.hpp).
#include "ranks.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

#ifdef HYPERGAS_MPI
#include <mpi.h>
#endif

namespace hypergas::cli::ranks {

namespace {
#ifdef HYPERGAS_MPI
constexpr int tag_request = 1, tag_assign = 2;
constexpr int min_pause_us = 250, max_pause_us = 4000;  // the coordinator's polls

/// A barrier that sleeps while it waits (MPI_Finalize's own synchronisation spins).
void quiet_barrier() {
  MPI_Request req;
  MPI_Ibarrier(MPI_COMM_WORLD, &req);
  for (int flag = 0;;) {
    MPI_Test(&req, &flag, MPI_STATUS_IGNORE);
    if (flag) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}
#endif
}  // namespace

bool built_with_mpi() {
#ifdef HYPERGAS_MPI
  return true;
#else
  return false;
#endif
}

bool launched() {
  if (!built_with_mpi()) return false;
  // Open MPI's mpirun, PMIx launchers (srun --mpi=pmix, prterun), PMI-1/2 (MPICH's hydra,
  // srun --mpi=pmi2).
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

int launcher_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* x = std::getenv(v)) return std::max(1, std::atoi(x));
  return 1;
}

Session::Session() {
#ifdef HYPERGAS_MPI
  if (!launched()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_SERIALIZED && size_ > 1) {
    if (rank_ == 0)
      std::fprintf(stderr, "hypergas: this MPI library does not provide MPI_THREAD_SERIALIZED, "
                           "which rank 0's coordinator thread needs\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
#endif
}

Session::~Session() {
#ifdef HYPERGAS_MPI
  if (mpi_) MPI_Finalize();
#endif
}

bool Session::agree(bool ok) const {
#ifdef HYPERGAS_MPI
  if (mpi_) {
    int v = ok ? 1 : 0;
    MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return v != 0;
  }
#endif
  return ok;
}

void Session::abort(int code) const {
#ifdef HYPERGAS_MPI
  if (mpi_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
#else
  (void)code;
#endif
}

DispatchStats dispatch(const Session& s, const std::vector<std::size_t>& todo,
                       const std::function<bool(std::size_t)>& work,
                       const std::function<void(std::size_t, bool, int)>& done,
                       bool first_on_root) {
  (void)first_on_root;  // used with MPI only
  DispatchStats st;
  if (!s.mpi() || s.size() == 1) {
    for (std::size_t t : todo) done(t, work(t), 0);
    return st;
  }
#ifdef HYPERGAS_MPI
  using Clock = std::chrono::steady_clock;
  if (s.rank() == 0) {
    std::mutex take_m, done_m;
    // with first_on_root, todo[0] is taken before the coordinator can hand it out
    const bool first = first_on_root && !todo.empty();
    std::size_t next = first ? 1 : 0;
    const auto take = [&]() -> long long {
      std::lock_guard<std::mutex> lock(take_m);
      return next < todo.size() ? static_cast<long long>(todo[next++]) : -1;
    };
    const auto report = [&](std::size_t t, bool ok, int rank) {
      std::lock_guard<std::mutex> lock(done_m);
      done(t, ok, rank);
    };
    std::atomic<bool> stop{false};
    std::exception_ptr coordinator_error;
    // The coordinator: answers each request (the requester's last task and its result,
    // and how long its previous request waited) with the next task, or -1 when none is
    // left; it ends once every other rank has been told -1.
    std::thread coordinator([&] {
      try {
        int active = s.size() - 1;
        // Polls back off from 0.25 ms to 4 ms while no request comes: each MPI_Iprobe runs
        // the MPI progress engine (about 30 us here), so a fixed 0.5 ms poll cost rank 0's
        // core 6 % (measured, docs/benchmarks.md), while a hand-out waits at most 4 ms.
        int pause_us = min_pause_us;
        while (active > 0 && !stop.load()) {
          int flag = 0;
          MPI_Status status;
          MPI_Iprobe(MPI_ANY_SOURCE, tag_request, MPI_COMM_WORLD, &flag, &status);
          if (!flag) {
            std::this_thread::sleep_for(std::chrono::microseconds(pause_us));
            pause_us = std::min(2 * pause_us, max_pause_us);
            continue;
          }
          pause_us = min_pause_us;
          long long msg[3];
          MPI_Recv(msg, 3, MPI_LONG_LONG, status.MPI_SOURCE, tag_request, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
          // the next task first, then the report of the last one (the caller's table
          // update): the requester does not wait for the bookkeeping
          long long t = take();
          MPI_Send(&t, 1, MPI_LONG_LONG, status.MPI_SOURCE, tag_assign, MPI_COMM_WORLD);
          if (t < 0) --active;
          else ++st.handed_out;
          if (msg[2] >= 0) {
            st.wait_s += static_cast<double>(msg[2]) * 1e-6;
            ++st.requests;
          }
          if (msg[0] >= 0) report(static_cast<std::size_t>(msg[0]), msg[1] != 0, status.MPI_SOURCE);
        }
      } catch (...) {
        coordinator_error = std::current_exception();
      }
    });
    try {
      if (first) report(todo[0], work(todo[0]), 0);
      for (long long t; !coordinator_error && (t = take()) >= 0;) {
        const bool ok = work(static_cast<std::size_t>(t));
        report(static_cast<std::size_t>(t), ok, 0);
      }
    } catch (...) {
      stop = true;
      coordinator.join();
      throw;
    }
    coordinator.join();
    if (coordinator_error) std::rethrow_exception(coordinator_error);
  } else {
    long long last = -1, ok = 0, wait_us = -1;
    for (;;) {
      long long msg[3] = {last, ok, wait_us};
      const auto t0 = Clock::now();
      MPI_Send(msg, 3, MPI_LONG_LONG, 0, tag_request, MPI_COMM_WORLD);
      long long t = -1;
      MPI_Recv(&t, 1, MPI_LONG_LONG, 0, tag_assign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      wait_us = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - t0).count();
      if (t < 0) break;
      ok = work(static_cast<std::size_t>(t)) ? 1 : 0;
      last = t;
    }
  }
  quiet_barrier();
#endif
  return st;
}

void ReplicaRanks::run(int replicas, const std::function<void(int)>& body,
                       std::span<std::vector<double>* const> results) {
  std::vector<std::size_t> todo(static_cast<std::size_t>(replicas));
  for (std::size_t r = 0; r < todo.size(); ++r) todo[r] = r;
  std::vector<std::size_t> mine;
  dispatch(
      s_, todo,
      [&](std::size_t r) {
        body(static_cast<int>(r));
        mine.push_back(r);
        return true;
      },
      [](std::size_t, bool, int) {}, true);
#ifdef HYPERGAS_MPI
  if (!s_.mpi() || s_.size() == 1) return;
  // Each rank's records (r, then results[j][r] for every j) to rank 0, then every array
  // from rank 0 to all.
  const std::size_t J = results.size();
  std::vector<double> pack;
  for (std::size_t r : mine) {
    pack.push_back(static_cast<double>(r));
    for (std::size_t j = 0; j < J; ++j) pack.push_back((*results[j])[r]);
  }
  int count = static_cast<int>(pack.size());
  std::vector<int> counts(static_cast<std::size_t>(s_.size())), displs(counts.size());
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (s_.rank() == 0) {
    int total = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      displs[i] = total;
      total += counts[i];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(pack.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  for (std::size_t i = 0; i < all.size(); i += J + 1) {
    const auto r = static_cast<std::size_t>(all[i]);
    for (std::size_t j = 0; j < J; ++j) (*results[j])[r] = all[i + 1 + j];
  }
  for (std::vector<double>* a : results)
    MPI_Bcast(a->data(), static_cast<int>(a->size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
#else
  (void)results;
#endif
}

}  // namespace hypergas::cli::ranks
