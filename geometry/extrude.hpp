// Extrusion of planar outlines into closed prism meshes along +z: caps from triangulate(), side
// walls as quads split into two triangles, every triangle counter-clockwise seen from outside.
// Not a sweep or loft: the cross-section is constant and the axis is z.
#pragma once

#include "geometry/mesh.hpp"
#include "geometry/outline.hpp"

namespace gearsim {

// A watertight prism over `outline` (outer CCW, holes CW) between z_min_m and z_max_m (m).
// Vertices: every outline point at z_min_m (outer then holes), then the same at z_max_m.
// Throws InputError for an invalid outline or unless z_min_m < z_max_m (both finite).
TriMesh extrude(const Outline2& outline, double z_min_m, double z_max_m);

// The outline swept along +z while it turns about the z axis by twist_rad_per_m per metre (a
// helical gear: helical.hpp's twist_rad_per_m), the section at z turned by twist·(z − z_mid) from
// the outline's own pose, z_mid the middle of [z_min_m, z_max_m]. The side walls are layers of
// quads, as many as keep each layer's turn under max_layer_turn_rad (> 0); twist 0 gives
// extrude()'s mesh. Vertices: every outline point on each layer, bottom first. Watertight and
// outward-oriented like extrude(). Throws InputError as extrude() and for a non-finite twist.
TriMesh extrude_twisted(const Outline2& outline, double z_min_m, double z_max_m, double twist_rad_per_m, double max_layer_turn_rad);

// The same for one convex counter-clockwise polygon (collinear points allowed). Throws InputError
// when the polygon is not convex within kConvexSineTolerance (see convex_decomposition.hpp).
TriMesh extrude_convex(const Polygon2& convex, double z_min_m, double z_max_m);

}  // namespace gearsim
