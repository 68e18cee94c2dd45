#include "sweep/sweep_dir.hpp"

#include <fstream>

#include "core/errors.hpp"
#include "sweep/case_list.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"
#include "input/input_limits.hpp"

namespace gearsim::sweep {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

// What DIR/sweep.json says of the sweep.
json sweep_json(const input::SweepFile& f) {
  json params = json::array();
  for (const input::SweepParameter& p : f.parameters) params.push_back(p.key);
  return {{"name", f.name},
          {"sweep_file", f.file.string()},
          {"content_hash", f.content_hash},
          {"content_hash_kind", "FNV-1a 64 of the sweep file's bytes"},
          {"scenario", f.scenario.string()},
          {"case_count", f.case_count},
          {"mode", f.grid ? "grid" : "cases"},
          {"parameters", params},
          {"set", f.set},
          {"collect", {{"summary", f.collect.summary}, {"analysis", f.collect.analysis}, {"metrics", f.collect.metrics}}},
          {"cases_dir", "cases"},
          {"table", {"sweep.csv", "sweep.h5"}}};
}

// Removes DIR's sweep outputs; returns how many there were.
int clear_sweep_outputs(const fs::path& dir) {
  int removed = 0;
  std::error_code ec;
  for (const char* f : {"sweep.json", "sweep.csv", "sweep.h5", "report.html"})
    if (fs::is_regular_file(fs::symlink_status(dir / f))) removed += fs::remove(dir / f, ec) ? 1 : 0;
  const fs::file_status cases = fs::symlink_status(dir / "cases");
  if (fs::is_directory(cases) || fs::is_symlink(cases)) removed += fs::remove_all(dir / "cases", ec) > 0 ? 1 : 0;
  if (ec) throw InputError((dir / "cases").string() + ": cannot remove the previous sweep's cases: " + ec.message());
  return removed;
}

}  // namespace

fs::path case_dir(const fs::path& dir, std::size_t index) { return dir / "cases" / case_folder_name(index); }

bool is_sweep_dir(const fs::path& dir) { return fs::is_regular_file(dir / "sweep.json"); }

json read_sweep_json(const fs::path& dir) {
  const fs::path p = dir / "sweep.json";
  if (!fs::exists(fs::symlink_status(p)))
    throw InputError(p.string() + ": not found (is " + dir.string() + " the --out folder of a `gearsim sweep`?)");
  const std::string text = read_input_file(p, input::limits::kMaxRecordBytes, "a sweep record");
  try {
    json j = json::parse(text);
    if (!j.is_object() || !j.contains("content_hash") || !j["content_hash"].is_string() || !j.contains("parameters") ||
        !j["parameters"].is_array() || !j.contains("case_count") || !j["case_count"].is_number_unsigned())
      throw InputError(p.string() + ": expected the object gearsim sweep writes (content_hash, parameters, case_count)");
    return j;
  } catch (const json::exception& e) {
    throw InputError(p.string() + ": not valid JSON: " + e.what());
  }
}

int prepare_sweep_dir(const fs::path& dir, const input::SweepFile& f, bool fresh) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder: " + ec.message());
  int removed = 0;
  if (fresh)
    removed = clear_sweep_outputs(dir);
  else if (is_sweep_dir(dir)) {
    const json old = read_sweep_json(dir);
    if (old["content_hash"].get<std::string>() != f.content_hash)
      throw InputError(f.file.string() + ": its content changed since the sweep in " + dir.string() + " began (sweep.json holds " +
                       old.value("sweep_file", std::string("?")) + " with hash " + old["content_hash"].get<std::string>() + ", now " +
                       f.content_hash + "): resuming would mix two sweeps; use --fresh to start over, or another --out");
  }
  fs::create_directory(dir / "cases", ec);
  if (ec) throw InputError((dir / "cases").string() + ": cannot create: " + ec.message());
  if (!fs::is_directory(fs::symlink_status(dir / "cases", ec)))
    throw InputError((dir / "cases").string() +
                     ": expected the sweep's cases folder, found a link or a file "
                     "(left as it is): remove it or choose another --out");
  write_output_file(dir / "sweep.json", sweep_json(f).dump(2) + "\n", Durability::Record);
  return removed;
}

}  // namespace gearsim::sweep
