// What the renderer draws, read back from unlit, un-anti-aliased frames: bodies in their colours
// where the camera puts them, the highlight, contact markers and force arrows over the bodies,
// overlay text, and the mesh cache that follows the meshes' owners.
#include <gtest/gtest.h>

#include <memory>

#include "render/renderer.hpp"
#include "render/shading_mesh.hpp"

namespace gearsim::render {
namespace test_renderer {

constexpr Rgb kRed{200, 10, 10};

RenderSettings flat() {
  RenderSettings s;
  s.width_px = 100;
  s.height_px = 100;
  s.lighting = Lighting::None;
  s.anti_aliasing = AntiAliasing::None;
  s.text_scale = 1;
  return s;
}

// Orthographic, along −z, 0.1 m tall: 1 px = 1 mm, +x right, +y up, origin at pixel (50, 50).
Camera top_view() {
  Camera c;
  c.projection = Projection::Orthographic;
  c.eye_m = {0, 0, 0.5};
  c.view_height_m = 0.1;
  return c;
}

Scene ball_at(const Eigen::Vector3d& centre_m, double radius_m) {
  Scene s;
  SceneBody b;
  b.name = "ball";
  b.mesh = std::make_shared<const TriMesh>(sphere_mesh({0, 0, 0}, radius_m, 24));
  b.pose.translation() = centre_m;
  b.colour = kRed;
  s.bodies.push_back(b);
  return s;
}

TEST(Renderer, BodyAppearsWhereItsPosePutsIt) {
  Renderer r(flat());
  const Image im = r.render(ball_at({0.03, 0.02, 0}, 0.005), top_view());
  EXPECT_EQ(im.at(80, 30), kRed);  // x = +30 mm → column 80; y = +20 mm → row 30 (rows run down)
  EXPECT_EQ(im.at(50, 50), flat().background);
  EXPECT_NEAR(double(count_pixels_not(im, flat().background)), 3.14159 * 25, 6.0);  // π r² in px
}

TEST(Renderer, HighlightedTrianglesTakeTheHighlightColour) {
  Renderer r(flat());
  Scene s = ball_at({0, 0, 0}, 0.02);
  s.bodies[0].highlight = std::make_shared<const std::vector<std::uint8_t>>(s.bodies[0].mesh->triangles.size(), 1);
  s.bodies[0].highlight_colour = {10, 200, 10};
  EXPECT_EQ(r.render(s, top_view()).at(50, 50), (Rgb{10, 200, 10}));
}

TEST(Renderer, ContactMarkerAndForceArrowAreDrawnOverTheBodies) {
  Renderer r(flat());
  Scene s = ball_at({0, 0, 0}, 0.04);  // the contact point lies inside this body
  s.contacts.push_back({{0, 0, 0}, {-200, 0, 0}});  // 200 N along −x
  s.arrow_m_per_N = 1e-4;  // 20 mm arrow
  s.marker_radius_m = 2e-3;
  const Image im = r.render(s, top_view());
  EXPECT_EQ(im.at(50, 50), s.marker_colour);
  EXPECT_EQ(im.at(40, 50), s.arrow_colour);  // 10 mm along the arrow
  EXPECT_EQ(im.at(60, 50), kRed);  // behind the point: the body
}

TEST(Renderer, OverlayTextIsDrawnTopLeft) {
  Renderer r(flat());
  Scene s = ball_at({0.03, -0.03, 0}, 0.005);
  const Image plain = r.render(s, top_view());
  s.overlay_lines = {"t = 0.5 s"};
  const Image text = r.render(s, top_view());
  long changed = 0;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 60; ++x) changed += text.at(x, y) != plain.at(x, y);
  EXPECT_GT(changed, 300);
  EXPECT_EQ(text.at(80, 80), plain.at(80, 80));
}

// Rows [first, last] holding anything but the background, or {-1, -1}.
std::pair<int, int> covered_rows(const Image& im, Rgb background) {
  int first = -1, last = -1;
  for (int y = 0; y < im.height_px; ++y)
    for (int x = 0; x < im.width_px; ++x)
      if (im.at(x, y) != background) {
        if (first < 0) first = y;
        last = y;
      }
  return {first, last};
}

TEST(Renderer, OverviewPresetFramesTheWholeScene) {
  Renderer r(flat());
  const Scene s = ball_at({0.1, 0.2, 0.3}, 0.05);  // far from the origin: the preset must find it
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    const Image im = r.render(s, overview_camera(scene_bounds(s), r.aspect(), 0.0, projection));
    const auto [first, last] = covered_rows(im, flat().background);
    // Inside the frame with the preset's 5 % margin, filling most of it (the preset fits the
    // bounding box: the ball spans 95 % orthographic, less in perspective, where the box's near
    // corners spread wider than the ball does).
    EXPECT_GT(first, 0);
    EXPECT_LT(last, im.height_px - 1);
    EXPECT_GT(last - first + 1, (projection == Projection::Orthographic ? 0.9 : 0.7) * im.height_px);
  }
}

TEST(Renderer, MeshCacheFollowsTheMeshOwners) {
  Renderer r(flat());
  const Scene kept = ball_at({0, 0, 0}, 0.01);
  for (int i = 0; i < 3; ++i) r.render(ball_at({0, 0, 0}, 0.01), top_view());  // a new mesh each frame
  EXPECT_EQ(r.cached_mesh_count(), 1u);  // the last one, freed at the next frame
  r.render(kept, top_view());
  r.render(kept, top_view());
  EXPECT_EQ(r.cached_mesh_count(), 1u);
}

}  // namespace test_renderer
}  // namespace gearsim::render
