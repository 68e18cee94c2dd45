// The boundary of a union of convex hulls, clipped exactly: every hull face minus the other
// hulls, for measuring how far the union strays from the input. Not a general mesh boolean.
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "geometry/approx_decomposition_detail.hpp"

namespace gearsim::approx_detail {
namespace {

// Splits the convex polygon p by the plane n.x = offset into its parts in front (n.x > offset)
// and behind; points on the plane go to both. Returns how far the front part reaches, m.
double split(const std::vector<Vec3>& p, const Vec3& n, double offset, std::vector<Vec3>& front, std::vector<Vec3>& back) {
  front.clear(), back.clear();
  double reach = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 &a = p[i], &b = p[(i + 1) % p.size()];
    const double sa = n.dot(a) - offset, sb = n.dot(b) - offset;
    reach = std::max(reach, sa);
    if (sa >= 0) front.push_back(a);
    if (sa <= 0) back.push_back(a);
    if ((sa > 0 && sb < 0) || (sa < 0 && sb > 0)) {
      const Vec3 x = a + (b - a) * (sa / (sa - sb));
      front.push_back(x), back.push_back(x);
    }
  }
  return reach;
}

}  // namespace

Hull make_hull(TriMesh mesh) {
  Hull h{std::move(mesh), {}, {}, {}, {}};
  h.lo = h.hi = h.mesh.vertices[0];
  for (const Vec3& v : h.mesh.vertices) h.lo = h.lo.cwiseMin(v), h.hi = h.hi.cwiseMax(v);
  for (const auto& t : h.mesh.triangles) {
    const auto& v = h.mesh.vertices;
    h.n.push_back((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized());
    h.d.push_back(h.n.back().dot(v[t[0]]));
  }
  return h;
}

TriMesh union_surface(const std::vector<Hull>& hulls, double probe_m, double eps_m) {
  TriMesh out;
  std::vector<std::vector<Vec3>> pieces, next;
  std::vector<Vec3> front, back, rest;
  for (std::size_t h = 0; h < hulls.size(); ++h) {
    const auto& v = hulls[h].mesh.vertices;
    for (std::size_t f = 0; f < hulls[h].mesh.triangles.size(); ++f) {
      const auto& t = hulls[h].mesh.triangles[f];
      const Vec3& normal = hulls[h].n[f];
      pieces.assign(1, {v[t[0]], v[t[1]], v[t[2]]});
      for (std::size_t g = 0; g < hulls.size() && !pieces.empty(); ++g) {
        if (g == h) continue;
        const Hull& o = hulls[g];
        next.clear();
        for (auto& poly : pieces) {
          Vec3 lo = poly[0], hi = poly[0];
          for (const Vec3& x : poly) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
          if ((hi.array() + probe_m < o.lo.array()).any() || (lo.array() - probe_m > o.hi.array()).any()) {
            next.push_back(std::move(poly));
            continue;
          }
          rest = poly;  // peel off the parts in front of each plane of o; what is left is covered
          for (std::size_t k = 0; k < o.n.size() && rest.size() >= 3; ++k) {
            if (split(rest, o.n[k], o.d[k] - probe_m * o.n[k].dot(normal), front, back) > eps_m) next.push_back(front);
            rest.swap(back);
          }
        }
        pieces.swap(next);
      }
      for (const auto& poly : pieces) {  // fan-triangulate the convex leftovers
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.insert(out.vertices.end(), poly.begin(), poly.end());
        for (std::uint32_t i = 1; i + 1 < poly.size(); ++i) out.triangles.push_back({base, base + i, base + i + 1});
      }
    }
  }
  return out;
}

}  // namespace gearsim::approx_detail
