// Rendered frames against committed golden images (Magnum's CompareImage idea): per-channel
// differences must stay under a max and a mean threshold. Regenerate after an intended change
// with GEARSIM_UPDATE_GOLDEN=1 (writes tests/render/golden/*.png); on a failure the frame is
// written to the build tree's test_output/render/golden/ for a look.
#include <gtest/gtest.h>

#include <cstdlib>
#include <numbers>

#include "geometry/planetary.hpp"
#include "render/planetary_pose.hpp"
#include "render/png_io.hpp"
#include "render/renderer.hpp"
#include "tests/render/paper_scene.hpp"

namespace gearsim::render {
namespace test_golden {

// Thresholds, per channel on 0–255. llvmpipe is deterministic on one machine (same Mesa, same
// LLVM): reruns are bit-identical. Another Mesa/LLVM may round shading differently (±2) and
// decide a pixel whose centre lies on an edge the other way; edge anti-aliasing then moves that
// pixel's share across the edge by its distance to the edge (< ¼ of a ~190 gear/background step
// ≈ 48 for a centre within ¼ px of the edge), so:
//  - max 64: a pixel at an edge decided the other way passes; a missing or moved tooth highlight
//    (a 200+ step over many pixels) does not;
//  - mean 0.3: scattered edge samples pass; turning the set by half a tooth pitch (mean 2.7,
//    max 244) or shifting the picture by one pixel does not (both checked below).
constexpr double kMaxThreshold = 64;
constexpr double kMeanThreshold = 0.3;

using Paper = test::PaperSet;

RenderSettings golden_settings() {
  RenderSettings s;  // edge anti-aliasing, Blinn–Phong, 30° crease angle
  s.width_px = 320;
  s.height_px = 240;
  s.text_scale = 1;
  return s;
}

// The whole set, tilted 30° to show depth, with planet 0's faulty tooth at the ring mesh.
Image overview(Renderer& r, const Paper& p, double extra_carrier_rad = 0) {
  const double period = 2 * std::numbers::pi * p.spec.planet.teeth / p.spec.ring.teeth;
  const double carrier = carrier_angle_tooth_at_sun(p.spec, p.geometry, 0, 0) + 0.5 * period + extra_carrier_rad;
  Scene scene = planetary_scene(p.meshes, kinematic_planetary_pose(p.spec, p.geometry, carrier));
  scene.overlay_lines = {"overview", "carrier " + std::to_string(carrier).substr(0, 5) + " rad"};
  return r.render(scene, overview_camera(scene_bounds(scene), r.aspect(), 30 * std::numbers::pi / 180));
}

// The faulty tooth in the middle of the sun mesh, seen along the mesh from above, with a contact force.
Image closeup(Renderer& r, const Paper& p) {
  const PlanetaryPose pose = kinematic_planetary_pose(p.spec, p.geometry, carrier_angle_tooth_at_sun(p.spec, p.geometry, 0, 0));
  Scene scene = planetary_scene(p.meshes, pose);
  const Eigen::Vector3d contact = sun_mesh_point(p.spec, p.geometry, pose, 0, 0.5 * p.spec.sun.face_width_m);
  const double beta = pose.carrier_angle_rad;
  const Eigen::Vector3d tangent(-std::sin(beta), std::cos(beta), 0);
  scene.contacts.push_back({contact, 150.0 * tangent});  // 150 N on the sun, drawn 1 mm per 50 N
  scene.arrow_m_per_N = 1e-3 / 50;
  scene.overlay_lines = {"planet 0, tooth 0 at the sun"};
  const Eigen::Vector3d view = tangent - 0.7 * Eigen::Vector3d::UnitZ();  // along the mesh, 35° down
  return r.render(scene, closeup_camera(contact, view, 12e-3));
}

void expect_matches_golden(const Image& frame, const std::string& name) {
  const std::filesystem::path golden = test::golden_dir() / (name + ".png");
  if (std::getenv("GEARSIM_UPDATE_GOLDEN")) write_png(frame, golden);
  const ImageDifference d = compare_images(frame, read_png(golden));
  EXPECT_LE(d.max, kMaxThreshold) << name;
  EXPECT_LE(d.mean, kMeanThreshold) << name;
  if (d.max > kMaxThreshold || d.mean > kMeanThreshold) write_png(frame, test::output_dir("golden") / (name + ".png"));
}

TEST(Golden, OverviewMatches) {
  Renderer r(golden_settings());
  expect_matches_golden(overview(r, test::paper_set()), "overview");
}

TEST(Golden, CloseUpOnTheFaultyToothMatches) {
  Renderer r(golden_settings());
  expect_matches_golden(closeup(r, test::paper_set()), "closeup_faulty_tooth");
}

// The thresholds must see a real change: the set turned by half a planet tooth pitch.
TEST(Golden, ThresholdsCatchHalfAToothOfRotation) {
  Renderer r(golden_settings());
  const Paper& p = test::paper_set();
  const double half_tooth_carrier = std::numbers::pi / p.spec.ring.teeth;  // planet moves ½ ring pitch
  const ImageDifference d = compare_images(overview(r, p, half_tooth_carrier), read_png(test::golden_dir() / "overview.png"));
  EXPECT_GT(d.mean, kMeanThreshold);
  EXPECT_GT(d.max, kMaxThreshold);
}

TEST(Golden, ThresholdsCatchAOnePixelShift) {
  const Image golden = read_png(test::golden_dir() / "closeup_faulty_tooth.png");
  Image shifted = golden;
  for (int y = 0; y < golden.height_px; ++y)
    for (int x = 1; x < golden.width_px; ++x) shifted.set(x, y, golden.at(x - 1, y));
  const ImageDifference d = compare_images(shifted, golden);
  EXPECT_GT(d.mean, kMeanThreshold);
}

}  // namespace test_golden
}  // namespace gearsim::render
