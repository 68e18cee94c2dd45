// Inside the gear mesher (gear_mesher.hpp), shared by its sources: the loops and the raw mesh
// gmsh returns (gear_mesher.cpp runs gmsh), the element size graded from refined boundary nodes
// (gear_mesher_grading.cpp), the optional split into quads (gear_mesher_subdivide.cpp) and the
// final QuadMesh2 with its boundary edges (gear_mesher_assemble.cpp). Not for use outside fe/.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "fe/constants.hpp"
#include "fe/outline_resample.hpp"
#include "fe/quad_mesh.hpp"

namespace gearsim::fe::mesher_detail {

using Eigen::Vector2d;

// Which loop a boundary node list belongs to.
enum class LoopRole { Toothed, Bore, Rim };

struct Loop {
  LoopRole role;
  ArcPolygon poly;
  ResampledLoop nodes;  // the boundary nodes handed to gmsh
};

// What gmsh returns, renumbered from 0: quads and any triangles Blossom left, and each loop's
// nodes as mesh node indices in loop order.
struct RawMesh {
  std::vector<Vector2d> nodes;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::vector<int>> loop_nodes;
};

// Key of the undirected edge between nodes a and b.
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

// Element size near boundary nodes whose spacing is finer than the radial rule: the size grows
// from a node's spacing by kSpacingGrading per unit distance from it, so refined flanks and
// fillets grade into the interior size instead of meeting it abruptly. A bucket grid finds the
// nodes close enough to matter.
class BoundaryGrading {
 public:
  BoundaryGrading(const std::vector<Loop>& loops, double coarsest_m);
  // Smallest graded size at (x, y), or `limit` when no refined node is close enough.
  double size_at(double x, double y, double limit) const;

 private:
  struct Node {
    Vector2d p;
    double h;
  };
  long cell_of(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static std::uint64_t key(long i, long j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
  }
  double cell_;
  std::vector<Node> nodes_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
};

// Splits quads into 4 and triangles into 3 quads (gear_mesher_subdivide.cpp), then smooths the
// interior nodes.
RawMesh subdivide(const RawMesh& in, const std::vector<Loop>& loops);

// The final mesh: quads turned counter-clockwise, boundary edges found per loop, checked closed.
QuadMesh2 assemble(RawMesh raw, const std::vector<Loop>& loops);

}  // namespace gearsim::fe::mesher_detail
