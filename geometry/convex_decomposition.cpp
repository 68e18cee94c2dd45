#include "geometry/convex_decomposition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

#include "core/errors.hpp"
#include "geometry/triangulate.hpp"

namespace gearsim {
namespace {

using Vec2 = Eigen::Vector2d;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Corner a -> b -> c turns left, or right by at most the convexity tolerance.
bool convex_corner(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e1 = b - a, e2 = c - b;
  return cross2(e1, e2) >= -kConvexSineTolerance * e1.norm() * e2.norm();
}

// Hertel–Mehlhorn: starting from the triangles, removes each diagonal whose two sides merge into
// a convex piece. Diagonals between non-reflex polygon corners (always removable) go first.
std::vector<Polygon2> hertel_mehlhorn(const std::vector<Vec2>& pos, const std::vector<std::array<int, 3>>& tris,
                                      const std::vector<char>& reflex) {
  const int nh = 3 * static_cast<int>(tris.size());
  std::vector<int> from(nh), to(nh), next(nh), prev(nh), twin(nh, -1);
  std::unordered_map<std::uint64_t, int> by_ends;
  auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  for (int h = 0; h < nh; ++h) {
    const int t = h / 3, j = h % 3;
    from[h] = tris[t][j], to[h] = tris[t][(j + 1) % 3];
    next[h] = 3 * t + (j + 1) % 3, prev[h] = 3 * t + (j + 2) % 3;
    const bool fresh = by_ends.emplace(key(from[h], to[h]), h).second;
    GEARSIM_CHECK(fresh, "triangulation repeats a directed edge");
  }
  std::vector<int> diagonals[2];  // [0]: no reflex end point, [1]: the rest
  for (int h = 0; h < nh; ++h) {
    const auto it = by_ends.find(key(to[h], from[h]));
    if (it == by_ends.end()) continue;
    twin[h] = it->second;
    if (h < twin[h]) diagonals[reflex[from[h]] || reflex[to[h]]].push_back(h);
  }
  std::vector<char> removed(nh, 0);
  for (const auto& list : diagonals)
    for (int d : list) {
      const int t = twin[d];
      const int in_u = prev[d], out_u = next[t], in_v = prev[t], out_v = next[d];
      if (!convex_corner(pos[from[in_u]], pos[from[d]], pos[to[out_u]]) || !convex_corner(pos[from[in_v]], pos[to[d]], pos[to[out_v]]))
        continue;
      next[in_u] = out_u, prev[out_u] = in_u, next[in_v] = out_v, prev[out_v] = in_v;
      removed[d] = removed[t] = 1;
    }
  std::vector<Polygon2> pieces;
  std::vector<char> seen(nh, 0);
  for (int h = 0; h < nh; ++h) {
    if (removed[h] || seen[h]) continue;
    Polygon2 piece;
    for (int e = h; !seen[e]; e = next[e]) seen[e] = 1, piece.points.push_back(pos[from[e]]);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// Reflex flags of a loop's corners (interior on the left of the loop's direction).
void mark_reflex(const std::vector<Vec2>& loop, std::vector<char>& reflex) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) reflex.push_back(cross2(loop[i] - loop[(i + n - 1) % n], loop[(i + 1) % n] - loop[i]) <= 0);
}

// A loop, counter-clockwise about the origin, with every gap mid-line crossing inserted.
struct CutLoop {
  std::vector<Vec2> pts;
  std::vector<int> cut;  // cut[k]: index in pts of the crossing with ray k
};

double ray_angle(const ToothLayout& lay, int k) { return lay.tooth0_angle_rad + (k + 0.5) * 2.0 * std::numbers::pi / lay.teeth; }

// Inserts the crossings of every gap mid-line ray into `loop`, or says why a ray does not cross
// it exactly once, counter-clockwise (the loop is then not star-shaped about the gear axis).
Check cut_loop(const std::vector<Vec2>& loop, const ToothLayout& lay, const std::string& name, CutLoop& out) {
  const int z = lay.teeth;
  const double step = 2.0 * std::numbers::pi / z;
  auto wedge = [&](const Vec2& p) {  // sector index: between rays k - 1 and k
    double a = std::atan2(p.y(), p.x()) - (lay.tooth0_angle_rad - 0.5 * step);
    a -= 2.0 * std::numbers::pi * std::floor(a / (2.0 * std::numbers::pi));
    return std::min(static_cast<int>(a / step), z - 1);
  };
  const std::size_t n = loop.size();
  std::vector<int> hits(std::size_t(z), 0), pending;
  out.cut.assign(std::size_t(z), -1);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &p = loop[i], &q = loop[(i + 1) % n];
    out.pts.push_back(p);
    const int ip = static_cast<int>(out.pts.size()) - 1;
    for (int k : pending) out.cut[std::size_t(k)] = ip;
    pending.clear();
    const int wp = wedge(p), wq = wedge(q);
    if (wp == wq) continue;
    if (cross2(p, q) <= 0)
      return Refusal{"the " + name + " is not star-shaped about the gear axis: its edge " + std::to_string(i) +
                     " crosses a gap mid-line clockwise"};
    for (int k = wp; k != wq; k = (k + 1) % z) {
      if (++hits[std::size_t(k)] > 1) return Refusal{"gap mid-line " + std::to_string(k) + " crosses the " + name + " more than once"};
      const Vec2 d(std::cos(ray_angle(lay, k)), std::sin(ray_angle(lay, k)));
      const double sp = cross2(d, p), sq = cross2(d, q), len = (q - p).norm();
      const double t = std::clamp(sp == sq ? 0.5 : sp / (sp - sq), 0.0, 1.0);
      if (t * len <= kCutSnap_m)
        out.cut[std::size_t(k)] = ip;
      else if ((1.0 - t) * len > kCutSnap_m)
        out.pts.push_back(p + t * (q - p)), out.cut[std::size_t(k)] = int(out.pts.size()) - 1;
      else if (i + 1 < n)
        pending.push_back(k);
      else
        out.cut[std::size_t(k)] = 0;
    }
  }
  int descents = 0;
  for (int k = 0; k < z; ++k) {
    if (hits[std::size_t(k)] != 1) return Refusal{"gap mid-line " + std::to_string(k) + " misses the " + name};
    const int a = out.cut[std::size_t(k)], b = out.cut[std::size_t((k + 1) % z)];
    if (a == b) return Refusal{"two gap mid-lines meet the " + name + " at one point"};
    descents += b < a;
  }
  if (descents != 1) return Refusal{"the " + name + " winds around the gear axis more than once"};
  return {};
}

// Points of `c` from cut k0 forward to cut k1, both included.
void append_arc(const CutLoop& c, int k0, int k1, std::vector<Vec2>& out) {
  const int n = static_cast<int>(c.pts.size());
  for (int i = c.cut[std::size_t(k0)];; i = (i + 1) % n) {
    out.push_back(c.pts[std::size_t(i)]);
    if (i == c.cut[std::size_t(k1)]) break;
  }
}

// Cuts the outline into tooth sectors and decomposes each, or refuses saying why not.
Check decompose_sectors(const Outline2& outline, const ToothLayout& lay, std::vector<ConvexPiece2>& pieces) {
  if (outline.holes.size() > 1)
    return Refusal{"the outline has " + std::to_string(outline.holes.size()) + " holes; sector cutting allows at most one"};
  CutLoop outer, inner;
  if (const Check why = cut_loop(outline.outer.points, lay, "outer boundary", outer); !why) return why;
  if (!outline.holes.empty()) {
    std::vector<Vec2> hole(outline.holes[0].points.rbegin(), outline.holes[0].points.rend());
    if (const Check why = cut_loop(hole, lay, "hole", inner); !why) return why;
  }
  for (int k = 0; k < lay.teeth; ++k) {
    const int k0 = (k + lay.teeth - 1) % lay.teeth;
    Polygon2 sector;
    append_arc(outer, k0, k, sector.points);
    if (outline.holes.empty()) {
      sector.points.emplace_back(0.0, 0.0);
    } else {
      std::vector<Vec2> arc;
      append_arc(inner, k0, k, arc);
      sector.points.insert(sector.points.end(), arc.rbegin(), arc.rend());
    }
    if (const Check c = check_polygon(sector, true, "sector " + std::to_string(k)); !c) return c;
    std::vector<char> reflex;
    mark_reflex(sector.points, reflex);
    for (Polygon2& p : hertel_mehlhorn(sector.points, detail::triangulate_unchecked(sector), reflex))
      pieces.push_back({std::move(p), k, 0.0});
  }
  return {};
}

// Decomposes the whole outline; tooth = sector of each piece's centroid (or -1).
void decompose_whole(const Outline2& outline, const std::optional<ToothLayout>& lay, std::vector<ConvexPiece2>& pieces) {
  const OutlineTriangulation t = detail::triangulate_unchecked(outline);
  std::vector<char> reflex;
  mark_reflex(outline.outer.points, reflex);
  for (const Polygon2& h : outline.holes) mark_reflex(h.points, reflex);
  for (Polygon2& p : hertel_mehlhorn(t.vertices, t.triangles, reflex)) {
    int tooth = -1;
    if (lay) {
      Vec2 c = Vec2::Zero();
      for (const Vec2& q : p.points) c += q;
      c /= double(p.points.size());
      const double step = 2.0 * std::numbers::pi / lay->teeth;
      const double a = std::atan2(c.y(), c.x()) - lay->tooth0_angle_rad + 0.5 * step;
      tooth = static_cast<int>(std::floor(a / step)) % lay->teeth;
      tooth = (tooth + lay->teeth) % lay->teeth;
    }
    pieces.push_back({std::move(p), tooth, 0.0});
  }
}

}  // namespace

bool is_convex(const Polygon2& polygon, double sine_tolerance) {
  const std::size_t n = polygon.points.size();
  if (n < 3 || !(signed_area(polygon) > 0)) return false;
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = polygon.points[(i + 1) % n] - polygon.points[i];
    const Vec2 e2 = polygon.points[(i + 2) % n] - polygon.points[(i + 1) % n];
    if (cross2(e1, e2) < -sine_tolerance * e1.norm() * e2.norm()) return false;
    turning += std::atan2(cross2(e1, e2), e1.dot(e2));
  }
  return std::abs(turning - 2.0 * std::numbers::pi) < 1e-6;  // once around, not a pentagram
}

ConvexDecomposition decompose(const Outline2& outline, const DecompositionOptions& options) {
  require_valid(outline);
  const auto& lay = options.tooth_layout;
  if (lay && (lay->teeth < 3 || !std::isfinite(lay->tooth0_angle_rad)))
    throw InputError("tooth layout: " + std::to_string(lay->teeth) + " teeth with tooth-0 angle " + std::to_string(lay->tooth0_angle_rad) +
                     " rad; need at least 3 teeth and a finite angle");
  ConvexDecomposition result;
  if (lay) {
    const Check sectors = decompose_sectors(outline, *lay, result.pieces);
    result.fallback_reason = sectors.reason();
    result.sectors_exact = sectors.ok();
    if (!result.sectors_exact) result.pieces.clear();
  }
  if (!result.sectors_exact) decompose_whole(outline, lay, result.pieces);
  for (ConvexPiece2& p : result.pieces) {
    p.area_m2 = signed_area(p.polygon);
    result.piece_area_sum_m2 += p.area_m2;
  }
  result.outline_area_m2 = area(outline);
  return result;
}

ConvexPieces3 extrude_pieces(const ConvexDecomposition& decomposition, const PrismFrame& frame, double w_min_m, double w_max_m) {
  if (!(w_min_m < w_max_m) || !std::isfinite(w_min_m) || !std::isfinite(w_max_m))
    throw InputError("piece extrusion range [" + std::to_string(w_min_m) + ", " + std::to_string(w_max_m) +
                     "] m: need finite w_min_m < w_max_m");
  ConvexPieces3 out;
  out.pieces.reserve(decomposition.pieces.size());
  for (const ConvexPiece2& p : decomposition.pieces) {
    ConvexPiece3 q{{}, p.tooth};
    q.points_m.reserve(2 * p.polygon.points.size());
    for (double w : {w_min_m, w_max_m})
      for (const Vec2& uv : p.polygon.points) q.points_m.push_back(frame.to_world(uv, w));
    out.pieces.push_back(std::move(q));
  }
  return out;
}

ConvexPieces3 extrude_pieces(const ConvexDecomposition& decomposition, const Prism& prism) {
  return extrude_pieces(decomposition, prism.frame, 0.0, prism.height_m);
}

}  // namespace gearsim
