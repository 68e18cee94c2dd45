// Prism recovery: decides whether a triangle mesh is an extrusion (a right prism over a planar
// outline) and, if so, returns that outline in a 2D frame together with the frame and height.
// Not a repair tool: a mesh that is almost but not quite prismatic (beyond tol_m) is rejected with
// the reason, and the outline is never simplified (only exactly collinear points are dropped).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "core/result.hpp"
#include "geometry/mesh.hpp"
#include "geometry/outline.hpp"

namespace gearsim {

// Points closer than this to the line through their neighbours (and between them) are dropped
// from recovered outlines, m. Normally 1e-12: far below any manufacturing error (µm) yet above
// the rounding of mesh coordinates of gear size (~1e-17 m), so only exact collinearity goes.
inline constexpr double kCollinearDrop_m = 1e-12;

// A right-handed orthonormal frame: world point = origin_m + u*x + v*y + w*z.
struct PrismFrame {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  Eigen::Vector3d z = Eigen::Vector3d::UnitZ();  // the extrusion axis

  Eigen::Vector3d to_world(const Eigen::Vector2d& uv_m, double w_m) const { return origin_m + uv_m.x() * x + uv_m.y() * y + w_m * z; }
};

// A right prism: `outline` (in the frame's u, v) swept from w = 0 to w = height_m along z.
struct Prism {
  PrismFrame frame;
  double height_m = 0.0;
  Outline2 outline;  // one outer loop (CCW about z), holes CW, m
  // The largest distance of a vertex between the caps from the outline, m: 0 where the side
  // walls have no vertices of their own; up to the chords' sagitta where an exporter tessellated
  // a curved wall between the caps (the outline's chords then lie inside the wall's true curve).
  double wall_deviation_m = 0.0;
};

// Recovers the prism of `mesh` within tol_m (m), or refuses naming the offending face, vertex or
// loop: the faces with every corner within tol_m of one of two parallel cap planes form the caps,
// every other face is perpendicular to them, every vertex between the caps lies on the side
// walls (within tol_m of the outline, as exporters that split the walls put them, or within the
// sagitta of its wall's chord where an exporter tessellated a curved wall between the caps:
// Prism::wall_deviation_m says how far), and the top
// cap's boundary forms one outer loop with holes. Candidate axes are the mean normals of the
// groups of near-parallel faces with the most area, whatever the faces' sizes or order (time
// linear in the mesh). The frame's origin is the world origin projected on the bottom
// cap; x is world x (or y) projected on the cap, so a mesh built about the world z axis keeps
// its coordinates. Throws InputError for an empty mesh, out-of-range indices or tol_m <= 0.
Result<Prism> recover_prism(const TriMesh& mesh, double tol_m);

}  // namespace gearsim
