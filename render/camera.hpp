// Camera: where the eye is and how it projects (perspective or orthographic), in metres, plus the
// two presets computed from a scene: the whole gearbox seen along −z, and a close-up on a point.
// Not the renderer's GL state: view_matrix() and projection_matrix() are plain maths.
#pragma once

#include <Eigen/Core>

#include "render/constants.hpp"

namespace gearsim::render {

enum class Projection { Perspective, Orthographic };

struct Camera {
  Projection projection = Projection::Perspective;
  Eigen::Vector3d eye_m{0, 0, 0.3};
  Eigen::Vector3d target_m{0, 0, 0};
  Eigen::Vector3d up{0, 1, 0};  // any vector not parallel to the view direction
  double fov_y_rad = constants::kDefaultFieldOfView_rad;  // perspective: vertical field of view
  double view_height_m = 0.1;  // orthographic: height of the view
  double near_m = 0.01, far_m = 10.0;  // clip distances from the eye
};

// An axis-aligned box, m.
struct Bounds {
  Eigen::Vector3d min_m = Eigen::Vector3d::Constant(0), max_m = Eigen::Vector3d::Constant(0);
};

// Throws InputError naming the field when the camera cannot project (eye on the target, up along
// the view direction, a field of view outside (0, π), non-positive sizes, near ≥ far).
void validate_camera(const Camera& camera);

// World → eye (right-handed, looking along −z of the eye frame).
Eigen::Matrix4d view_matrix(const Camera& camera);
// Eye → clip for a viewport of the given width/height ratio (OpenGL conventions).
Eigen::Matrix4d projection_matrix(const Camera& camera, double aspect);

// The whole scene, looking along −z (from +z, +y up in the image), fitted to the eight corners
// of `bounds` with a small margin. tilt_rad > 0 swings the eye toward −y about the scene's
// centre (0 = straight along the axis), to show the gears' faces in depth. Throws InputError for
// non-finite or inverted bounds, or a non-positive aspect (width/height).
Camera overview_camera(const Bounds& bounds, double aspect, double tilt_rad = 0.0, Projection projection = Projection::Perspective);

// A close-up on `point_m`: looking along `view_direction` (from the eye toward the point), the
// view `view_height_m` tall at the point, seen through a vertical field of view fov_y_rad
// (perspective: a narrower one puts the eye farther away, with less depth distortion). Up is +y
// projected on the image plane (+x when the view runs along y).
Camera closeup_camera(const Eigen::Vector3d& point_m, const Eigen::Vector3d& view_direction, double view_height_m,
                      Projection projection = Projection::Perspective, double fov_y_rad = constants::kDefaultFieldOfView_rad);

}  // namespace gearsim::render
