#include "fe/gear_mesh_regions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace gearsim::fe {

using Eigen::Vector2d;

namespace {

// Radius band of the tip land: both edge ends on the tip circle within this, m. 1 µm: boundary
// nodes lie on the outline within the chordal deviation (0.5 µm by default).
constexpr double kOnCircle_m = 1e-6;

}  // namespace

std::vector<ToothedEdgeTag> tag_toothed_edges(const QuadMesh2& mesh, const GearSpec& spec, const GearDimensions& dims) {
  if (spec.teeth <= 0) throw InputError("tag_toothed_edges: gear '" + spec.name + "' teeth must be positive");
  const double pitch_angle = 2.0 * std::numbers::pi / spec.teeth;
  const double r_lo = std::min(dims.form_radius_m, dims.tip_radius_m);
  const double r_hi = std::max(dims.form_radius_m, dims.tip_radius_m);
  std::vector<ToothedEdgeTag> tags;
  tags.reserve(mesh.toothed_edges.size());
  for (const QuadEdge& e : mesh.toothed_edges) {
    const auto [a, b] = edge_points(mesh, e);
    const Vector2d mid = 0.5 * (a + b);
    // Angle from tooth 0's centre line, then the nearest tooth and the offset from its line.
    const double rel = std::atan2(mid.y(), mid.x()) - spec.tooth0_angle_rad;
    const double k = std::round(rel / pitch_angle);
    const double off = rel - k * pitch_angle;
    ToothedEdgeTag t;
    t.tooth = static_cast<int>(std::lround(k)) % spec.teeth;
    if (t.tooth < 0) t.tooth += spec.teeth;
    t.side = off >= 0 ? Flank::Ccw : Flank::Cw;
    const double r = mid.norm();
    const bool tip_land = std::abs(a.norm() - dims.tip_radius_m) < kOnCircle_m && std::abs(b.norm() - dims.tip_radius_m) < kOnCircle_m;
    t.on_flank = !tip_land && r > r_lo && r < r_hi;
    tags.push_back(t);
  }
  return tags;
}

std::vector<QuadEdge> select_tooth_edges(const QuadMesh2& mesh, const std::vector<ToothedEdgeTag>& tags, const ToothEdgeSelection& which) {
  GEARSIM_CHECK(tags.size() == mesh.toothed_edges.size(), "edge tags not made for this mesh");
  std::vector<QuadEdge> out;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const ToothedEdgeTag& t = tags[i];
    if (std::find(which.teeth.begin(), which.teeth.end(), t.tooth) == which.teeth.end()) continue;
    if (which.flanks_only && !t.on_flank) continue;
    if (which.one_side && t.side != which.side) continue;
    out.push_back(mesh.toothed_edges[i]);
  }
  return out;
}

std::vector<int> root_elements(const QuadMesh2& mesh, const std::vector<ToothedEdgeTag>& tags, const GearDimensions& dims, GearKind kind,
                               int tooth, Flank side) {
  GEARSIM_CHECK(tags.size() == mesh.toothed_edges.size(), "edge tags not made for this mesh");
  std::vector<int> out;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const ToothedEdgeTag& t = tags[i];
    if (t.tooth != tooth || t.side != side || t.on_flank) continue;
    const auto [a, b] = edge_points(mesh, mesh.toothed_edges[i]);
    const double r = (0.5 * (a + b)).norm();
    const bool root_side = kind == GearKind::External ? r < dims.form_radius_m : r > dims.form_radius_m;
    if (root_side) out.push_back(mesh.toothed_edges[i].first);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace gearsim::fe
