// libFuzzer target: the input as a mesh file, through what a scenario does with a mesh named in
// it (read_mesh_gear: import, validation as a solid, prism recovery, gear recognition), then the
// checks against a tooth layout and the unit. The first byte picks the unit; the rest is the file
// (STL, binary or ASCII as Assimp detects it, or, in fuzz_mesh_obj, OBJ). An InputError is an expected
// rejection; any other exception escapes, and libFuzzer reports it as a crash.
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "fuzz/fuzz_input_file.hpp"
#include "core/errors.hpp"
#include "geometry/mesh_gear.hpp"

namespace {

using namespace gearsim;

// The format this target feeds: fuzz_mesh STL (binary or ASCII, as Assimp detects it),
// fuzz_mesh_obj OBJ. Two targets rather than a byte choosing: Assimp's OBJ importer allocates and
// fills a 16 MiB line buffer per file (IOStreamBuffer), ~80 ms a file under ASan here (5 800 fresh
// pages) against ~3–7 ms for an STL, and a mixed corpus spends its time on it.
#ifdef GEARSIM_FUZZ_MESH_OBJ
constexpr bool kObj = true;
#else
constexpr bool kObj = false;
#endif

// The units a scenario gives meshes most: mm (CAD), m, inch.
constexpr LengthUnit kUnits[] = {LengthUnit::Millimetre, LengthUnit::Metre, LengthUnit::Inch};

void read_as_scenario_does(const std::filesystem::path& file, LengthUnit unit) {
  const MeshGearFile f = read_mesh_gear(file, unit);
  if (!f.gear || !f.gear->recognition) return;
  const RecognisedGear& g = *f.gear->recognition;
  (void)check_unit(g, unit);
  // A layout as a scenario would give it: the recognised count, tooth 0 a small angle off.
  (void)check_layout(g, ToothLayout{g.teeth, g.tooth0_angle_rad + 0.3 * std::numbers::pi / 180});
  (void)check_layout(g, ToothLayout{g.teeth + 1, 0.0});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fuzz::InputFolder folder("mesh");
  if (size < 1) return 0;
  const LengthUnit unit = kUnits[data[0] % 3];
  const std::filesystem::path file = folder.write(kObj ? "input.obj" : "input.stl", data + 1, size - 1);
  try {
    read_as_scenario_does(file, unit);
  } catch (const InputError&) {
    // Refused with a message: expected for most inputs.
  }
  return 0;
}
