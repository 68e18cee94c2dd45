// Planar outlines: simple polygons and polygons with holes, in metres, in the gear's plane
// (x, y; the gear axis is +z). Not a general polygon-set library: no Booleans here.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace gearsim {

// A closed simple polygon; the last point is not repeated.
struct Polygon2 {
  std::vector<Eigen::Vector2d> points;  // m
};

// An outer boundary (counter-clockwise) with holes (clockwise).
struct Outline2 {
  Polygon2 outer;
  std::vector<Polygon2> holes;
};

// Signed area (positive for counter-clockwise), m^2.
double signed_area(const Polygon2& p);

// Area enclosed by an outline (outer minus holes), m^2.
double area(const Outline2& o);

}  // namespace gearsim
