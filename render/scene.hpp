// Scene: what one frame shows, in metres and newtons — posed bodies (a shared, immutable TriMesh
// each, with an optional per-triangle highlight such as a faulty tooth), contact points with force
// arrows, and overlay text. Plain data; validate_scene() rejects what cannot be drawn.
// Not GPU state: the Renderer uploads each mesh once and reuses it while the pointer lives.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh.hpp"
#include "render/camera.hpp"
#include "render/image.hpp"

namespace gearsim::render {

struct SceneBody {
  std::string name;  // names the body in error messages
  std::shared_ptr<const TriMesh> mesh;  // body frame, m; must not change once rendered
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // body → world, m
  Rgb colour{180, 180, 180};
  // One entry per triangle, non-zero = drawn in highlight_colour; null or empty = none.
  std::shared_ptr<const std::vector<std::uint8_t>> highlight;
  Rgb highlight_colour{230, 40, 30};
};

// A contact point and the force acting there, world frame.
struct ContactMarker {
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
};

struct Scene {
  std::vector<SceneBody> bodies;
  std::vector<ContactMarker> contacts;
  double arrow_m_per_N = 0;  // arrow length per newton, m/N (0: points only, no arrows)
  double marker_radius_m = 0.4e-3;  // contact point sphere radius; arrow shafts are 0.4× this
  Rgb marker_colour{255, 220, 0};
  Rgb arrow_colour{40, 200, 255};
  std::vector<std::string> overlay_lines;  // drawn top-left in a built-in bitmap font
};

// Throws InputError naming the body or marker: no bodies, a body without a mesh or triangles, a
// triangle index out of range, a highlight of the wrong length, a pose that is not a finite rigid
// transform, non-finite markers, a negative or non-finite arrow scale, a non-positive marker radius.
void validate_scene(const Scene& scene);

// Bounding box of every posed body's vertices (the markers excluded), m.
Bounds scene_bounds(const Scene& scene);

}  // namespace gearsim::render
