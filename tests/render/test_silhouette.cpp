// The renderer against geometry: a gear seen along its axis through an orthographic camera, drawn
// in one flat colour without anti-aliasing, covers as many pixels as its outline's area
// (geometry/outline.hpp) divided by the pixel area.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "geometry/extrude.hpp"
#include "geometry/gear_profile.hpp"
#include "render/renderer.hpp"
#include "tests/render/paper_scene.hpp"

namespace gearsim::render {
namespace test_silhouette {

constexpr int kSize_px = 400;

// Silhouette area of `spec`'s gear seen along −z, m², and the analytic area.
std::pair<double, double> silhouette_and_outline_area(const GearSpec& spec) {
  const GearOutline o = make_gear_outline(spec);
  Scene scene;
  SceneBody body;
  body.name = spec.name;
  body.mesh = std::make_shared<const TriMesh>(extrude(o.outline, -0.5 * spec.face_width_m, 0.5 * spec.face_width_m));
  body.colour = {255, 255, 255};
  scene.bodies.push_back(body);
  RenderSettings settings;
  settings.width_px = settings.height_px = kSize_px;
  settings.anti_aliasing = AntiAliasing::None;  // each pixel is in or out: its centre decides
  settings.lighting = Lighting::None;
  settings.background = {0, 0, 0};
  Renderer renderer(settings);
  Camera camera;
  camera.projection = Projection::Orthographic;
  camera.eye_m = {0, 0, 0.1};
  camera.view_height_m = 1.05 * 2 * std::max(o.dims.tip_radius_m, 0.5 * spec.rim_diameter_m);
  const Image image = renderer.render(scene, camera);
  const double pixel_m = camera.view_height_m / kSize_px;
  return {double(count_pixels_not(image, settings.background)) * pixel_m * pixel_m, area(o.outline)};
}

// Pixel centres sample the outline without bias; over ~10⁵ covered pixels and a few thousand
// edge pixels the count errs by ~0.1 %. The bound is 1 %.
constexpr double kRelativeTolerance = 0.01;

TEST(Silhouette, SunAreaMatchesItsOutline) {
  const auto [rendered, analytic] = silhouette_and_outline_area(test::external_gear(24));
  EXPECT_NEAR(rendered / analytic, 1.0, kRelativeTolerance) << rendered << " vs " << analytic << " m²";
}

TEST(Silhouette, FaultyPlanetAreaMatchesItsOutline) {
  const auto [rendered, analytic] = silhouette_and_outline_area(test::paper_faulty_planet());
  EXPECT_NEAR(rendered / analytic, 1.0, kRelativeTolerance) << rendered << " vs " << analytic << " m²";
}

TEST(Silhouette, RingAreaMatchesItsOutline) {
  const auto [rendered, analytic] = silhouette_and_outline_area(test::internal_gear(96));
  EXPECT_NEAR(rendered / analytic, 1.0, kRelativeTolerance) << rendered << " vs " << analytic << " m²";
}

}  // namespace test_silhouette
}  // namespace gearsim::render
