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

SweepTable gather_table(const std::filesystem::path& dir, const std::vector<std::string>& parameter_columns,
                        std::size_t case_count) {
  SweepTable t;
  t.parameter_columns = parameter_columns;
  std::vector<std::optional<CaseRecord>> records;
  for (std::size_t i = 0; i < case_count; ++i) {
    records.push_back(read_case_record(case_dir(dir, i)));
    if (!records.back()) continue;
    if (records.back()->index != i)
      throw InputError((case_dir(dir, i) / "case.json").string() + ": key index: " + std::to_string(records.back()->index) +
                       ", expected " + std::to_string(i) + " (the record of another case)");
    add_columns(t, records.back()->metrics);
  }
  for (std::size_t i = 0; i < case_count; ++i) {
    TableRow row;
    row.index = i;
    row.status = records[i] ? status_name(records[i]->status) : "not run";
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
        if (j.is_number()) v = j.get<double>();
        else if (!j.is_null())
          throw InputError((case_dir(dir, i) / "case.json").string() + ": key metrics." + m + ": expected a number or null");
      }
      row.metrics.push_back(v);
    }
    if (records[i]) row.error = records[i]->error;
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
  std::ofstream out = open_output_file(file);
  if (!out) throw InputError(file.string() + ": cannot write");
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
  if (!out) throw InputError(file.string() + ": cannot write");
}

StatusCounts count_statuses(const SweepTable& t) {
  StatusCounts c;
  for (const TableRow& r : t.rows) {
    if (r.status == "completed") ++c.completed;
    else if (r.status == "diverged") ++c.diverged;
    else if (r.status == "failed") ++c.failed;
    else if (r.status == "interrupted") ++c.interrupted;
    else ++c.not_run;
  }
  return c;
}

}  // namespace gearsim::sweep
