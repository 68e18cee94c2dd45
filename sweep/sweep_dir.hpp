// A sweep's output folder DIR: DIR/sweep.json (which sweep file, by content hash, the case count
// and columns: what resume and `gearsim report` read), DIR/cases/<index>/ (one run folder and
// case.json per case), DIR/sweep.csv and DIR/sweep.h5 (the gathered table). Everything the sweep
// writes stays inside DIR under these fixed names. Not the runner.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "input/sweep_file.hpp"

namespace gearsim::sweep {

// DIR/cases/<index zero-padded>.
std::filesystem::path case_dir(const std::filesystem::path& dir, std::size_t index);

// Makes DIR ready for the sweep. With `fresh`, first removes DIR's sweep outputs (cases/,
// sweep.json, sweep.csv, sweep.h5, report.html; other files stay). Without it, InputError when
// DIR/sweep.json records a sweep file of other content (the hash differs): resuming would mix
// cases of two sweeps. Writes DIR/sweep.json. Returns how many sweep outputs were removed.
int prepare_sweep_dir(const std::filesystem::path& dir, const input::SweepFile& file, bool fresh);

// DIR/sweep.json; InputError when DIR holds none or it is damaged.
nlohmann::ordered_json read_sweep_json(const std::filesystem::path& dir);
bool is_sweep_dir(const std::filesystem::path& dir);

}  // namespace gearsim::sweep
