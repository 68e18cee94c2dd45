// Triangulation of simple polygons and of outlines with holes (ear clipping), plus the validity
// check every consumer of an outline shares (simple loops, orientation, holes inside the outer).
// Keeps every input vertex (collinear ones included) so extrusion caps meet the side walls
// without T-junctions. Not a constrained Delaunay triangulator: triangle shape is not optimised.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "geometry/outline.hpp"

namespace gearsim {

// Triangles over an outline's vertices: outer points first, then each hole's points, in input
// order. Every triangle is counter-clockwise.
struct OutlineTriangulation {
  std::vector<Eigen::Vector2d> vertices;  // m
  std::vector<std::array<int, 3>> triangles;  // indices into vertices, counter-clockwise
};

// Triangulates a simple counter-clockwise polygon: n - 2 counter-clockwise triangles over its
// point indices. Throws InputError when the polygon has < 3 points, a repeated point, zero area,
// clockwise orientation or intersecting edges.
std::vector<std::array<int, 3>> triangulate(const Polygon2& polygon);

// Triangulates an outline: holes are bridged to the outer boundary (Eberly / earcut style) and
// the resulting single ring is ear-clipped. Throws InputError as above, and when a hole crosses or
// touches another loop, or lies outside the outer boundary or inside another hole.
OutlineTriangulation triangulate(const Outline2& outline);

// Passes when `polygon` is a valid simple polygon of the given orientation, else refused saying
// why. `name` names it in the message ("outer boundary", "hole 2").
Check check_polygon(const Polygon2& polygon, bool counter_clockwise, const std::string& name);

// Passes when `outline` is valid (see triangulate), else refused saying why.
Check check_outline(const Outline2& outline);

// Throws InputError with check_outline's reason when the outline is invalid.
void require_valid(const Outline2& outline);

namespace detail {
// The same triangulations without the validity check, for polygons this library built itself
// (sector polygons, convex pieces). A broken invariant throws InternalError.
std::vector<std::array<int, 3>> triangulate_unchecked(const Polygon2& polygon);
OutlineTriangulation triangulate_unchecked(const Outline2& outline);
}  // namespace detail

}  // namespace gearsim
