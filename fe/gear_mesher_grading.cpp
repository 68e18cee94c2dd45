// The element size near refined boundary nodes (BoundaryGrading, gear_mesher_detail.hpp): each
// node's spacing grown by kSpacingGrading per unit distance, found through a bucket grid. Not the
// radial sizing rule (mesh_size_at_radius, gear_mesher.cpp).
#include <algorithm>
#include <cmath>

#include "fe/gear_mesher_detail.hpp"

namespace gearsim::fe::mesher_detail {

BoundaryGrading::BoundaryGrading(const std::vector<Loop>& loops, double coarsest_m) : cell_(coarsest_m / kSpacingGrading) {
  for (const Loop& l : loops) {
    const auto& p = l.nodes.points;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double h = 0.5 * ((p[(i + 1) % n] - p[i]).norm() + (p[i] - p[(i + n - 1) % n]).norm());
      if (h >= coarsest_m) continue;
      nodes_.push_back({p[i], h});
      grid_[key(cell_of(p[i].x()), cell_of(p[i].y()))].push_back(nodes_.size() - 1);
    }
  }
}

double BoundaryGrading::size_at(double x, double y, double limit) const {
  if (nodes_.empty()) return limit;
  const long cx = cell_of(x), cy = cell_of(y);
  double h = limit;
  for (long i = cx - 1; i <= cx + 1; ++i)
    for (long j = cy - 1; j <= cy + 1; ++j) {
      const auto it = grid_.find(key(i, j));
      if (it == grid_.end()) continue;
      for (std::size_t k : it->second) {
        const Node& nd = nodes_[k];
        h = std::min(h, nd.h + kSpacingGrading * std::hypot(x - nd.p.x(), y - nd.p.y()));
      }
    }
  return h;
}

}  // namespace gearsim::fe::mesher_detail
