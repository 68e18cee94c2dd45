// The committed gear meshes in assets/gears are exactly what the spec generates today (the meshes
// are never hand-edited), and generation is deterministic.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "app/gear_report.hpp"
#include "input/gearset_file.hpp"
#include "geometry/mesh_io.hpp"

namespace gearsim::input {
namespace test_assets_current {

std::string bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void expect_current(const std::string& spec, const std::string& folder) {
  const std::filesystem::path src(GEARSIM_SOURCE_DIR);
  const GearSetFile f = load_gearset(src / spec);
  // One folder per test: ctest runs the tests of this file in parallel.
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() /
      ("gearsim_assets_check_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::create_directories(tmp);
  for (const GearSpec& s : f.gears) {
    const GearBody b = make_gear_body(s, f.density_kg_m3);
    for (auto [fmt, ext] : {std::pair{MeshFormat::StlBinary, ".stl"}, std::pair{MeshFormat::Obj, ".obj"}}) {
      export_mesh(b.mesh, tmp / (s.name + ext), fmt, LengthUnit::Millimetre);
      const std::string committed = bytes(src / folder / (s.name + ext));
      ASSERT_FALSE(committed.empty()) << s.name << ext << " missing from " << folder;
      EXPECT_TRUE(committed == bytes(tmp / (s.name + ext)))
          << s.name << ext << " differs: regenerate with gearsim gears " << spec << " --out " << folder;
    }
  }
  std::filesystem::remove_all(tmp);
}

TEST(Assets, PaperGearMeshesMatchTheirSpec) { expect_current("assets/specs/paper_gearset.yaml", "assets/gears"); }

TEST(Assets, SpurPairMeshesMatchTheirSpec) { expect_current("assets/specs/spur_pair_gearset.yaml", "assets/gears/spur_pair"); }

}  // namespace test_assets_current
}  // namespace gearsim::input
