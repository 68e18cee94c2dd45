#include "geometry/triangulate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>
#include <tuple>

#include "core/errors.hpp"

namespace gearsim {
namespace {

using Vec2 = Eigen::Vector2d;

// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise. Evaluated
// from the lexicographically smallest corner, so every rotation of (a, b, c) rounds to the same
// value and every reflection to its negation: decisions about one triangle never disagree.
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  auto less = [](const Vec2* p, const Vec2* q) { return p->x() < q->x() || (p->x() == q->x() && p->y() < q->y()); };
  const Vec2 *p = &a, *q = &b, *r = &c;
  bool flip = false;
  if (less(q, p)) std::swap(p, q), flip = !flip;
  if (less(r, q)) std::swap(q, r), flip = !flip;
  if (less(q, p)) std::swap(p, q), flip = !flip;
  const double d = (q->x() - p->x()) * (r->y() - p->y()) - (q->y() - p->y()) * (r->x() - p->x());
  return flip ? -d : d;
}

std::string at(const Vec2& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x() << ", " << p.y() << ") m";
  return s.str();
}

// Closed segments ab and cd share at least one point.
bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto within = [](const Vec2& s, const Vec2& e, const Vec2& p) {
    return std::min(s.x(), e.x()) <= p.x() && p.x() <= std::max(s.x(), e.x()) && std::min(s.y(), e.y()) <= p.y() &&
           p.y() <= std::max(s.y(), e.y());
  };
  return (d1 == 0 && within(c, d, a)) || (d2 == 0 && within(c, d, b)) || (d3 == 0 && within(a, b, c)) || (d4 == 0 && within(a, b, d));
}

// Per-loop checks that need no other loop: size, finite points, no repeated point, orientation.
std::optional<std::string> basic_defect(const Polygon2& p, bool ccw, const std::string& name) {
  const std::size_t n = p.points.size();
  if (n < 3) return name + " has " + std::to_string(n) + " points; a polygon needs at least 3";
  for (std::size_t i = 0; i < n; ++i) {
    if (!p.points[i].allFinite()) return name + " point " + std::to_string(i) + " is not finite";
    if (p.points[i] == p.points[(i + 1) % n])
      return name + " points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " coincide at " + at(p.points[i]);
  }
  const double a = signed_area(p);
  if (a == 0.0) return name + " has zero area";
  if ((a > 0) != ccw)
    return name + " is " + (a > 0 ? "counter-clockwise" : "clockwise") + "; expected " + (ccw ? "counter-clockwise" : "clockwise");
  return std::nullopt;
}

// First pair of touching edges among the loops (sweep over x), as a message.
std::optional<std::string> find_crossing(const std::vector<const Polygon2*>& loops, const std::vector<std::string>& names) {
  struct Edge {
    Vec2 a, b;
    int loop, index, n;
  };
  std::vector<Edge> edges;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& pts = loops[l]->points;
    const int n = static_cast<int>(pts.size());
    for (int i = 0; i < n; ++i) edges.push_back({pts[i], pts[(i + 1) % n], int(l), i, n});
  }
  auto min_x = [](const Edge& e) { return std::min(e.a.x(), e.b.x()); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& e, const Edge& f) { return min_x(e) < min_x(f); });
  std::vector<const Edge*> active;
  for (const Edge& e : edges) {
    std::size_t kept = 0;
    for (const Edge* f : active) {
      if (std::max(f->a.x(), f->b.x()) < min_x(e)) continue;  // f ends left of e: retire it
      active[kept++] = f;
      if (std::max(e.a.y(), e.b.y()) < std::min(f->a.y(), f->b.y()) || std::max(f->a.y(), f->b.y()) < std::min(e.a.y(), e.b.y())) continue;
      bool bad;
      if (e.loop == f->loop && (e.index == (f->index + 1) % e.n || f->index == (e.index + 1) % e.n)) {
        // Neighbours share a vertex: they only fail when the second folds back over the first.
        const Edge& s = (e.index == (f->index + 1) % e.n) ? *f : e;
        const Edge& t = (&s == &e) ? *f : e;
        bad = orient(s.a, s.b, t.b) == 0 && (s.b - s.a).dot(t.b - t.a) < 0;
      } else {
        bad = segments_touch(e.a, e.b, f->a, f->b);
      }
      if (bad)
        return names[f->loop] + " edge " + std::to_string(f->index) + " and " + names[e.loop] + " edge " + std::to_string(e.index) +
               " intersect near " + at(e.a);
    }
    active.resize(kept);
    active.push_back(&e);
  }
  return std::nullopt;
}

// Strict point-in-polygon by crossing number (valid when p is not on the boundary).
bool inside(const Polygon2& poly, const Vec2& p) {
  bool in = false;
  const std::size_t n = poly.points.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly.points[i];
    const Vec2& b = poly.points[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) in = !in;
  }
  return in;
}

// A ring of nodes (a doubly linked list); bridged holes make two nodes share one vertex id.
struct Ring {
  std::vector<Vec2> pos;
  std::vector<int> id, prev, next;
  int add(const Vec2& p, int vid) {
    pos.push_back(p), id.push_back(vid), prev.push_back(-1), next.push_back(-1);
    return static_cast<int>(pos.size()) - 1;
  }
  void link(int a, int b) { next[a] = b, prev[b] = a; }
  double turn(int v) const { return orient(pos[prev[v]], pos[v], pos[next[v]]); }
  int loop(const std::vector<Vec2>& pts, int first_id) {
    const int first = static_cast<int>(pos.size());
    for (std::size_t i = 0; i < pts.size(); ++i) add(pts[i], first_id + static_cast<int>(i));
    for (int i = first; i < static_cast<int>(pos.size()); ++i) link(i, i + 1 < static_cast<int>(pos.size()) ? i + 1 : first);
    return first;
  }
  // Direction a -> b points into the interior wedge at node a (interior on the left).
  bool locally_inside(int a, const Vec2& b) const {
    const Vec2 &P = pos[prev[a]], &A = pos[a], &N = pos[next[a]];
    if (orient(P, A, N) > 0) return orient(A, N, b) >= 0 && orient(A, b, P) >= 0;
    return orient(A, P, b) <= 0 || orient(A, b, N) <= 0;
  }
};

// Links the hole whose rightmost node is h into the ring through start (Eberly's bridge): cast
// a ray to +x, take the nearest upward edge, then the visible node of least angle to the ray.
void bridge_hole(Ring& r, int start, int h) {
  const Vec2 H = r.pos[h];
  double hit_x = std::numeric_limits<double>::infinity();
  int m = -1;
  int p = start;
  do {
    const Vec2 &P = r.pos[p], &Q = r.pos[r.next[p]];
    if (P.y() <= H.y() && H.y() <= Q.y() && P.y() < Q.y()) {
      const double x = H.y() == P.y() ? P.x() : H.y() == Q.y() ? Q.x() : P.x() + (H.y() - P.y()) * (Q.x() - P.x()) / (Q.y() - P.y());
      if (x >= H.x() && x < hit_x) {
        hit_x = x;
        m = H.y() == P.y() ? p : H.y() == Q.y() ? r.next[p] : (P.x() > Q.x() ? p : r.next[p]);
      }
    }
    p = r.next[p];
  } while (p != start);
  GEARSIM_CHECK(m >= 0, "no outer edge right of hole vertex " + at(H));
  const Vec2 I(hit_x, H.y()), M = r.pos[m];
  const double s = orient(H, I, M);
  int best = -1;
  double best_tan = std::numeric_limits<double>::infinity();
  p = start;
  do {
    const Vec2& P = r.pos[p];
    const bool in_triangle = s == 0 ? P == M : orient(H, I, P) * s >= 0 && orient(I, M, P) * s >= 0 && orient(M, H, P) * s >= 0;
    if (in_triangle && P.x() > H.x() && r.locally_inside(p, H)) {
      const double tan = std::abs(P.y() - H.y()) / (P.x() - H.x());
      if (best < 0 || tan < best_tan || (tan == best_tan && P.x() < r.pos[best].x())) best = p, best_tan = tan;
    }
    p = r.next[p];
  } while (p != start);
  GEARSIM_CHECK(best >= 0, "no visible bridge vertex for hole vertex " + at(H));
  const int h2 = r.add(H, r.id[h]), m2 = r.add(r.pos[best], r.id[best]);
  const int after = r.next[best], before = r.prev[h];
  r.link(best, h), r.link(before, h2), r.link(h2, m2), r.link(m2, after);
}

// Ear clipping, smallest diagonal first. Only reflex or collinear nodes can block an ear, so
// only those are binned in a uniform grid for the emptiness test.
std::vector<std::array<int, 3>> clip_ears(Ring& r, int start) {
  std::vector<int> nodes;
  for (int p = start; nodes.empty() || p != start; p = r.next[p]) nodes.push_back(p);
  GEARSIM_CHECK(nodes.size() >= 3, "ring has fewer than 3 nodes");
  Vec2 lo = r.pos[start], hi = lo;
  std::vector<int> blockers;
  for (int v : nodes) {
    lo = lo.cwiseMin(r.pos[v]), hi = hi.cwiseMax(r.pos[v]);
    if (r.turn(v) <= 0) blockers.push_back(v);
  }
  const Vec2 ext = (hi - lo).cwiseMax(1e-300);
  const double cell = std::sqrt(ext.x() * ext.y() / double(std::max<std::size_t>(blockers.size(), 1)));
  const int nx = std::clamp(int(ext.x() / cell) + 1, 1, 1024), ny = std::clamp(int(ext.y() / cell) + 1, 1, 1024);
  auto cx = [&](double x) { return std::clamp(int((x - lo.x()) / ext.x() * nx), 0, nx - 1); };
  auto cy = [&](double y) { return std::clamp(int((y - lo.y()) / ext.y() * ny), 0, ny - 1); };
  std::vector<int> cell_start(std::size_t(nx * ny + 1), 0), items(blockers.size());
  for (int v : blockers) ++cell_start[std::size_t(cy(r.pos[v].y()) * nx + cx(r.pos[v].x()) + 1)];
  for (std::size_t i = 1; i < cell_start.size(); ++i) cell_start[i] += cell_start[i - 1];
  std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
  for (int v : blockers) items[std::size_t(fill[std::size_t(cy(r.pos[v].y()) * nx + cx(r.pos[v].x()))]++)] = v;

  std::vector<char> alive(r.pos.size(), 0);
  for (int v : nodes) alive[std::size_t(v)] = 1;
  // No live reflex or collinear node (other than a copy of a corner) in the closed triangle.
  auto is_ear = [&](int a, int v, int c, bool strict) {
    const Vec2 &A = r.pos[a], &B = r.pos[v], &C = r.pos[c];
    const Vec2 tlo = A.cwiseMin(B).cwiseMin(C), thi = A.cwiseMax(B).cwiseMax(C);
    for (int y = cy(tlo.y()); y <= cy(thi.y()); ++y)
      for (int x = cx(tlo.x()); x <= cx(thi.x()); ++x)
        for (int k = cell_start[std::size_t(y * nx + x)]; k < cell_start[std::size_t(y * nx + x + 1)]; ++k) {
          const int p = items[std::size_t(k)];
          const Vec2& P = r.pos[p];
          if (!alive[std::size_t(p)] || p == a || p == v || p == c || P == A || P == B || P == C) continue;
          const double o1 = orient(A, B, P), o2 = orient(B, C, P), o3 = orient(C, A, P);
          const bool in = strict ? (o1 > 0 && o2 > 0 && o3 > 0) : (o1 >= 0 && o2 >= 0 && o3 >= 0);
          if (in && r.turn(p) <= 0) return false;
        }
    return true;
  };
  using Entry = std::tuple<double, int, int>;  // squared diagonal length, node, stamp
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  std::vector<int> stamp(r.pos.size(), 0), blocked;
  auto offer = [&](int v) {
    if (r.turn(v) > 0) heap.emplace((r.pos[r.next[v]] - r.pos[r.prev[v]]).squaredNorm(), v, stamp[std::size_t(v)]);
  };
  for (int v : nodes) offer(v);
  std::vector<std::array<int, 3>> tris;
  tris.reserve(nodes.size() - 2);
  auto clip = [&](int v) {
    const int a = r.prev[v], c = r.next[v];
    tris.push_back({r.id[a], r.id[v], r.id[c]});
    alive[std::size_t(v)] = 0;
    r.link(a, c);
    ++stamp[std::size_t(a)], ++stamp[std::size_t(c)];
    offer(a), offer(c);
    start = a;
  };
  std::size_t remaining = nodes.size();
  bool clipped_since_refill = true;
  while (remaining > 3) {
    if (heap.empty()) {
      if (!clipped_since_refill) {  // last resort: ignore blockers on the triangle's boundary
        int v = start;
        while (!(r.turn(v) > 0 && is_ear(r.prev[v], v, r.next[v], true))) {
          v = r.next[v];
          GEARSIM_CHECK(v != start, "ear clipping found no ear; polygon not simple?");
        }
        clip(v), --remaining;
      }
      for (int v : blocked)
        if (alive[std::size_t(v)]) offer(v);
      blocked.clear();
      clipped_since_refill = false;
      continue;
    }
    const auto [key, v, s] = heap.top();
    heap.pop();
    if (!alive[std::size_t(v)] || s != stamp[std::size_t(v)] || r.turn(v) <= 0) continue;
    if (!is_ear(r.prev[v], v, r.next[v], false)) {
      blocked.push_back(v);
      continue;
    }
    clip(v), --remaining, clipped_since_refill = true;
  }
  GEARSIM_CHECK(r.turn(start) > 0, "last triangle is degenerate");
  tris.push_back({r.id[r.prev[start]], r.id[start], r.id[r.next[start]]});
  return tris;
}

}  // namespace

Check check_polygon(const Polygon2& polygon, bool counter_clockwise, const std::string& name) {
  if (auto d = basic_defect(polygon, counter_clockwise, name)) return Refusal{*d};
  if (auto d = find_crossing({&polygon}, {name})) return Refusal{*d};
  return {};
}

// The first defect of the outline's loops, nothing when it is valid.
static std::optional<std::string> outline_defect(const Outline2& outline) {
  std::vector<const Polygon2*> loops{&outline.outer};
  std::vector<std::string> names{"outer boundary"};
  if (auto d = basic_defect(outline.outer, true, names[0])) return d;
  for (std::size_t i = 0; i < outline.holes.size(); ++i) {
    loops.push_back(&outline.holes[i]);
    names.push_back("hole " + std::to_string(i));
    if (auto d = basic_defect(outline.holes[i], false, names.back())) return d;
  }
  if (auto d = find_crossing(loops, names)) return d;
  // No loop touches another, so one point per hole decides the nesting.
  for (std::size_t i = 0; i < outline.holes.size(); ++i) {
    const Vec2& p = outline.holes[i].points[0];
    if (!inside(outline.outer, p)) return names[i + 1] + " lies outside the outer boundary";
    for (std::size_t j = 0; j < outline.holes.size(); ++j)
      if (j != i && inside(outline.holes[j], p)) return names[i + 1] + " lies inside " + names[j + 1];
  }
  return std::nullopt;
}

Check check_outline(const Outline2& outline) {
  if (auto d = outline_defect(outline)) return Refusal{*d};
  return {};
}

void require_valid(const Outline2& outline) {
  if (const Check c = check_outline(outline); !c) throw InputError("invalid outline: " + c.reason());
}

std::vector<std::array<int, 3>> triangulate(const Polygon2& polygon) {
  if (const Check c = check_polygon(polygon, true, "polygon"); !c) throw InputError("cannot triangulate: " + c.reason());
  return detail::triangulate_unchecked(polygon);
}

OutlineTriangulation triangulate(const Outline2& outline) {
  require_valid(outline);
  return detail::triangulate_unchecked(outline);
}

namespace detail {

std::vector<std::array<int, 3>> triangulate_unchecked(const Polygon2& polygon) {
  Ring r;
  const int start = r.loop(polygon.points, 0);
  return clip_ears(r, start);
}

OutlineTriangulation triangulate_unchecked(const Outline2& outline) {
  OutlineTriangulation t;
  Ring r;
  const int start = r.loop(outline.outer.points, 0);
  t.vertices = outline.outer.points;
  std::vector<std::pair<double, int>> order;  // (-max x, rightmost node) per hole
  for (const Polygon2& hole : outline.holes) {
    const int first = r.loop(hole.points, static_cast<int>(t.vertices.size()));
    t.vertices.insert(t.vertices.end(), hole.points.begin(), hole.points.end());
    int right = first;
    for (int v = first; v < first + static_cast<int>(hole.points.size()); ++v)
      if (r.pos[v].x() > r.pos[right].x()) right = v;
    order.emplace_back(-r.pos[right].x(), right);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [neg_x, h] : order) bridge_hole(r, start, h);
  t.triangles = clip_ears(r, start);
  return t;
}

}  // namespace detail
}  // namespace gearsim
