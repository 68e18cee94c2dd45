#include "physics/fe/outline_resample.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/errors.hpp"
#include "physics/fe/constants.hpp"

namespace gearsim::fe {

using Eigen::Vector2d;

namespace {

// Turning angle of the boundary at vertex i, rad (signed; 0 on a straight run).
double turn_at(const std::vector<Vector2d>& p, int i) {
  const int n = static_cast<int>(p.size());
  const Vector2d a = p[i] - p[(i + n - 1) % n];
  const Vector2d b = p[(i + 1) % n] - p[i];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

}  // namespace

ArcPolygon make_arc_polygon(const Polygon2& polygon) {
  ArcPolygon r;
  r.points = polygon.points;
  const int n = static_cast<int>(r.points.size());
  GEARSIM_CHECK(n >= 3, "outline loop with fewer than 3 points");
  r.s_m.resize(n);
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    r.s_m[i] = s;
    s += (r.points[(i + 1) % n] - r.points[i]).norm();
  }
  r.perimeter_m = s;
  return r;
}

ArcPoint point_at_arc_length(const ArcPolygon& poly, double s_m, double snap_m) {
  // Wrap s into [0, perimeter) and find the chord [i, i+1] holding it.
  double s = std::fmod(s_m, poly.perimeter_m);
  if (s < 0) s += poly.perimeter_m;
  const int n = static_cast<int>(poly.points.size());
  const int i = static_cast<int>(std::upper_bound(poly.s_m.begin(), poly.s_m.end(), s) -
                                 poly.s_m.begin()) - 1;
  const int j = (i + 1) % n;
  const double s_i = poly.s_m[i];
  const double s_j = (j == 0) ? poly.perimeter_m : poly.s_m[j];
  // Snap to the nearer chord end when it is close enough: vertices are exact curve points.
  if (s - s_i <= s_j - s) {
    if (s - s_i <= snap_m) return {poly.points[i], s_i};
  } else if (s_j - s <= snap_m) {
    return {poly.points[j], poly.s_m[j]};
  }
  const double f = (s - s_i) / (s_j - s_i);
  return {poly.points[i] + f * (poly.points[j] - poly.points[i]), s};
}

ResampledLoop resample_loop(const ArcPolygon& poly, double spacing_m) {
  const int n = static_cast<int>(poly.points.size());
  // Corners: vertices where the outline turns sharply; a smooth loop starts at vertex 0.
  std::vector<int> corners;
  for (int i = 0; i < n; ++i)
    if (std::abs(turn_at(poly.points, i)) > kOutlineCornerTurn_rad) corners.push_back(i);
  if (corners.empty()) corners.push_back(0);
  const int nc = static_cast<int>(corners.size());

  // Segments per stretch between consecutive corners: the nearest whole number to length/spacing.
  std::vector<double> length(nc);
  std::vector<int> segments(nc);
  int total = 0;
  for (int c = 0; c < nc; ++c) {
    const double s0 = poly.s_m[corners[c]];
    double s1 = (c + 1 < nc) ? poly.s_m[corners[c + 1]] : poly.s_m[corners[0]] + poly.perimeter_m;
    if (nc == 1) s1 = s0 + poly.perimeter_m;
    length[c] = s1 - s0;
    segments[c] = std::max(1, static_cast<int>(std::lround(length[c] / spacing_m)));
    total += segments[c];
  }
  // At least 4 nodes, and an even count: add segments where they are longest.
  while (total < 4 || total % 2 != 0) {
    int longest = 0;
    for (int c = 1; c < nc; ++c)
      if (length[c] / segments[c] > length[longest] / segments[longest]) longest = c;
    ++segments[longest];
    ++total;
  }

  // Equal arc lengths within each stretch, snapped to vertices where one is close.
  ResampledLoop r;
  r.points.reserve(total);
  r.s_m.reserve(total);
  for (int c = 0; c < nc; ++c) {
    const double s0 = poly.s_m[corners[c]];
    const double step = length[c] / segments[c];
    r.points.push_back(poly.points[corners[c]]);
    r.s_m.push_back(s0);
    for (int k = 1; k < segments[c]; ++k) {
      const ArcPoint a = point_at_arc_length(poly, s0 + step * k, kSnapToVertexFraction * step);
      r.points.push_back(a.p);
      r.s_m.push_back(a.s_m);
    }
  }
  return r;
}

}  // namespace gearsim::fe
