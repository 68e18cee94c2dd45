// Reading back the tooth contacts of a per-step HDF5 log (step_log.hpp wrote it): one row per
// tooth-pair contact per step, column by column (formats 1 and 2, docs/hdf5-log.md). For analysis
// of a finished run; a reader of exactly what the writer documents, not a general HDF5 browser.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gearsim::sim {

struct StepLogContacts {
  double time_step_s = 0;
  std::vector<std::string> pairs;  // gear pair names "a__b", index = the `pair` column
  std::vector<double> time_s;  // the row's step time, s: time_step_s summed step times, as World::time_s()
  std::vector<std::int64_t> step, pair, tooth_a, tooth_b, flank_a;
  std::vector<double> normal_impulse_N_s;
};

// Throws InputError naming the file and the dataset when the file is not a gearsim step log.
StepLogContacts read_step_log_contacts(const std::filesystem::path& path);

}  // namespace gearsim::sim
