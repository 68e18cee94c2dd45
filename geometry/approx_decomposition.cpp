#include "geometry/approx_decomposition.hpp"

#include <Eigen/Geometry>
#include <HACD/hacdHACD.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <queue>
#include <sstream>
#include <unordered_set>

#include "core/errors.hpp"
#include "geometry/hausdorff.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_validate.hpp"

namespace gearsim {
namespace {

using Vec3 = Eigen::Vector3d;
using Clock = std::chrono::steady_clock;

// HACD scales its input so the bounding-box diagonal is 2 * kHacdScale (NormalizeData) and
// measures concavity in those units; this is its default scale factor.
constexpr double kHacdScale = 1000.0;
// Hull faces are pushed this many bounding-box diagonals outward before they are clipped by the
// other hulls, so a face shared by two hulls back to back counts as inside the union. 1e-10:
// 1e6 times the rounding of the plane tests, and the only error of the clipping (5e-12 m at 5 cm).
constexpr double kUnionProbeRelative = 1e-10;
// A union volume further than this fraction from the input's is worth a warning (dimensionless).
constexpr double kUnionVolumeWarning = 0.01;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

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
  for (std::uint32_t i = 0; i < p.size(); ++i) if (p[i].x() < p[i0].x()) i0 = i;
  auto farthest = [&](auto&& dist) {
    std::uint32_t best = 0;
    for (std::uint32_t i = 0; i < p.size(); ++i) if (dist(p[i]) > dist(p[best])) best = i;
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

// A hull with its face planes and bounding box, for clipping.
struct Hull {
  TriMesh mesh;
  std::vector<Vec3> n;    // unit outward face normals
  std::vector<double> d;  // n . x on each face, m
  Vec3 lo, hi;            // bounding box, m
};

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

// Splits the convex polygon p by the plane n.x = offset into its parts in front (n.x > offset)
// and behind; points on the plane go to both. Returns how far the front part reaches, m.
double split(const std::vector<Vec3>& p, const Vec3& n, double offset, std::vector<Vec3>& front,
             std::vector<Vec3>& back) {
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

// The boundary of the union of the hulls: every hull face minus the other hulls, clipped exactly
// (a convex polygon minus a convex solid is a few convex polygons, one per plane crossed). A face
// point counts as covered when, pushed probe_m along its face normal, it is inside or on another
// hull, so faces of two hulls lying back to back are dropped and coplanar same-side faces kept.
// Front parts reaching less than eps_m off the plane are rounding slivers along the cut: dropped.
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
            if (split(rest, o.n[k], o.d[k] - probe_m * o.n[k].dot(normal), front, back) > eps_m)
              next.push_back(front);
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

// Quadric-error (Garland–Heckbert) half-edge collapses, cheapest first, until at most `target`
// triangles remain: the kept end stays an input vertex, small but curved features (a bore)
// outlive long flat runs, and a collapse is refused when it would break the manifold (link
// condition: the two ends share exactly two neighbours) or flip or flatten a triangle.
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
    for (auto t : faces_of[v]) for (auto w : tris[t]) if (w != v) n.push_back(w);
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
      for (auto& v : moved) if (v == from) v = to;
      const Vec3 before = normal(tris[t]), after = normal(moved);
      if (!(after.dot(before) > 0.0) || after.squaredNorm() < 1e-6 * before.squaredNorm()) return false;
    }
    for (auto t : faces_of[from]) {
      if (has(tris[t], to)) {  // one of the two triangles on the edge: gone
        for (auto v : tris[t]) if (v != from) std::erase(faces_of[v], t);
        --alive;
      } else {
        for (auto& v : tris[t]) if (v == from) v = to;
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
    if (std::any_of(faces_of[e.from].begin(), faces_of[e.from].end(), [&](auto t) { return has(tris[t], e.to); }))
      collapse(e.from, e.to);
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

std::string three_digits(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

}  // namespace

TriMesh convex_hull(const std::vector<Vec3>& points_m) {
  for (std::size_t i = 0; i < points_m.size(); ++i)
    if (!points_m[i].allFinite())
      throw InputError("convex_hull: point " + std::to_string(i) + " is not finite");
  TriMesh hull;
  if (points_m.size() >= 4)
    hull = hull_or_empty(points_m, constants::kHullPlaneRelativeTolerance * diagonal(points_m));
  if (hull.triangles.empty())
    throw InputError("convex_hull: " + std::to_string(points_m.size()) +
                     " points do not span a volume; need 4 or more points not in one plane");
  return hull;
}

ApproxDecomposition approximate_decomposition(const TriMesh& mesh,
                                              const ApproxDecompositionOptions& options) {
  const std::string who = "approximate_decomposition: ";
  if (mesh.triangles.empty()) throw InputError(who + "mesh has no triangles");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw InputError(who + "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                         " of " + std::to_string(mesh.vertices.size()));
  require_valid_solid(validate_mesh(mesh), "approximate_decomposition input");
  if (options.min_clusters < 1) throw InputError(who + "min_clusters must be >= 1");
  if (!(options.max_concavity_m > 0) || !std::isfinite(options.max_concavity_m))
    throw InputError(who + "max_concavity_m = " + std::to_string(options.max_concavity_m) + ": need > 0");
  if (options.max_vertices_per_hull < 4) throw InputError(who + "max_vertices_per_hull must be >= 4");
  if (!(options.compactness_weight >= 0) || !std::isfinite(options.compactness_weight))
    throw InputError(who + "compactness_weight must be finite and >= 0");
  if (options.max_hacd_triangles < 4) throw InputError(who + "max_hacd_triangles must be >= 4");
  if (options.tooth_layout && options.tooth_layout->teeth < 3)
    throw InputError(who + "tooth layout with " + std::to_string(options.tooth_layout->teeth) + " teeth; need >= 3");
  const double diag_m = diagonal(mesh.vertices);
  const double spacing_m = options.sample_spacing_m.value_or(diag_m / constants::kDefaultDeviationSamplesPerDiagonal);
  if (!(spacing_m > 0) || !std::isfinite(spacing_m))
    throw InputError(who + "sample_spacing_m = " + std::to_string(spacing_m) + ": need > 0");

  ApproxDecomposition out;
  out.sample_spacing_m = spacing_m;
  // Decimate a large mesh first: HACD's run time is superlinear (see max_hacd_triangles).
  TriMesh work = mesh.triangles.size() > options.max_hacd_triangles ? decimate(mesh, options.max_hacd_triangles) : mesh;
  if (work.triangles.size() != mesh.triangles.size())
    out.warnings.push_back("approximate decomposition: " + std::to_string(mesh.triangles.size()) +
                           " triangles decimated to " + std::to_string(work.triangles.size()) +
                           " for HACD (quadric-error edge collapses)");
  out.hacd_triangles = work.triangles.size();

  // HACD: its own copies (it normalises the points in place), concavity in its units.
  const auto t0 = Clock::now();
  std::vector<HACD::Vec3<HACD::Real>> points;
  for (const Vec3& v : work.vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<HACD::Vec3<long>> triangles;
  for (const auto& t : work.triangles) triangles.emplace_back(long(t[0]), long(t[1]), long(t[2]));
  const double hacd_per_m = 2.0 * kHacdScale / diagonal(work.vertices);
  HACD::HACD hacd;
  hacd.SetPoints(points.data());
  hacd.SetNPoints(points.size());
  hacd.SetTriangles(triangles.data());
  hacd.SetNTriangles(triangles.size());
  hacd.SetScaleFactor(kHacdScale);
  hacd.SetNClusters(std::size_t(options.min_clusters));
  hacd.SetConcavity(options.max_concavity_m * hacd_per_m);
  hacd.SetNVerticesPerCH(std::size_t(options.max_vertices_per_hull));
  hacd.SetCompacityWeight(options.compactness_weight);
  hacd.SetVolumeWeight(0.0);      // HACD's cost multiplies it by a local never set (0): only slows
  hacd.SetConnectDist(-1.0);      // never bridge separate shells
  hacd.SetAddFacesPoints(true);   // left uninitialised by HACD's constructor
  hacd.SetAddNeighboursDistPoints(options.add_neighbour_points);
  hacd.SetAddExtraDistPoints(options.add_opposite_points);
  GEARSIM_CHECK(hacd.Compute(/*fullCH=*/false, /*exportDistPoints=*/false), "HACD::Compute failed");
  out.hacd_seconds = seconds_since(t0);

  // Our own hull of each cluster's hull points (input vertices, to HACD's normalisation round
  // trip of ~1e-16 of the size): no interior points, outward faces we can clip with.
  const auto t1 = Clock::now();
  std::vector<Hull> hulls;
  std::size_t flat = 0;
  for (std::size_t c = 0; c < hacd.GetNClusters(); ++c) {
    std::vector<HACD::Vec3<HACD::Real>> cp(hacd.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> ct(hacd.GetNTrianglesCH(c));
    hacd.GetCH(c, cp.data(), ct.data());
    std::vector<Vec3> pts;
    for (const auto& q : cp) pts.emplace_back(q.X(), q.Y(), q.Z());
    TriMesh h = hull_or_empty(pts, constants::kHullPlaneRelativeTolerance * diag_m);
    if (h.triangles.empty()) { ++flat; continue; }
    hulls.push_back(make_hull(std::move(h)));
  }
  if (hulls.empty())
    throw InputError(who + "every HACD cluster is flat (no volume) at max_concavity_m = " +
                     std::to_string(options.max_concavity_m) + " m; try a larger one");
  if (flat > 0)
    out.warnings.push_back("approximate decomposition: " + std::to_string(flat) +
                           " flat HACD cluster(s) dropped (no volume)");
  const double pitch_rad = options.tooth_layout ? 2.0 * std::numbers::pi / options.tooth_layout->teeth : 0.0;
  for (const Hull& h : hulls) {
    ConvexPiece3 piece{h.mesh.vertices, -1};
    out.hull_volume_sum_m3 += signed_volume_m3(h.mesh);
    if (options.tooth_layout) {
      const Vec3 c = mass_properties(h.mesh, 1.0).centre_of_mass_m;
      const double turns = (std::atan2(c.y(), c.x()) - options.tooth_layout->tooth0_angle_rad) / pitch_rad;
      const int teeth = options.tooth_layout->teeth;
      piece.tooth = ((static_cast<int>(std::floor(turns + 0.5)) % teeth) + teeth) % teeth;
    }
    out.pieces.pieces.push_back(std::move(piece));
  }

  // Measure: the input surface against the union's boundary.
  const TriMesh boundary = union_surface(hulls, kUnionProbeRelative * diag_m, constants::kHullPlaneRelativeTolerance * diag_m);
  out.deviation_m = hausdorff_distance(mesh, boundary, spacing_m);
  out.input_volume_m3 = signed_volume_m3(mesh);
  out.union_volume_m3 = signed_volume_m3(boundary);
  out.measure_seconds = seconds_since(t1);
  const double volume_error = out.union_volume_m3 / out.input_volume_m3 - 1.0;
  if (std::abs(volume_error) > kUnionVolumeWarning)
    out.warnings.push_back("approximate decomposition: the union of the hulls is " +
                           three_digits(100.0 * volume_error) + " % off the input's volume (> 0: " +
                           "hulls bridge concavities; < 0: voids between hulls inside the solid)");

  std::ostringstream method;
  method << "HACD (Bullet Extras libHACD): max concavity " << options.max_concavity_m * 1e3
         << " mm, <= " << options.max_vertices_per_hull << " vertices per hull, neighbour points "
         << (options.add_neighbour_points ? "on" : "off") << ", "
         << out.hacd_triangles << " triangles in, " << out.pieces.pieces.size() << " hulls out";
  out.method = method.str();
  out.warnings.insert(out.warnings.begin(),
                      "approximate decomposition: µm-scale flank errors are not preserved "
                      "(measured deviation " + three_digits(out.deviation_m * 1e6) + " µm)");
  return out;
}

}  // namespace gearsim
