#include "sweep/sweep_runner.hpp"

#include "core/errors.hpp"
#include "core/folder_lock.hpp"
#include "input/sweep_file.hpp"
#include "sweep/case_list.hpp"
#include "sweep/sweep_dir.hpp"
#include "sweep/validate.hpp"

namespace gearsim::sweep {

namespace fs = std::filesystem;

namespace {

// The job of a case: its folder, the base scenario, its overrides, what to collect.
CaseJob job_of(const input::SweepFile& f, const Case& c, const fs::path& dir) {
  return {c.index, case_dir(dir, c.index), f.scenario, c.parameters, c.overrides, f.collect};
}

}  // namespace

SweepOutcome run_sweep(const SweepOptions& o, const Scheduler& schedule, const StartFn& started) {
  const input::SweepFile f = input::load_sweep_file(o.sweep_file);
  const std::vector<Case> cases = expand_cases(f);
  validate_cases(f, cases);
  const fs::path dir = fs::absolute(o.out_dir).lexically_normal();
  SweepOutcome out;
  out.cases = cases.size();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder: " + ec.message());
  const FolderLock lock(dir, "gearsim sweep");  // one sweep (or report) at a time in the folder
  out.removed_outputs = prepare_sweep_dir(dir, f, o.fresh);
  // Resume: a case whose case.json holds a final status has run; the others (re)run, also one
  // whose folder or record is damaged (its run says what is wrong).
  std::vector<CaseJob> jobs;
  for (const Case& c : cases) {
    std::optional<CaseRecord> r;
    try {
      r = read_case_record(case_dir(dir, c.index));
    } catch (const InputError&) {}
    if (r && is_final(r->status))
      ++out.skipped;
    else
      jobs.push_back(job_of(f, c, dir));
  }
  if (started) started(out.cases, jobs.size());
  out.ran = schedule(jobs).size();
  // The table, from the case folders only, in index order.
  std::vector<std::string> columns;
  for (const input::SweepParameter& p : f.parameters) columns.push_back(p.key);
  out.table = gather_table(dir, columns, cases.size());
  out.csv = dir / "sweep.csv";
  out.h5 = dir / "sweep.h5";
  write_table_csv(out.table, out.csv);
  write_table_h5(out.table, out.h5);
  out.statuses = count_statuses(out.table);
  return out;
}

}  // namespace gearsim::sweep
