// Measured surface deviation: the symmetric Hausdorff distance between two triangle surfaces,
// and the check that matters for collision geometry — how far the boundary of the union of the
// convex pieces lies from the input mesh. Sampled: every triangle is bisected until its edges are
// <= sample_spacing_m and every corner is a sample (so every input vertex and edge end is one);
// each sample's distance to the other surface is exact (point-to-triangle, uniform-grid search).
// The true distance lies between the result and the result + sample_spacing_m / sqrt(3) (the
// largest distance from a surface point to its nearest sample); vertex errors are seen exactly.
// Not a volume comparison (see the volumes in DecompositionDeviation) and not a mesh Boolean.
#pragma once

#include "geometry/convex_decomposition.hpp"
#include "geometry/mesh.hpp"

namespace gearsim {

// Symmetric Hausdorff distance between the surfaces of a and b, m. Throws InputError when a mesh
// is empty, an index is out of range, or sample_spacing_m is not positive.
double hausdorff_distance(const TriMesh& a, const TriMesh& b, double sample_spacing_m);

// The boundary of the union of extruded convex pieces: every cap, plus the side walls over the
// cap edges that no other piece shares (pieces from one decomposition share edges exactly).
TriMesh union_boundary(const ConvexPieces3& pieces);

struct DecompositionDeviation {
  double hausdorff_m = 0.0;  // input surface vs union boundary, m
  double input_volume_m3 = 0.0;  // divergence theorem over the input triangles, m^3
  double pieces_volume_m3 = 0.0;  // sum of the piece prisms' volumes, m^3
  double relative_volume_error = 0.0;  // (pieces - input) / input: the area check times height
  std::size_t union_boundary_triangles = 0;
};

// How far the convex pieces' union deviates from the input mesh, measured (see file comment).
DecompositionDeviation decomposition_deviation(const TriMesh& input, const ConvexPieces3& pieces, double sample_spacing_m);

}  // namespace gearsim
