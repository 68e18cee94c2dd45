// Test helpers: measure a tessellated outline the way a gear metrologist would (where it crosses
// a circle, where a line meets it, how far a point lies from it). Header-only, tests only.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/outline.hpp"
#include "geometry/tessellate.hpp"

namespace gearsim::test {

// Points where the closed polygon crosses the circle |p| = r (linear interpolation on the edge;
// exact to the tessellation's chordal deviation).
inline std::vector<Eigen::Vector2d> circle_crossings(const Polygon2& poly, double r) {
  std::vector<Eigen::Vector2d> out;
  const auto& v = poly.points;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d& a = v[i];
    const Eigen::Vector2d& b = v[(i + 1) % v.size()];
    const double fa = a.norm() - r, fb = b.norm() - r;
    if ((fa < 0) == (fb < 0)) continue;
    // Solve |a + t(b − a)| = r for t in [0, 1].
    const Eigen::Vector2d d = b - a;
    const double A = d.squaredNorm(), B = 2 * a.dot(d), C = a.squaredNorm() - r * r;
    const double disc = std::sqrt(std::max(0.0, B * B - 4 * A * C));
    double t = (-B + disc) / (2 * A);
    if (t < 0 || t > 1) t = (-B - disc) / (2 * A);
    out.push_back(a + t * d);
  }
  return out;
}

// Nearest intersection (signed parameter s) of the line p + s·n with the polygon, within |s| < span.
inline std::optional<double> line_hit(const Polygon2& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& n, double span) {
  std::optional<double> best;
  const auto& v = poly.points;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d& a = v[i];
    const Eigen::Vector2d e = v[(i + 1) % v.size()] - a;
    const double den = n.x() * (-e.y()) - n.y() * (-e.x());
    if (std::abs(den) < 1e-30) continue;
    const Eigen::Vector2d w = a - p;
    const double s = (w.x() * (-e.y()) - w.y() * (-e.x())) / den;
    const double t = (n.x() * w.y() - n.y() * w.x()) / den;
    if (t < 0 || t > 1 || std::abs(s) > span) continue;
    if (!best || std::abs(s) < std::abs(*best)) best = s;
  }
  return best;
}

// Distance from a point to the polygon's boundary.
inline double distance_to_boundary(const Polygon2& poly, const Eigen::Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  const auto& v = poly.points;
  for (std::size_t i = 0; i < v.size(); ++i) d = std::min(d, distance_to_segment(p, v[i], v[(i + 1) % v.size()]));
  return d;
}

// Signed distance to the polygon's boundary: positive inside (even-odd rule).
inline double signed_distance(const Polygon2& poly, const Eigen::Vector2d& p) {
  bool inside = false;
  const auto& v = poly.points;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) && p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
      inside = !inside;
  const double d = distance_to_boundary(poly, p);
  return inside ? d : -d;
}

// Polar angle in (−π, π].
inline double polar(const Eigen::Vector2d& p) { return std::atan2(p.y(), p.x()); }

}  // namespace gearsim::test
