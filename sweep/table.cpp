#include "sweep/table.hpp"

#include <cstdio>
#include <fstream>

#include "core/errors.hpp"
#include "sweep/case_record.hpp"
#include "sweep/sweep_dir.hpp"
#include "core/output_file.hpp"

namespace gearsim::sweep {
namespace {

// Adds the record's metric columns not yet known, in its order.
void add_columns(SweepTable& t, const nlohmann::ordered_json& metrics) {
  for (const auto& [name, value] : metrics.items()) {
    bool known = false;
    for (const std::string& c : t.metric_columns) known = known || c == name;
    if (!known) t.metric_columns.push_back(name);
  }
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

// "" when the case folder DIR is absent or a folder of its own; else what stands there instead.
static std::string folder_problem(const std::filesystem::path& dir) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::symlink_status(dir, ec);
  if (!std::filesystem::exists(st) || std::filesystem::is_directory(st)) return "";
  return dir.string() + ": expected a case folder, found " + (std::filesystem::is_symlink(st) ? "a link" : "a file") + " (left as it is)";
}

SweepTable gather_table(const std::filesystem::path& dir, const std::vector<std::string>& parameter_columns, std::size_t case_count) {
  SweepTable t;
  t.parameter_columns = parameter_columns;
  std::vector<std::optional<CaseRecord>> records;
  std::vector<std::string> problems(case_count);  // a case whose folder or record is damaged
  for (std::size_t i = 0; i < case_count; ++i) {
    try {
      problems[i] = folder_problem(case_dir(dir, i));
      records.push_back(problems[i].empty() ? read_case_record(case_dir(dir, i)) : std::nullopt);
    } catch (const InputError& e) {
      problems[i] = e.what();
      records.push_back(std::nullopt);
    }
    if (!records.back()) continue;
    if (records.back()->index != i)
      throw InputError((case_dir(dir, i) / "case.json").string() + ": key index: " + std::to_string(records.back()->index) + ", expected " +
                       std::to_string(i) + " (the record of another case)");
    add_columns(t, records.back()->metrics);
  }
  for (std::size_t i = 0; i < case_count; ++i) {
    TableRow row;
    row.index = i;
    row.status = records[i] ? status_name(records[i]->status) : problems[i].empty() ? "not run" : "failed";
    for (const std::string& key : parameter_columns) {
      std::string value;
      if (records[i])
        for (const auto& [k, v] : records[i]->parameters)
          if (k == key) value = v;
      row.parameters.push_back(value);
    }
    for (const std::string& m : t.metric_columns) {
      std::optional<double> v;
      if (records[i] && records[i]->metrics.contains(m)) {
        const auto& j = records[i]->metrics[m];
        if (j.is_number())
          v = j.get<double>();
        else if (!j.is_null())
          throw InputError((case_dir(dir, i) / "case.json").string() + ": key metrics." + m + ": expected a number or null");
      }
      row.metrics.push_back(v);
    }
    if (records[i])
      row.error = records[i]->error;
    else
      row.error = problems[i];
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string metric_text(const std::optional<double>& v) {
  if (!v) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", *v);
  return buf;
}

void write_table_csv(const SweepTable& t, const std::filesystem::path& file) {
  OutputFile out(file, Durability::Record);
  out << "index";
  for (const std::string& c : t.parameter_columns) out << "," << csv_cell(c);
  out << ",status";
  for (const std::string& c : t.metric_columns) out << "," << csv_cell(c);
  out << "\n";
  for (const TableRow& r : t.rows) {
    out << r.index;
    for (const std::string& p : r.parameters) out << "," << csv_cell(p);
    out << "," << r.status;
    for (const auto& m : r.metrics) out << "," << metric_text(m);
    out << "\n";
  }
  out.commit();
}

StatusCounts count_statuses(const SweepTable& t) {
  StatusCounts c;
  for (const TableRow& r : t.rows) {
    if (r.status == "completed")
      ++c.completed;
    else if (r.status == "diverged")
      ++c.diverged;
    else if (r.status == "failed")
      ++c.failed;
    else if (r.status == "interrupted")
      ++c.interrupted;
    else
      ++c.not_run;
  }
  return c;
}

}  // namespace gearsim::sweep
