// Extrusion: closed, consistently oriented prisms whose volume (divergence theorem) is area * h.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"

namespace gearsim {
namespace test_extrude {

// Signed volume by the divergence theorem: positive when the triangles face outward.
double signed_volume(const TriMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
  return v / 6.0;
}

// Watertight and consistently oriented: every directed edge once, and its reverse once.
void expect_closed(const TriMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : m.triangles)
    for (int j = 0; j < 3; ++j) ++edges[std::make_pair(t[j], t[(j + 1) % 3])];
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << e.first << "->" << e.second;
    const auto twin = edges.find({e.second, e.first});
    EXPECT_TRUE(twin != edges.end() && twin->second == 1) << "open edge " << e.first << "->" << e.second;
  }
}

TEST(Extrude, LShapePrismIsClosedWithVolumeAreaTimesHeight) {
  Outline2 l;
  l.outer = Polygon2{{{0, 0}, {0.02, 0}, {0.02, 0.01}, {0.01, 0.01}, {0.01, 0.02}, {0, 0.02}}};
  const TriMesh m = extrude(l, -0.005, 0.010);
  expect_closed(m);
  EXPECT_EQ(m.vertices.size(), 12u);
  EXPECT_EQ(m.triangles.size(), 2u * 4 + 2u * 6);  // two caps of n - 2, n side quads
  // 3e-4 m^2 * 0.015 m; 1e-18 m^3 is rounding of ~20 triple products of 1e-6 m^3 terms.
  EXPECT_NEAR(signed_volume(m), 3e-4 * 0.015, 1e-18);
}

TEST(Extrude, HoleIsCarvedOutOfTheVolume) {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  o.holes.push_back(Polygon2{{{1, 1}, {1, 2}, {2, 2}, {2, 1}}});
  const TriMesh m = extrude(o, 0.0, 2.0);
  expect_closed(m);
  EXPECT_NEAR(signed_volume(m), 15.0 * 2.0, 1e-12);  // (16 - 1) * 2, rounding only
}

TEST(Extrude, ConvexPolygonWithCollinearCornerGivesAPrism) {
  const Polygon2 hex{{{1, 0}, {0.5, 0.866}, {-0.5, 0.866}, {-1, 0}, {-0.5, -0.866}, {0, -0.866}, {0.5, -0.866}}};
  const TriMesh m = extrude_convex(hex, 1.0, 1.5);
  expect_closed(m);
  EXPECT_NEAR(signed_volume(m), signed_area(hex) * 0.5, 1e-14);
  // Every face of a convex prism faces away from its centroid.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& v : m.vertices) c += v / double(m.vertices.size());
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
    EXPECT_GT(n.dot(m.vertices[t[0]] - c), 0.0);
  }
}

TEST(Extrude, RejectsBadInput) {
  const Polygon2 l{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  EXPECT_THROW(extrude_convex(l, 0.0, 1.0), InputError);  // concave
  Outline2 sq;
  sq.outer = Polygon2{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_THROW(extrude(sq, 1.0, 1.0), InputError);  // empty height
  EXPECT_THROW(extrude(sq, 2.0, 1.0), InputError);  // inverted range
}

}  // namespace test_extrude
}  // namespace gearsim
