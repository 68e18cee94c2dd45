// A numeric CSV file with a header row, as `gearsim run` writes them (state.csv, contacts.csv):
// read whole, by column. Bad input names the file, line and column. Not a general CSV parser
// (no quoting, numbers only).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gearsim::input {

struct CsvTable {
  std::filesystem::path path;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> data;  // data[c][row]

  bool has(const std::string& column) const;
  // The column's values; InputError naming the file and column when it is absent.
  const std::vector<double>& column(const std::string& name) const;
  std::size_t rows() const { return data.empty() ? 0 : data.front().size(); }
};

CsvTable read_csv(const std::filesystem::path& path);

}  // namespace gearsim::input
