// A case's record, DIR/cases/<index>/case.json: its parameters and overrides, how it ended
// (status, exit code, the tail of its error output) and the metrics collected from its run
// folder. Written by whoever ran the case (a local thread or an MPI worker), read back by the
// table and by resume: the one place a case's result lives.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gearsim::sweep {

enum class CaseStatus {
  Completed,  // the run finished inside its physical bounds and its metrics were collected
  Diverged,  // the run left its physical bounds (exit 4)
  Failed,  // any other end: a refused override (exit 2), a crash, analysis or metrics failing
  Interrupted,  // stopped by SIGINT/SIGTERM (exit 130/143): run again on resume
};

std::string status_name(CaseStatus s);  // "completed", "diverged", "failed", "interrupted"
// A run's status from `gearsim run`'s exit code (app/exit_codes.hpp).
CaseStatus status_of_exit_code(int exit_code);
// Final: resume skips the case (every status but Interrupted).
bool is_final(CaseStatus s);

struct CaseRecord {
  std::size_t index = 0;
  std::vector<std::pair<std::string, std::string>> parameters;  // (key, value text), column order
  std::vector<std::string> overrides;  // the --set list the run got
  CaseStatus status = CaseStatus::Failed;
  int exit_code = 0;  // of the step that ended the case (run, analyze), 0 when all passed
  std::string error;  // the tail of the failing step's stderr, or why metrics failed
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();  // column → number or null
  double wall_seconds = 0;  // the case's wall time, s (not in the table: it differs run to run)
};

nlohmann::ordered_json case_record_json(const CaseRecord& r);
// InputError naming `where` and the key when the JSON is not a case record.
CaseRecord case_record_from_json(const nlohmann::ordered_json& j, const std::string& where);

// Writes case_dir/case.json through a temporary file and a rename: a reader sees the old record
// or the new one, never half of one.
void write_case_record(const std::filesystem::path& case_dir, const CaseRecord& r);
// case_dir/case.json, or nothing when absent; InputError when it is damaged.
std::optional<CaseRecord> read_case_record(const std::filesystem::path& case_dir);

}  // namespace gearsim::sweep
