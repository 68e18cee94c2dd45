// A gear mesh brought into its gear frame wherever and however the CAD tool modelled it: about
// x, y or −z, off the origin. The frame's axis and origin land on the gear's, the tooth angles
// read as in the tool (seen from the positive end of its axis).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>
#include <numbers>

#include "geometry/extrude.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/mesh_gear.hpp"
#include "tests/support/gear_specs.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_mesh_gear {

using gearsim::constants::kPi;

// Gear 23 (m 1 mm, bore 8 mm) with tooth 0 at 5°, extruded 10 mm, moved by `pose`.
TriMesh posed_gear(const Eigen::Isometry3d& pose) {
  GearSpec s = test::external_gear(23);
  s.tooth0_angle_rad = 5 * kPi / 180;
  TriMesh m = extrude(make_gear_outline(s).outline, 0.0, 0.010);
  for (Eigen::Vector3d& v : m.vertices) v = pose * v;
  return m;
}

MeshGear gear_of(const TriMesh& m) {
  const Result<Prism> pr = recover_prism(m, kCadPrismTolerance_m);
  EXPECT_TRUE(pr.ok()) << pr.reason();
  return mesh_gear(pr.optional().value_or(Prism{}));
}

TEST(MeshGear, AGearOffTheOriginIsRecentredOnItsAxis) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.040, -0.025, 0.003);
  const MeshGear g = gear_of(posed_gear(pose));
  ASSERT_TRUE(g.recognition) << g.recognition.reason();
  EXPECT_EQ(g.recognition->teeth, 23);
  // The offset in the cap plane, and the frame origin on the axis at mid face width (1e-9 m:
  // the centroid of float-free vertices, exact to rounding).
  EXPECT_NEAR((g.axis_offset_m - Eigen::Vector2d(0.040, -0.025)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((g.origin_m - Eigen::Vector3d(0.040, -0.025, 0.008)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(g.recognition->axis_m.norm(), 0.0, 1e-12);
  EXPECT_NEAR(std::remainder(g.recognition->tooth0_angle_rad - 5 * kPi / 180, 2 * kPi / 23), 0.0, 1e-5);
  // A point on the axis maps to the gear frame's origin.
  EXPECT_NEAR(g.to_gear(Eigen::Vector3d(0.040, -0.025, 0.008)).norm(), 0.0, 1e-9);
}

TEST(MeshGear, AGearModelledAboutXKeepsItsTeethAndFaceWidth) {
  // Gear axis along world +x: rotate the z-modelled gear by +90° about y (z → x).
  Eigen::Isometry3d pose(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()));
  const MeshGear g = gear_of(posed_gear(pose));
  ASSERT_TRUE(g.recognition) << g.recognition.reason();
  EXPECT_EQ(g.recognition->teeth, 23);
  EXPECT_NEAR(g.face_width_m, 0.010, 1e-12);
  EXPECT_NEAR(std::abs(g.rotation.col(2).dot(Eigen::Vector3d::UnitX())), 1.0, 1e-12);
  EXPECT_TRUE(g.recognition->involute);
}

TEST(MeshGear, AGearModelledAboutMinusZIsMirroredIntoPlusZ) {
  // Turned over about x: its axis points along −z; seen from −z the teeth run the other way.
  Eigen::Isometry3d pose(Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitX()));
  const MeshGear g = gear_of(posed_gear(pose));
  ASSERT_TRUE(g.recognition) << g.recognition.reason();
  EXPECT_GT(g.rotation.col(2).z(), 0.0);
  // Turning over about x maps polar angle θ to −θ: tooth 0 at −5°.
  EXPECT_NEAR(std::remainder(g.recognition->tooth0_angle_rad + 5 * kPi / 180, 2 * kPi / 23), 0.0, 1e-5);
}

TEST(MeshGear, LayoutChecksNameWhatTheMeshShows) {
  const MeshGear g = gear_of(posed_gear(Eigen::Isometry3d::Identity()));
  ASSERT_TRUE(g.recognition);
  const RecognisedGear& r = *g.recognition;
  const double pitch = 2 * kPi / 23, t0 = 5 * kPi / 180;
  EXPECT_TRUE(check_layout(r, {23, t0}));
  EXPECT_TRUE(check_layout(r, {23, t0 + 7 * pitch}));  // another tooth numbered 0: same layout
  EXPECT_TRUE(check_layout(r, {23, t0 + 0.015 * pitch}));  // within 2 % of a pitch
  EXPECT_NE(check_layout(r, {23, t0 + 0.5 * pitch}).reason().find("50 % of a pitch"), std::string::npos);
  EXPECT_NE(check_layout(r, {24, t0}).reason().find("24 teeth given, the mesh shows 23"), std::string::npos);
  EXPECT_TRUE(check_unit(r, LengthUnit::Millimetre));
}

// OpenSCAD MCAD gears (tests/data/mcad: module 1 mm, 20°, 5 facets per involute, a radial flank
// from the root up to the base circle): the z 24 wheel has one vertex per flank in the usual
// 60–90 % window of the depth, so the fit must widen to the whole flank. Both recognised gears
// carry the base radius z·m·cos α / 2 their generator used within 0.5 µm (a two-parameter fit
// through six vertices a flank near the base circle; 0.5 µm is 0.01 % of r_b, far inside the
// 0.2 % that separates standard pressure angles).
TEST(MeshGear, CoarselyFacetedMcadInvolutesGiveTheirBaseCircles) {
  for (int z : {12, 24}) {
    const std::string file = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/mcad_m1_z" + std::to_string(z) + "_a20_f5_b005.stl";
    const MeshGearFile f = read_mesh_gear(file, LengthUnit::Millimetre);
    ASSERT_TRUE(f.gear.has_value()) << f.prism.reason();
    ASSERT_TRUE(f.gear->recognition.ok()) << f.gear->recognition.reason();
    const RecognisedGear& g = *f.gear->recognition;
    EXPECT_EQ(g.teeth, z);
    ASSERT_TRUE(g.involute) << "z " << z;
    const double rb = 0.5 * z * 1e-3 * std::cos(20 * kPi / 180);
    EXPECT_NEAR(g.ccw.base_radius_m, rb, 0.5e-6) << "z " << z;
    EXPECT_NEAR(g.cw.base_radius_m, rb, 0.5e-6) << "z " << z;
    EXPECT_TRUE(g.standard) << "z " << z;
    EXPECT_NEAR(g.module_m, 1e-3, 1e-12) << "z " << z;
    EXPECT_NEAR(g.pressure_angle_rad, 20 * kPi / 180, 1e-9) << "z " << z;
  }
}

// FreeCAD 0.20's exports (tests/data/freecad, made there by FreeCAD): a z 6 gear whose flank faces
// were meshed with 824 vertices between the caps (0.002 mm deflection), refused as "not a
// prism" before side-wall vertices were accepted; a 12 mm ring whose largest cap triangle ranks
// 211th by area, after 75 wall directions, refused along a wall's normal before the axis came
// from the area of every face.
TEST(MeshGear, FreecadExportsAreThePrismsOfTheirGears) {
  const std::string dir = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/";
  const MeshGearFile z6 = read_mesh_gear(dir + "fc_m1_z6_a25_face1_l0p002r0p5.stl", LengthUnit::Millimetre);
  ASSERT_TRUE(z6.gear.has_value()) << z6.prism.reason();
  EXPECT_NEAR(z6.gear->face_width_m, 1e-3, 1e-9);
  ASSERT_TRUE(z6.gear->recognition.ok()) << z6.gear->recognition.reason();
  EXPECT_EQ(z6.gear->recognition->teeth, 6);
  EXPECT_FALSE(z6.gear->recognition->internal);
  ASSERT_TRUE(z6.gear->recognition->involute);
  // r_b = m·z·cos 25°/2 = 2.7189 mm; FreeCAD's Bézier flanks read 2.1 µm inside it.
  EXPECT_NEAR(z6.gear->recognition->base_radius_m, 3e-3 * std::cos(25 * kPi / 180), 3e-6);
  const MeshGearFile ring = read_mesh_gear(dir + "fcring_m1_z30_a25_face12_l0p1r0p5.stl", LengthUnit::Millimetre);
  ASSERT_TRUE(ring.gear.has_value()) << ring.prism.reason();
  EXPECT_NEAR(std::abs(ring.prism->frame.z.z()), 1.0, 1e-12);
  EXPECT_NEAR(ring.gear->face_width_m, 12e-3, 1e-9);
  ASSERT_TRUE(ring.gear->recognition.ok()) << ring.gear->recognition.reason();
  EXPECT_EQ(ring.gear->recognition->teeth, 30);
  EXPECT_TRUE(ring.gear->recognition->internal);
}

TEST(MeshGear, CoarseFreecadExportsWithCurvedWallsTessellatedBetweenTheCapsAreTheirGears) {
  // FreeCAD at 0.1 mm / 0.5 rad puts vertices on the bore cylinder at mid-height, 33.8 µm outside
  // the caps' chords; at 0.02 mm / 10° on the flanks and fillets at ten heights, up to 6.9 µm
  // outside (tests/data/freecad/README.md). Both are prisms of their caps within the chords'
  // sagitta, and their gears.
  const std::string dir = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/freecad/";
  struct Case {
    const char* file;
    int teeth;
    double face_m, deviation_m;
  };
  for (const Case& c : {Case{"fc_m3_z17_a20_l0p1r0p5.stl", 17, 12e-3, 33.8e-6}, Case{"fc_m3_z16_a25_l0p02a10.stl", 16, 12e-3, 6.9e-6}}) {
    const MeshGearFile f = read_mesh_gear(dir + c.file, LengthUnit::Millimetre);
    ASSERT_TRUE(f.gear.has_value()) << c.file << ": " << f.prism.reason();
    EXPECT_NEAR(f.prism->wall_deviation_m, c.deviation_m, 0.1e-6) << c.file;
    EXPECT_NEAR(f.gear->face_width_m, c.face_m, 1e-9) << c.file;
    ASSERT_TRUE(f.gear->recognition.ok()) << c.file << ": " << f.gear->recognition.reason();
    EXPECT_EQ(f.gear->recognition->teeth, c.teeth) << c.file;
    EXPECT_FALSE(f.gear->recognition->internal) << c.file;
  }
}

// CAD exports carry coordinate noise: ±0.5 µm drawn for every coordinate of every vertex (so
// the caps are no longer planes and top and bottom outlines differ by up to 1 µm) still reads as
// the prism of the 23-tooth gear, its base circle within the 2 µm of the acceptance.
TEST(MeshGear, HalfAMicrometreOfVertexNoiseIsStillTheGear) {
  TriMesh m = posed_gear(Eigen::Isometry3d::Identity());
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // ±0.5 µm, a fixed LCG: the same mesh every run
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 1e-6;
  };
  for (Eigen::Vector3d& v : m.vertices) v += Eigen::Vector3d(uniform(), uniform(), uniform());
  const MeshGear g = gear_of(m);
  ASSERT_TRUE(g.recognition) << g.recognition.reason();
  const RecognisedGear& r = *g.recognition;
  EXPECT_EQ(r.teeth, 23);
  ASSERT_TRUE(r.involute);
  EXPECT_NEAR(r.base_radius_m, 0.5 * 23e-3 * std::cos(20 * kPi / 180), 2e-6);
  EXPECT_NEAR(g.face_width_m, 0.010, 1e-6);
}

}  // namespace test_mesh_gear
}  // namespace gearsim
