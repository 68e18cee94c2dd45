#include "geometry/hausdorff.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"

namespace gearsim {
namespace {

using Vec3 = Eigen::Vector3d;

// Above this many samples the spacing is rejected as too fine (memory-free, but hours of work).
constexpr double kMaxSamples = 2e8;

void require_mesh(const TriMesh& m, const char* name) {
  if (m.triangles.empty()) throw InputError(std::string("hausdorff: mesh ") + name + " has no triangles");
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::uint32_t v : m.triangles[t])
      if (v >= m.vertices.size())
        throw InputError(std::string("hausdorff: mesh ") + name + " triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                         " of " + std::to_string(m.vertices.size()));
}

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  return len2 == 0.0 ? a : Vec3(a + std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) * ab);
}

// Exact closest point on triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  if (ab.cross(ac).squaredNorm() <= 1e-30 * ab.squaredNorm() * ac.squaredNorm()) {  // degenerate
    const Vec3 q[3] = {closest_on_segment(p, a, b), closest_on_segment(p, b, c), closest_on_segment(p, c, a)};
    return *std::min_element(q, q + 3, [&](const Vec3& x, const Vec3& y) { return (x - p).squaredNorm() < (y - p).squaredNorm(); });
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  // Inside: drop p onto the plane (well conditioned even for slivers, unlike the barycentrics).
  const Vec3 n = ab.cross(ac);
  return p - n * (ap.dot(n) / n.squaredNorm());
}

// Triangles binned by bounding box in a uniform grid; nearest-surface queries search shells of
// cells outward until no unvisited cell can hold anything closer.
class TriangleGrid {
 public:
  explicit TriangleGrid(const TriMesh& mesh) : mesh_(mesh), stamp_(mesh.triangles.size(), 0) {
    lo_ = hi_ = mesh.vertices[mesh.triangles[0][0]];
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
      for (auto v : t) lo_ = lo_.cwiseMin(mesh.vertices[v]), hi_ = hi_.cwiseMax(mesh.vertices[v]);
      area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    }
    const double ntri = double(mesh.triangles.size());
    cell_ = std::max(std::sqrt(area / ntri), 1e-9 * (hi_ - lo_).norm() + 1e-300);
    for (;;) {
      double cells = 1.0;
      for (int i = 0; i < 3; ++i) cells *= std::floor((hi_[i] - lo_[i]) / cell_) + 1.0;
      if (cells <= std::max(4096.0, 8.0 * ntri)) break;
      cell_ *= 1.25;
    }
    for (int i = 0; i < 3; ++i) n_[i] = static_cast<int>((hi_[i] - lo_[i]) / cell_) + 1;
    start_.assign(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill(start_.begin(), start_.end() - 1);
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        Vec3 tlo = mesh.vertices[tri[0]], thi = tlo;
        for (auto v : tri) tlo = tlo.cwiseMin(mesh.vertices[v]), thi = thi.cwiseMax(mesh.vertices[v]);
        const auto a = cell_of(tlo), b = cell_of(thi);
        const bool one_cell = a == b;
        for (int z = a[2]; z <= b[2]; ++z)
          for (int y = a[1]; y <= b[1]; ++y)
            for (int x = a[0]; x <= b[0]; ++x) {
              if (!one_cell && !touches(tri, x, y, z)) continue;
              if (pass == 0)
                ++start_[index(x, y, z) + 1];
              else
                items_[std::size_t(fill[index(x, y, z)]++)] = static_cast<int>(t);
            }
      }
      if (pass == 0) {
        for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
        items_.resize(std::size_t(start_.back()));
      }
    }
  }

  // Distance from p to the surface; stops early with any value <= good_enough_m. The triangle
  // nearest to the previous query is tried first: successive samples lie close together.
  double distance(const Vec3& p, double good_enough_m) {
    ++query_;
    double best = std::numeric_limits<double>::infinity();
    auto test = [&](int t) {
      const auto& tri = mesh_.triangles[std::size_t(t)];
      const double d = (closest_on_triangle(p, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]) - p).norm();
      if (d < best) best = d, hint_ = t;
    };
    if (hint_ >= 0) {
      test(hint_);
      if (best <= good_enough_m) return best;
      stamp_[std::size_t(hint_)] = query_;
    }
    const auto c = cell_of(p);
    for (int r = 0;; ++r) {
      std::array<int, 3> a, b;
      for (int i = 0; i < 3; ++i) a[i] = std::max(c[i] - r, 0), b[i] = std::min(c[i] + r, n_[i] - 1);
      for (int z = a[2]; z <= b[2]; ++z)
        for (int y = a[1]; y <= b[1]; ++y)
          for (int x = a[0]; x <= b[0]; ++x) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r) continue;
            for (int k = start_[index(x, y, z)]; k < start_[index(x, y, z) + 1]; ++k) {
              const int t = items_[std::size_t(k)];
              if (stamp_[std::size_t(t)] == query_) continue;
              stamp_[std::size_t(t)] = query_;
              test(t);
            }
          }
      if (best <= good_enough_m) return best;
      double bound = std::numeric_limits<double>::infinity();  // to any cell not yet visited
      for (int i = 0; i < 3; ++i) {
        if (a[i] > 0) bound = std::min(bound, p[i] - (lo_[i] + a[i] * cell_));
        if (b[i] < n_[i] - 1) bound = std::min(bound, lo_[i] + (b[i] + 1) * cell_ - p[i]);
      }
      if (best <= bound) return best;  // also ends the search once the whole grid is visited
    }
  }

 private:
  // Conservative: the triangle comes within the cell's circumscribed sphere.
  bool touches(const std::array<std::uint32_t, 3>& tri, int x, int y, int z) const {
    const Vec3 centre = lo_ + cell_ * Vec3(x + 0.5, y + 0.5, z + 0.5);
    const Vec3 q = closest_on_triangle(centre, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
    return (q - centre).norm() <= 0.8660254037844387 * cell_ * (1.0 + 1e-9);  // sqrt(3) / 2
  }
  std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = static_cast<int>(std::clamp(std::floor((p[i] - lo_[i]) / cell_), 0.0, double(n_[i] - 1)));
    return c;
  }
  std::size_t index(int x, int y, int z) const {
    return (std::size_t(z) * std::size_t(n_[1]) + std::size_t(y)) * std::size_t(n_[0]) + std::size_t(x);
  }

  const TriMesh& mesh_;
  Vec3 lo_, hi_;
  double cell_ = 0.0;
  std::array<int, 3> n_{};
  std::vector<int> start_, items_, stamp_;
  int query_ = 0;
  int hint_ = -1;  // triangle nearest to the previous query
};

// Largest distance from a sample of `from` to the surface `to`.
double directed_hausdorff(const TriMesh& from, TriangleGrid& to, double spacing) {
  double worst = 0.0;
  auto visit = [&](const Vec3& p) { worst = std::max(worst, to.distance(p, worst)); };
  std::vector<std::array<Vec3, 3>> stack;
  for (const auto& t : from.triangles) {
    const Vec3 &a = from.vertices[t[0]], &b = from.vertices[t[1]], &c = from.vertices[t[2]];
    visit(a), visit(b), visit(c);
    stack.push_back({a, b, c});
    while (!stack.empty()) {  // bisect the longest edge until every edge is <= spacing
      const auto tri = stack.back();
      stack.pop_back();
      int k = 0;  // longest edge: tri[k] -> tri[k + 1]
      for (int j = 1; j < 3; ++j)
        if ((tri[(j + 1) % 3] - tri[j]).squaredNorm() > (tri[(k + 1) % 3] - tri[k]).squaredNorm()) k = j;
      if ((tri[(k + 1) % 3] - tri[k]).norm() <= spacing) continue;
      const Vec3 m = 0.5 * (tri[k] + tri[(k + 1) % 3]);
      visit(m);
      stack.push_back({tri[k], m, tri[(k + 2) % 3]});
      stack.push_back({m, tri[(k + 1) % 3], tri[(k + 2) % 3]});
    }
  }
  return worst;
}

double estimated_samples(const TriMesh& m, double spacing) {
  double n = 0.0;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    n += 3.0 + 4.0 * (b - a).cross(c - a).norm() / (spacing * spacing) + ((b - a).norm() + (c - b).norm() + (a - c).norm()) / spacing;
  }
  return n;
}

double volume(const TriMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]]));
  return v / 6.0;
}

// Directed edge between exact 3D points, hashed on their bit patterns.
struct EdgeKey {
  std::array<double, 6> c;
  bool operator==(const EdgeKey& o) const { return c == o.c; }
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (double d : k.c) {
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return std::size_t(h);
  }
};
EdgeKey edge_key(const Vec3& a, const Vec3& b) { return {{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}}; }

}  // namespace

double hausdorff_distance(const TriMesh& a, const TriMesh& b, double sample_spacing_m) {
  require_mesh(a, "a");
  require_mesh(b, "b");
  if (!(sample_spacing_m > 0) || !std::isfinite(sample_spacing_m))
    throw InputError("hausdorff: sample spacing " + std::to_string(sample_spacing_m) + " m: need > 0");
  const double samples = estimated_samples(a, sample_spacing_m) + estimated_samples(b, sample_spacing_m);
  if (samples > kMaxSamples)
    throw InputError("hausdorff: sample spacing " + std::to_string(sample_spacing_m) + " m needs ~" + std::to_string(samples) +
                     " samples; use a coarser spacing");
  TriangleGrid grid_a(a), grid_b(b);
  return std::max(directed_hausdorff(a, grid_b, sample_spacing_m), directed_hausdorff(b, grid_a, sample_spacing_m));
}

TriMesh union_boundary(const ConvexPieces3& pieces) {
  std::unordered_map<EdgeKey, int, EdgeKeyHash> edges;
  for (std::size_t p = 0; p < pieces.pieces.size(); ++p) {
    const auto& pts = pieces.pieces[p].points_m;
    if (pts.size() < 6 || pts.size() % 2 != 0)
      throw InputError("convex piece " + std::to_string(p) + " has " + std::to_string(pts.size()) +
                       " points; need 2n (bottom ring, top ring) with n >= 3");
    const std::size_t n = pts.size() / 2;
    for (std::size_t i = 0; i < n; ++i) ++edges[edge_key(pts[i], pts[(i + 1) % n])];
  }
  TriMesh mesh;
  for (const auto& piece : pieces.pieces) {
    const auto& pts = piece.points_m;
    const auto n = static_cast<std::uint32_t>(pts.size() / 2);
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), pts.begin(), pts.end());
    for (std::uint32_t i = 1; i + 1 < n; ++i) {
      mesh.triangles.push_back({base, base + i + 1, base + i});  // bottom cap
      mesh.triangles.push_back({base + n, base + n + i, base + n + i + 1});  // top cap
    }
    for (std::uint32_t i = 0; i < n; ++i) {  // walls only where no neighbour shares the edge
      const std::uint32_t j = (i + 1) % n;
      if (edges.count(edge_key(pts[j], pts[i]))) continue;
      mesh.triangles.push_back({base + i, base + j, base + n + j});
      mesh.triangles.push_back({base + i, base + n + j, base + n + i});
    }
  }
  return mesh;
}

DecompositionDeviation decomposition_deviation(const TriMesh& input, const ConvexPieces3& pieces, double sample_spacing_m) {
  DecompositionDeviation d;
  const TriMesh boundary = union_boundary(pieces);
  d.union_boundary_triangles = boundary.triangles.size();
  d.hausdorff_m = hausdorff_distance(input, boundary, sample_spacing_m);
  d.input_volume_m3 = volume(input);
  for (const auto& piece : pieces.pieces) {
    const auto& pts = piece.points_m;
    const std::size_t n = pts.size() / 2;
    Vec3 area_vector = Vec3::Zero();  // of the bottom ring, m^2
    for (std::size_t i = 0; i < n; ++i) area_vector += 0.5 * pts[i].cross(pts[(i + 1) % n]);
    d.pieces_volume_m3 += area_vector.dot(pts[n] - pts[0]);
  }
  d.relative_volume_error = (d.pieces_volume_m3 - d.input_volume_m3) / d.input_volume_m3;
  return d;
}

}  // namespace gearsim
