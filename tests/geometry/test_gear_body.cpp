// The paper's four gears through the whole pipeline: watertight mesh, exact convex pieces with
// tooth indices, measured union deviation, mass properties of the prism.
#include <gtest/gtest.h>

#include <set>

#include "geometry/gear_body.hpp"
#include "geometry/hausdorff.hpp"
#include "geometry/mesh_validate.hpp"
#include "tests/support/gear_specs.hpp"

namespace gearsim {
namespace test_gear_body {

class PaperGear : public ::testing::TestWithParam<GearSpec> {};

TEST_P(PaperGear, MeshIsAWatertightOutwardSolid) {
  const GearBody b = make_gear_body(GetParam(), 7580);
  const MeshReport r = validate_mesh(b.mesh);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.outward_oriented());
}

TEST_P(PaperGear, VolumeIsOutlineAreaTimesFaceWidth) {
  const GearBody b = make_gear_body(GetParam(), 7580);
  // Prism volume = area · b; both sums are exact up to rounding (1e-12 relative).
  EXPECT_NEAR(b.mass.volume_m3, area(b.outline.outline) * b.spec.face_width_m, 1e-12 * b.mass.volume_m3);
}

TEST_P(PaperGear, ConvexPiecesAreExactAndEveryToothHasItsOwn) {
  const GearBody b = make_gear_body(GetParam(), 7580);
  EXPECT_TRUE(b.decomposition.sectors_exact);
  std::set<int> teeth;
  for (const ConvexPiece2& p : b.decomposition.pieces) {
    EXPECT_TRUE(is_convex(p.polygon));
    teeth.insert(p.tooth);
  }
  EXPECT_EQ(static_cast<int>(teeth.size()), b.spec.teeth);
  EXPECT_EQ(*teeth.begin(), 0);
  EXPECT_EQ(*teeth.rbegin(), b.spec.teeth - 1);
  // Measured: every mesh vertex is sampled, edges and faces every 0.5 mm. The bound is
  // 1 µm; the pieces reuse the outline's vertices, so only rounding separates them.
  const DecompositionDeviation d = decomposition_deviation(b.mesh, b.pieces, 0.5e-3);
  EXPECT_LE(d.hausdorff_m, 1e-6);
  EXPECT_NEAR(d.relative_volume_error, 0.0, 1e-12);
}

GearSpec faulty_planet() {
  GearSpec s = test::external_gear(36, 0.010);
  s.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Paper, PaperGear, ::testing::Values(test::external_gear(24), test::external_gear(36, 0.010), faulty_planet(), test::internal_gear(96)),
    [](const ::testing::TestParamInfo<GearSpec>& i) { return std::string(i.index == 2 ? "faulty_planet" : i.param.name); });

}  // namespace test_gear_body
}  // namespace gearsim
