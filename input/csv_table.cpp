#include "input/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "input/input_limits.hpp"

namespace gearsim::input {

bool CsvTable::has(const std::string& name) const { return std::find(columns.begin(), columns.end(), name) != columns.end(); }

const std::vector<double>& CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw InputError(path.string() + ": no column '" + name + "'");
  return data[static_cast<std::size_t>(it - columns.begin())];
}

CsvTable read_csv(const std::filesystem::path& path) {
  InputFile in(path, limits::kMaxCsvLogBytes, "a run's CSV log");
  CsvTable t;
  t.path = path;
  std::string line;
  if (!std::getline(in, line)) throw InputError(path.string() + ": empty file, expected a header row");
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) t.columns.push_back(name);
  t.data.assign(t.columns.size(), {});
  for (long n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::size_t c = 0, start = 0;
    while (start <= line.size()) {
      const std::size_t end = std::min(line.find(',', start), line.size());
      if (c >= t.columns.size())
        throw InputError(path.string() + ":" + std::to_string(n) + ": more values than the " + std::to_string(t.columns.size()) +
                         " columns of the header");
      double v = 0;
      const auto [ptr, ec] = std::from_chars(line.data() + start, line.data() + end, v);
      if (ec != std::errc() || ptr != line.data() + end)
        throw InputError(path.string() + ":" + std::to_string(n) + ": column '" + t.columns[c] + "': '" + line.substr(start, end - start) +
                         "' is not a number");
      t.data[c].push_back(v);
      ++c;
      start = end + 1;
    }
    if (c != t.columns.size())
      throw InputError(path.string() + ":" + std::to_string(n) + ": " + std::to_string(c) + " values, expected " +
                       std::to_string(t.columns.size()));
  }
  return t;
}

}  // namespace gearsim::input
