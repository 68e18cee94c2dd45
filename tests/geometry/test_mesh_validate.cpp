// Mesh validation: a closed cube passes; each kind of bad mesh is counted, located (first face,
// edge or vertex) and rejected by require_valid_solid with a message naming file and place.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "geometry/mesh_validate.hpp"

namespace gearsim {
namespace test_mesh_validate {

// Unit cube [0,1]³ in m; vertex index = x + 2y + 4z; faces counter-clockwise from outside.
TriMesh cube(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  TriMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back(offset + Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

// The message require_valid_solid throws for `m`, read as file "gear.stl".
std::string rejection(const TriMesh& m) {
  try {
    require_valid_solid(validate_mesh(m), "gear.stl");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(MeshValidate, ClosedCubeIsAValidSolid) {
  const MeshReport r = validate_mesh(cube());
  EXPECT_EQ(r.triangle_count, 12u);
  EXPECT_EQ(r.vertex_count, 8u);
  EXPECT_TRUE(r.finite());
  EXPECT_TRUE(r.no_degenerate_faces());
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.outward_oriented());
  EXPECT_NEAR(r.signed_volume_m3, 1.0, 1e-15);  // a few roundings of O(1) sums
  EXPECT_NO_THROW(require_valid_solid(r, "gear.stl"));
}

TEST(MeshValidate, CubeMissingAFaceIsNotWatertight) {
  TriMesh m = cube();
  m.triangles.erase(m.triangles.begin() + 2, m.triangles.begin() + 4);  // the +z face
  const MeshReport r = validate_mesh(m);
  EXPECT_FALSE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_EQ(r.open_edge_count, 4u);
  ASSERT_TRUE(r.first_open_edge);
  EXPECT_EQ(r.first_open_edge->face, 3u);  // {0, 5, 4}: its edge 5 -> 4 lost its partner
  EXPECT_EQ(r.first_open_edge->face_count, 1u);
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: not watertight: edge (5, 4) from (1000, 0, 1000) mm "
                  "to (0, 0, 1000) mm belongs to 1 face (face 3");
}

TEST(MeshValidate, FinOnACubeEdgeIsNonManifold) {
  // A third face on the cube edge (0, 1).
  TriMesh m = cube();
  m.vertices.emplace_back(0.5, -1.0, -1.0);
  m.triangles.push_back({0, 1, 8});
  const MeshReport r = validate_mesh(m);
  EXPECT_FALSE(r.manifold());
  EXPECT_EQ(r.nonmanifold_edge_count, 1u);
  ASSERT_TRUE(r.first_nonmanifold_edge);
  EXPECT_EQ(r.first_nonmanifold_edge->face_count, 3u);
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: not manifold: edge (1, 0) from (1000, 0, 0) mm to "
                  "(0, 0, 0) mm belongs to 3 faces (faces 0, 4, ...)");
}

TEST(MeshValidate, CubesTouchingAtACornerHaveANonManifoldVertex) {
  // Second cube shares only vertex 7 = (1,1,1) of the first.
  TriMesh m = cube();
  const TriMesh other = cube(Eigen::Vector3d(1, 1, 1));
  for (int i = 1; i < 8; ++i) m.vertices.push_back(other.vertices[i]);
  const auto remap = [](std::uint32_t v) { return v == 0 ? 7u : 7u + v; };
  for (const auto& t : other.triangles) m.triangles.push_back({remap(t[0]), remap(t[1]), remap(t[2])});
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_FALSE(r.manifold());
  EXPECT_EQ(r.nonmanifold_vertex_count, 1u);
  ASSERT_TRUE(r.first_nonmanifold_vertex);
  EXPECT_EQ(r.first_nonmanifold_vertex->vertex, 7u);
  EXPECT_EQ(r.first_nonmanifold_vertex->fan_count, 2u);
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: not manifold: vertex 7 at (1000, 1000, 1000) mm joins "
                  "2 separate fans of faces (first face 3)");
}

TEST(MeshValidate, OneFlippedFaceIsInconsistentlyOriented) {
  TriMesh m = cube();
  std::swap(m.triangles[5][1], m.triangles[5][2]);  // {0, 5, 4} -> {0, 4, 5}
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_FALSE(r.consistently_oriented());
  EXPECT_EQ(r.misoriented_edge_count, 3u);  // the three edges of the flipped face
  ASSERT_TRUE(r.first_misoriented_edge);
  EXPECT_EQ(r.first_misoriented_edge->other_face, 5u);
  // Lowest face on a misoriented edge: {4, 5, 6} (face 2), sharing 4 -> 5 with the flipped one.
  EXPECT_CONTAINS(rejection(m), "gear.stl: inconsistent orientation: edge (4, 5)");
  EXPECT_CONTAINS(rejection(m), "traversed in the same direction by faces 2 and 5");
}

TEST(MeshValidate, InsideOutCubeHasNegativeVolume) {
  TriMesh m = cube();
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_FALSE(r.outward_oriented());
  EXPECT_NEAR(r.signed_volume_m3, -1.0, 1e-15);  // as for the closed cube
  EXPECT_CONTAINS(rejection(m), "gear.stl: inside out: signed volume -1 m^3 is not positive");
}

TEST(MeshValidate, NanCoordinateIsNotFinite) {
  TriMesh m = cube();
  m.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  const MeshReport r = validate_mesh(m);
  EXPECT_FALSE(r.finite());
  EXPECT_EQ(r.nonfinite_vertex_count, 1u);
  ASSERT_TRUE(r.first_nonfinite_vertex);
  EXPECT_EQ(r.first_nonfinite_vertex->vertex, 3u);
  EXPECT_EQ(r.first_nonfinite_vertex->face, 1u);  // {1, 2, 3}
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: vertex 3 has a non-finite coordinate (1000, nan, 0) mm "
                  "(face 1");
}

TEST(MeshValidate, FaceRepeatingAVertexIsDegenerate) {
  TriMesh m = cube();
  m.triangles.push_back({6, 6, 2});
  const MeshReport r = validate_mesh(m);
  EXPECT_FALSE(r.no_degenerate_faces());
  EXPECT_TRUE(r.watertight());  // its "edges" are left out of the topology
  ASSERT_TRUE(r.first_degenerate_face);
  EXPECT_EQ(r.first_degenerate_face->face, 12u);
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: degenerate face 12 (vertices 6, 6, 2) at (0, 1000, 1000) "
                  "mm repeats a vertex");
}

TEST(MeshValidate, CollinearFaceIsDegenerate) {
  TriMesh m = cube();
  m.vertices.emplace_back(0.5, 0.0, 0.0);  // midpoint of edge (0, 1)
  m.triangles.push_back({0, 8, 1});
  const MeshReport r = validate_mesh(m);
  EXPECT_EQ(r.degenerate_face_count, 1u);
  ASSERT_TRUE(r.first_degenerate_face);
  EXPECT_EQ(r.first_degenerate_face->area_m2, 0.0);  // exactly collinear in binary
  EXPECT_CONTAINS(rejection(m),
                  "gear.stl: degenerate face 12 (vertices 0, 8, 1) at (0, 0, 0) mm "
                  "has area 0 m^2");
}

TEST(MeshValidate, DegenerateToleranceIsHeightOverLongestEdge) {
  // A triangle of base 1 m and height h: degenerate exactly when h < 1e-7 (relative height).
  const auto sliver = [](double h) {
    TriMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}};
    m.triangles = {{0, 1, 2}};
    return validate_mesh(m).degenerate_face_count;
  };
  EXPECT_EQ(sliver(2e-7), 0u);
  EXPECT_EQ(sliver(0.5e-7), 1u);
}

TEST(MeshValidate, EmptyMeshIsRejected) { EXPECT_CONTAINS(rejection(TriMesh{}), "gear.stl: no triangles"); }

TEST(MeshValidate, IndexOutOfRangeIsAnInternalError) {
  TriMesh m = cube();
  m.triangles.push_back({0, 1, 99});
  EXPECT_THROW(validate_mesh(m), InternalError);
}

}  // namespace test_mesh_validate
}  // namespace gearsim
