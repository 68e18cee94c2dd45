// The gathered table of a sweep: one row per case in index order — index, each parameter (the
// column named by its key path), status, then each metric (the collector's column names, which
// carry their units). Built only from the cases' case.json files, so it is the same bytes
// whichever ranks or threads ran the cases. Written as DIR/sweep.csv and DIR/sweep.h5.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gearsim::sweep {

struct TableRow {
  std::size_t index = 0;
  std::vector<std::string> parameters;  // value texts, in parameter-column order
  std::string status;  // a case status, or "not run" (no case.json)
  std::vector<std::optional<double>> metrics;  // in metric-column order; nothing: not collected
  std::string error;  // the case's error text (not in the CSV)
};

struct SweepTable {
  std::vector<std::string> parameter_columns;
  std::vector<std::string> metric_columns;  // every metric any case holds, in order of first appearance
  std::vector<TableRow> rows;
};

// Reads DIR/cases/<i>/case.json for i < case_count. InputError when a record is damaged or is of
// another case, or holds a metric that is neither a number nor null.
SweepTable gather_table(const std::filesystem::path& dir, const std::vector<std::string>& parameter_columns, std::size_t case_count);

// A metric as the CSV writes it: %.17g (reads back to the same double), "" when missing.
std::string metric_text(const std::optional<double>& v);

// CSV: a header, then one row per case; a cell with a comma, quote or newline is quoted.
void write_table_csv(const SweepTable& t, const std::filesystem::path& file);
// HDF5: one dataset per column under /table (index int64; parameters as numbers when every value
// of the column reads as one, else text; status text; metrics float64 with NaN where missing),
// and /table/columns listing the column names in order. No timestamps: same table, same bytes.
void write_table_h5(const SweepTable& t, const std::filesystem::path& file);

// Counts of a table's statuses.
struct StatusCounts {
  std::size_t completed = 0, diverged = 0, failed = 0, interrupted = 0, not_run = 0;
};
StatusCounts count_statuses(const SweepTable& t);

}  // namespace gearsim::sweep
