// Exact convex decomposition of planar gear outlines, for Bullet's convex shapes: the outline is
// optionally cut into per-tooth sectors along the gap mid-lines, each part is triangulated and
// the triangles merged by Hertel–Mehlhorn into convex pieces whose union IS the outline (shared
// vertices and edges, no overlap, no gap, no moved vertex: µm flank errors survive).
// Not an approximate decomposition (V-HACD, HACD): no hulls, no simplification, and it works on
// prisms only; the extruded pieces are point sets, the Bullet shapes are built elsewhere.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/outline.hpp"
#include "geometry/prism.hpp"

namespace gearsim {

// A piece corner still counts as convex when it turns clockwise by at most this sine of angle
// (dimensionless). Normally 1e-12: collinear corners are convex, and so are the ~1e-16 rad
// kinks that rounding leaves at inserted cut points; the shape error is < 1e-12 * edge length.
inline constexpr double kConvexSineTolerance = 1e-12;
// A gap mid-line crossing closer than this to an edge end point is taken at the end point, m.
// Normally 1e-12: avoids 1e-18 m slivers, invisible next to µm manufacturing errors.
inline constexpr double kCutSnap_m = 1e-12;

// Where the teeth are: tooth k's centre line points at tooth0_angle_rad + k * 2*pi/teeth about
// the origin (the gear axis); the gap mid-lines lie half a pitch either side.
struct ToothLayout {
  int teeth = 0;  // >= 3
  double tooth0_angle_rad = 0.0;  // rad, counter-clockwise from +x
};

struct DecompositionOptions {
  std::optional<ToothLayout> tooth_layout;  // when set, cut into tooth sectors first
};

struct ConvexPiece2 {
  Polygon2 polygon;  // convex, counter-clockwise, m
  int tooth = -1;  // 0..teeth-1; -1 without a tooth layout
  double area_m2 = 0.0;  // m^2
};

struct ConvexDecomposition {
  std::vector<ConvexPiece2> pieces;
  // True when the outline was cut along the gap mid-lines, so every piece lies in its tooth's
  // sector. False without a layout, or after a fallback (tooth = sector of the piece centroid).
  bool sectors_exact = false;
  std::string fallback_reason;  // why the sector cut was impossible; empty otherwise
  double piece_area_sum_m2 = 0.0;  // m^2
  double outline_area_m2 = 0.0;  // m^2
  double relative_area_error() const { return (piece_area_sum_m2 - outline_area_m2) / outline_area_m2; }
};

// Decomposes a valid outline (see triangulate.hpp) into convex pieces. The sector cut needs at
// most one hole (bore, or an internal gear's toothed loop) and every gap mid-line ray crossing
// each loop exactly once; otherwise the whole outline is decomposed (sectors_exact = false).
// Throws InputError for an invalid outline or a layout with fewer than 3 teeth.
ConvexDecomposition decompose(const Outline2& outline, const DecompositionOptions& options = {});

// True when `polygon` is counter-clockwise, turns once, and every corner is convex within
// `sine_tolerance` (collinear corners count as convex).
bool is_convex(const Polygon2& polygon, double sine_tolerance = kConvexSineTolerance);

// One extruded convex piece: the corners of its bottom cap (counter-clockwise about the
// extrusion axis) followed by the same corners on the top cap, m.
struct ConvexPiece3 {
  std::vector<Eigen::Vector3d> points_m;  // 2n points: bottom ring, then top ring in the same order
  int tooth = -1;
};

struct ConvexPieces3 {
  std::vector<ConvexPiece3> pieces;
};

// Extrudes every piece from w_min_m to w_max_m along frame.z, in the frame's world coordinates.
ConvexPieces3 extrude_pieces(const ConvexDecomposition& decomposition, const PrismFrame& frame, double w_min_m, double w_max_m);

// Extrudes every piece over a recovered prism, back in the mesh's own 3D frame.
ConvexPieces3 extrude_pieces(const ConvexDecomposition& decomposition, const Prism& prism);

}  // namespace gearsim
