// Prism recovery: an extruded outline comes back unchanged (vertex set, area, height, frame);
// meshes that are not right prisms are rejected with a reason.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

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
  std::sort(v.begin(), v.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
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
  const Eigen::Matrix3d rot = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  for (Vec3& v : m.vertices) v = rot * v + Vec3(0.1, -0.2, 0.3);
  const Result<Prism> r = recover_prism(m, 1e-9);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_NEAR(std::abs(r->frame.z.dot(rot * Vec3::UnitZ())), 1.0, 1e-15);
  EXPECT_NEAR(r->height_m, 0.05, 1e-15);  // rounding of rotated coordinates
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
  o.outer = Polygon2{{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0.5, 1 + 1e-9}, {0, 1}}};  // 1 nm bump on top
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

// The extruded prism of `o` with its caps only (vertices: the outline's points at z0, then at z1).
TriMesh caps_only(const Outline2& o, double z0, double z1) {
  TriMesh m = extrude(o, z0, z1);
  std::vector<std::array<std::uint32_t, 3>> caps;
  for (const auto& t : m.triangles)
    if (m.vertices[t[0]].z() == m.vertices[t[1]].z() && m.vertices[t[1]].z() == m.vertices[t[2]].z()) caps.push_back(t);
  m.triangles = caps;
  return m;
}

// Rebuilds the side walls of an extruded prism (vertices: the outline's points at z0, then at z1)
// as an exporter that splits them does: each wall column gets a vertex between the caps, at a
// height that varies along the loop, moved `off_m` out of the wall plane.
TriMesh split_walls(const Outline2& o, double z0, double z1, double off_m) {
  TriMesh m = caps_only(o, z0, z1);
  const auto n = static_cast<std::uint32_t>(m.vertices.size() / 2);
  std::uint32_t first = 0;
  std::vector<const Polygon2*> loops{&o.outer};
  for (const Polygon2& h : o.holes) loops.push_back(&h);
  for (const Polygon2* loop : loops) {
    const auto k = static_cast<std::uint32_t>(loop->points.size());
    const auto mid0 = static_cast<std::uint32_t>(m.vertices.size());
    for (std::uint32_t i = 0; i < k; ++i) {
      const Vec2 e = loop->points[(i + 1) % k] - loop->points[i];
      const Vec2 out = Vec2(e.y(), -e.x()).normalized();  // outward for CCW outers and CW holes
      const double h = z0 + (z1 - z0) * (0.3 + 0.4 * ((i * 7) % 11) / 10.0);
      const Vec2 p = loop->points[i] + off_m * out;
      m.vertices.emplace_back(p.x(), p.y(), h);
    }
    for (std::uint32_t i = 0; i < k; ++i) {
      const std::uint32_t j = (i + 1) % k;
      const std::uint32_t bi = first + i, bj = first + j, ti = bi + n, tj = bj + n, mi = mid0 + i, mj = mid0 + j;
      m.triangles.push_back({bi, bj, mj});
      m.triangles.push_back({bi, mj, mi});
      m.triangles.push_back({mi, mj, tj});
      m.triangles.push_back({mi, tj, ti});
    }
    first += k;
  }
  return m;
}

TEST(Prism, VerticesOnTheSideWallsBetweenTheCapsAreAccepted) {
  // FreeCAD's fine export puts vertices on the walls between the caps, up to 0.79 µm out of the
  // wall plane; within the 2 µm tolerance the mesh is the prism of its caps' outline.
  Outline2 o = l_shape();
  o.outer.points = {{0, 0}, {0.02, 0}, {0.02, 0.01}, {0.01, 0.01}, {0.01, 0.02}, {0, 0.02}};
  o.holes.push_back(Polygon2{{{0.002, 0.002}, {0.002, 0.004}, {0.004, 0.004}, {0.004, 0.002}}});
  const TriMesh m = split_walls(o, 0.0, 0.01, 0.79e-6);
  const Result<Prism> r = recover_prism(m, 2e-6);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_EQ(sorted(r->outline.outer.points), sorted(o.outer.points));  // the caps' points, exactly
  ASSERT_EQ(r->outline.holes.size(), 1u);
  EXPECT_NEAR(r->height_m, 0.01, 1e-18);
  // Moved 5 µm out of the walls, the same vertices make it no prism within 2 µm.
  const Result<Prism> off = recover_prism(split_walls(o, 0.0, 0.01, 5e-6), 2e-6);
  EXPECT_FALSE(off);
}

// Rebuilds the side walls of an extruded prism as an exporter that tessellates a curved wall
// does: each wall column gets a vertex at mid-height, halfway along its chord, `factor` times the
// chord's sagitta s out of it (factor 1: on the circle the loop samples, radius r).
TriMesh tessellated_walls(const Outline2& o, double z0, double z1, double r, double factor) {
  TriMesh m = caps_only(o, z0, z1);  // one loop, no holes
  const auto n = static_cast<std::uint32_t>(m.vertices.size() / 2);
  const auto k = static_cast<std::uint32_t>(o.outer.points.size());
  for (std::uint32_t i = 0; i < k; ++i) {
    const Vec2 a = o.outer.points[i], b = o.outer.points[(i + 1) % k], e = b - a;
    const double s = r - std::sqrt(r * r - e.squaredNorm() / 4);
    const Vec2 p = (a + b) / 2 + factor * s * Vec2(e.y(), -e.x()).normalized();
    m.vertices.emplace_back(p.x(), p.y(), (z0 + z1) / 2);
  }
  for (std::uint32_t i = 0; i < k; ++i) {
    const std::uint32_t j = (i + 1) % k, bi = i, bj = j, ti = i + n, tj = j + n, mi = 2 * n + i;
    m.triangles.push_back({bi, bj, mi});
    m.triangles.push_back({bj, tj, mi});
    m.triangles.push_back({tj, ti, mi});
    m.triangles.push_back({ti, bi, mi});
  }
  return m;
}

TEST(Prism, ACurvedWallTessellatedBetweenTheCapsIsThePrismOfItsCapsWithinItsChordsSagitta) {
  // FreeCAD's coarse exports (0.1 mm, 0.5 rad) put vertices on a bore's or flank's true surface
  // between the caps: 42 µm outside the caps' chords on an 8 mm bore. A 48-gon of radius 10 mm
  // (a turn of 7.5° per chord): its wall vertices on the circle lie 21.4 µm outside the chords.
  Outline2 o;
  const int k = 48;
  const double r = 0.010;
  for (int i = 0; i < k; ++i) o.outer.points.emplace_back(r * std::cos(2 * M_PI * i / k), r * std::sin(2 * M_PI * i / k));
  const double sagitta = r * (1 - std::cos(M_PI / k));
  const Result<Prism> on = recover_prism(tessellated_walls(o, 0.0, 0.004, r, 1.0), 2e-6);
  ASSERT_TRUE(on) << on.reason();
  EXPECT_EQ(sorted(on->outline.outer.points), sorted(o.outer.points));  // the caps' points, exactly
  EXPECT_NEAR(on->wall_deviation_m, sagitta, 1e-12);
  EXPECT_NEAR(on->height_m, 0.004, 1e-18);
  // Three times as far out (a bulge, not a tessellation of the caps' curve): no prism.
  const Result<Prism> bulged = recover_prism(tessellated_walls(o, 0.0, 0.004, r, 3.0), 2e-6);
  ASSERT_FALSE(bulged);
  EXPECT_NE(bulged.reason().find("off its side walls"), std::string::npos) << bulged.reason();
  // An exact prism reports no wall deviation.
  const Result<Prism> plain = recover_prism(extrude(o, 0.0, 0.004), 2e-6);
  ASSERT_TRUE(plain) << plain.reason();
  EXPECT_EQ(plain->wall_deviation_m, 0.0);
}

TEST(Prism, TheCapIsFoundWhenEveryCapTriangleIsSmallerThanTheWalls) {
  // A ring exported with a fine cap and coarse walls: its 400 wall directions (each shared by
  // the outer and the inner wall) all have larger triangles than any cap triangle, so a search
  // seeded by single triangles meets 64 wall directions before the cap. Shuffled: the axis must
  // not depend on the triangles' order.
  Outline2 ring;
  const int k = 400;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * M_PI * i / k;
    ring.outer.points.emplace_back(0.030 * std::cos(a), 0.030 * std::sin(a));
  }
  for (int i = k; i-- > 0;) {
    const double a = 2 * M_PI * i / k;
    ring.holes.resize(1);
    ring.holes[0].points.emplace_back(0.028 * std::cos(a), 0.028 * std::sin(a));
  }
  TriMesh m = extrude(ring, 0.0, 0.05);
  double cap_max = 0, wall_min = 1;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    (a.z() == b.z() && b.z() == c.z() ? cap_max : wall_min) =
        a.z() == b.z() && b.z() == c.z() ? std::max(cap_max, area) : std::min(wall_min, area);
  }
  ASSERT_LT(cap_max, wall_min);  // the case being tested
  std::reverse(m.triangles.begin(), m.triangles.end());
  for (std::size_t i = 0; i + 7 < m.triangles.size(); i += 7) std::swap(m.triangles[i], m.triangles[i + 5]);
  const Result<Prism> r = recover_prism(m, 2e-6);
  ASSERT_TRUE(r) << r.reason();
  EXPECT_NEAR(std::abs(r->frame.z.z()), 1.0, 1e-15);
  EXPECT_NEAR(r->height_m, 0.05, 1e-17);
  EXPECT_NEAR(area(r->outline), M_PI * (0.030 * 0.030 - 0.028 * 0.028), 1e-6);  // the 400-gons' area
}

}  // namespace test_prism
}  // namespace gearsim
