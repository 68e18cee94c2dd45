// libFuzzer target: the input as a scenario file, through the real loader (load_scenario: YAML,
// macros, gear specs and mesh files it names, every check). The file is written as
// scenarios/input.yaml in a private folder whose specs/, gears/ and data/ link to the
// repository's assets/specs, assets/gears and tests/data, so that the seed scenarios'
// relative paths (../specs/paper_gearset.yaml, ../gears/spur_pair/pinion.stl,
// ../data/mcad/…) resolve as from assets/scenarios. An InputError is an expected rejection;
// any other exception escapes, and libFuzzer reports it as a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>

#include "input/scenario_file.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "core/errors.hpp"

namespace {

namespace fs = std::filesystem;

// The repository: $GEARSIM_SOURCE_DIR, else the one this target was built from.
fs::path source_dir() {
  const char* env = std::getenv("GEARSIM_SOURCE_DIR");
  return env && *env ? fs::path(env) : fs::path(GEARSIM_SOURCE_DIR);
}

// scenarios/ for the input; specs/, gears/ and data/ linked to the repository's.
bool link_assets(const fs::path& dir) {
  const fs::path src = source_dir();
  fs::create_directory(dir / "scenarios");
  fs::create_directory_symlink(src / "assets/specs", dir / "specs");
  fs::create_directory_symlink(src / "assets/gears", dir / "gears");
  fs::create_directory_symlink(src / "tests/data", dir / "data");
  return true;
}

const gearsim::fuzz::InputFolder& scenario_folder() {
  static const gearsim::fuzz::InputFolder folder("scenario");
  [[maybe_unused]] static const bool linked = link_assets(folder.dir());
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path file = scenario_folder().write("scenarios/input.yaml", data, size);
  try {
    (void)gearsim::input::load_scenario(file);
  } catch (const gearsim::InputError&) {
    // Refused with a message naming file, line and key: expected for most inputs.
  }
  return 0;
}
