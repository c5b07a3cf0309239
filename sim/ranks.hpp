// sim/ranks.hpp -- the processes of a job: MPI ranks under an MPI launcher, else
// this one process; and the dynamic distribution of tasks over them.
//
// MPI is used only when the command was built with it (CMake found MPI: HYPERGAS_MPI) and
// a launcher started it (mpirun/mpiexec of Open MPI or MPICH, srun: their environment
// variables); otherwise the same command runs every task in this process. Tasks are
// handed out one at a time by rank 0: a rank that finishes a task asks for the next, so
// long and short tasks balance without any estimate of their cost. Rank 0 runs tasks too;
// its coordinator is a second thread that polls for requests, every 0.25 ms after a
// request and backing off to every 4 ms while none comes (MPI_THREAD_SERIALIZED: that
// thread makes the only MPI calls while tasks run), so it costs about 1 % of a core and
// adds at most 4 ms to a hand-out. Ranks
// that run out of tasks wait in a polled, non-blocking barrier (MPI_Ibarrier, 1 ms sleeps)
// rather than spinning in MPI_Finalize, so an oversubscribed node gives their cores to the
// ranks still working.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "hypergas/studies/replicas.hpp"

namespace hypergas::cli::ranks {

/// Whether this command was built with MPI.
bool built_with_mpi();
/// Whether an MPI launcher started this process (and the command was built with MPI).
bool launched();
/// The number of processes a launcher says it started (its environment), 1 if none: with
/// a command built without MPI, more than 1 means every process would run the whole job.
int launcher_size();

/// MPI_Init_thread at construction and MPI_Finalize at destruction when launched();
/// otherwise one process of rank 0. One per process.
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool mpi() const { return mpi_; }
  /// Rank 0's `ok` on every rank (collective; `ok` of other ranks is ignored).
  bool agree(bool ok) const;
  /// Ends every rank of the job at once with `code` (MPI_Abort), or does nothing without MPI.
  void abort(int code) const;

 private:
  bool mpi_ = false;
  int rank_ = 0, size_ = 1;
};

/// What the distribution measured (rank 0's view of the whole job).
struct DispatchStats {
  std::size_t handed_out = 0;    ///< tasks handed to other ranks
  double wait_s = 0.0;           ///< their total time from request to assignment
  std::size_t requests = 0;      ///< requests those waits cover
};

/// Runs every task of `todo` (collective; only rank 0's list counts) once, each on the
/// first rank free; with `first_on_root`, todo[0] runs on rank 0. work(t) runs task t here
/// and returns whether it succeeded; done(t, ok, rank) is then called on rank 0
/// (serialised: from one thread at a time). An exception from work() leaves dispatch on
/// the rank where it happened (rank 0 first stops its coordinator); the caller then ends the
/// job with Session::abort, since the other ranks still wait on it.
DispatchStats dispatch(const Session& s, const std::vector<std::size_t>& todo,
                       const std::function<bool(std::size_t)>& work,
                       const std::function<void(std::size_t, bool, int)>& done,
                       bool first_on_root = false);

/// The replicas of `run --replicas` and of `report` over the ranks (studies::ReplicaSpread):
/// handed out as dispatch() hands out tasks, replica 0 on rank 0, the result arrays then
/// gathered on rank 0 and broadcast to every rank. Results are the same numbers as on one
/// process: each replica is a pure function of its seed.
class ReplicaRanks final : public studies::ReplicaSpread {
 public:
  explicit ReplicaRanks(const Session& s) : s_(s) {}
  void run(int replicas, const std::function<void(int)>& body,
           std::span<std::vector<double>* const> results) override;
  bool root() const override { return s_.rank() == 0; }

 private:
  const Session& s_;
};

}  // namespace hypergas::cli::ranks
