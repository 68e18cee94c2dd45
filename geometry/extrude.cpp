#include "geometry/extrude.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "geometry/convex_decomposition.hpp"
#include "core/errors.hpp"
#include "geometry/triangulate.hpp"

namespace gearsim {
namespace {

void require_z_range(double z_min_m, double z_max_m) {
  if (!std::isfinite(z_min_m) || !std::isfinite(z_max_m) || !(z_min_m < z_max_m))
    throw InputError("extrusion range [" + std::to_string(z_min_m) + ", " + std::to_string(z_max_m) + "] m: need finite z_min_m < z_max_m");
}

// Bottom ring, top ring, caps from `triangles`, side quads along each loop (first index, size).
TriMesh build_prism(const std::vector<Eigen::Vector2d>& points, const std::vector<std::array<int, 3>>& triangles,
                    const std::vector<std::pair<int, int>>& loops, double z_min_m, double z_max_m) {
  TriMesh mesh;
  const auto n = static_cast<std::uint32_t>(points.size());
  mesh.vertices.reserve(2 * points.size());
  for (double z : {z_min_m, z_max_m})
    for (const Eigen::Vector2d& p : points) mesh.vertices.emplace_back(p.x(), p.y(), z);
  mesh.triangles.reserve(2 * triangles.size() + 2 * points.size());
  for (const auto& t : triangles) {
    const auto a = static_cast<std::uint32_t>(t[0]), b = static_cast<std::uint32_t>(t[1]), c = static_cast<std::uint32_t>(t[2]);
    mesh.triangles.push_back({a, c, b});  // bottom cap faces -z
    mesh.triangles.push_back({a + n, b + n, c + n});  // top cap faces +z
  }
  // The material lies left of each loop edge i -> j, so (i, j, j', i') faces outward.
  for (const auto& [first, size] : loops)
    for (int k = 0; k < size; ++k) {
      const auto i = static_cast<std::uint32_t>(first + k);
      const auto j = static_cast<std::uint32_t>(first + (k + 1) % size);
      mesh.triangles.push_back({i, j, j + n});
      mesh.triangles.push_back({i, j + n, i + n});
    }
  return mesh;
}

}  // namespace

TriMesh extrude(const Outline2& outline, double z_min_m, double z_max_m) {
  require_z_range(z_min_m, z_max_m);
  const OutlineTriangulation t = triangulate(outline);
  std::vector<std::pair<int, int>> loops{{0, static_cast<int>(outline.outer.points.size())}};
  int first = loops[0].second;
  for (const Polygon2& h : outline.holes) {
    loops.emplace_back(first, static_cast<int>(h.points.size()));
    first += static_cast<int>(h.points.size());
  }
  return build_prism(t.vertices, t.triangles, loops, z_min_m, z_max_m);
}

TriMesh extrude_twisted(const Outline2& outline, double z_min_m, double z_max_m, double twist_rad_per_m, double max_layer_turn_rad) {
  require_z_range(z_min_m, z_max_m);
  if (!std::isfinite(twist_rad_per_m) || !(max_layer_turn_rad > 0))
    throw InputError("twisted extrusion: need a finite twist and a positive turn per layer");
  if (twist_rad_per_m == 0) return extrude(outline, z_min_m, z_max_m);
  const OutlineTriangulation t = triangulate(outline);
  const double length = z_max_m - z_min_m, mid = 0.5 * (z_min_m + z_max_m);
  const int layers = std::max(1, static_cast<int>(std::ceil(std::abs(twist_rad_per_m) * length / max_layer_turn_rad)));
  const auto n = static_cast<std::uint32_t>(t.vertices.size());
  TriMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(layers + 1) * n);
  for (int l = 0; l <= layers; ++l) {
    const double z = z_min_m + length * l / layers;
    const Eigen::Rotation2Dd turn(twist_rad_per_m * (z - mid));
    for (const Eigen::Vector2d& p : t.vertices) {
      const Eigen::Vector2d q = turn * p;
      mesh.vertices.emplace_back(q.x(), q.y(), z);
    }
  }
  const std::uint32_t top = static_cast<std::uint32_t>(layers) * n;
  for (const auto& tri : t.triangles) {
    const auto a = static_cast<std::uint32_t>(tri[0]), b = static_cast<std::uint32_t>(tri[1]), c = static_cast<std::uint32_t>(tri[2]);
    mesh.triangles.push_back({a, c, b});  // bottom cap faces -z
    mesh.triangles.push_back({a + top, b + top, c + top});  // top cap faces +z
  }
  std::vector<std::pair<int, int>> loops{{0, static_cast<int>(outline.outer.points.size())}};
  int first = loops[0].second;
  for (const Polygon2& h : outline.holes) {
    loops.emplace_back(first, static_cast<int>(h.points.size()));
    first += static_cast<int>(h.points.size());
  }
  // Each layer's quads as build_prism's: the material left of each loop edge i -> j. A turned
  // quad is not flat: one diagonal cuts a sliver off the ruled surface, the other adds one, so the
  // layers take them in turn and the slivers cancel to second order in the turn per layer.
  for (int l = 0; l < layers; ++l) {
    const std::uint32_t lo = static_cast<std::uint32_t>(l) * n, hi = lo + n;
    for (const auto& [start, size] : loops)
      for (int k = 0; k < size; ++k) {
        const auto i = static_cast<std::uint32_t>(start + k), j = static_cast<std::uint32_t>(start + (k + 1) % size);
        if (l % 2 == 0) {
          mesh.triangles.push_back({lo + i, lo + j, hi + j});
          mesh.triangles.push_back({lo + i, hi + j, hi + i});
        } else {
          mesh.triangles.push_back({lo + i, lo + j, hi + i});
          mesh.triangles.push_back({lo + j, hi + j, hi + i});
        }
      }
  }
  return mesh;
}

TriMesh extrude_convex(const Polygon2& convex, double z_min_m, double z_max_m) {
  require_z_range(z_min_m, z_max_m);
  if (const Check c = check_polygon(convex, true, "convex polygon"); !c) throw InputError("cannot extrude: " + c.reason());
  if (!is_convex(convex, kConvexSineTolerance))
    throw InputError("cannot extrude: polygon with " + std::to_string(convex.points.size()) + " points is not convex");
  const auto tris = detail::triangulate_unchecked(convex);
  return build_prism(convex.points, tris, {{0, static_cast<int>(convex.points.size())}}, z_min_m, z_max_m);
}

}  // namespace gearsim
