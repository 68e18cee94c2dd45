// The optional split of a raw gmsh mesh into quads only (quads into 4, triangles into 3), with
// new boundary nodes placed on the outline and the interior smoothed. Not the meshing itself
// (gear_mesher.cpp).
#include <cmath>
#include <unordered_map>
#include <utility>

#include "fe/gear_mesher_detail.hpp"

namespace gearsim::fe::mesher_detail {
namespace {

// Laplacian smoothing of the interior nodes (each moves to the mean of its edge neighbours,
// all at once per sweep), boundary nodes fixed: evens out the quads next to boundary midpoints
// that moved from their chord onto the outline.
void smooth_interior(RawMesh& m) {
  std::vector<char> fixed(m.nodes.size(), 0);
  for (const auto& ids : m.loop_nodes)
    for (int i : ids) fixed[i] = 1;
  std::vector<std::vector<int>> neighbours(m.nodes.size());
  for (const auto& q : m.quads)
    for (int e = 0; e < 4; ++e) {
      neighbours[q[e]].push_back(q[(e + 1) % 4]);
      neighbours[q[(e + 1) % 4]].push_back(q[e]);
    }
  for (int sweep = 0; sweep < kSubdivisionSmoothingSweeps; ++sweep) {
    std::vector<Vector2d> next = m.nodes;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      if (fixed[i] || neighbours[i].empty()) continue;
      Vector2d sum = Vector2d::Zero();
      for (int j : neighbours[i]) sum += m.nodes[j];
      next[i] = sum / static_cast<double>(neighbours[i].size());
    }
    m.nodes = std::move(next);
  }
}

}  // namespace

// Splits quads into 4 and triangles into 3 quads. Edge midpoints of boundary edges go onto the
// outline polygon (half way along its arc between the edge's nodes); interior ones are midpoints.
RawMesh subdivide(const RawMesh& in, const std::vector<Loop>& loops) {
  RawMesh out;
  out.nodes = in.nodes;
  std::unordered_map<std::uint64_t, int> midpoint;
  // Boundary midpoints first, loop by loop, refining each loop's node list.
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& ids = in.loop_nodes[k];
    const auto& s = loops[k].nodes.s_m;
    const ArcPolygon& poly = loops[k].poly;
    std::vector<int> refined;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::size_t j = (i + 1) % ids.size();
      double ds = std::fmod(s[j] - s[i], poly.perimeter_m);
      if (ds <= 0) ds += poly.perimeter_m;
      const ArcPoint m = point_at_arc_length(poly, s[i] + 0.5 * ds, kSnapToVertexFraction * 0.5 * ds);
      midpoint[edge_key(ids[i], ids[j])] = static_cast<int>(out.nodes.size());
      refined.push_back(ids[i]);
      refined.push_back(static_cast<int>(out.nodes.size()));
      out.nodes.push_back(m.p);
    }
    out.loop_nodes.push_back(std::move(refined));
  }
  auto mid = [&](int a, int b) {
    const auto [it, added] = midpoint.try_emplace(edge_key(a, b), static_cast<int>(out.nodes.size()));
    if (added) out.nodes.push_back(0.5 * (in.nodes[a] + in.nodes[b]));
    return it->second;
  };
  auto centre = [&](const Vector2d& c) {
    out.nodes.push_back(c);
    return static_cast<int>(out.nodes.size()) - 1;
  };
  for (const auto& q : in.quads) {
    const int m01 = mid(q[0], q[1]), m12 = mid(q[1], q[2]), m23 = mid(q[2], q[3]), m30 = mid(q[3], q[0]);
    const int c = centre(0.25 * (in.nodes[q[0]] + in.nodes[q[1]] + in.nodes[q[2]] + in.nodes[q[3]]));
    out.quads.push_back({q[0], m01, c, m30});
    out.quads.push_back({m01, q[1], m12, c});
    out.quads.push_back({c, m12, q[2], m23});
    out.quads.push_back({m30, c, m23, q[3]});
  }
  for (const auto& t : in.triangles) {
    const int m01 = mid(t[0], t[1]), m12 = mid(t[1], t[2]), m20 = mid(t[2], t[0]);
    const int c = centre((in.nodes[t[0]] + in.nodes[t[1]] + in.nodes[t[2]]) / 3.0);
    out.quads.push_back({t[0], m01, c, m20});
    out.quads.push_back({m01, t[1], m12, c});
    out.quads.push_back({c, m12, t[2], m20});
  }
  smooth_interior(out);
  return out;
}

}  // namespace gearsim::fe::mesher_detail
