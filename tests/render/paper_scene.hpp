// Render-test helpers: the paper's planetary set (sun 24, planets 36, ring 96, m = 1 mm) built
// in code, with planet 0 carrying the 43 µm flank error on tooth 0 and that tooth highlighted.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

#include "geometry/planetary.hpp"
#include "render/planetary_scene.hpp"
#include "tests/support/gear_specs.hpp"

namespace gearsim::test {

inline PlanetarySpec paper_planetary() { return {external_gear(24), external_gear(36, 0.010), internal_gear(96), 3}; }

inline GearSpec paper_faulty_planet() {
  GearSpec s = external_gear(36, 0.010);
  s.name = "planet_faulty";
  s.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  return s;
}

// Meshes with planet 0 faulty and its tooth 0 highlighted.
inline render::PlanetaryMeshes paper_meshes() {
  const PlanetarySpec s = paper_planetary();
  return render::planetary_meshes(s, {paper_faulty_planet(), s.planet, s.planet}, {{0, 0}});
}

// The set, its analysis (≈0.5 s: the interference check) and meshes, built once per test binary.
struct PaperSet {
  PlanetarySpec spec = paper_planetary();
  PlanetaryGeometry geometry = analyse_planetary(spec);
  render::PlanetaryMeshes meshes = paper_meshes();
};

inline const PaperSet& paper_set() {
  static const PaperSet set;
  return set;
}

inline std::filesystem::path golden_dir() { return std::filesystem::path(GEARSIM_SOURCE_DIR) / "tests" / "render" / "golden"; }

// A scratch folder for this test binary's outputs, inside the build tree.
inline std::filesystem::path output_dir(const std::string& name) {
  const std::filesystem::path p = std::filesystem::path(GEARSIM_BINARY_DIR) / "test_output" / "render" / name;
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace gearsim::test
