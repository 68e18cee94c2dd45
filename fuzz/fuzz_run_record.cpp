// libFuzzer target: the input as a run folder's records, through the readers that `analyze`,
// `report` and `render` use on them. Byte 0 picks the record, the rest is its bytes:
//  0: scenario.json (read_scenario_record: the expanded scenario, validated like a scenario file);
//  1: summary.json (parsed and validate_summary_record());
//  2: .gearsim-manifest (FolderManifest::read: no name may leave the folder).
// An InputError is an expected rejection; any other exception escapes, and libFuzzer reports it.
#include <cstddef>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/folder_manifest.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "input/run_record_check.hpp"
#include "input/scenario_record.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const gearsim::fuzz::InputFolder folder("run_record");
  if (size == 0) return 0;
  const char* const names[] = {"scenario.json", "summary.json", gearsim::FolderManifest::kFileName};
  const int which = data[0] % 3;
  const auto file = folder.write(names[which], data + 1, size - 1);
  try {
    if (which == 0) (void)gearsim::input::read_scenario_record(folder.dir());
    if (which == 1) {
      const auto j = nlohmann::ordered_json::parse(data + 1, data + size, nullptr, false);
      if (!j.is_discarded()) gearsim::input::validate_summary_record(j, file.string());
    }
    if (which == 2) (void)gearsim::FolderManifest::read(folder.dir());
  } catch (const gearsim::InputError&) {
    // Refused naming the file and key: expected for most inputs.
  }
  return 0;
}
