#include "fe/quad_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearsim::fe {

using Eigen::Vector2d;

namespace {
double cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

double quad_area(const QuadMesh2& mesh, int quad) {
  // Shoelace over the four corners.
  const auto& q = mesh.quads[quad];
  double a = 0.0;
  for (int e = 0; e < 4; ++e) a += cross(mesh.nodes[q[e]], mesh.nodes[q[(e + 1) % 4]]);
  return 0.5 * a;
}

double mesh_area(const QuadMesh2& mesh) {
  double a = 0.0;
  for (int i = 0; i < static_cast<int>(mesh.quads.size()); ++i) a += quad_area(mesh, i);
  return a;
}

QuadMeshQuality quad_mesh_quality(const QuadMesh2& mesh) {
  QuadMeshQuality r;
  r.quads = static_cast<int>(mesh.quads.size());
  r.nodes = static_cast<int>(mesh.nodes.size());
  r.min_angle_rad = r.min_scaled_jacobian = r.min_edge_m = std::numeric_limits<double>::infinity();
  r.max_angle_rad = r.max_edge_m = 0.0;
  for (const auto& q : mesh.quads) {
    for (int c = 0; c < 4; ++c) {
      // Corner c between the edge to the next node and the edge to the previous one.
      const Vector2d p = mesh.nodes[q[c]];
      const Vector2d to_next = mesh.nodes[q[(c + 1) % 4]] - p;
      const Vector2d to_prev = mesh.nodes[q[(c + 3) % 4]] - p;
      const double ln = to_next.norm(), lp = to_prev.norm();
      const double sj = (ln > 0 && lp > 0) ? cross(to_next, to_prev) / (ln * lp) : 0.0;
      const double angle = std::atan2(cross(to_next, to_prev), to_next.dot(to_prev));
      r.min_scaled_jacobian = std::min(r.min_scaled_jacobian, sj);
      r.min_angle_rad = std::min(r.min_angle_rad, angle);
      r.max_angle_rad = std::max(r.max_angle_rad, angle);
      r.min_edge_m = std::min(r.min_edge_m, ln);
      r.max_edge_m = std::max(r.max_edge_m, ln);
    }
  }
  return r;
}

std::pair<Vector2d, Vector2d> edge_points(const QuadMesh2& mesh, QuadEdge edge) {
  const auto& q = mesh.quads[edge.first];
  return {mesh.nodes[q[edge.second]], mesh.nodes[q[(edge.second + 1) % 4]]};
}

}  // namespace gearsim::fe
