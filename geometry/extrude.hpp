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

// The same for one convex counter-clockwise polygon (collinear points allowed). Throws InputError
// when the polygon is not convex within kConvexSineTolerance (see convex_decomposition.hpp).
TriMesh extrude_convex(const Polygon2& convex, double z_min_m, double z_max_m);

}  // namespace gearsim
