// Quadric-error (Garland–Heckbert) decimation of a triangle mesh by half-edge collapses, which
// brings a large mesh down to what HACD can decompose in reasonable time. Not a remesher: the
// kept vertices are input vertices, unmoved.
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <iterator>
#include <queue>
#include <vector>

#include "geometry/approx_decomposition_detail.hpp"
#include "geometry/mesh_validate.hpp"

namespace gearsim::approx_detail {

TriMesh decimate(const TriMesh& m, std::size_t target) {
  std::vector<std::array<std::uint32_t, 3>> tris = m.triangles;
  std::vector<std::vector<std::uint32_t>> faces_of(m.vertices.size());
  std::vector<Eigen::Matrix4d> quadric(m.vertices.size(), Eigen::Matrix4d::Zero());
  std::vector<std::uint32_t> stamp(m.vertices.size(), 0);  // bumped when a quadric changes
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    const auto& v = m.vertices;
    const Vec3 n = (v[tris[t][1]] - v[tris[t][0]]).cross(v[tris[t][2]] - v[tris[t][0]]).normalized();
    const Eigen::Vector4d plane(n.x(), n.y(), n.z(), -n.dot(v[tris[t][0]]));
    for (auto i : tris[t]) faces_of[i].push_back(t), quadric[i] += plane * plane.transpose();
  }
  struct Item {
    double cost;
    std::uint32_t from, to, from_stamp, to_stamp;
    bool operator>(const Item& o) const { return cost > o.cost; }
  };
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  auto push = [&](std::uint32_t from, std::uint32_t to) {
    const Eigen::Vector4d p(m.vertices[to].x(), m.vertices[to].y(), m.vertices[to].z(), 1.0);
    queue.push({p.dot((quadric[from] + quadric[to]) * p), from, to, stamp[from], stamp[to]});
  };
  auto push_edges = [&](std::uint32_t t) {
    for (int k = 0; k < 3; ++k) push(tris[t][k], tris[t][(k + 1) % 3]), push(tris[t][(k + 1) % 3], tris[t][k]);
  };
  for (std::uint32_t t = 0; t < tris.size(); ++t) push_edges(t);
  auto neighbours = [&](std::uint32_t v) {
    std::vector<std::uint32_t> n;
    for (auto t : faces_of[v])
      for (auto w : tris[t])
        if (w != v) n.push_back(w);
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    return n;
  };
  auto normal = [&](const std::array<std::uint32_t, 3>& t) {
    return Vec3((m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]));
  };
  auto has = [](const std::array<std::uint32_t, 3>& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; };
  std::size_t alive = tris.size();
  auto collapse = [&](std::uint32_t from, std::uint32_t to) {
    const auto nf = neighbours(from), nt = neighbours(to);
    std::vector<std::uint32_t> common;
    std::set_intersection(nf.begin(), nf.end(), nt.begin(), nt.end(), std::back_inserter(common));
    if (common.size() != 2) return false;
    for (auto t : faces_of[from]) {
      if (has(tris[t], to)) continue;
      auto moved = tris[t];
      for (auto& v : moved)
        if (v == from) v = to;
      const Vec3 before = normal(tris[t]), after = normal(moved);
      if (!(after.dot(before) > 0.0) || after.squaredNorm() < 1e-6 * before.squaredNorm()) return false;
    }
    for (auto t : faces_of[from]) {
      if (has(tris[t], to)) {  // one of the two triangles on the edge: gone
        for (auto v : tris[t])
          if (v != from) std::erase(faces_of[v], t);
        --alive;
      } else {
        for (auto& v : tris[t])
          if (v == from) v = to;
        faces_of[to].push_back(t);
      }
    }
    faces_of[from].clear();
    quadric[to] += quadric[from], ++stamp[to];
    for (auto t : faces_of[to]) push_edges(t);
    return true;
  };
  while (alive > target && !queue.empty()) {
    const Item e = queue.top();
    queue.pop();
    if (e.from_stamp != stamp[e.from] || e.to_stamp != stamp[e.to] || faces_of[e.from].empty()) continue;
    if (std::any_of(faces_of[e.from].begin(), faces_of[e.from].end(), [&](auto t) { return has(tris[t], e.to); })) collapse(e.from, e.to);
  }
  TriMesh out;
  std::vector<std::uint32_t> index(m.vertices.size(), kNoIndex);
  for (std::uint32_t v = 0; v < m.vertices.size(); ++v)
    if (!faces_of[v].empty()) index[v] = std::uint32_t(out.vertices.size()), out.vertices.push_back(m.vertices[v]);
  for (std::uint32_t t = 0; t < tris.size(); ++t)
    if (!faces_of[tris[t][0]].empty() && std::count(faces_of[tris[t][0]].begin(), faces_of[tris[t][0]].end(), t))
      out.triangles.push_back({index[tris[t][0]], index[tris[t][1]], index[tris[t][2]]});
  return out;
}

}  // namespace gearsim::approx_detail
