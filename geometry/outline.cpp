#include "geometry/outline.hpp"

namespace gearsim {

double signed_area(const Polygon2& p) {
  double a = 0.0;
  const std::size_t n = p.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& u = p.points[i];
    const Eigen::Vector2d& v = p.points[(i + 1) % n];
    a += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * a;
}

double area(const Outline2& o) {
  double a = signed_area(o.outer);
  for (const Polygon2& h : o.holes) a += signed_area(h);  // holes are clockwise: negative
  return a;
}

}  // namespace gearsim
