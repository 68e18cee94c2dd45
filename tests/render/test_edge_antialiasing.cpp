// Edge anti-aliasing (render/edge_antialiasing.hpp) against closed forms and a reference: pixels
// along a straight edge take the exact area fraction of a square cut by a line (polygon clipping
// in the test); a gear's anti-aliased silhouette holds its outline's area in its grey levels; the
// paper's frames come closer to a 16-sample supersampled reference than frames without it; and
// only edges that outline what was drawn, and are not hidden, blend pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geometry/extrude.hpp"
#include "geometry/gear_profile.hpp"
#include "render/constants.hpp"
#include "render/edge_antialiasing.hpp"
#include "render/planetary_pose.hpp"
#include "render/renderer.hpp"
#include "tests/render/paper_scene.hpp"

namespace gearsim::render {
namespace test_edge_antialiasing {

using Eigen::Vector2d;

constexpr Rgb kWhite{255, 255, 255}, kBlack{0, 0, 0};

// White bodies on black, unlit: a pixel's grey level is 255 × its covered fraction.
RenderSettings coverage_settings(int size_px, AntiAliasing aa) {
  RenderSettings s;
  s.width_px = s.height_px = size_px;
  s.anti_aliasing = aa;
  s.lighting = Lighting::None;
  s.background = kBlack;
  return s;
}

// Orthographic, along −z, 1 px = 1 mm, world origin at the frame's centre, +y up.
Camera top_view(int size_px) {
  Camera c;
  c.projection = Projection::Orthographic;
  c.eye_m = {0, 0, 0.5};
  c.view_height_m = 1e-3 * size_px;
  return c;
}

Scene white_prism(const Polygon2& outline_m, double thickness_m) {
  SceneBody b;
  b.name = "prism";
  b.mesh = std::make_shared<const TriMesh>(extrude_convex(outline_m, -thickness_m, 0));
  b.colour = kWhite;
  Scene s;
  s.bodies.push_back(b);
  return s;
}

// Area of the unit-less polygon `p` clipped to the half-planes on the left of each directed side
// of the convex counter-clockwise polygon `convex` (Sutherland–Hodgman), by the shoelace formula.
double clipped_area(std::vector<Vector2d> p, const std::vector<Vector2d>& convex) {
  for (std::size_t i = 0; i < convex.size() && !p.empty(); ++i) {
    const Vector2d a = convex[i], d = convex[(i + 1) % convex.size()] - a;
    const auto inside = [&](const Vector2d& q) { return d.x() * (q.y() - a.y()) - d.y() * (q.x() - a.x()) >= 0; };
    std::vector<Vector2d> out;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vector2d& s = p[j];
      const Vector2d& e = p[(j + 1) % p.size()];
      const double ds = d.x() * (s.y() - a.y()) - d.y() * (s.x() - a.x());
      const double de = d.x() * (e.y() - a.y()) - d.y() * (e.x() - a.x());
      if (inside(s)) out.push_back(s);
      if ((ds >= 0) != (de >= 0)) out.push_back(s + (ds / (ds - de)) * (e - s));
    }
    p = out;
  }
  double twice = 0;
  for (std::size_t j = 0; j < p.size(); ++j) twice += p[j].x() * p[(j + 1) % p.size()].y() - p[(j + 1) % p.size()].x() * p[j].y();
  return 0.5 * twice;
}

// Exact coverage is reproduced up to the final rounding to a byte (±0.5) and float sums: ±1 level.
constexpr double kCoverageTolerance_levels = 1.0;

TEST(EdgeAntiAliasing, PixelsAlongAStraightEdgeTakeTheirExactCoveredFraction) {
  constexpr int kSize = 64;
  // A 30 mm square turned by 20°, off-centre by a fraction of a pixel, in pixel units (x right, y down).
  std::vector<Vector2d> square_px;
  Polygon2 square_m;
  for (int k = 0; k < 4; ++k) {
    const double a = 20.0 * std::numbers::pi / 180 + k * std::numbers::pi / 2;
    const Vector2d p_mm = Vector2d(0.37, -0.21) + 15.0 * std::sqrt(2.0) * Vector2d(std::cos(a), std::sin(a));
    square_m.points.push_back(1e-3 * p_mm);
    square_px.push_back({kSize / 2.0 + p_mm.x(), kSize / 2.0 - p_mm.y()});
  }
  std::vector<Vector2d> clockwise_px(square_px.rbegin(), square_px.rend());  // y down mirrors the turn
  Renderer r(coverage_settings(kSize, AntiAliasing::Edge));
  const Image im = r.render(white_prism(square_m, 1e-3), top_view(kSize));
  int edge_pixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // Away from the corners, where two edges share a pixel and the method approximates.
      double corner_px = 1e9;
      for (const Vector2d& c : square_px) corner_px = std::min(corner_px, (c - Vector2d(x + 0.5, y + 0.5)).norm());
      if (corner_px < 2.0) continue;
      const double covered = clipped_area({{x, y}, {x + 1.0, y}, {x + 1.0, y + 1.0}, {x, y + 1.0}}, clockwise_px);
      if (covered > 0 && covered < 1) ++edge_pixels;
      EXPECT_NEAR(im.at(x, y).r, 255 * covered, kCoverageTolerance_levels) << "pixel (" << x << ", " << y << ")";
    }
  EXPECT_GT(edge_pixels, 4 * 30);  // the test saw the edges: 4 sides of ≥ 30 px, ≥ 1 cut pixel per column
}

// The grey levels of a gear seen along its axis, summed, against its outline's area; and how many
// silhouette pixels are neither gear nor background.
struct SilhouetteCoverage {
  double area_ratio = 0;  // Σ grey/255 · pixel area / outline area
  long partial_pixels = 0;  // grey strictly between 0 and 255
  double perimeter_px = 0;  // the outline's length in pixels
};

SilhouetteCoverage silhouette_coverage(const GearSpec& spec, AntiAliasing aa) {
  constexpr int kSize = 400;
  const GearOutline o = make_gear_outline(spec);
  Scene scene;
  SceneBody body;
  body.name = spec.name;
  body.mesh = std::make_shared<const TriMesh>(extrude(o.outline, -0.5 * spec.face_width_m, 0.5 * spec.face_width_m));
  body.colour = kWhite;
  scene.bodies.push_back(body);
  Renderer renderer(coverage_settings(kSize, aa));
  Camera camera = top_view(kSize);
  camera.view_height_m = 1.05 * 2 * std::max(o.dims.tip_radius_m, 0.5 * spec.rim_diameter_m);
  const Image image = renderer.render(scene, camera);
  const double pixel_m = camera.view_height_m / kSize;
  SilhouetteCoverage c;
  double grey = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int g = image.at(x, y).g;
      grey += g / 255.0;
      if (g > 0 && g < 255) ++c.partial_pixels;
    }
  c.area_ratio = grey * pixel_m * pixel_m / area(o.outline);
  std::vector<const Polygon2*> loops{&o.outline.outer};
  for (const Polygon2& h : o.outline.holes) loops.push_back(&h);
  for (const Polygon2* l : loops)
    for (std::size_t i = 0; i < l->points.size(); ++i)
      c.perimeter_px += (l->points[(i + 1) % l->points.size()] - l->points[i]).norm() / pixel_m;
  return c;
}

// Without anti-aliasing the area comes from counting pixel centres: ~1e-3 off (test_silhouette).
// The grey levels carry each edge pixel's fraction: rounding ~3000 partial pixels by up to half a
// level each bounds the error at 0.7e-4 of the sun's ~86 000 px; corners, where the method
// approximates, add the rest. Measured 1.6e-5 (sun) and 9.3e-5 (ring); 2e-4 allowed.
constexpr double kCoverageAreaTolerance = 2e-4;

TEST(EdgeAntiAliasing, SunSilhouetteHoldsItsOutlineAreaInGreyLevels) {
  const SilhouetteCoverage aa = silhouette_coverage(test::external_gear(24), AntiAliasing::Edge);
  EXPECT_NEAR(aa.area_ratio, 1.0, kCoverageAreaTolerance);
  // Every column or row the outline crosses holds at least one partial pixel; the outline's
  // length is a lower bound on their number (equal for an edge along x or y). Measured: sun 3022
  // partial pixels for a 2518 px outline, ring 3830 for 3246 px.
  EXPECT_GT(double(aa.partial_pixels), aa.perimeter_px);
  EXPECT_EQ(silhouette_coverage(test::external_gear(24), AntiAliasing::None).partial_pixels, 0);
}

TEST(EdgeAntiAliasing, RingSilhouetteHoldsItsOutlineAreaInGreyLevels) {
  const SilhouetteCoverage aa = silhouette_coverage(test::internal_gear(96), AntiAliasing::Edge);
  EXPECT_NEAR(aa.area_ratio, 1.0, kCoverageAreaTolerance);
  EXPECT_GT(double(aa.partial_pixels), aa.perimeter_px);
}

// --- The paper's frames against a reference with 16 samples per pixel -------------------------

// The golden test's overview and a close-up on the sun mesh, 320×240, drawn with `aa`.
Image paper_frame(AntiAliasing aa, bool closeup, int scale = 1) {
  const test::PaperSet& p = test::paper_set();
  RenderSettings s;
  s.width_px = 320 * scale;
  s.height_px = 240 * scale;
  s.anti_aliasing = aa;
  Renderer r(s);
  const double period = 2 * std::numbers::pi * p.spec.planet.teeth / p.spec.ring.teeth;
  const PlanetaryPose pose =
      kinematic_planetary_pose(p.spec, p.geometry, carrier_angle_tooth_at_sun(p.spec, p.geometry, 0, 0) + 0.5 * period);
  const Scene scene = planetary_scene(p.meshes, pose);
  const Camera camera = closeup ? closeup_camera(sun_mesh_point(p.spec, p.geometry, pose, 0, 5e-3), Eigen::Vector3d(0.3, 1, -0.7), 12e-3)
                                : overview_camera(scene_bounds(scene), r.aspect(), 30 * std::numbers::pi / 180);
  const Image im = r.render(scene, camera);
  return scale > 1 ? downscale(im, scale) : im;
}

// Mean absolute error per channel (0–255) against the frame drawn at 4×4 the size without
// anti-aliasing and box-filtered down. Measured with Mesa 22.3 llvmpipe: overview none 1.165,
// edge 0.412, MSAA 4× 0.392; close-up none 0.274, edge 0.061, MSAA 4× 0.112. Edge AA must cut
// the error at least 2× (measured 2.8× and 4.5×) and stay within 25 % of MSAA 4×'s (measured
// 5 % above it in the overview, half of it in the close-up): thin features no pixel centre hits
// stay lost, the rest is as smooth as 4 samples.
constexpr double kMinErrorReduction = 2.0;
constexpr double kMaxErrorOverMsaa4 = 1.25;

void expect_close_to_reference(bool closeup) {
  const Image reference = paper_frame(AntiAliasing::None, closeup, 4);
  const double none = compare_images(paper_frame(AntiAliasing::None, closeup), reference).mean;
  const double edge = compare_images(paper_frame(AntiAliasing::Edge, closeup), reference).mean;
  const double msaa = compare_images(paper_frame(AntiAliasing::Multisample, closeup), reference).mean;
  EXPECT_LE(edge * kMinErrorReduction, none) << "edge " << edge << ", none " << none;
  EXPECT_LE(edge, kMaxErrorOverMsaa4 * msaa) << "edge " << edge << ", MSAA 4× " << msaa;
}

TEST(EdgeAntiAliasing, OverviewComesCloserToASupersampledReference) { expect_close_to_reference(false); }

TEST(EdgeAntiAliasing, CloseUpComesCloserToASupersampledReference) { expect_close_to_reference(true); }

// --- Which edges blend, on hand-made frames ---------------------------------------------------

// A 16×16 frame, black left of x = 8, white from there; a vertical edge at x = 8.3, depth 0.5.
struct StepFrame {
  Image image{16, 16, kBlack};
  std::vector<float> depth = std::vector<float>(16 * 16, 1.0f);  // nothing drawn: the far plane
  std::vector<WindowEdge> edges{{8.3f, 0, 0.5f, 0.01f, 8.3f, 16, 0.5f, 0.01f}};
  StepFrame() {
    for (int y = 0; y < 16; ++y)
      for (int x = 8; x < 16; ++x) image.set(x, y, kWhite);
  }
};

TEST(EdgeAntiAliasing, PixelTakesTheFractionAcrossTheEdgeFromItsNeighbour) {
  StepFrame f;
  EdgeBlendBuffers buffers;
  antialias_edges(f.image, f.depth, f.edges, buffers);
  for (int y = 0; y < 16; ++y) {
    EXPECT_EQ(f.image.at(7, y), kBlack);
    EXPECT_NEAR(f.image.at(8, y).r, 0.7 * 255, 0.5 + 1e-9);  // [8, 9] lies 0.3 left of the edge
    EXPECT_EQ(f.image.at(9, y), kWhite);
  }
}

TEST(EdgeAntiAliasing, EdgeBehindWhatWasDrawnBlendsNothing) {
  StepFrame f;
  std::fill(f.depth.begin(), f.depth.end(), 0.2f);  // a surface at 0.2 covers the edge at 0.5
  const Image drawn = f.image;
  EdgeBlendBuffers buffers;
  antialias_edges(f.image, f.depth, f.edges, buffers);
  EXPECT_EQ(f.image, drawn);
}

TEST(EdgeAntiAliasing, EdgesCrowdingOnePixelMixNoFurtherThanTheColourAcross) {
  StepFrame f;
  f.edges.assign(4, f.edges[0]);  // 4 × 0.3 of pixel 8 claimed across: scaled back to all of it
  EdgeBlendBuffers buffers;
  antialias_edges(f.image, f.depth, f.edges, buffers);
  for (int y = 0; y < 16; ++y) EXPECT_EQ(f.image.at(8, y), kBlack);
  // The buffers are left clean for the next frame: a repeat of the single edge gives 0.7 again.
  StepFrame g;
  antialias_edges(g.image, g.depth, g.edges, buffers);
  EXPECT_NEAR(g.image.at(8, 0).r, 0.7 * 255, 0.5 + 1e-9);
}

// A 2 mm cube from extrude_convex: 12 triangles, 18 edges of which 6 are face diagonals.
TriMesh cube() {
  Polygon2 square;
  square.points = {{-1e-3, -1e-3}, {1e-3, -1e-3}, {1e-3, 1e-3}, {-1e-3, 1e-3}};
  return extrude_convex(square, -1e-3, 1e-3);
}

TEST(EdgeAntiAliasing, CubeHasTwelveCreasesAndNoDiagonals) {
  const MeshEdges e = mesh_edges(cube(), constants::kDefaultCreaseAngle_rad);
  ASSERT_EQ(e.edges.size(), 12u);  // the diagonals join coplanar faces: never an outline
  for (const auto& edge : e.edges) EXPECT_TRUE(edge.feature);
}

TEST(EdgeAntiAliasing, HighlightBoundaryIsAFeatureEdge) {
  const TriMesh m = cube();
  std::vector<std::uint8_t> highlight(m.triangles.size(), 0);
  highlight[0] = 1;  // one half of one face: its diagonal now bounds the highlight
  EXPECT_EQ(mesh_edges(m, constants::kDefaultCreaseAngle_rad, &highlight).edges.size(), 13u);
}

TEST(EdgeAntiAliasing, CubeSeenAlongItsAxisIsOutlinedByItsTopFaceOnly) {
  const MeshEdges e = mesh_edges(cube(), constants::kDefaultCreaseAngle_rad);
  const Camera camera = top_view(64);
  EdgeProjection view;
  view.projection = projection_matrix(camera, 1.0);
  view.width_px = view.height_px = 64;
  std::vector<WindowEdge> outline;
  append_outline_edges(e, view_matrix(camera), view, outline);
  // Top edges: top face toward the eye, side faces edge-on. Vertical and bottom edges join faces
  // none of which faces the eye.
  ASSERT_EQ(outline.size(), 4u);
  for (const WindowEdge& w : outline) {
    EXPECT_NEAR(std::abs(w.x0 - 32) + std::abs(w.y0 - 32), 2.0, 1e-4);  // corners at ±1 px
    EXPECT_FLOAT_EQ(w.z0, w.z1);
  }
}

}  // namespace test_edge_antialiasing
}  // namespace gearsim::render
