#include "sweep/case_record.hpp"

#include <fstream>

#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"
#include "input/input_limits.hpp"

namespace gearsim::sweep {

using json = nlohmann::ordered_json;

namespace {

// Exit codes of `gearsim run` (app/exit_codes.hpp; the library does not link the app).
constexpr int kExitDiverged = 4, kExitSigint = 130, kExitSigterm = 143;

const char* const kStatusNames[] = {"completed", "diverged", "failed", "interrupted"};

}  // namespace

std::string status_name(CaseStatus s) { return kStatusNames[static_cast<int>(s)]; }

CaseStatus status_of_exit_code(int code) {
  if (code == 0) return CaseStatus::Completed;
  if (code == kExitDiverged) return CaseStatus::Diverged;
  if (code == kExitSigint || code == kExitSigterm) return CaseStatus::Interrupted;
  return CaseStatus::Failed;
}

bool is_final(CaseStatus s) { return s != CaseStatus::Interrupted; }

json case_record_json(const CaseRecord& r) {
  json params = json::object();
  for (const auto& [k, v] : r.parameters) params[k] = v;
  return {{"index", r.index},         {"parameters", params}, {"overrides", r.overrides}, {"status", status_name(r.status)},
          {"exit_code", r.exit_code}, {"error", r.error},     {"metrics", r.metrics},     {"wall_seconds", r.wall_seconds}};
}

CaseRecord case_record_from_json(const json& j, const std::string& where) {
  const auto need = [&](const char* key, bool ok) {
    if (!j.is_object() || !j.contains(key) || !ok) throw InputError(where + ": key " + key + ": missing or of the wrong type");
  };
  CaseRecord r;
  try {
    need("index", j.contains("index") && j["index"].is_number_unsigned());
    need("parameters", j.contains("parameters") && j["parameters"].is_object());
    need("overrides", j.contains("overrides") && j["overrides"].is_array());
    need("status", j.contains("status") && j["status"].is_string());
    need("exit_code", j.contains("exit_code") && j["exit_code"].is_number_integer());
    need("metrics", j.contains("metrics") && j["metrics"].is_object());
    r.index = j["index"].get<std::size_t>();
    for (const auto& [k, v] : j["parameters"].items()) r.parameters.emplace_back(k, v.get<std::string>());
    r.overrides = j["overrides"].get<std::vector<std::string>>();
    const std::string s = j["status"].get<std::string>();
    bool known = false;
    for (int i = 0; i < 4; ++i)
      if (s == kStatusNames[i]) r.status = static_cast<CaseStatus>(i), known = true;
    if (!known) throw InputError(where + ": key status: '" + s + "' is not a case status");
    r.exit_code = j["exit_code"].get<int>();
    r.error = j.value("error", "");
    r.metrics = j["metrics"];
    r.wall_seconds = j.value("wall_seconds", 0.0);
  } catch (const json::exception& e) {
    throw InputError(where + ": not a case record: " + e.what());
  }
  return r;
}

void write_case_record(const std::filesystem::path& case_dir, const CaseRecord& r) {
  write_output_file(case_dir / "case.json", case_record_json(r).dump(2) + "\n", Durability::Record);
}

std::optional<CaseRecord> read_case_record(const std::filesystem::path& case_dir) {
  namespace fs = std::filesystem;
  const fs::path p = case_dir / "case.json";
  std::error_code ec;
  // Only a record inside a case folder of its own: a link where the folder or record belongs is
  // not followed (the case is then rerun, or named in the table, by the caller).
  if (!fs::is_directory(fs::symlink_status(case_dir, ec))) return std::nullopt;
  const fs::file_status st = fs::symlink_status(p, ec);
  if (!fs::exists(st)) return std::nullopt;
  if (!fs::is_regular_file(st)) throw InputError(p.string() + ": expected a case record (a regular file)");
  const std::string text = read_input_file(p, input::limits::kMaxRecordBytes, "a case record");
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(p.string() + ": not valid JSON: " + e.what());
  }
  return case_record_from_json(j, p.string());
}

}  // namespace gearsim::sweep
