#include "geometry/prism.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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

// Face normals are binned on a grid of this pitch over the unit sphere (rad, chord); a face
// counts toward the candidate axes of its own and the 26 neighbouring bins, so faces within
// this angle of each other always share a candidate. Normally 1e-3: caps of an extrusion are
// parallel to rounding (~1e-12 rad on gear meshes), and curved side walls spread over many bins.
constexpr double kAxisBin_rad = 1e-3;
// The largest turn (rad) between two edges of a cap outline that still samples a smooth curve:
// exporters tessellate curves at an angular deflection of at most ~0.5 rad (FreeCAD's coarsest
// default, MeshPart's AngularDeflection); a larger turn is a corner of the outline.
constexpr double kSampledTurn_rad = 0.6;
// At most this many candidate axes are tried, largest face area first.
constexpr int kMaxAxisCandidates = 64;

// Hash of a cell of a 2D grid (welding and the wall-vertex grid).
std::uint64_t key(std::int64_t x, std::int64_t y) { return std::uint64_t(x) * 73856093u ^ std::uint64_t(y) * 19349663u; }

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Candidate extrusion axes: the area-weighted mean normals of groups of near-parallel faces
// (either sense), most area first, no two within 3 bins of each other. Linear in the faces:
// every face normal, in both senses, goes to its bin of a grid of pitch kAxisBin_rad; a bin's
// weight is the face area of its 3×3×3 neighbourhood, whatever the faces' sizes or order.
std::vector<Vec3> candidate_axes(const std::vector<Vec3>& face_n) {
  struct Bin {
    std::array<std::int64_t, 3> cell;
    double area = 0;  // sum of |n| (twice the face areas)
    Vec3 sum = Vec3::Zero();  // sum of the face normals in this bin's sense
  };
  std::vector<Bin> bins;
  std::unordered_map<std::uint64_t, std::vector<int>> index;  // hashed cell -> bins
  auto hash = [](const std::array<std::int64_t, 3>& c) {
    return std::uint64_t(c[0]) * 73856093u ^ std::uint64_t(c[1]) * 19349663u ^ std::uint64_t(c[2]) * 83492791u;
  };
  auto find = [&](const std::array<std::int64_t, 3>& c) -> int {
    const auto it = index.find(hash(c));
    if (it != index.end())
      for (int b : it->second)
        if (bins[b].cell == c) return b;
    return -1;
  };
  for (const Vec3& n : face_n) {
    const double len = n.norm();
    if (!(len > 0) || !std::isfinite(len)) continue;
    for (const double sense : {1.0, -1.0}) {
      const Vec3 u = sense * n / len;
      const std::array<std::int64_t, 3> c{static_cast<std::int64_t>(std::floor(u.x() / kAxisBin_rad)),
                                          static_cast<std::int64_t>(std::floor(u.y() / kAxisBin_rad)),
                                          static_cast<std::int64_t>(std::floor(u.z() / kAxisBin_rad))};
      int b = find(c);
      if (b < 0) {
        b = static_cast<int>(bins.size());
        bins.push_back(Bin{c});
        index[hash(c)].push_back(b);
      }
      bins[b].area += len;
      bins[b].sum += sense * n;
    }
  }
  // Each bin with its neighbourhood's area and mean normal.
  std::vector<std::pair<double, Vec3>> groups(bins.size());
  for (std::size_t b = 0; b < bins.size(); ++b) {
    double area = 0;
    Vec3 sum = Vec3::Zero();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto& c = bins[b].cell;
          const int nb = find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (nb >= 0) area += bins[nb].area, sum += bins[nb].sum;
        }
    groups[b] = {area, sum};
  }
  std::vector<int> order(bins.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (groups[a].first != groups[b].first) return groups[a].first > groups[b].first;
    return bins[a].cell < bins[b].cell;  // ties in a fixed order: deterministic
  });
  std::vector<Vec3> axes;
  const double cos_apart = std::cos(3 * kAxisBin_rad);
  for (int b : order) {
    if (static_cast<int>(axes.size()) == kMaxAxisCandidates) break;
    if (!(groups[b].second.norm() > 0)) continue;
    const Vec3 axis = groups[b].second.normalized();
    if (std::none_of(axes.begin(), axes.end(), [&](const Vec3& a) { return std::abs(a.dot(axis)) >= cos_apart; })) axes.push_back(axis);
  }
  return axes;
}

// The axis refined from the caps a candidate finds: the faces with every corner within tol of
// the lowest or the highest plane across it, their normals summed (each turned toward the
// axis). A cap's summed normals depend on its boundary alone, not on how it is triangulated or
// on noise inside it, so small noisy cap triangles tilted beyond the candidates' bins count as
// much as the rest. Repeated while the axis moves (at most 4 times).
Vec3 refined_axis(const TriMesh& mesh, const std::vector<Vec3>& face_n, Vec3 axis, double tol) {
  for (int pass = 0; pass < 4; ++pass) {
    double w_lo = std::numeric_limits<double>::infinity(), w_hi = -w_lo;
    for (const Vec3& v : mesh.vertices) w_lo = std::min(w_lo, v.dot(axis)), w_hi = std::max(w_hi, v.dot(axis));
    Vec3 sum = Vec3::Zero();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      int lo = 0, hi = 0;
      for (std::uint32_t v : mesh.triangles[t]) {
        const double w = mesh.vertices[v].dot(axis);
        lo += w - w_lo <= tol, hi += w_hi - w <= tol;
      }
      if (lo == 3 || hi == 3) sum += face_n[t].dot(axis) >= 0 ? face_n[t] : Vec3(-face_n[t]);
    }
    if (!(sum.norm() > 0)) break;
    const Vec3 next = sum.normalized();
    const bool moved = (next - axis).norm() > 1e-15;
    axis = next;
    if (!moved) break;
  }
  return axis;
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
    if (ab.norm() == 0.0 || std::abs(cross2(ab, p - a)) / ab.norm() > kCollinearDrop_m || (p - a).dot(ab) <= 0 || (p - b).dot(-ab) <= 0)
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

// Distance from p to the segment ab.
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// The turn (rad, 0 to π) of a closed polygon at each vertex.
std::vector<double> turns(const Polygon2& p) {
  const std::size_t n = p.points.size();
  std::vector<double> t(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 in = p.points[i] - p.points[(i + n - 1) % n], out = p.points[(i + 1) % n] - p.points[i];
    t[i] = std::abs(std::atan2(cross2(in, out), in.dot(out)));
  }
  return t;
}

// Every vertex between the caps lies within tol of the outline (a side wall), or within its
// edge's chord allowance beyond that, or the refusal names the first that does not. An
// exporter that tessellates a curved side wall (a bore's cylinder, a flank) puts vertices on the
// true surface between the caps, off the cap outline's chord by up to the chord's sagitta:
// L²/(8R) = L·θ/8 for a chord of length L on a circle sampled at a turn θ per chord. Each
// edge's allowance is twice that, from the smaller turn at its two ends (at a sharp corner the
// turn is the corner's, not the wall's curvature), and none where both ends turn more than
// kSampledTurn_rad (corners of a polygon, not samples of a curve). `allowance` gets each wall vertex's (its
// nearest edge's) and `curvature` its edge's turn per length (rad/m: the wall's curvature there,
// 0 where the edge is no sample of a curve), `deviation` the largest distance of a wall vertex
// from the outline. Outline
// edges are binned on a grid whose cell (the mean edge length, at least 4·tol and 1e-6 of the
// perimeter, and the largest allowance) bounds the work: each edge is walked in steps of a cell
// and goes to the 3×3 cells around each step, so a vertex within its allowance of an edge finds
// it in its own cell.
Check wall_vertices_on_outline(const Outline2& outline, const std::vector<Vec2>& uv, const std::vector<double>& w,
                               const std::vector<std::size_t>& wall, double tol, double w_lo, double w_hi, std::vector<double>& allowance,
                               std::vector<double>& curvature, double& deviation) {
  deviation = 0;
  if (wall.empty()) return {};
  std::vector<std::pair<Vec2, Vec2>> edges;
  std::vector<double> edge_allowance, edge_curvature;
  double length = 0;
  auto add = [&](const Polygon2& p) {
    const std::vector<double> turn = turns(p);
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const std::size_t j = (i + 1) % p.points.size();
      edges.emplace_back(p.points[i], p.points[j]);
      const double l = (edges.back().second - edges.back().first).norm();
      length += l;
      const double sampled = std::min(turn[i], turn[j]);
      edge_allowance.push_back(sampled <= kSampledTurn_rad ? l * sampled / 4 : 0.0);
      edge_curvature.push_back(sampled <= kSampledTurn_rad && l > 0 ? sampled / l : 0.0);
    }
  };
  add(outline.outer);
  for (const Polygon2& h : outline.holes) add(h);
  const double cell = std::max({length / static_cast<double>(edges.size()), 4 * tol, 1e-6 * length,
                                *std::max_element(edge_allowance.begin(), edge_allowance.end())});
  auto to_cell = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto& [a, b] = edges[e];
    const auto steps = static_cast<std::int64_t>(std::ceil((b - a).norm() / cell));
    for (std::int64_t k = 0; k <= steps; ++k) {
      const Vec2 p = steps > 0 ? Vec2(a + (b - a) * (double(k) / double(steps))) : a;
      const std::int64_t cx = to_cell(p.x()), cy = to_cell(p.y());
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          auto& list = grid[key(cx + dx, cy + dy)];
          if (list.empty() || list.back() != static_cast<int>(e)) list.push_back(static_cast<int>(e));
        }
    }
  }
  for (std::size_t i : wall) {
    double best = std::numeric_limits<double>::infinity();
    int nearest = -1;
    const auto it = grid.find(key(to_cell(uv[i].x()), to_cell(uv[i].y())));
    if (it != grid.end())
      for (int e : it->second)
        if (const double d = segment_distance(uv[i], edges[e].first, edges[e].second); d < best) best = d, nearest = e;
    if (nearest < 0 || best > tol + edge_allowance[static_cast<std::size_t>(nearest)]) {
      // Not near an edge of its own cell: the distance to the nearest edge, for the message.
      for (const auto& [a, b] : edges) best = std::min(best, segment_distance(uv[i], a, b));
      return Refusal{
          "vertex " + std::to_string(i) + " lies " + fmt(w[i] - w_lo) + " m above the bottom cap of a " + fmt(w_hi - w_lo) +
          " m prism and " + fmt(best) + " m off its side walls" +
          (nearest >= 0 ? " (its wall's chord allows " + fmt(tol + edge_allowance[static_cast<std::size_t>(nearest)]) + " m)" : "")};
    }
    allowance[i] = edge_allowance[static_cast<std::size_t>(nearest)];
    curvature[i] = edge_curvature[static_cast<std::size_t>(nearest)];
    deviation = std::max(deviation, best);
  }
  return {};
}

// Tries `axis`: fills `prism`, or refuses saying why the mesh is not a prism along it.
Check try_axis(const TriMesh& mesh, const Vec3& axis, double tol, Prism& prism) {
  const std::size_t nv = mesh.vertices.size();
  PrismFrame f = frame_for(axis);
  std::vector<double> w(nv);
  for (std::size_t i = 0; i < nv; ++i) w[i] = mesh.vertices[i].dot(f.z);
  const double w_lo = *std::min_element(w.begin(), w.end()), w_hi = *std::max_element(w.begin(), w.end());
  if (w_hi - w_lo <= tol) return Refusal{"the mesh is flat along this axis"};
  // Level 0: on the bottom cap, 1: on the top cap, 2: on a side wall between them (exporters
  // put vertices there; each must lie on the outline within tol, checked below).
  std::vector<int> level(nv);
  std::vector<std::size_t> wall_vertices;
  double sum_lo = 0, sum_hi = 0;
  int n_lo = 0, n_hi = 0;
  for (std::size_t i = 0; i < nv; ++i) {
    // Offsets from the extreme planes (<= tol) average without the rounding of a sum of heights.
    if (w[i] - w_lo <= tol)
      level[i] = 0, sum_lo += w[i] - w_lo, ++n_lo;
    else if (w_hi - w[i] <= tol)
      level[i] = 1, sum_hi += w[i] - w_hi, ++n_hi;
    else
      level[i] = 2, wall_vertices.push_back(i);
  }
  const double bottom = w_lo + sum_lo / n_lo, top = w_hi + sum_hi / n_hi;
  f.origin_m = bottom * f.z;
  std::vector<Vec2> uv(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3 d = mesh.vertices[i] - f.origin_m;
    uv[i] = Vec2(d.dot(f.x), d.dot(f.y));
  }
  // Caps keep all three corners on one plane; every other face projects onto a segment: within
  // tol, and where it has wall vertices (a face across a curved wall's tessellation, checked once
  // the outline is known) within their chord allowance or the sagitta of its own span e on the
  // wall's curvature κ there, twice e²·κ/8 (a face may span several of the caps' chords).
  std::vector<double> allowance(nv, 0.0), curvature(nv, 0.0);
  auto off_wall_line = [&](std::size_t t) -> Check {
    const auto& tri = mesh.triangles[t];
    const std::array<Vec2, 3> p{uv[tri[0]], uv[tri[1]], uv[tri[2]]};
    int k = 0;  // the corner opposite the longest projected edge
    for (int j = 1; j < 3; ++j)
      if ((p[(j + 1) % 3] - p[(j + 2) % 3]).norm() > (p[(k + 1) % 3] - p[(k + 2) % 3]).norm()) k = j;
    const Vec2 e = p[(k + 2) % 3] - p[(k + 1) % 3];
    const double off = e.norm() <= tol ? 0.0 : std::abs(cross2(e, p[k] - p[(k + 1) % 3])) / e.norm();
    const double kappa = std::max({curvature[tri[0]], curvature[tri[1]], curvature[tri[2]]});
    if (off > tol + std::max({allowance[tri[0]], allowance[tri[1]], allowance[tri[2]], e.squaredNorm() * kappa / 4}))
      return Refusal{"face " + std::to_string(t) + " is not perpendicular to the caps: a corner lies " + fmt(off) + " m off its wall line"};
    return {};
  };
  double top_area = 0, bottom_area = 0;
  std::vector<std::size_t> top_faces, curved_wall_faces;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const int l0 = level[tri[0]], l1 = level[tri[1]], l2 = level[tri[2]];
    const Vec2 &a = uv[tri[0]], &b = uv[tri[1]], &c = uv[tri[2]];
    if (l0 == l1 && l1 == l2 && l0 != 2) {
      const double area = 0.5 * cross2(b - a, c - a);
      (l0 ? top_area : bottom_area) += area;
      if (l0) top_faces.push_back(t);
      continue;
    }
    if (l0 == 2 || l1 == 2 || l2 == 2)
      curved_wall_faces.push_back(t);
    else if (const Check perpendicular = off_wall_line(t); !perpendicular)
      return perpendicular;
  }
  // Weld top-cap corners closer than tol, then keep the directed edges without a reverse twin.
  std::unordered_map<std::uint64_t, std::vector<int>> cells;
  std::vector<int> weld(nv, -1);
  std::vector<Vec2> welded;
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
  auto edge_key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
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
      return Refusal{"the top cap boundary branches at (" + fmt(welded[a].x()) + ", " + fmt(welded[a].y()) + ") m"};
    out[a] = b;
  }
  std::vector<std::vector<Vec2>> loops;
  std::vector<char> seen(welded.size(), 0);
  for (std::size_t s = 0; s < welded.size(); ++s) {
    if (out[s] < 0 || seen[s]) continue;
    std::vector<Vec2> loop;
    for (int v = int(s); !seen[v]; v = out[v]) {
      if (out[v] < 0) return Refusal{"the top cap boundary is open at (" + fmt(welded[v].x()) + ", " + fmt(welded[v].y()) + ") m"};
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
    for (std::size_t i = 0; i < p.points.size(); ++i) perimeter += (p.points[(i + 1) % p.points.size()] - p.points[i]).norm();
    if (signed_area(p) > 0)
      ++outers, prism.outline.outer = std::move(p);
    else
      prism.outline.holes.push_back(std::move(p));
  }
  if (outers != 1) return Refusal{"the top cap has " + std::to_string(outers) + " outer loops; exactly one is supported"};
  if (std::abs(top_area + bottom_area) > tol * perimeter)
    return Refusal{"the caps differ: top area " + fmt(top_area) + " m^2, bottom area " + fmt(-bottom_area) + " m^2"};
  if (const Check c = check_outline(prism.outline); !c) return Refusal{"the recovered outline is invalid: " + c.reason()};
  if (const Check c =
          wall_vertices_on_outline(prism.outline, uv, w, wall_vertices, tol, w_lo, w_hi, allowance, curvature, prism.wall_deviation_m);
      !c)
    return c;
  for (std::size_t t : curved_wall_faces)
    if (const Check c = off_wall_line(t); !c) return c;
  prism.frame = f;
  prism.height_m = top - bottom;
  return {};
}

}  // namespace

Result<Prism> recover_prism(const TriMesh& mesh, double tol_m) {
  if (!(tol_m > 0) || !std::isfinite(tol_m)) throw InputError("prism tolerance " + fmt(tol_m) + " m: need > 0");
  if (mesh.triangles.empty()) throw InputError("prism recovery: the mesh has no triangles");
  std::vector<Vec3> face_n;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw InputError("prism recovery: triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) + " of " +
                         std::to_string(mesh.vertices.size()));
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    face_n.push_back((b - a).cross(c - a));
  }
  std::string reason;  // along the first candidate axis: the largest face cluster's normal
  for (const Vec3& candidate : candidate_axes(face_n)) {
    const Vec3 axis = refined_axis(mesh, face_n, candidate, tol_m);
    Prism prism;
    const Check why = try_axis(mesh, axis, tol_m, prism);
    if (why) return prism;
    if (reason.empty()) {
      const Vec3 shown = frame_for(axis).z;
      reason = "not a prism along its largest face cluster's normal (" + fmt(shown.x() + 0.0) + ", " + fmt(shown.y() + 0.0) + ", " +
               fmt(shown.z() + 0.0) + "): " + why.reason();
    }
  }
  return Refusal{reason.empty() ? "every face is degenerate" : reason};
}

}  // namespace gearsim
