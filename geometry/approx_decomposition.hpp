// Approximate convex decomposition of a NON-prismatic solid mesh (a CAD gear with chamfers, a hub,
// helical teeth) with HACD — Mamou's Hierarchical Approximate Convex Decomposition, the libHACD of
// Bullet Extras — and the MEASURED deviation of the union of the hulls from the input surface.
// Not exact: hulls bridge concavities up to max_concavity_m, so µm flank errors are lost (for
// prisms use convex_decomposition.hpp, which keeps them). Not a Bullet object: pieces are point
// sets in metres; HACD's internal units and normalisation never leave approx_decomposition.cpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/convex_decomposition.hpp"
#include "geometry/mesh.hpp"

namespace gearsim {

namespace constants {
// Default largest concavity of one HACD cluster, m. Normally 0.1 mm: a twentieth of the tooth
// depth of a 1 mm module gear (2.25 mm). HACD does not keep gear teeth even so: it checks the
// concavity at cluster points only, and 20–80 tooth gears came out 2.4–5 mm off (measured).
inline constexpr double kDefaultApproxConcavity_m = 0.1e-3;
// Default number of deviation samples along the input's bounding-box diagonal (dimensionless).
// Normally 400: a 32 mm gear is sampled every 80 µm and measuring takes ~1 s.
inline constexpr double kDefaultDeviationSamplesPerDiagonal = 400.0;
// Points closer than this fraction of their bounding-box diagonal to a hull plane count as on it
// (dimensionless). Normally 1e-12: ~1e4 times the rounding of the plane tests, 1e-13 m at 0.1 m.
inline constexpr double kHullPlaneRelativeTolerance = 1e-12;
}  // namespace constants

struct ApproxDecompositionOptions {
  // HACD stops merging at this many clusters (>= 1). Normally 1: a convex input gives one hull.
  int min_clusters = 1;
  // Largest concavity a cluster may reach, m: the distance, along the surface normals, from the
  // cluster's surface to its hull. Smaller keeps more detail and gives more pieces.
  double max_concavity_m = constants::kDefaultApproxConcavity_m;
  // Largest number of vertices per hull (>= 4). Normally 100: Bullet's convex-hull shapes cost
  // one support-point loop per vertex; HACD keeps the vertices that add most volume, so a capped
  // hull may miss cluster corners (the measured deviation shows it).
  int max_vertices_per_hull = 100;
  // HACD's compactness weight (dimensionless, >= 0): merges first the clusters whose boundary is
  // short for their area. Normally 0.1 (HACD's default).
  double compactness_weight = 0.1;
  // Count the neighbouring clusters' points that a merged hull would swallow in its concavity.
  // Normally on: without it HACD bridges gear tooth spaces (it only checks a cluster's own
  // points); with it, fewer bridges but some voids between hulls inside the solid.
  bool add_neighbour_points = true;
  // Add, for every triangle, the surface point across the solid (ray along the inner normal) to
  // the concavity test, which keeps thin walls apart. O(n²) ray casts in HACD (+1 s at 3000
  // triangles), and no gain measured on gears, so off by default.
  bool add_opposite_points = false;
  // Meshes with more triangles are decimated to this many before HACD (>= 4). HACD's run time is
  // superlinear and erratic: gears at 2000 triangles took 0.5–3 s, an hourglass 10 s (40 s at
  // 3000), a gear of 8556 over 5 min. Quadric-error collapses keep input vertices; the deviation
  // is still measured against the original mesh.
  std::size_t max_hacd_triangles = 2000;
  // Spacing of the deviation samples, m (> 0). Unset: the input's bounding-box diagonal divided
  // by kDefaultDeviationSamplesPerDiagonal. The measured deviation may fall short of the true one
  // by up to spacing / sqrt(3) (see hausdorff.hpp).
  std::optional<double> sample_spacing_m;
  // When set, each piece gets the tooth whose sector (about the z axis through the origin, see
  // ToothLayout) holds the piece's centroid; otherwise tooth = -1.
  std::optional<ToothLayout> tooth_layout;
};

struct ApproxDecomposition {
  ConvexPieces3 pieces;  // points_m = the vertices of each hull (no interior points), m
  // Measured: the symmetric Hausdorff distance (hausdorff.hpp, sampled every sample_spacing_m)
  // between the input surface and the boundary of the union of the hulls, m. That boundary is
  // every hull face minus the other hulls, clipped exactly (a face lying back to back on another
  // hull's face is inside the union). It counts hulls bulging out of the solid, input surface
  // left uncovered or buried, and voids between hulls inside the solid.
  double deviation_m = 0.0;
  double input_volume_m3 = 0.0;  // divergence theorem over the input, m^3
  double union_volume_m3 = 0.0;  // divergence theorem over the union's boundary, m^3
  double hull_volume_sum_m3 = 0.0;  // sum of the hull volumes (overlaps counted twice), m^3
  double sample_spacing_m = 0.0;  // the spacing used, m
  std::size_t hacd_triangles = 0;  // triangles handed to HACD (after any decimation)
  double hacd_seconds = 0.0;  // wall time in HACD, s
  double measure_seconds = 0.0;  // wall time measuring the deviation, s
  std::string method;  // what was run, with its parameters in SI units
  std::vector<std::string> warnings;  // always the lost-µm-errors note, plus any trouble
};

// Decomposes a valid solid (see require_valid_solid) into convex hulls. Throws InputError for an
// empty, non-finite or invalid mesh, for out-of-range options (naming the value), and when HACD
// leaves no cluster with a volume. Not thread-safe: HACD keeps a global cancel flag.
ApproxDecomposition approximate_decomposition(const TriMesh& mesh, const ApproxDecompositionOptions& options = {});

// The convex hull of points_m: its vertices (a subset of the input, unmoved) and outward
// counter-clockwise triangles; points within kHullPlaneRelativeTolerance of a face are dropped.
// Throws InputError for non-finite points or fewer than 4 points not in one plane.
TriMesh convex_hull(const std::vector<Eigen::Vector3d>& points_m);

}  // namespace gearsim
