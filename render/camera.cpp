#include "render/camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace gearsim::render {
namespace {

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

// Distance at which a view `height` tall at the target fills the vertical field of view.
double distance_for_height(double height_m, double fov_y_rad) { return 0.5 * height_m / std::tan(0.5 * fov_y_rad); }

// Up vector for a view direction: +y projected off the direction, or +x when they are parallel.
Eigen::Vector3d up_for(const Eigen::Vector3d& dir) {
  const Eigen::Vector3d y(0, 1, 0);
  return std::abs(dir.normalized().dot(y)) > 0.99 ? Eigen::Vector3d(1, 0, 0) : y;
}

}  // namespace

void validate_camera(const Camera& c) {
  if (!finite(c.eye_m) || !finite(c.target_m) || !finite(c.up)) throw InputError("camera: eye_m, target_m and up must be finite");
  const Eigen::Vector3d d = c.target_m - c.eye_m;
  if (d.norm() <= 0) throw InputError("camera: eye_m coincides with target_m");
  if (c.up.norm() <= 0 || d.normalized().cross(c.up.normalized()).norm() < 1e-9)
    throw InputError("camera: up must be non-zero and not parallel to the view direction");
  if (!(c.near_m > 0) || !(c.far_m > c.near_m) || !std::isfinite(c.far_m)) throw InputError("camera: expected 0 < near_m < far_m (finite)");
  if (c.projection == Projection::Perspective && !(c.fov_y_rad > 0 && c.fov_y_rad < std::numbers::pi))
    throw InputError("camera: fov_y_rad must lie in (0, π)");
  if (c.projection == Projection::Orthographic && !(c.view_height_m > 0 && std::isfinite(c.view_height_m)))
    throw InputError("camera: view_height_m must be positive");
}

Eigen::Matrix4d view_matrix(const Camera& c) {
  const Eigen::Vector3d f = (c.target_m - c.eye_m).normalized();
  const Eigen::Vector3d s = f.cross(c.up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(c.eye_m);
  m(1, 3) = -u.dot(c.eye_m);
  m(2, 3) = f.dot(c.eye_m);
  return m;
}

Eigen::Matrix4d projection_matrix(const Camera& c, double aspect) {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  const double n = c.near_m, f = c.far_m;
  if (c.projection == Projection::Perspective) {
    const double t = 1.0 / std::tan(0.5 * c.fov_y_rad);
    p(0, 0) = t / aspect;
    p(1, 1) = t;
    p(2, 2) = -(f + n) / (f - n);
    p(2, 3) = -2 * f * n / (f - n);
    p(3, 2) = -1;
  } else {
    const double h = 0.5 * c.view_height_m, w = h * aspect;
    p(0, 0) = 1 / w;
    p(1, 1) = 1 / h;
    p(2, 2) = -2 / (f - n);
    p(2, 3) = -(f + n) / (f - n);
    p(3, 3) = 1;
  }
  return p;
}

Camera overview_camera(const Bounds& b, double aspect, double tilt_rad, Projection projection) {
  if (!(aspect > 0) || !std::isfinite(aspect)) throw InputError("overview_camera: aspect must be positive");
  if (!b.min_m.allFinite() || !b.max_m.allFinite() || (b.max_m - b.min_m).minCoeff() < 0)
    throw InputError("overview_camera: bounds must be finite with min_m ≤ max_m");
  const Eigen::Vector3d centre = 0.5 * (b.min_m + b.max_m);
  const double radius = std::max(0.5 * (b.max_m - b.min_m).norm(), 1e-6);
  Camera c;
  c.projection = projection;
  c.target_m = centre;
  const Eigen::AngleAxisd tilt(tilt_rad, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d back = tilt * Eigen::Vector3d::UnitZ();  // from the centre toward the eye
  c.up = tilt * Eigen::Vector3d::UnitY();
  const Eigen::Vector3d right = c.up.cross(back);
  // Fit the box's eight corners: a corner q (from the centre) lies |q·right| across and |q·up| up
  // at depth d − q·back; in view when those stay inside tan(half field) times the depth.
  const double tan_y = std::tan(0.5 * c.fov_y_rad), tan_x = tan_y * aspect;
  double distance = 0, half_height = 0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner((k & 1 ? b.max_m : b.min_m).x(), (k & 2 ? b.max_m : b.min_m).y(), (k & 4 ? b.max_m : b.min_m).z());
    const Eigen::Vector3d q = corner - centre;
    const double x = std::abs(q.dot(right)), y = std::abs(q.dot(c.up));
    distance = std::max(distance, q.dot(back) + std::max(x / tan_x, y / tan_y));
    half_height = std::max(half_height, std::max(y, x / aspect));
  }
  distance = std::max(distance * (1 + constants::kOverviewMargin), radius * (1 + constants::kOverviewMargin));
  c.eye_m = centre + distance * back;
  c.view_height_m = 2 * half_height * (1 + constants::kOverviewMargin);
  c.near_m = std::max(distance - 2 * radius, distance * constants::kNearFraction);
  c.far_m = distance + 2 * radius;
  return c;
}

Camera closeup_camera(const Eigen::Vector3d& point_m, const Eigen::Vector3d& view_direction, double view_height_m, Projection projection,
                      double fov_y_rad) {
  if (!finite(point_m) || !finite(view_direction) || view_direction.norm() <= 0)
    throw InputError("closeup_camera: point_m and view_direction must be finite, the direction non-zero");
  if (!(view_height_m > 0) || !std::isfinite(view_height_m)) throw InputError("closeup_camera: view_height_m must be positive");
  if (!(fov_y_rad > 0 && fov_y_rad < std::numbers::pi)) throw InputError("closeup_camera: fov_y_rad must lie in (0, π)");
  Camera c;
  c.projection = projection;
  c.fov_y_rad = fov_y_rad;
  c.target_m = point_m;
  c.view_height_m = view_height_m;
  const double distance = distance_for_height(view_height_m, c.fov_y_rad);
  const Eigen::Vector3d dir = view_direction.normalized();
  c.eye_m = point_m - distance * dir;
  c.up = up_for(dir);
  c.near_m = distance * constants::kNearFraction;
  c.far_m = distance * constants::kFarFraction;
  return c;
}

}  // namespace gearsim::render
