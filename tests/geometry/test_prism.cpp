// Prism recovery: an extruded outline comes back unchanged (vertex set, area, height, frame);
// meshes that are not right prisms are rejected with a reason.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/prism.hpp"

namespace gearsim {
namespace test_prism {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

Outline2 l_shape() {  // 20 mm L, one reflex corner
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {0.02, 0}, {0.02, 0.01}, {0.01, 0.01}, {0.01, 0.02}, {0, 0.02}}};
  return o;
}

std::vector<Vec2> sorted(std::vector<Vec2> v) {
  std::sort(v.begin(), v.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  return v;
}

TEST(Prism, ExtrudedLShapeComesBackExactly) {
  const TriMesh m = extrude(l_shape(), 0.001, 0.006);
  const Result<Prism> r = recover_prism(m, 1e-9);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_EQ(sorted(r->outline.outer.points), sorted(l_shape().outer.points));  // bit-exact
  EXPECT_TRUE(r->outline.holes.empty());
  EXPECT_NEAR(area(r->outline), 3e-4, 1e-18);  // m^2; exact inputs, rounding only
  EXPECT_NEAR(r->height_m, 0.005, 1e-18);
  EXPECT_EQ(r->frame.z, Vec3::UnitZ());
  EXPECT_NEAR(r->frame.origin_m.z(), 0.001, 1e-18);
}

TEST(Prism, HoleIsRecoveredClockwise) {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  o.holes.push_back(Polygon2{{{1, 1}, {1, 2}, {2, 2}, {2, 1}}});
  const Result<Prism> r = recover_prism(extrude(o, 0.0, 1.0), 1e-9);
  ASSERT_TRUE(r) << r.reason();
  ASSERT_EQ(r->outline.holes.size(), 1u);
  EXPECT_LT(signed_area(r->outline.holes[0]), 0.0);
  EXPECT_NEAR(area(r->outline), 15.0, 1e-14);
}

TEST(Prism, RotatedAndTallPrismIsFoundAlongItsAxis) {
  // 50 mm tall: every side wall is larger than the caps, so the axis is not the biggest face.
  TriMesh m = extrude(l_shape(), 0.0, 0.05);
  const Eigen::Matrix3d rot =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  for (Vec3& v : m.vertices) v = rot * v + Vec3(0.1, -0.2, 0.3);
  const Result<Prism> r = recover_prism(m, 1e-9);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_NEAR(std::abs(r->frame.z.dot(rot * Vec3::UnitZ())), 1.0, 1e-15);
  EXPECT_NEAR(r->height_m, 0.05, 1e-15);       // rounding of rotated coordinates
  EXPECT_NEAR(area(r->outline), 3e-4, 1e-17);  // m^2
  // Mapping the recovered outline back lands on mesh vertices (within rounding, 1e-15 m).
  for (const Vec2& p : r->outline.outer.points) {
    const Vec3 w = r->frame.to_world(p, 0.0);
    double best = 1.0;
    for (const Vec3& v : m.vertices) best = std::min(best, (v - w).norm());
    EXPECT_LT(best, 1e-15);
  }
}

TEST(Prism, ExactlyCollinearPointsGoButNearlyCollinearOnesStay) {
  Outline2 o;
  o.outer =
      Polygon2{{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0.5, 1 + 1e-9}, {0, 1}}};  // 1 nm bump on top
  const Result<Prism> r = recover_prism(extrude(o, 0.0, 1.0), 1e-12);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_EQ(r->outline.outer.points.size(), 5u);  // (0.5, 0) dropped, the bump kept
}

TEST(Prism, TetrahedronIsRejectedWithAReason) {
  TriMesh t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const Result<Prism> r = recover_prism(t, 1e-9);
  EXPECT_FALSE(r);
  EXPECT_NE(r.reason().find("perpendicular"), std::string::npos) << r.reason();
}

TEST(Prism, TiltedWallsAreRejected) {
  // A sheared prism: both caps parallel, every wall leaning by 0.1 mm over 10 mm.
  TriMesh m = extrude(l_shape(), 0.0, 0.01);
  for (Vec3& v : m.vertices) v.x() += 0.01 * v.z();
  const Result<Prism> r = recover_prism(m, 1e-6);
  EXPECT_FALSE(r);
  EXPECT_NE(r.reason().find("perpendicular"), std::string::npos) << r.reason();
}

TEST(Prism, TwoSeparateBodiesAreRejected) {
  TriMesh a = extrude(l_shape(), 0.0, 0.01), b = a;
  for (Vec3& v : b.vertices) v.x() += 0.05;
  const auto base = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  const Result<Prism> r = recover_prism(a, 1e-9);
  EXPECT_FALSE(r);
  EXPECT_NE(r.reason().find("2 outer loops"), std::string::npos) << r.reason();
}

TEST(Prism, MalformedInputThrows) {
  TriMesh m = extrude(l_shape(), 0.0, 0.01);
  EXPECT_THROW(recover_prism(m, 0.0), InputError);
  m.triangles[0][1] = 999;
  EXPECT_THROW(recover_prism(m, 1e-9), InputError);
}

}  // namespace test_prism
}  // namespace gearsim
