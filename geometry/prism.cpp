#include "geometry/prism.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "geometry/triangulate.hpp"

namespace gearsim {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Faces whose unit normals are within this angle of a seed face (rad) join its cluster when
// looking for candidate axes. Normally 1e-3: caps of an extrusion are parallel to rounding.
constexpr double kAxisClusterAngle_rad = 1e-3;
// At most this many face clusters are tried as the extrusion axis.
constexpr int kMaxAxisCandidates = 64;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Area-weighted mean normals of clusters of near-parallel faces (either sense), largest first.
std::vector<Vec3> candidate_axes(const std::vector<Vec3>& face_n) {
  std::vector<int> order(face_n.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return face_n[a].squaredNorm() > face_n[b].squaredNorm(); });
  std::vector<char> taken(face_n.size(), 0);
  std::vector<std::pair<double, Vec3>> clusters;  // (area, mean normal)
  const double cos_tol = std::cos(kAxisClusterAngle_rad);
  for (int seed : order) {
    if (taken[seed] || face_n[seed].norm() == 0.0) continue;
    if (static_cast<int>(clusters.size()) == kMaxAxisCandidates) break;
    const Vec3 s = face_n[seed].normalized();
    Vec3 sum = Vec3::Zero();
    for (std::size_t f = 0; f < face_n.size(); ++f) {
      const double len = face_n[f].norm();
      if (taken[f] || len == 0.0) continue;
      const double c = face_n[f].dot(s) / len;
      if (std::abs(c) < cos_tol) continue;
      taken[f] = 1;
      sum += c > 0 ? face_n[f] : Vec3(-face_n[f]);
    }
    clusters.emplace_back(sum.norm(), sum.normalized());
  }
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Vec3> axes;
  for (const auto& c : clusters) axes.push_back(c.second);
  return axes;
}

// Frame with the given axis: its largest component positive, x from world x (or y).
PrismFrame frame_for(Vec3 z) {
  int big = 0;
  z.cwiseAbs().maxCoeff(&big);
  if (z[big] < 0) z = -z;
  PrismFrame f;
  f.z = z;
  const Vec3 ref = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  f.x = (ref - ref.dot(z) * z).normalized();
  f.y = z.cross(f.x);
  return f;
}

// Drops points within kCollinearDrop_m of the segment joining their neighbours.
std::vector<Vec2> drop_collinear(const std::vector<Vec2>& pts) {
  const int n = static_cast<int>(pts.size());
  std::vector<int> prev(n), next(n), work(n);
  std::vector<char> alive(n, 1);
  for (int i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n, work[i] = i;
  int count = n;
  while (!work.empty() && count > 3) {
    const int i = work.back();
    work.pop_back();
    if (!alive[i]) continue;
    const Vec2 &a = pts[prev[i]], &p = pts[i], &b = pts[next[i]];
    const Vec2 ab = b - a;
    if (ab.norm() == 0.0 || std::abs(cross2(ab, p - a)) / ab.norm() > kCollinearDrop_m ||
        (p - a).dot(ab) <= 0 || (p - b).dot(-ab) <= 0)
      continue;
    alive[i] = 0, --count;
    next[prev[i]] = next[i], prev[next[i]] = prev[i];
    work.push_back(prev[i]), work.push_back(next[i]);
  }
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i)
    if (alive[i]) out.push_back(pts[i]);
  return out;
}

// Tries `axis`: fills `prism`, or refuses saying why the mesh is not a prism along it.
Check try_axis(const TriMesh& mesh, const Vec3& axis, double tol, Prism& prism) {
  const std::size_t nv = mesh.vertices.size();
  PrismFrame f = frame_for(axis);
  std::vector<double> w(nv);
  for (std::size_t i = 0; i < nv; ++i) w[i] = mesh.vertices[i].dot(f.z);
  const double w_lo = *std::min_element(w.begin(), w.end()),
               w_hi = *std::max_element(w.begin(), w.end());
  if (w_hi - w_lo <= tol) return Refusal{"the mesh is flat along this axis"};
  std::vector<int> level(nv);
  double sum_lo = 0, sum_hi = 0;
  int n_lo = 0, n_hi = 0;
  for (std::size_t i = 0; i < nv; ++i) {
    // Offsets from the extreme planes (<= tol) average without the rounding of a sum of heights.
    if (w[i] - w_lo <= tol)
      level[i] = 0, sum_lo += w[i] - w_lo, ++n_lo;
    else if (w_hi - w[i] <= tol)
      level[i] = 1, sum_hi += w[i] - w_hi, ++n_hi;
    else
      return Refusal{"vertex " + std::to_string(i) + " lies " + fmt(w[i] - w_lo) +
             " m above the bottom cap of a " + fmt(w_hi - w_lo) + " m prism"};
  }
  const double bottom = w_lo + sum_lo / n_lo, top = w_hi + sum_hi / n_hi;
  f.origin_m = bottom * f.z;
  std::vector<Vec2> uv(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3 d = mesh.vertices[i] - f.origin_m;
    uv[i] = Vec2(d.dot(f.x), d.dot(f.y));
  }
  // Caps keep all three corners on one plane; every other face must project onto a segment.
  double top_area = 0, bottom_area = 0;
  std::vector<std::size_t> top_faces;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const int l0 = level[tri[0]], l1 = level[tri[1]], l2 = level[tri[2]];
    const Vec2 &a = uv[tri[0]], &b = uv[tri[1]], &c = uv[tri[2]];
    if (l0 == l1 && l1 == l2) {
      const double area = 0.5 * cross2(b - a, c - a);
      (l0 ? top_area : bottom_area) += area;
      if (l0) top_faces.push_back(t);
      continue;
    }
    const std::array<Vec2, 3> p{a, b, c};
    int k = 0;  // the corner opposite the longest projected edge
    for (int j = 1; j < 3; ++j)
      if ((p[(j + 1) % 3] - p[(j + 2) % 3]).norm() > (p[(k + 1) % 3] - p[(k + 2) % 3]).norm())
        k = j;
    const Vec2 e = p[(k + 2) % 3] - p[(k + 1) % 3];
    const double off =
        e.norm() <= tol ? 0.0 : std::abs(cross2(e, p[k] - p[(k + 1) % 3])) / e.norm();
    if (off > tol)
      return Refusal{"face " + std::to_string(t) + " is not perpendicular to the caps: a corner lies " +
             fmt(off) + " m off its wall line"};
  }
  // Weld top-cap corners closer than tol, then keep the directed edges without a reverse twin.
  std::unordered_map<std::uint64_t, std::vector<int>> cells;
  std::vector<int> weld(nv, -1);
  std::vector<Vec2> welded;
  auto key = [](std::int64_t x, std::int64_t y) {
    return std::uint64_t(x) * 73856093u ^ std::uint64_t(y) * 19349663u;
  };
  auto weld_id = [&](std::uint32_t v) {
    if (weld[v] >= 0) return weld[v];
    const auto cx = static_cast<std::int64_t>(std::floor(uv[v].x() / tol));
    const auto cy = static_cast<std::int64_t>(std::floor(uv[v].y() / tol));
    for (std::int64_t dx = -1; dx <= 1 && weld[v] < 0; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && weld[v] < 0; ++dy)
        for (int id : cells[key(cx + dx, cy + dy)])
          if ((welded[id] - uv[v]).norm() <= tol) weld[v] = id;
    if (weld[v] < 0) {
      weld[v] = static_cast<int>(welded.size());
      welded.push_back(uv[v]);
      cells[key(cx, cy)].push_back(weld[v]);
    }
    return weld[v];
  };
  std::unordered_map<std::uint64_t, int> open;
  auto edge_key = [](int a, int b) {
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  };
  for (std::size_t t : top_faces)
    for (int j = 0; j < 3; ++j) {
      const int a = weld_id(mesh.triangles[t][j]), b = weld_id(mesh.triangles[t][(j + 1) % 3]);
      if (a == b) continue;
      auto twin = open.find(edge_key(b, a));
      if (twin != open.end() && twin->second > 0)
        --twin->second;
      else
        ++open[edge_key(a, b)];
    }
  std::vector<int> out(welded.size(), -1);
  for (const auto& [k, count] : open) {
    if (count == 0) continue;
    const int a = int(k >> 32), b = int(k & 0xffffffffu);
    if (count > 1 || out[a] >= 0)
      return Refusal{"the top cap boundary branches at (" + fmt(welded[a].x()) + ", " + fmt(welded[a].y()) +
             ") m"};
    out[a] = b;
  }
  std::vector<std::vector<Vec2>> loops;
  std::vector<char> seen(welded.size(), 0);
  for (std::size_t s = 0; s < welded.size(); ++s) {
    if (out[s] < 0 || seen[s]) continue;
    std::vector<Vec2> loop;
    for (int v = int(s); !seen[v]; v = out[v]) {
      if (out[v] < 0)
        return Refusal{"the top cap boundary is open at (" + fmt(welded[v].x()) + ", " +
               fmt(welded[v].y()) + ") m"};
      seen[v] = 1;
      loop.push_back(welded[v]);
    }
    loops.push_back(drop_collinear(loop));
  }
  prism = Prism{};
  int outers = 0;
  double perimeter = 0;
  for (auto& loop : loops) {
    Polygon2 p{std::move(loop)};
    for (std::size_t i = 0; i < p.points.size(); ++i)
      perimeter += (p.points[(i + 1) % p.points.size()] - p.points[i]).norm();
    if (signed_area(p) > 0)
      ++outers, prism.outline.outer = std::move(p);
    else
      prism.outline.holes.push_back(std::move(p));
  }
  if (outers != 1)
    return Refusal{"the top cap has " + std::to_string(outers) + " outer loops; exactly one is supported"};
  if (std::abs(top_area + bottom_area) > tol * perimeter)
    return Refusal{"the caps differ: top area " + fmt(top_area) + " m^2, bottom area " + fmt(-bottom_area) +
           " m^2"};
  if (const Check c = check_outline(prism.outline); !c) return Refusal{"the recovered outline is invalid: " + c.reason()};
  prism.frame = f;
  prism.height_m = top - bottom;
  return {};
}

}  // namespace

Result<Prism> recover_prism(const TriMesh& mesh, double tol_m) {
  if (!(tol_m > 0) || !std::isfinite(tol_m))
    throw InputError("prism tolerance " + fmt(tol_m) + " m: need > 0");
  if (mesh.triangles.empty()) throw InputError("prism recovery: the mesh has no triangles");
  std::vector<Vec3> face_n;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw InputError("prism recovery: triangle " + std::to_string(t) + " uses vertex " +
                         std::to_string(v) + " of " + std::to_string(mesh.vertices.size()));
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    face_n.push_back((b - a).cross(c - a));
  }
  std::string reason;  // along the first candidate axis: the largest face cluster's normal
  for (const Vec3& axis : candidate_axes(face_n)) {
    Prism prism;
    const Check why = try_axis(mesh, axis, tol_m, prism);
    if (why) return prism;
    if (reason.empty()) {
      const Vec3 shown = frame_for(axis).z;
      reason = "not a prism along its largest face cluster's normal (" + fmt(shown.x() + 0.0) + ", " +
               fmt(shown.y() + 0.0) + ", " + fmt(shown.z() + 0.0) + "): " + why.reason();
    }
  }
  return Refusal{reason.empty() ? "every face is degenerate" : reason};
}

}  // namespace gearsim
