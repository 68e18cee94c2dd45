// The final quad mesh of a gear from gmsh's raw mesh: every quad counter-clockwise, the toothed,
// bore and rim edges found per loop, the boundary checked closed. Not the meshing itself
// (gear_mesher.cpp).
#include <map>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "fe/gear_mesher_detail.hpp"

namespace gearsim::fe::mesher_detail {

// The final mesh: quads turned counter-clockwise, boundary edges found per loop, checked closed.
QuadMesh2 assemble(RawMesh raw, const std::vector<Loop>& loops) {
  QuadMesh2 m;
  m.nodes = std::move(raw.nodes);
  m.quads = std::move(raw.quads);
  for (auto& q : m.quads) {
    double a = 0.0;
    for (int e = 0; e < 4; ++e) {
      const Vector2d& p = m.nodes[q[e]];
      const Vector2d& r = m.nodes[q[(e + 1) % 4]];
      a += p.x() * r.y() - p.y() * r.x();
    }
    if (a < 0) std::swap(q[1], q[3]);
  }
  // Edges used by exactly one quad are boundary edges.
  std::map<std::uint64_t, std::pair<QuadEdge, int>> edges;
  for (int qi = 0; qi < static_cast<int>(m.quads.size()); ++qi)
    for (int e = 0; e < 4; ++e) {
      auto& slot = edges[edge_key(m.quads[qi][e], m.quads[qi][(e + 1) % 4])];
      slot.first = {qi, e};
      ++slot.second;
    }
  std::size_t boundary = 0;
  for (const auto& [key, use] : edges) {
    GEARSIM_CHECK(use.second <= 2, "mesh edge shared by more than two quads");
    if (use.second == 1) ++boundary;
  }
  std::size_t on_loops = 0;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& ids = raw.loop_nodes[k];
    std::vector<QuadEdge>& list = loops[k].role == LoopRole::Toothed ? m.toothed_edges
                                  : loops[k].role == LoopRole::Bore  ? m.inner_edges
                                                                     : m.outer_edges;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const auto it = edges.find(edge_key(ids[i], ids[(i + 1) % ids.size()]));
      GEARSIM_CHECK(it != edges.end() && it->second.second == 1, "outline segment is not a boundary edge of the mesh");
      list.push_back(it->second.first);
    }
    on_loops += ids.size();
    if (loops[k].role == LoopRole::Bore) m.bore_nodes = ids;
    if (loops[k].role == LoopRole::Rim) m.rim_nodes = ids;
  }
  GEARSIM_CHECK(boundary == on_loops,
                "mesh has " + std::to_string(boundary) + " boundary edges but its outline loops have " + std::to_string(on_loops));
  return m;
}

}  // namespace gearsim::fe::mesher_detail
