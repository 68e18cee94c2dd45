#include "sweep/case_runner.hpp"

#include <chrono>
#include <mutex>

#include "core/errors.hpp"
#include "sweep/process.hpp"

namespace gearsim::sweep {

using json = nlohmann::ordered_json;

namespace {

// The collectors read files and run the analysis (FFTW plans are not thread-safe): one at a time.
std::mutex g_collect_mutex;

// Runs one `gearsim` step of the case; its stdout and stderr go to CASE_DIR/<name>.out/.err.log.
// Returns the outcome with the stderr tail as the error of a failed step.
ProcessOutcome step(const CaseJob& job, const CaseContext& ctx, const std::string& name, std::vector<std::string> args,
                    std::string& error) {
  args.insert(args.begin(), ctx.executable.string());
  const std::filesystem::path err = job.dir / (name + ".err.log");
  ProcessOutcome o = run_process(args, job.dir / (name + ".out.log"), err, ctx.stop);
  if (!o.failure.empty())
    error = o.failure;
  else if (o.exit_code != 0)
    error = "gearsim " + name + ": " + file_tail(err, kErrorTailBytes);
  return o;
}

// The metrics of a completed case; Failed with the reason when they cannot be had.
void collect_metrics(const CaseJob& job, const CaseContext& ctx, CaseRecord& r) {
  if (!ctx.collect) return;
  std::lock_guard<std::mutex> lock(g_collect_mutex);
  try {
    r.metrics = ctx.collect(job.dir, job.collect);
  } catch (const std::exception& e) {
    r.status = CaseStatus::Failed;
    r.error = std::string("collecting the metrics: ") + e.what();
  }
}

}  // namespace

std::string make_case_folder(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto kind = [](const fs::file_status& st) {
    return fs::is_symlink(st) ? "a link" : fs::is_regular_file(st) ? "a file" : "something else";
  };
  const fs::file_status parent = fs::symlink_status(dir.parent_path(), ec);
  if (!fs::is_directory(parent))
    return dir.parent_path().string() + ": expected the sweep's cases folder, found " + kind(parent) + " (left as it is)";
  const fs::file_status own = fs::symlink_status(dir, ec);
  if (!fs::exists(own)) {
    if (!fs::create_directory(dir, ec) && ec) return dir.string() + ": cannot create the case folder: " + ec.message();
    return "";
  }
  if (!fs::is_directory(own)) return dir.string() + ": expected a case folder, found " + kind(own) + " (left as it is)";
  return "";
}

json case_job_json(const CaseJob& job) {
  json params = json::array();
  for (const auto& [k, v] : job.parameters) params.push_back({k, v});
  return {{"index", job.index},
          {"dir", job.dir.string()},
          {"scenario", job.scenario.string()},
          {"parameters", params},
          {"overrides", job.overrides},
          {"collect", {{"summary", job.collect.summary}, {"analysis", job.collect.analysis}, {"metrics", job.collect.metrics}}}};
}

CaseJob case_job_from_json(const json& j) {
  try {
    CaseJob job;
    job.index = j.at("index").get<std::size_t>();
    job.dir = j.at("dir").get<std::string>();
    job.scenario = j.at("scenario").get<std::string>();
    for (const json& p : j.at("parameters")) job.parameters.emplace_back(p.at(0).get<std::string>(), p.at(1).get<std::string>());
    job.overrides = j.at("overrides").get<std::vector<std::string>>();
    job.collect.summary = j.at("collect").at("summary").get<std::vector<std::string>>();
    job.collect.analysis = j.at("collect").at("analysis").get<std::vector<std::string>>();
    job.collect.metrics = j.at("collect").at("metrics").get<std::vector<std::string>>();
    return job;
  } catch (const json::exception& e) {
    throw InputError(std::string("sweep: a case job that is not one: ") + e.what());
  }
}

CaseRecord run_case(const CaseJob& job, const CaseContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  CaseRecord r{job.index, job.parameters, job.overrides, CaseStatus::Failed, 0, "", json::object(), 0};
  // A link or a file where the case folder belongs: the case fails, named, and nothing there is
  // touched (its record is the sweep table's row, not a case.json written through the link).
  if (const std::string problem = make_case_folder(job.dir); !problem.empty()) {
    r.error = problem;
    return r;
  }
  std::error_code ec;
  std::filesystem::remove(job.dir / "case.json", ec);
  // The run: every override as one --set=key=value argument (never an option of its own).
  // --force: the case folder holds the sweep's own logs of this run beside it.
  std::vector<std::string> args{"run", job.scenario.string(), "--out", job.dir.string(), "--no-analyze", "--force"};
  for (const std::string& o : job.overrides) args.push_back("--set=" + o);
  ProcessOutcome o = step(job, ctx, "run", args, r.error);
  r.exit_code = o.exit_code;
  r.status = o.failure.empty() ? status_of_exit_code(o.exit_code) : CaseStatus::Failed;
  // Its analysis, when analysis.json keys are collected.
  if (r.status == CaseStatus::Completed && !job.collect.analysis.empty()) {
    o = step(job, ctx, "analyze", {"analyze", job.dir.string()}, r.error);
    r.exit_code = o.exit_code;
    if (o.exit_code != 0 || !o.failure.empty())
      r.status = status_of_exit_code(o.exit_code) == CaseStatus::Interrupted ? CaseStatus::Interrupted : CaseStatus::Failed;
  }
  if (r.status == CaseStatus::Completed) collect_metrics(job, ctx, r);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // A record that cannot be written (a full disk) fails the case, named; the sweep goes on.
  try {
    write_case_record(job.dir, r);
  } catch (const OutputError& e) {
    r.status = CaseStatus::Failed;
    r.error = std::string("its record was not written: ") + e.what() + (r.error.empty() ? "" : "; " + r.error);
  }
  return r;
}

}  // namespace gearsim::sweep
