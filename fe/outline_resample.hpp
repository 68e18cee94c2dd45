// Boundary nodes for a mesher: a closed outline polygon resampled at a chosen spacing, keeping
// every node ON the polygon (outline vertices lie exactly on the true curve; points between
// them within the outline's chordal deviation) and every corner of the outline as a node.
// Not a smoother and not a curve fit: no node is ever moved off the polygon.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/outline.hpp"

namespace gearsim::fe {

// A closed polygon with its arc-length coordinate: s of vertex i is the length from vertex 0.
struct ArcPolygon {
  std::vector<Eigen::Vector2d> points;  // m
  std::vector<double> s_m;  // m, s_m[i] for points[i]; s_m[0] = 0
  double perimeter_m = 0.0;
};

ArcPolygon make_arc_polygon(const Polygon2& polygon);

// A point on the polygon and its arc-length coordinate.
struct ArcPoint {
  Eigen::Vector2d p;  // m
  double s_m = 0.0;  // m, in [0, perimeter)
};

// The point at arc length s (taken modulo the perimeter). It is the nearest vertex when one lies
// within snap_m of s along the polygon, else the point on the chord between two vertices.
ArcPoint point_at_arc_length(const ArcPolygon& poly, double s_m, double snap_m);

// Resampled nodes in the polygon's order, with their arc-length coordinates.
struct ResampledLoop {
  std::vector<Eigen::Vector2d> points;  // m
  std::vector<double> s_m;  // m, arc-length coordinate of each node on the polygon
};

// Nodes about spacing_m apart along the polygon: corners (vertices turning the boundary by more
// than kOutlineCornerTurn_rad) are nodes; each stretch between corners is cut into equal arc
// lengths, snapped to vertices within kSnapToVertexFraction of the spacing. The node count is
// even (a quad mesh needs an even number of boundary edges) and at least 4.
//
// With max_sagitta_m > 0 the spacing also shrinks where the outline curves, so that a straight
// edge between two nodes stays within max_sagitta_m of the curve: the local spacing is
// min(spacing_m, √(8 ρ max_sagitta_m)) with ρ the outline's radius of curvature there, graded so
// that it changes by at most kSpacingGrading per unit arc length, and nodes are placed at equal
// steps of ∫ ds / spacing(s) within each stretch.
ResampledLoop resample_loop(const ArcPolygon& poly, double spacing_m, double max_sagitta_m = 0.0);

// Local target spacing at every polygon vertex, m (the rule above; spacing_m everywhere when
// max_sagitta_m ≤ 0). Exposed for tests and the mesher's interior sizing.
std::vector<double> local_spacing(const ArcPolygon& poly, double spacing_m, double max_sagitta_m);

// Largest distance of a straight edge between consecutive nodes from the polygon between them, m.
double max_edge_sagitta(const ArcPolygon& poly, const ResampledLoop& loop);

}  // namespace gearsim::fe
