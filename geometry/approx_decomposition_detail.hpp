// Inside the approximate convex decomposition (approx_decomposition.hpp), shared by its sources:
// the incremental convex hull (approx_decomposition_hull.cpp), the boundary of a union of hulls
// (approx_decomposition_union.cpp) and the quadric-error decimation that shrinks HACD's input
// (approx_decomposition_decimate.cpp); approx_decomposition.cpp runs HACD between them.
// Not for use outside geometry/.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "geometry/mesh.hpp"

namespace gearsim::approx_detail {

using Vec3 = Eigen::Vector3d;

// Length of the bounding-box diagonal of p (not empty), m.
double diagonal(const std::vector<Vec3>& p);

// Incremental convex hull; an empty mesh when the points do not span a volume beyond eps_m.
TriMesh hull_or_empty(const std::vector<Vec3>& p, double eps_m);

// A hull with its face planes and bounding box, for clipping.
struct Hull {
  TriMesh mesh;
  std::vector<Vec3> n;  // unit outward face normals
  std::vector<double> d;  // n . x on each face, m
  Vec3 lo, hi;  // bounding box, m
};

// The hull's face planes and bounding box; mesh is a convex hull with at least one triangle.
Hull make_hull(TriMesh mesh);

// The boundary of the union of the hulls: every hull face minus the other hulls, clipped exactly
// (a convex polygon minus a convex solid is a few convex polygons, one per plane crossed). A face
// point counts as covered when, pushed probe_m along its face normal, it is inside or on another
// hull, so faces of two hulls lying back to back are dropped and coplanar same-side faces kept.
// Front parts reaching less than eps_m off the plane are rounding slivers along the cut: dropped.
TriMesh union_surface(const std::vector<Hull>& hulls, double probe_m, double eps_m);

// Quadric-error (Garland–Heckbert) half-edge collapses, cheapest first, until at most `target`
// triangles remain: the kept end stays an input vertex, small but curved features (a bore)
// outlive long flat runs, and a collapse is refused when it would break the manifold (link
// condition: the two ends share exactly two neighbours) or flip or flatten a triangle.
TriMesh decimate(const TriMesh& m, std::size_t target);

}  // namespace gearsim::approx_detail
