// The incremental 3-D convex hull: convex_hull() (approx_decomposition.hpp) and the unchecked
// hull_or_empty() that the decomposition runs on HACD's cluster points. Not a decomposition.
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_set>

#include "core/errors.hpp"
#include "geometry/approx_decomposition.hpp"
#include "geometry/approx_decomposition_detail.hpp"

namespace gearsim {
namespace approx_detail {

double diagonal(const std::vector<Vec3>& p) {
  Vec3 lo = p[0], hi = p[0];
  for (const Vec3& q : p) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  return (hi - lo).norm();
}

// Incremental convex hull; an empty mesh when the points do not span a volume beyond eps_m.
TriMesh hull_or_empty(const std::vector<Vec3>& p, double eps_m) {
  struct Face {
    std::array<std::uint32_t, 3> v;
    Vec3 n;  // unit outward normal
    double d;  // n . x on the plane, m
    bool alive;
  };
  if (p.size() < 4) return {};
  std::uint32_t i0 = 0, i1 = 0, i2 = 0, i3 = 0;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    if (p[i].x() < p[i0].x()) i0 = i;
  auto farthest = [&](auto&& dist) {
    std::uint32_t best = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i)
      if (dist(p[i]) > dist(p[best])) best = i;
    return best;
  };
  i1 = farthest([&](const Vec3& q) { return (q - p[i0]).norm(); });
  const Vec3 axis = (p[i1] - p[i0]).normalized();
  i2 = farthest([&](const Vec3& q) { return (q - p[i0]).cross(axis).norm(); });
  const Vec3 normal = (p[i1] - p[i0]).cross(p[i2] - p[i0]).normalized();
  i3 = farthest([&](const Vec3& q) { return std::abs((q - p[i0]).dot(normal)); });
  if (!(std::abs((p[i3] - p[i0]).dot(normal)) > eps_m) || !normal.allFinite()) return {};

  std::vector<Face> faces;
  auto add_face = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Vec3 n = (p[b] - p[a]).cross(p[c] - p[a]).normalized();
    faces.push_back({{a, b, c}, n, n.dot(p[a]), true});
  };
  const Vec3 inner = (p[i0] + p[i1] + p[i2] + p[i3]) / 4.0;
  for (auto f : {std::array{i0, i1, i2}, {i0, i3, i1}, {i1, i3, i2}, {i2, i3, i0}}) {
    if ((p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]).dot(inner - p[f[0]]) > 0) std::swap(f[1], f[2]);
    add_face(f[0], f[1], f[2]);
  }
  std::unordered_set<std::uint64_t> edges;
  auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    // Faces that see p[i]; a point no face sees is inside (or within eps_m of) the hull so far.
    edges.clear();
    std::vector<std::size_t> visible;
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (faces[f].alive && faces[f].n.dot(p[i]) - faces[f].d > eps_m) visible.push_back(f);
    if (visible.empty()) continue;
    for (std::size_t f : visible)
      for (int k = 0; k < 3; ++k) edges.insert(key(faces[f].v[k], faces[f].v[(k + 1) % 3]));
    // Replace them by a cone from p[i] over the horizon (visible edges whose twin is hidden).
    for (std::size_t f : visible) {
      faces[f].alive = false;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = faces[f].v[k], b = faces[f].v[(k + 1) % 3];
        if (!edges.count(key(b, a))) add_face(a, b, i);
      }
    }
  }
  TriMesh hull;
  std::map<std::uint32_t, std::uint32_t> index;
  for (const Face& f : faces) {
    if (!f.alive) continue;
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = index.emplace(f.v[k], std::uint32_t(hull.vertices.size()));
      if (fresh) hull.vertices.push_back(p[f.v[k]]);
      t[k] = it->second;
    }
    hull.triangles.push_back(t);
  }
  return hull;
}

}  // namespace approx_detail

TriMesh convex_hull(const std::vector<Eigen::Vector3d>& points_m) {
  for (std::size_t i = 0; i < points_m.size(); ++i)
    if (!points_m[i].allFinite()) throw InputError("convex_hull: point " + std::to_string(i) + " is not finite");
  TriMesh hull;
  if (points_m.size() >= 4)
    hull = approx_detail::hull_or_empty(points_m, constants::kHullPlaneRelativeTolerance * approx_detail::diagonal(points_m));
  if (hull.triangles.empty())
    throw InputError("convex_hull: " + std::to_string(points_m.size()) +
                     " points do not span a volume; need 4 or more points not in one plane");
  return hull;
}

}  // namespace gearsim
