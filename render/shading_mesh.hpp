// The CPU side of drawing a TriMesh: vertices with a normal smoothed across edges flatter than a
// crease angle and kept sharp across steeper ones (crisp gear edges, smooth involute flanks),
// plus the highlight flag; and the marker shapes (sphere, arrow) as TriMeshes.
// Not GPU code: renderer.cpp uploads these arrays as they are.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "geometry/mesh.hpp"

namespace gearsim::render {

// Interleaved vertex as uploaded: position (m, body frame), unit normal, highlight (0 or 1).
struct ShadedVertex {
  float position[3];
  float normal[3];
  float highlight;
};

// Indexed triangles: corners that share position, normal and highlight share a vertex (a gear's
// vertex typically splits in two: cap and wall), so the vertex shader runs ~3× less than with
// one vertex per corner.
struct ShadingMesh {
  std::vector<ShadedVertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle, the TriMesh's winding
};

// crease_angle_rad = 0 gives face (flat) normals. `highlight` is null/empty or one entry per
// triangle. Degenerate triangles get their neighbours' normal.
ShadingMesh shading_mesh(const TriMesh& mesh, double crease_angle_rad, const std::vector<std::uint8_t>* highlight = nullptr);

// A closed UV sphere of radius_m about centre_m.
TriMesh sphere_mesh(const Eigen::Vector3d& centre_m, double radius_m, int segments = 12);

// A closed arrow from `from_m` to `to_m`: a cylinder shaft of shaft_radius_m and a cone head
// (length ≤ a third of the arrow, radius 2.5× the shaft). Empty when the two points coincide.
TriMesh arrow_mesh(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m, double shaft_radius_m, int segments = 16);

// Appends b's triangles (and vertices) to a.
void append_mesh(TriMesh& a, const TriMesh& b);

}  // namespace gearsim::render
