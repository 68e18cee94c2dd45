#include "render/tooth_highlight.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/triangulate.hpp"
#include "geometry/constants.hpp"

namespace gearsim::render {
namespace {

using gearsim::constants::kPi;

// Angle difference wrapped to (−π, π].
double wrap(double a) { return a - 2 * kPi * std::floor((a + kPi) / (2 * kPi)); }

// Index of the loop point whose polar angle is closest to `angle` (the loop is star-shaped about
// the axis, so that is where the ray at `angle` crosses it).
int nearest_in_angle(const Polygon2& loop, double angle) {
  int best = 0;
  double best_d = 1e9;
  for (int i = 0; i < static_cast<int>(loop.points.size()); ++i) {
    const double d = std::abs(wrap(std::atan2(loop.points[i].y(), loop.points[i].x()) - angle));
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

}  // namespace

HighlightedGearMesh gear_mesh_with_highlighted_teeth(const GearSpec& spec, const std::vector<int>& teeth) {
  for (int t : teeth)
    if (t < 0 || t >= spec.teeth)
      throw InputError("highlighted tooth: gear '" + spec.name + "': tooth " + std::to_string(t) + " out of range [0, " +
                       std::to_string(spec.teeth) + ")");
  const GearOutline go = make_gear_outline(spec);
  const double half = 0.5 * spec.face_width_m;
  HighlightedGearMesh out;
  TriMesh base = extrude(go.outline, -half, half);
  if (teeth.empty()) {
    out.highlight.assign(base.triangles.size(), 0);
    out.mesh = std::move(base);
    return out;
  }
  // The toothed loop: counter-clockwise outer loop (external) or clockwise hole (internal).
  const bool internal = spec.kind == GearKind::Internal;
  const Polygon2& loop = internal ? go.outline.holes.front() : go.outline.outer;
  const int offset = internal ? static_cast<int>(go.outline.outer.points.size()) : 0;
  const int n = static_cast<int>(loop.points.size());
  const auto total = static_cast<std::uint32_t>(base.vertices.size() / 2);

  // Walk each tooth along the loop from one gap mid-line to the other. External teeth close with
  // the chord between the walk's ends (inside the root circle, away from the tooth); internal
  // teeth point inward, across that chord, so they close outside the root circle through the
  // corner Q where the root circle's tangents at both ends meet.
  std::vector<std::vector<int>> walks;  // loop indices
  std::vector<char> removed(n, 0), tooth_edge(n, 0);
  std::vector<int> corner_after(n, -1);  // internal: extra point index following loop index a
  std::vector<Eigen::Vector2d> extra;  // the corners Q
  // Gap g lies between teeth g − 1 and g. By symmetry its mid-line often falls exactly between
  // two outline points: the same gap must give the same point for both of its teeth.
  const auto gap_point = [&](int g) {
    g = (g % spec.teeth + spec.teeth) % spec.teeth;
    return nearest_in_angle(loop, spec.tooth0_angle_rad + (g - 0.5) * 2 * kPi / spec.teeth);
  };
  for (int t : teeth) {
    int a = gap_point(t), b = gap_point(t + 1);
    if (internal) std::swap(a, b);
    std::vector<int> walk{a};
    for (int i = a; i != b; i = (i + 1) % n) {
      tooth_edge[i] = 1;
      walk.push_back((i + 1) % n);
    }
    for (std::size_t m = 1; m + 1 < walk.size(); ++m) removed[walk[m]] = 1;
    if (internal) {
      const Eigen::Vector2d pa = loop.points[a], pb = loop.points[b];
      const double half_span = 0.5 * std::abs(wrap(std::atan2(pa.y(), pa.x()) - std::atan2(pb.y(), pb.x())));
      corner_after[a] = static_cast<int>(extra.size());
      extra.push_back((pa + pb).normalized() * (0.5 * (pa.norm() + pb.norm()) / std::cos(half_span)));
    }
    walks.push_back(std::move(walk));
  }
  // Cap points: the outline's (mesh vertices 0..total−1 at the bottom, +total at the top), then
  // the corners (appended to the mesh, bottom and top).
  out.mesh.vertices = base.vertices;
  for (const Eigen::Vector2d& q : extra) out.mesh.vertices.emplace_back(q.x(), q.y(), -half);
  for (const Eigen::Vector2d& q : extra) out.mesh.vertices.emplace_back(q.x(), q.y(), half);
  const auto e = static_cast<std::uint32_t>(extra.size());
  const auto bottom = [&](std::uint32_t id) { return id < total ? id : 2 * total + (id - total); };
  const auto top = [&](std::uint32_t id) { return id < total ? id + total : 2 * total + e + (id - total); };
  const auto add_cap = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint8_t h) {
    out.mesh.triangles.push_back({bottom(a), bottom(c), bottom(b)});  // bottom faces −z
    out.mesh.triangles.push_back({top(a), top(b), top(c)});
    out.highlight.push_back(h);
    out.highlight.push_back(h);
  };

  // The cap without the teeth: the toothed loop short-cut by the chords (through the corners).
  Outline2 rest = go.outline;
  Polygon2& rest_loop = internal ? rest.holes.front() : rest.outer;
  std::vector<std::uint32_t> loop_ids;
  rest_loop.points.clear();
  for (int i = 0; i < n; ++i) {
    if (removed[i]) continue;
    rest_loop.points.push_back(loop.points[i]);
    loop_ids.push_back(static_cast<std::uint32_t>(offset + i));
    if (corner_after[i] >= 0) {
      rest_loop.points.push_back(extra[corner_after[i]]);
      loop_ids.push_back(total + static_cast<std::uint32_t>(corner_after[i]));
    }
  }
  std::vector<std::uint32_t> rest_ids;  // triangulation vertex (outer, then holes) → cap point
  const auto append_loop = [&](const Polygon2& p, int first, bool toothed) {
    if (toothed) {
      rest_ids.insert(rest_ids.end(), loop_ids.begin(), loop_ids.end());
      return;
    }
    for (int i = 0; i < static_cast<int>(p.points.size()); ++i) rest_ids.push_back(static_cast<std::uint32_t>(first + i));
  };
  append_loop(go.outline.outer, 0, !internal);
  int first = static_cast<int>(go.outline.outer.points.size());
  for (std::size_t h = 0; h < go.outline.holes.size(); ++h) {
    append_loop(go.outline.holes[h], first, internal && h == 0);
    first += static_cast<int>(go.outline.holes[h].points.size());
  }
  for (const auto& t : triangulate(rest).triangles) add_cap(rest_ids[t[0]], rest_ids[t[1]], rest_ids[t[2]], 0);

  // Each tooth polygon (walk, then back through its corner) is counter-clockwise: along the outer
  // loop counter-clockwise then back inside, or along the ring's clockwise hole then back outside.
  for (std::size_t w = 0; w < walks.size(); ++w) {
    Polygon2 tooth;
    std::vector<std::uint32_t> ids;
    for (int i : walks[w]) {
      tooth.points.push_back(loop.points[i]);
      ids.push_back(static_cast<std::uint32_t>(offset + i));
    }
    if (internal) {
      tooth.points.push_back(extra[corner_after[walks[w].front()]]);
      ids.push_back(total + static_cast<std::uint32_t>(corner_after[walks[w].front()]));
    }
    for (const auto& t : triangulate(tooth)) add_cap(ids[t[0]], ids[t[1]], ids[t[2]], 1);
  }
  // Side walls as extruded: triangles spanning both layers, first vertex = the edge's start.
  for (const auto& t : base.triangles) {
    const bool spans_bottom = t[0] < total || t[1] < total || t[2] < total;
    const bool spans_top = t[0] >= total || t[1] >= total || t[2] >= total;
    if (!(spans_bottom && spans_top)) continue;
    const int i = static_cast<int>(t[0] % total) - offset;
    out.mesh.triangles.push_back(t);
    out.highlight.push_back(i >= 0 && i < n && tooth_edge[i] ? 1 : 0);
  }
  return out;
}

}  // namespace gearsim::render
