// libFuzzer target: the input as `--set` overrides (one per line) on a small valid scenario (a
// wheel on a hinge), through load_scenario: the key path's parser, the value's YAML (aliases,
// depth, keys given twice), the edited tree's validation. An InputError is an expected rejection;
// any other exception escapes, and libFuzzer reports it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "input/scenario_file.hpp"

namespace {

constexpr char kWheel[] =
    "name: t\n"
    "duration_s: 0.1\n"
    "bodies:\n"
    "  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
    "joints:\n"
    "  - {name: hinge, body: wheel}\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const gearsim::fuzz::InputFolder folder("set");
  static const auto scenario = folder.write("wheel.yaml", reinterpret_cast<const std::uint8_t*>(kWheel), sizeof kWheel - 1);
  std::vector<std::string> overrides;
  std::string line;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n')
      overrides.push_back(line), line.clear();
    else
      line += static_cast<char>(data[i]);
  }
  overrides.push_back(line);
  try {
    (void)gearsim::input::load_scenario(scenario, overrides);
  } catch (const gearsim::InputError&) {
    // Refused naming the --set and the key: expected for most inputs.
  }
  return 0;
}
