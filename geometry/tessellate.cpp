#include "geometry/tessellate.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/constants.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

void subdivide(const Curve2& curve, double ta, const Eigen::Vector2d& pa, double tb, const Eigen::Vector2d& pb, double tol, int depth,
               std::vector<Eigen::Vector2d>& out) {
  const double tm = 0.5 * (ta + tb);
  const Eigen::Vector2d pm = curve(tm);
  const Eigen::Vector2d pq1 = curve(0.5 * (ta + tm));
  const Eigen::Vector2d pq3 = curve(0.5 * (tm + tb));
  const double dev = std::max({distance_to_segment(pm, pa, pb), distance_to_segment(pq1, pa, pb), distance_to_segment(pq3, pa, pb)});
  if (dev <= tol) {
    out.push_back(pa);
    return;
  }
  GEARSIM_CHECK(depth < constants::kMaxSubdivisionDepth, "curve subdivision does not converge");
  subdivide(curve, ta, pa, tm, pm, tol, depth + 1, out);
  subdivide(curve, tm, pm, tb, pb, tol, depth + 1, out);
}

}  // namespace

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

void tessellate_curve(const Curve2& curve, double t0, double t1, double tol, std::vector<Eigen::Vector2d>& out) {
  GEARSIM_CHECK(tol > 0, "chordal deviation must be positive");
  // Start from 8 spans so that a curve whose midpoint happens to lie on the chord (an S-bend) is
  // still refined.
  constexpr int kStartSpans = 8;
  Eigen::Vector2d prev = curve(t0);
  for (int i = 0; i < kStartSpans; ++i) {
    const double ta = t0 + (t1 - t0) * i / kStartSpans;
    const double tb = t0 + (t1 - t0) * (i + 1) / kStartSpans;
    const Eigen::Vector2d next = curve(tb);
    subdivide(curve, ta, prev, tb, next, tol, 0, out);
    prev = next;
  }
}

int arc_segments(double radius_m, double span_rad, double tol) {
  const double span = std::abs(span_rad);
  if (span == 0.0) return 0;
  if (tol >= radius_m) return 1;
  // Sagitta of a chord spanning angle θ: R(1 − cos(θ/2)) ≤ tol  ⇔  θ ≤ 2·acos(1 − tol/R).
  const double max_step = 2.0 * std::acos(1.0 - tol / radius_m);
  return std::max(1, static_cast<int>(std::ceil(span / max_step - 1e-12)));
}

void tessellate_arc(const Eigen::Vector2d& centre, double radius_m, double a0, double a1, double tol, std::vector<Eigen::Vector2d>& out) {
  const int n = arc_segments(radius_m, a1 - a0, tol);
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    out.push_back(centre + radius_m * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
}

}  // namespace gearsim
