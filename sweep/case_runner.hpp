// One case run to its end: `gearsim run BASE --out CASE_DIR --no-analyze --set=…` as a child
// process (this same binary), then `gearsim analyze CASE_DIR` when analysis keys are collected,
// then the metrics read from the case folder by the caller's collector, and case.json written.
// A case that fails is recorded, never thrown. The job is plain data (and JSON, for an MPI
// worker), so whoever runs it needs nothing but the job.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "input/sweep_file.hpp"
#include "sweep/case_record.hpp"

namespace gearsim::sweep {

struct CaseJob {
  std::size_t index = 0;
  std::filesystem::path dir;  // DIR/cases/<index>, absolute
  std::filesystem::path scenario;  // the base scenario, absolute
  std::vector<std::pair<std::string, std::string>> parameters;
  std::vector<std::string> overrides;
  input::SweepCollect collect;
};

nlohmann::ordered_json case_job_json(const CaseJob& job);
// InputError when the JSON is not a job (a message between MPI ranks of different builds).
CaseJob case_job_from_json(const nlohmann::ordered_json& j);

// The metrics of a finished run folder as {column: number or null}, in column order; InputError
// naming the file and key when one cannot be had. Runs under a lock: one at a time per process.
using MetricCollector = std::function<nlohmann::ordered_json(const std::filesystem::path& case_dir, const input::SweepCollect& collect)>;

struct CaseContext {
  std::filesystem::path executable;  // gearsim itself (process.hpp self_executable)
  MetricCollector collect;
  // Polled while a child runs: a signal number > 0 is passed on to it (a sweep asked to stop).
  std::function<int()> stop;
};

// Runs the job and writes its case.json; returns the record written.
CaseRecord run_case(const CaseJob& job, const CaseContext& context);

// Makes the case folder DIR where it is absent; "" when DIR is then a folder of its own, else
// what stands there instead (a link, a file; also where the cases folder should be), named, for
// the case's failure. Never follows a link and never removes anything.
std::string make_case_folder(const std::filesystem::path& dir);

// How much of a failing step's stderr a record keeps, bytes.
constexpr std::size_t kErrorTailBytes = 2000;

}  // namespace gearsim::sweep
