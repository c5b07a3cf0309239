// bench/mpi_handout_probe.cpp -- the cost of handing out one task under MPI, two designs:
//   coordinator  rank 0 runs tasks on its main thread while a second thread answers
//                requests (MPI_Iprobe polled every 0.5 ms, MPI_THREAD_SERIALIZED): the
//                design of sim/ranks.cpp;
//   counter      a shared counter in an MPI window on rank 0, taken with MPI_Fetch_and_op
//                under MPI_Win_lock (passive target), rank 0 busy with tasks meanwhile.
// Every rank takes `tasks` tasks of `work_us` microseconds of spinning each; the probe
// prints each design's mean time from asking to receiving a task (the hand-out) over the
// ranks other than 0, and the wall time. Build and run (not part of the CMake build):
//   mpicxx -O2 -std=c++20 bench/mpi_handout_probe.cpp -o /tmp/probe -pthread
//   mpirun -np 2 /tmp/probe 400 2000
#include <mpi.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

using Clock = std::chrono::steady_clock;

static void spin(int us) {
  const auto end = Clock::now() + std::chrono::microseconds(us);
  while (Clock::now() < end) {
  }
}

static double us_since(Clock::time_point t) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t).count();
}

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const long total = argc > 1 ? std::atol(argv[1]) : 400;
  const int work = argc > 2 ? std::atoi(argv[2]) : 2000;

  // Design 1: coordinator thread on rank 0.
  double wait = 0;
  long asked = 0;
  MPI_Barrier(MPI_COMM_WORLD);
  auto t0 = Clock::now();
  if (rank == 0) {
    std::atomic<long> next{0};
    std::thread coord([&] {
      int active = size - 1;
      while (active > 0) {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, 1, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
          std::this_thread::sleep_for(std::chrono::microseconds(500));
          continue;
        }
        long dummy;
        MPI_Recv(&dummy, 1, MPI_LONG, st.MPI_SOURCE, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        long t = next.fetch_add(1);
        if (t >= total) t = -1, --active;
        MPI_Send(&t, 1, MPI_LONG, st.MPI_SOURCE, 2, MPI_COMM_WORLD);
      }
    });
    while (next.fetch_add(1) < total) spin(work);
    coord.join();
  } else {
    for (;;) {
      long t = 0;
      const auto a = Clock::now();
      MPI_Send(&t, 1, MPI_LONG, 0, 1, MPI_COMM_WORLD);
      MPI_Recv(&t, 1, MPI_LONG, 0, 2, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      wait += us_since(a);
      ++asked;
      if (t < 0) break;
      spin(work);
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double wall1 = us_since(t0);
  double sums[2] = {wait, static_cast<double>(asked)}, tot[2];
  MPI_Reduce(sums, tot, 2, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("coordinator: %.1f us per hand-out (%g requests), wall %.3f s\n",
                tot[1] > 0 ? tot[0] / tot[1] : 0.0, tot[1], wall1 * 1e-6);

  // Design 2: shared counter, MPI_Fetch_and_op.
  long* base = nullptr;
  MPI_Win win;
  MPI_Win_allocate(rank == 0 ? sizeof(long) : 0, sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD,
                   &base, &win);
  if (rank == 0) *base = 0;
  MPI_Barrier(MPI_COMM_WORLD);
  wait = 0;
  asked = 0;
  t0 = Clock::now();
  const long one = 1;
  for (;;) {
    long t = 0;
    const auto a = Clock::now();
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, win);
    MPI_Fetch_and_op(&one, &t, MPI_LONG, 0, 0, MPI_SUM, win);
    MPI_Win_unlock(0, win);
    if (rank != 0) wait += us_since(a), ++asked;
    if (t >= total) break;
    spin(work);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double wall2 = us_since(t0);
  sums[0] = wait;
  sums[1] = static_cast<double>(asked);
  MPI_Reduce(sums, tot, 2, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("counter:     %.1f us per hand-out (%g requests), wall %.3f s\n",
                tot[1] > 0 ? tot[0] / tot[1] : 0.0, tot[1], wall2 * 1e-6);
  MPI_Win_free(&win);
  MPI_Finalize();
}
