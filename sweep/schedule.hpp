// Running a sweep's case jobs: on local threads (each running one child process at a time), or
// over MPI ranks, where rank 0 hands out one case at a time to whichever worker asks (dynamic
// scheduling: a slow case holds up only its worker) and workers run them and report back. MPI is
// initialised only when the sweep runs under mpirun (mpi_requested()); a plain sweep never needs
// it. Every case writes its own case.json wherever it ran; results are for progress only.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

#include "sweep/case_runner.hpp"

namespace gearsim::sweep {

struct Progress {
  std::size_t done = 0;  // cases finished in this invocation
  std::size_t to_run = 0;  // cases this invocation runs (the rest were finished before: resume)
  std::size_t failed = 0;  // of the done, those not completed
  double elapsed_s = 0;  // since the first case started, s
  double eta_s = -1;  // remaining, s, from the mean time per case so far; -1 before the first
  const CaseRecord* last = nullptr;  // the case that just finished
};
using ProgressFn = std::function<void(const Progress&)>;

// Counts the finished case `r` into p (done, failed, elapsed since `start`, ETA) and passes p to
// `report`; the schedulers call it once per case, one at a time.
void count_finished(Progress& p, const CaseRecord& r, std::chrono::steady_clock::time_point start, const ProgressFn& report);

// Runs the jobs on `parallel` threads (≥ 1), taking them in order; stops taking new ones once
// context.stop() returns non-zero. Returns the records, in the order they finished.
std::vector<CaseRecord> run_local(const std::vector<CaseJob>& jobs, int parallel, const CaseContext& context, const ProgressFn& progress);

// True when this process is one rank of several under mpirun (OMPI_COMM_WORLD_SIZE or PMI_SIZE
// greater than 1 in the environment).
bool mpi_requested();

// MPI_Init on construction, MPI_Finalize on destruction; rank and size of MPI_COMM_WORLD.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

// Rank 0: hands out the jobs one at a time to the workers that ask, gathers their records, and
// sends every worker the stop message when no job is left (with no jobs: releases the workers at
// once, e.g. after the sweep file was refused). Polls, so that it does not spin a core the
// workers need.
std::vector<CaseRecord> run_mpi_master(const std::vector<CaseJob>& jobs, const ProgressFn& progress, const std::function<int()>& stop);
// Ranks > 0: asks for jobs and runs them until rank 0 says stop.
void run_mpi_worker(const CaseContext& context);

}  // namespace gearsim::sweep
