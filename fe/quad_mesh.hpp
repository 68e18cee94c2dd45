// QuadMesh2: a planar mesh of 4-node quadrilaterals (CalculiX CPS4/CPS4R) with its boundary edges
// grouped by the loop they lie on, and the quality numbers an analyst checks before solving.
// Not a mesher (gear_mesher.hpp makes one) and not a deck writer.
#pragma once

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

namespace gearsim::fe {

// A boundary edge: (quad index, local edge e), the edge running from the quad's node e to node
// (e + 1) mod 4.
using QuadEdge = std::pair<int, int>;

struct QuadMesh2 {
  std::vector<Eigen::Vector2d> nodes;  // m, in the gear's plane (body frame)
  std::vector<std::array<int, 4>> quads;  // 0-based node indices, counter-clockwise (area > 0)
  // Boundary edges in the order they follow their loop:
  std::vector<QuadEdge> toothed_edges;  // the toothed loop (flanks, fillets, tips, roots)
  std::vector<QuadEdge> inner_edges;  // the bore of an external gear (empty if solid or internal)
  std::vector<QuadEdge> outer_edges;  // the rim of an internal gear (empty for external)
  std::vector<int> bore_nodes;  // nodes on the bore circle, in loop order
  std::vector<int> rim_nodes;  // nodes on the rim circle, in loop order
};

// Shape numbers over all quads. Interior angles in rad; the scaled Jacobian at a corner is the
// sine of its interior angle signed by orientation (1 for a right angle, ≤ 0 inverted/degenerate).
struct QuadMeshQuality {
  int quads = 0;
  int nodes = 0;
  double min_angle_rad = 0.0;
  double max_angle_rad = 0.0;
  double min_scaled_jacobian = 0.0;
  double min_edge_m = 0.0;
  double max_edge_m = 0.0;
};

// Signed area of one quad, m² (positive when counter-clockwise).
double quad_area(const QuadMesh2& mesh, int quad);

// Sum of the quads' signed areas, m².
double mesh_area(const QuadMesh2& mesh);

QuadMeshQuality quad_mesh_quality(const QuadMesh2& mesh);

// Endpoints of a boundary edge, m.
std::pair<Eigen::Vector2d, Eigen::Vector2d> edge_points(const QuadMesh2& mesh, QuadEdge edge);

}  // namespace gearsim::fe
