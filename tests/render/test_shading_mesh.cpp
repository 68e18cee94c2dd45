// What the renderer draws, checked on the CPU: crease-angle normals (crisp gear edges, smooth
// flanks), shared vertices, closed outward marker shapes, and the highlighted-tooth mesh that is
// the same solid as the plain one with exactly the tooth's triangles marked.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/gear_body.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_validate.hpp"
#include "render/constants.hpp"
#include "render/shading_mesh.hpp"
#include "render/tooth_highlight.hpp"
#include "tests/render/paper_scene.hpp"
#include "geometry/constants.hpp"

namespace gearsim::render {
namespace test_shading_mesh {

using gearsim::constants::kPi;

TriMesh sun_mesh() {
  const GearSpec s = test::external_gear(24);
  return extrude(make_gear_outline(s).outline, -0.005, 0.005);
}

TEST(ShadingMesh, CapNormalsStayAxialAndFlankNormalsStayRadial) {
  const TriMesh m = sun_mesh();
  const ShadingMesh sm = shading_mesh(m, constants::kDefaultCreaseAngle_rad);
  ASSERT_EQ(sm.indices.size(), 3 * m.triangles.size());
  for (const ShadedVertex& v : sm.vertices) {
    const double nz = v.normal[2];
    if (std::abs(v.position[2]) > 0.0049 && std::abs(nz) > 0.5) {
      EXPECT_NEAR(std::abs(nz), 1.0, 1e-6);  // a cap vertex: its normal is not bent by the walls
    } else {
      EXPECT_NEAR(nz, 0.0, 1e-6);  // a wall vertex: no cap in its smoothing
    }
  }
  // Cap and wall split each outline vertex in two: far fewer vertices than corners.
  EXPECT_LT(sm.vertices.size(), sm.indices.size() / 2);
}

TEST(ShadingMesh, ZeroCreaseAngleGivesFaceNormals) {
  TriMesh m = sun_mesh();
  const ShadingMesh sm = shading_mesh(m, 0.0);
  for (std::size_t t = 0; t < m.triangles.size(); t += 97) {
    const auto& tri = m.triangles[t];
    const Eigen::Vector3d n = (m.vertices[tri[1]] - m.vertices[tri[0]]).cross(m.vertices[tri[2]] - m.vertices[tri[0]]).normalized();
    const ShadedVertex& v = sm.vertices[sm.indices[3 * t]];
    EXPECT_NEAR(n.dot(Eigen::Vector3d(v.normal[0], v.normal[1], v.normal[2])), 1.0, 1e-6) << t;
  }
}

TEST(ShadingMesh, MarkerShapesAreClosedAndOutward) {
  for (const TriMesh& m : {sphere_mesh({0.01, 0, 0}, 0.001), arrow_mesh({0, 0, 0}, {0.003, 0.004, 0.001}, 2e-4)}) {
    const MeshReport r = validate_mesh(m);
    EXPECT_TRUE(r.watertight());
    EXPECT_TRUE(r.outward_oriented());
  }
  EXPECT_TRUE(arrow_mesh({1, 2, 3}, {1, 2, 3}, 1e-3).triangles.empty());
}

TEST(ToothHighlight, MeshIsTheSameSolidWithTheToothMarked) {
  const GearSpec spec = test::paper_faulty_planet();
  const HighlightedGearMesh h = gear_mesh_with_highlighted_teeth(spec, {0});
  const GearBody plain = make_gear_body(spec, 7580);
  EXPECT_EQ(h.mesh.vertices, plain.mesh.vertices);
  EXPECT_EQ(h.mesh.triangles.size(), plain.mesh.triangles.size());
  const MeshReport r = validate_mesh(h.mesh);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.outward_oriented());
  // Same volume to rounding: only the caps' triangulation changed.
  EXPECT_NEAR(mass_properties(h.mesh, 7580).volume_m3, plain.mass.volume_m3, 1e-12 * plain.mass.volume_m3);
  // Every marked triangle lies in tooth 0's sector (± half a pitch about +x, widened by the
  // 0.015 rad of one root-arc chord: the boundary is the outline vertex nearest the gap
  // mid-line), outside the root circle.
  const GearDimensions d = gear_dimensions(spec);
  double top_area = 0;
  for (std::size_t t = 0; t < h.mesh.triangles.size(); ++t) {
    if (!h.highlight[t]) continue;
    const auto& tri = h.mesh.triangles[t];
    for (std::uint32_t i : tri) {
      const Eigen::Vector3d& v = h.mesh.vertices[i];
      EXPECT_LE(std::abs(std::atan2(v.y(), v.x())), kPi / 36 + 0.015);
      EXPECT_GE(std::hypot(v.x(), v.y()), d.root_radius_m - 1e-6);
    }
    const Eigen::Vector3d n = (h.mesh.vertices[tri[1]] - h.mesh.vertices[tri[0]]).cross(h.mesh.vertices[tri[2]] - h.mesh.vertices[tri[0]]);
    if (n.z() > 0) top_area += 0.5 * n.z();
  }
  // The marked top cap is one tooth: roughly the annulus root–tip over z teeth, halved (a
  // tooth fills about half its pitch); 20 % covers the fillets and the chord.
  const double tooth_area = 0.5 * kPi * (std::pow(d.tip_radius_m, 2) - std::pow(d.root_radius_m, 2)) / 36;
  EXPECT_NEAR(top_area, tooth_area, 0.2 * tooth_area);
}

// Internal teeth close outside the root circle through an extra point; neighbouring teeth share
// the point of their common gap.
TEST(ToothHighlight, AdjacentInternalTeethKeepTheSolid) {
  const GearSpec ring = test::internal_gear(96);
  const HighlightedGearMesh h = gear_mesh_with_highlighted_teeth(ring, {5, 6});
  const MeshReport r = validate_mesh(h.mesh);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.consistently_oriented());
  const double plain_m3 = mass_properties(make_gear_body(ring, 7580).mesh, 7580).volume_m3;
  EXPECT_NEAR(r.signed_volume_m3, plain_m3, 1e-12 * plain_m3);
  std::size_t marked = 0;
  for (std::uint8_t f : h.highlight) marked += f;
  EXPECT_GT(marked, 20u);
  EXPECT_THROW(gear_mesh_with_highlighted_teeth(ring, {96}), InputError);
}

}  // namespace test_shading_mesh
}  // namespace gearsim::render
