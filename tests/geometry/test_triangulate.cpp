// Ear-clipping triangulation: triangle count n - 2 (+ 2 per hole), area preserved, every
// triangle counter-clockwise, every directed edge used once, and invalid polygons rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/triangulate.hpp"

namespace gearsim {
namespace test_triangulate {

using Vec2 = Eigen::Vector2d;
using Tris = std::vector<std::array<int, 3>>;

double tri_area(const std::vector<Vec2>& v, const std::array<int, 3>& t) {
  const Vec2 a = v[t[1]] - v[t[0]], b = v[t[2]] - v[t[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

// Sum of triangle areas, and checks that no triangle is clockwise or degenerate and no directed
// edge repeats (so the triangles cannot overlap once their areas add up to the polygon's).
double checked_area(const std::vector<Vec2>& v, const Tris& tris) {
  double sum = 0.0;
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : tris) {
    EXPECT_GT(tri_area(v, t), 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
    sum += tri_area(v, t);
    for (int j = 0; j < 3; ++j) EXPECT_EQ(++edges[std::make_pair(t[j], t[(j + 1) % 3])], 1);
  }
  return sum;
}

Polygon2 comb(int teeth) {  // a base 1 high with `teeth` 1-wide teeth up to y = 4, 1 apart
  const double w = 2.0 * teeth - 1;
  Polygon2 p{{{0, 0}, {w, 0}}};
  for (int k = teeth - 1; k >= 0; --k) {
    p.points.push_back({2.0 * k + 1, 4});
    p.points.push_back({2.0 * k, 4});
    if (k > 0) p.points.push_back({2.0 * k, 1}), p.points.push_back({2.0 * k - 1, 1});
  }
  return p;
}

TEST(Triangulate, SquareGivesTwoTrianglesOfUnitArea) {
  const Polygon2 sq{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Tris t = triangulate(sq);
  EXPECT_EQ(t.size(), 2u);
  EXPECT_NEAR(checked_area(sq.points, t), 1.0, 1e-15);  // exact sums of halves
}

TEST(Triangulate, LShapeGivesFourTrianglesOfAreaThree) {
  const Polygon2 l{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  const Tris t = triangulate(l);
  EXPECT_EQ(t.size(), 4u);
  EXPECT_NEAR(checked_area(l.points, t), 3.0, 1e-15);
}

TEST(Triangulate, CombKeepsNMinusTwoTrianglesAndItsArea) {
  const Polygon2 c = comb(7);
  const Tris t = triangulate(c);
  EXPECT_EQ(t.size(), c.points.size() - 2);
  EXPECT_NEAR(signed_area(c), 13.0 + 7 * 3.0, 1e-12);  // base 13 x 1, seven 1 x 3 teeth
  EXPECT_NEAR(checked_area(c.points, t), signed_area(c), 1e-12);  // rounding only
}

TEST(Triangulate, CollinearPointsAreKeptWithoutDegenerateTriangles) {
  // A unit square with three extra points on its bottom edge and one on its left edge.
  const Polygon2 p{{{0, 0}, {0.25, 0}, {0.5, 0}, {0.75, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.5}}};
  const Tris t = triangulate(p);
  EXPECT_EQ(t.size(), p.points.size() - 2);
  EXPECT_NEAR(checked_area(p.points, t), 1.0, 1e-15);
}

TEST(Triangulate, DenseCircleOfTenThousandPoints) {
  Polygon2 p;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    p.points.push_back({0.1 * std::cos(a), 0.1 * std::sin(a)});
  }
  const Tris t = triangulate(p);
  EXPECT_EQ(t.size(), std::size_t(n - 2));
  // Relative 1e-12: 10^4 triangle areas summed in double.
  EXPECT_NEAR(checked_area(p.points, t), signed_area(p), 1e-12 * signed_area(p));
}

TEST(Triangulate, HoleAreaIsSubtracted) {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  o.holes.push_back(Polygon2{{{1, 1}, {1, 2}, {2, 2}, {2, 1}}});  // clockwise
  o.holes.push_back(Polygon2{{{3, 2}, {2.5, 3}, {3.5, 3}}});  // clockwise triangle
  const OutlineTriangulation t = triangulate(o);
  EXPECT_EQ(t.vertices.size(), 11u);
  EXPECT_EQ(t.triangles.size(),
            11u + 2 * 2 - 2);  // n + 2h - 2 for a triangulated polygon with h holes
  EXPECT_NEAR(checked_area(t.vertices, t.triangles), 16.0 - 1.0 - 0.5, 1e-14);
}

TEST(Triangulate, HolesInAGearLikeRing) {
  // A 64-gon ring with six bolt holes: several bridges into one ring.
  Outline2 o;
  for (int i = 0; i < 64; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 64;
    o.outer.points.push_back({0.05 * std::cos(a), 0.05 * std::sin(a)});
  }
  for (int h = 0; h < 6; ++h) {
    Polygon2 hole;
    const Vec2 c(0.03 * std::cos(h * std::numbers::pi / 3), 0.03 * std::sin(h * std::numbers::pi / 3));
    for (int i = 0; i < 16; ++i) {
      const double a = -2.0 * std::numbers::pi * i / 16;  // clockwise
      hole.points.push_back(c + 0.006 * Vec2(std::cos(a), std::sin(a)));
    }
    o.holes.push_back(hole);
  }
  const OutlineTriangulation t = triangulate(o);
  EXPECT_EQ(t.triangles.size(), t.vertices.size() + 2 * 6 - 2);
  EXPECT_NEAR(checked_area(t.vertices, t.triangles), area(o), 1e-15);  // m^2, ~8e-3 m^2 total
}

void expect_rejected(const Polygon2& p, const std::string& fragment) {
  try {
    triangulate(p);
    ADD_FAILURE() << "accepted a polygon that should fail with '" << fragment << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Triangulate, RejectsInvalidPolygonsWithAReason) {
  expect_rejected(Polygon2{{{0, 0}, {1, 0}}}, "at least 3");
  expect_rejected(Polygon2{{{0, 0}, {1, 0}, {2, 0}}}, "zero area");
  expect_rejected(Polygon2{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}},
                  "zero area");  // bow-tie: areas cancel
  expect_rejected(Polygon2{{{0, 0}, {4, 0}, {4, 4}, {2, -1}, {0, 4}}},
                  "intersect");  // net area > 0
  expect_rejected(Polygon2{{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}, "clockwise");
  expect_rejected(Polygon2{{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}, "coincide");
}

TEST(Triangulate, RejectsHolesThatCrossOrLieOutside) {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}};
  o.holes.push_back(Polygon2{{{3, 1}, {3, 2}, {5, 2}, {5, 1}}});  // crosses the outer boundary
  EXPECT_THROW(triangulate(o), InputError);
  o.holes[0] = Polygon2{{{5, 1}, {5, 2}, {6, 2}, {6, 1}}};  // entirely outside
  EXPECT_THROW(triangulate(o), InputError);
  o.holes[0] = Polygon2{{{1, 1}, {2, 1}, {2, 2}, {1, 2}}};  // counter-clockwise hole
  EXPECT_THROW(triangulate(o), InputError);
}

}  // namespace test_triangulate
}  // namespace gearsim
