#include "fe/outline_resample.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "fe/constants.hpp"

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
  const int i = static_cast<int>(std::upper_bound(poly.s_m.begin(), poly.s_m.end(), s) - poly.s_m.begin()) - 1;
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

std::vector<double> local_spacing(const ArcPolygon& poly, double spacing_m, double max_sagitta_m) {
  const auto& p = poly.points;
  const int n = static_cast<int>(p.size());
  std::vector<double> h(n, spacing_m);
  if (!(max_sagitta_m > 0)) return h;
  for (int i = 0; i < n; ++i) {
    if (std::abs(turn_at(p, i)) > kOutlineCornerTurn_rad) continue;  // a corner is a node anyway
    // Radius of the circle through the vertex and its neighbours (all exact curve points).
    const Vector2d a = p[i] - p[(i + n - 1) % n];
    const Vector2d b = p[(i + 1) % n] - p[i];
    const Vector2d c = p[(i + 1) % n] - p[(i + n - 1) % n];
    const double cross = std::abs(a.x() * b.y() - a.y() * b.x());
    if (cross <= 0) continue;  // straight
    const double rho = a.norm() * b.norm() * c.norm() / (2.0 * cross);
    h[i] = std::min(spacing_m, std::sqrt(8.0 * rho * max_sagitta_m));
  }
  // Grade: |h_i − h_j| ≤ kSpacingGrading · arc distance, sweeping both ways round the loop twice.
  auto ds = [&](int i, int j) {  // arc length from i to j = i + 1 (cyclic)
    double d = (j == 0 ? poly.perimeter_m : poly.s_m[j]) - poly.s_m[i];
    return d;
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      h[j] = std::min(h[j], h[i] + kSpacingGrading * ds(i, j));
    }
    for (int i = n - 1; i >= 0; --i) {
      const int j = (i + 1) % n;
      h[i] = std::min(h[i], h[j] + kSpacingGrading * ds(i, j));
    }
  }
  return h;
}

ResampledLoop resample_loop(const ArcPolygon& poly, double spacing_m, double max_sagitta_m) {
  const int n = static_cast<int>(poly.points.size());
  const std::vector<double> h = local_spacing(poly, spacing_m, max_sagitta_m);
  // Corners: vertices where the outline turns sharply; a smooth loop starts at vertex 0.
  std::vector<int> corners;
  for (int i = 0; i < n; ++i)
    if (std::abs(turn_at(poly.points, i)) > kOutlineCornerTurn_rad) corners.push_back(i);
  if (corners.empty()) corners.push_back(0);
  const int nc = static_cast<int>(corners.size());

  // Cumulative node density D(s) = ∫ ds / h at the vertices, unrolled from corner 0 once round
  // the loop (index k ↔ vertex (corners[0] + k) mod n, k = 0..n).
  const int v0 = corners[0];
  std::vector<double> s_un(n + 1), d_un(n + 1);
  for (int k = 0; k <= n; ++k) {
    const int v = (v0 + k) % n;
    s_un[k] = poly.s_m[v] - poly.s_m[v0] + ((v0 + k) >= n ? poly.perimeter_m : 0.0);
    if (k == 0) {
      d_un[k] = 0.0;
    } else {
      const int u = (v0 + k - 1) % n;
      d_un[k] = d_un[k - 1] + (s_un[k] - s_un[k - 1]) * 0.5 * (1.0 / h[u] + 1.0 / h[v]);
    }
  }
  auto unrolled = [&](int vertex) { return (vertex - v0 + n) % n; };

  // Segments per stretch between consecutive corners: the nearest whole number to its density.
  std::vector<int> k0(nc), k1(nc);
  std::vector<double> density(nc);
  std::vector<int> segments(nc);
  int total = 0;
  for (int c = 0; c < nc; ++c) {
    k0[c] = unrolled(corners[c]);
    k1[c] = (c + 1 < nc) ? unrolled(corners[c + 1]) : n;
    density[c] = d_un[k1[c]] - d_un[k0[c]];
    segments[c] = std::max(1, static_cast<int>(std::lround(density[c])));
    total += segments[c];
  }
  // At least 4 nodes, and an even count: add segments where they are longest.
  while (total < 4 || total % 2 != 0) {
    int longest = 0;
    for (int c = 1; c < nc; ++c)
      if (density[c] / segments[c] > density[longest] / segments[longest]) longest = c;
    ++segments[longest];
    ++total;
  }

  // Equal steps of density within each stretch, snapped to vertices where one is close.
  ResampledLoop r;
  r.points.reserve(total);
  r.s_m.reserve(total);
  for (int c = 0; c < nc; ++c) {
    r.points.push_back(poly.points[corners[c]]);
    r.s_m.push_back(poly.s_m[corners[c]]);
    const double step = density[c] / segments[c];
    int k = k0[c];
    for (int m = 1; m < segments[c]; ++m) {
      const double target = d_un[k0[c]] + step * m;
      while (k + 1 < k1[c] && d_un[k + 1] < target) ++k;
      const double f = (target - d_un[k]) / (d_un[k + 1] - d_un[k]);
      const double s_local = s_un[k] + f * (s_un[k + 1] - s_un[k]);
      const double h_local = h[(v0 + k) % n] + f * (h[(v0 + k + 1) % n] - h[(v0 + k) % n]);
      const ArcPoint a = point_at_arc_length(poly, poly.s_m[v0] + s_local, kSnapToVertexFraction * step * h_local);
      r.points.push_back(a.p);
      r.s_m.push_back(a.s_m);
    }
  }
  return r;
}

double max_edge_sagitta(const ArcPolygon& poly, const ResampledLoop& loop) {
  const int n = static_cast<int>(poly.points.size());
  const int m = static_cast<int>(loop.points.size());
  double worst = 0.0;
  for (int i = 0; i < m; ++i) {
    const Vector2d& a = loop.points[i];
    const Vector2d& b = loop.points[(i + 1) % m];
    const Vector2d ab = b - a;
    const double len = ab.norm();
    double s0 = loop.s_m[i];
    double s1 = loop.s_m[(i + 1) % m];
    if (s1 <= s0) s1 += poly.perimeter_m;
    // Polygon vertices strictly between the two nodes, by arc length.
    int v = static_cast<int>(std::upper_bound(poly.s_m.begin(), poly.s_m.end(), s0) - poly.s_m.begin());
    for (int k = 0; k < n; ++k, ++v) {
      const int w = v % n;
      const double s = poly.s_m[w] + (v >= n ? poly.perimeter_m : 0.0);
      if (s >= s1) break;
      const Vector2d ap = poly.points[w] - a;
      const double d = len > 0 ? std::abs(ab.x() * ap.y() - ab.y() * ap.x()) / len : ap.norm();
      worst = std::max(worst, d);
    }
  }
  return worst;
}

}  // namespace gearsim::fe
