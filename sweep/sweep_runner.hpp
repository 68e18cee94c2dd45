// A whole sweep, as one call: the sweep file read and its cases expanded, every case validated
// against the base scenario before any runs, DIR prepared (resume or --fresh), the cases not yet
// finished run by the scheduler the caller picks (local threads or MPI rank 0), and the table
// gathered from the case folders into DIR/sweep.csv and DIR/sweep.h5. Prints nothing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/schedule.hpp"
#include "sweep/table.hpp"

namespace gearsim::sweep {

struct SweepOptions {
  std::filesystem::path sweep_file;
  std::filesystem::path out_dir;
  bool fresh = false;  // clear DIR's sweep outputs first
};

// Runs the jobs (the cases still to run, index order) and returns their records.
using Scheduler = std::function<std::vector<CaseRecord>(const std::vector<CaseJob>& jobs)>;

struct SweepOutcome {
  std::size_t cases = 0;  // in the sweep
  std::size_t skipped = 0;  // finished before (resume)
  std::size_t ran = 0;  // run by this call
  int removed_outputs = 0;  // with --fresh: sweep outputs of an earlier sweep removed
  StatusCounts statuses;  // over the whole table
  SweepTable table;  // what sweep.csv and sweep.h5 hold
  std::filesystem::path csv, h5;
};

// Called once the cases are known and validated, before any runs: (cases, to run).
using StartFn = std::function<void(std::size_t cases, std::size_t to_run)>;

// InputError (naming the sweep file, case and key) before anything runs when the file or a
// case is refused, or DIR holds a sweep of another file.
SweepOutcome run_sweep(const SweepOptions& options, const Scheduler& schedule, const StartFn& started = {});

}  // namespace gearsim::sweep
