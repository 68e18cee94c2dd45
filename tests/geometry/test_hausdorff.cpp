// Hausdorff distance between triangle surfaces, against closed-form cases, and the
// decomposition deviation: zero for an exact decomposition, large when a piece is wrong.
#include <gtest/gtest.h>

#include "geometry/convex_decomposition.hpp"
#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/hausdorff.hpp"

namespace gearsim {
namespace test_hausdorff {

TriMesh cube(double side_m, const Eigen::Vector3d& offset) {
  Outline2 sq;
  sq.outer = Polygon2{{{0, 0}, {side_m, 0}, {side_m, side_m}, {0, side_m}}};
  TriMesh m = extrude(sq, 0.0, side_m);
  for (auto& v : m.vertices) v += offset;
  return m;
}

Outline2 l_shape() {
  Outline2 o;
  o.outer = Polygon2{{{0, 0}, {0.02, 0}, {0.02, 0.01}, {0.01, 0.01}, {0.01, 0.02}, {0, 0.02}}};
  return o;
}

TEST(Hausdorff, MeshAgainstItselfIsZero) {
  const TriMesh m = extrude(l_shape(), 0.0, 0.005);
  // Every sample lies on a triangle; what remains is rounding (one ulp of 0.02 m is 3.5e-18 m).
  EXPECT_NEAR(hausdorff_distance(m, m, 1e-3), 0.0, 1e-17);
}

TEST(Hausdorff, CubeShiftedOneMillimetreIsOneMillimetreAway) {
  // The farthest points are the middle of the face x = 0 (from the shifted cube's face x = 1 mm)
  // and its mirror; around them the distance is a 1 mm plateau, so sampling hits it exactly.
  const TriMesh a = cube(0.01, Eigen::Vector3d::Zero());
  const TriMesh b = cube(0.01, Eigen::Vector3d(1e-3, 0, 0));
  EXPECT_NEAR(hausdorff_distance(a, b, 0.5e-3), 1e-3, 1e-15);  // rounding of 1e-2 m coordinates
}

TEST(Hausdorff, MicrometreBumpAtAVertexIsSeenAtCoarseSpacing) {
  // A 10 mm triangle against the same triangle split at its centroid, raised by 1 µm there.
  TriMesh flat, bumped;
  flat.vertices = {{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}};
  flat.triangles = {{0, 1, 2}};
  bumped.vertices = flat.vertices;
  bumped.vertices.push_back({0.01 / 3, 0.01 / 3, 1e-6});
  bumped.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  // Every vertex is a sample, so a 5 mm spacing still finds the 1 µm peak exactly.
  EXPECT_NEAR(hausdorff_distance(flat, bumped, 5e-3), 1e-6, 1e-18);
}

TEST(Hausdorff, ExactDecompositionHasZeroDeviation) {
  const Outline2 l = l_shape();
  const ConvexDecomposition d = decompose(l);
  const DecompositionDeviation dev = decomposition_deviation(extrude(l, 0.0, 0.005), extrude_pieces(d, PrismFrame{}, 0.0, 0.005), 0.5e-3);
  EXPECT_NEAR(dev.hausdorff_m, 0.0, 1e-17);  // rounding of 1e-2 m coordinates
  EXPECT_NEAR(dev.input_volume_m3, 3e-4 * 0.005, 1e-20);
  EXPECT_NEAR(dev.relative_volume_error, 0.0, 1e-14);
  // Two quads: caps of 2 + 2 triangles at each end; the shared edge gets no wall, the 6 outline
  // edges get 2 triangles each.
  EXPECT_EQ(dev.union_boundary_triangles, 2u * 4 + 2u * 6);
}

TEST(Hausdorff, MissingOrMovedPieceIsMeasured) {
  const Outline2 l = l_shape();
  const TriMesh input = extrude(l, 0.0, 0.005);
  ConvexPieces3 pieces = extrude_pieces(decompose(l), PrismFrame{}, 0.0, 0.005);
  ASSERT_EQ(pieces.pieces.size(), 2u);

  ConvexPieces3 moved = pieces;  // a 43 µm shift: no volume change, but internal walls appear
  for (auto& p : moved.pieces[1].points_m) p.x() += 43e-6;
  const DecompositionDeviation shifted = decomposition_deviation(input, moved, 0.5e-3);
  EXPECT_GT(shifted.hausdorff_m, 43e-6);
  EXPECT_NEAR(shifted.relative_volume_error, 0.0, 1e-14);

  ConvexPieces3 missing = pieces;  // one piece gone: the volume check sees it
  missing.pieces.pop_back();
  const DecompositionDeviation gone = decomposition_deviation(input, missing, 0.5e-3);
  EXPECT_GT(gone.hausdorff_m, 1e-3);  // half the missing piece's 10 mm width, at least
  EXPECT_LT(gone.relative_volume_error, -0.3);
}

TEST(Hausdorff, RejectsBadInput) {
  const TriMesh m = cube(0.01, Eigen::Vector3d::Zero());
  EXPECT_THROW(hausdorff_distance(m, m, 0.0), InputError);
  EXPECT_THROW(hausdorff_distance(m, TriMesh{}, 1e-3), InputError);
  EXPECT_THROW(hausdorff_distance(m, m, 1e-9), InputError);  // ~1e13 samples
}

}  // namespace test_hausdorff
}  // namespace gearsim
