// Mesh validation: does a TriMesh bound a solid? Counts and locates non-finite coordinates,
// degenerate faces, open and non-manifold edges, non-manifold vertices, inconsistently oriented
// edges and inside-out meshes, keeping the first offender of each check (lowest face or vertex
// index, so the report is deterministic).
// Not repair: nothing here changes a mesh. A bad mesh is reported (validate_mesh) or rejected
// with a message naming the file and the offending face/edge (require_valid_solid).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "geometry/mesh.hpp"

namespace gearsim {

// --- Constants of mesh validation (candidates for geometry/constants.hpp) ----------------------
namespace constants {
// A face is degenerate when its height over its longest edge is below this (dimensionless),
// i.e. 2·area < tol·(longest edge)². 1e-7 is just below float32's epsilon (1.19e-7): meshes arrive
// as float32 (STL), so a thinner face cannot be told apart from three collinear points and its
// normal is noise. Normally 1e-7; a sound gear-tooth strip (20 mm × 2 µm) sits at 1e-4.
inline constexpr double kDegenerateFaceRelativeHeight = 1e-7;
}  // namespace constants

inline constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();

// A vertex that fails a check.
struct VertexDefect {
  std::uint32_t vertex = kNoIndex;
  Eigen::Vector3d p_m = Eigen::Vector3d::Zero();  // its position, m
  std::uint32_t face = kNoIndex;  // lowest face using it (kNoIndex if none)
  std::uint32_t fan_count = 0;  // separate fans of faces around it (non-manifold vertex only)
};

// A face that fails a check.
struct FaceDefect {
  std::uint32_t face = kNoIndex;
  std::array<std::uint32_t, 3> vertices{kNoIndex, kNoIndex, kNoIndex};
  std::array<Eigen::Vector3d, 3> p_m{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  // corner positions, m
  double area_m2 = 0.0;
};

// An edge that fails a check, written in the winding of its lowest face.
struct EdgeDefect {
  std::array<std::uint32_t, 2> vertices{kNoIndex, kNoIndex};
  std::array<Eigen::Vector3d, 2> p_m{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  // m
  std::uint32_t face = kNoIndex;  // lowest face on the edge
  std::uint32_t other_face = kNoIndex;  // second-lowest face on the edge, if any
  std::uint32_t face_count = 0;  // faces sharing the edge
};

// What validate_mesh found. Faces that repeat a vertex index are counted as degenerate and left
// out of the edge and vertex checks (their edges are not edges).
struct MeshReport {
  std::size_t triangle_count = 0;
  std::size_t vertex_count = 0;
  std::size_t nonfinite_vertex_count = 0;  // vertices with a NaN or infinite coordinate
  std::size_t degenerate_face_count = 0;  // repeated vertex or area below tolerance
  std::size_t open_edge_count = 0;  // edges with exactly one face
  std::size_t nonmanifold_edge_count = 0;  // edges with more than two faces
  std::size_t nonmanifold_vertex_count = 0;  // vertices whose faces form more than one fan
  std::size_t misoriented_edge_count = 0;  // two-face edges both faces traverse the same way
  double signed_volume_m3 = 0.0;  // > 0 when the faces wind counter-clockwise outside

  std::optional<VertexDefect> first_nonfinite_vertex;
  std::optional<FaceDefect> first_degenerate_face;
  std::optional<EdgeDefect> first_open_edge;
  std::optional<EdgeDefect> first_nonmanifold_edge;
  std::optional<VertexDefect> first_nonmanifold_vertex;
  std::optional<EdgeDefect> first_misoriented_edge;

  bool finite() const { return nonfinite_vertex_count == 0; }
  bool no_degenerate_faces() const { return degenerate_face_count == 0; }
  // Every edge shared by exactly two faces.
  bool watertight() const { return open_edge_count == 0 && nonmanifold_edge_count == 0; }
  bool manifold() const { return nonmanifold_edge_count == 0 && nonmanifold_vertex_count == 0; }
  // Each two-face edge traversed in opposite directions by its faces.
  bool consistently_oriented() const { return misoriented_edge_count == 0; }
  bool outward_oriented() const { return signed_volume_m3 > 0.0; }
  bool valid_solid() const {
    return triangle_count > 0 && finite() && no_degenerate_faces() && watertight() && manifold() && consistently_oriented() &&
           outward_oriented();
  }
};

// Runs every check on the mesh. Vertex indices must be in range (a TriMesh invariant:
// GEARSIM_CHECK); everything else is reported, not thrown.
MeshReport validate_mesh(const TriMesh& mesh);

// Throws InputError unless report.valid_solid(), naming `source_name` (usually the file) and the
// first failing check with its face/edge/vertex, coordinates in mm, e.g.
//   "gear.stl: not watertight: edge (12, 57) from (1, 2, 3) mm to (1, 2, 4) mm belongs to
//    1 face (face 33); expected every edge shared by exactly two faces".
// Checks in order: no triangles, non-finite, degenerate, non-manifold edge, non-manifold vertex,
// open edge, inconsistent orientation, inside out.
void require_valid_solid(const MeshReport& report, const std::string& source_name);

}  // namespace gearsim
