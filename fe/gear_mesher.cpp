#include "fe/gear_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <string>
#include <unordered_map>

#include "core/errors.hpp"
#include "fe/gear_mesher_detail.hpp"
#include "fe/outline_resample.hpp"

namespace gearsim::fe {

using Eigen::Vector2d;

namespace mesher_detail {
namespace {

void require(bool ok, const std::string& field, const std::string& what) {
  if (!ok) throw InputError("mesh sizing: " + field + " " + what);
}

void validate_sizing(const MeshSizingDef& s) {
  require(std::isfinite(s.flank_size_m) && s.flank_size_m > 0, "flank_size_m",
          "must be a positive length in m, got " + std::to_string(s.flank_size_m));
  require(std::isfinite(s.core_size_m) && s.core_size_m >= s.flank_size_m, "core_size_m",
          "must be at least flank_size_m (" + std::to_string(s.flank_size_m) + " m), got " + std::to_string(s.core_size_m));
  require(std::isfinite(s.transition_m) && s.transition_m >= 0, "transition_m",
          "must be a length ≥ 0 in m, got " + std::to_string(s.transition_m));
  require(std::isfinite(s.max_sagitta_m) && s.max_sagitta_m >= 0, "max_sagitta_m",
          "must be a length ≥ 0 in m (0: no limit), got " + std::to_string(s.max_sagitta_m));
}

double mean_radius(const Polygon2& p) {
  double r = 0.0;
  for (const Vector2d& q : p.points) r += q.norm();
  return r / static_cast<double>(p.points.size());
}

// gmsh is one global state: one session at a time, always finalized, never printing.
std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

class GmshSession {
 public:
  GmshSession() : lock_(gmsh_mutex()) {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);  // one thread: reproducible meshes
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::lock_guard<std::mutex> lock_;
};

// Each loop's nodes as gmsh points joined by straight lines of one element each (so gmsh adds no
// boundary node) and the plane surface they bound; point_tags[k] gets loop k's points. Returns
// the surface's tag.
int add_gmsh_geometry(const std::vector<Loop>& loops, std::vector<std::vector<int>>& point_tags) {
  std::vector<int> curve_loops;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& pts = loops[k].nodes.points;
    for (const Vector2d& p : pts) point_tags[k].push_back(gmsh::model::geo::addPoint(p.x(), p.y(), 0.0));
    std::vector<int> lines;
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      const int line = gmsh::model::geo::addLine(point_tags[k][i], point_tags[k][(i + 1) % n]);
      gmsh::model::geo::mesh::setTransfiniteCurve(line, 2);
      lines.push_back(line);
    }
    curve_loops.push_back(gmsh::model::geo::addCurveLoop(lines));
  }
  const int surface = gmsh::model::geo::addPlaneSurface(curve_loops);
  gmsh::model::geo::synchronize();
  return surface;
}

// The generated mesh read back: nodes renumbered from 0 in increasing gmsh tag, the surface's
// elements, and each loop's nodes.
RawMesh read_gmsh_mesh(int surface, const std::vector<std::vector<int>>& point_tags) {
  // Nodes, renumbered from 0 in increasing gmsh tag.
  RawMesh raw;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  std::vector<std::size_t> order(tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  std::unordered_map<std::size_t, int> index;
  for (std::size_t i : order) {
    index[tags[i]] = static_cast<int>(raw.nodes.size());
    raw.nodes.emplace_back(xyz[3 * i], xyz[3 * i + 1]);
  }

  // Elements of the surface: 3 = 4-node quadrangle, 2 = 3-node triangle.
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elem_tags, elem_nodes;
  gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 2, surface);
  for (std::size_t t = 0; t < types.size(); ++t) {
    const auto& en = elem_nodes[t];
    if (types[t] == 3) {
      for (std::size_t e = 0; e + 3 < en.size(); e += 4)
        raw.quads.push_back({index.at(en[e]), index.at(en[e + 1]), index.at(en[e + 2]), index.at(en[e + 3])});
    } else if (types[t] == 2) {
      for (std::size_t e = 0; e + 2 < en.size(); e += 3)
        raw.triangles.push_back({index.at(en[e]), index.at(en[e + 1]), index.at(en[e + 2])});
    } else {
      GEARSIM_CHECK(false, "gmsh returned element type " + std::to_string(types[t]));
    }
  }

  // Each loop's nodes: the mesh node on each geometry point.
  for (const auto& pts : point_tags) {
    std::vector<int> ids;
    for (int pt : pts) {
      std::vector<std::size_t> nt;
      gmsh::model::mesh::getNodes(nt, xyz, param, 0, pt, false, false);
      GEARSIM_CHECK(nt.size() == 1, "gmsh point without exactly one mesh node");
      ids.push_back(index.at(nt[0]));
    }
    raw.loop_nodes.push_back(std::move(ids));
  }
  return raw;
}

// One gmsh run: each loop's nodes joined by straight lines of one element each (so gmsh adds no
// boundary node), a plane surface, triangles of size size_of(x, y) recombined by Blossom.
template <class SizeFn>
RawMesh run_gmsh(const std::vector<Loop>& loops, SizeFn size_of) {
  GmshSession session;
  try {
    gmsh::model::add("gear");
    std::vector<std::vector<int>> point_tags(loops.size());
    const int surface = add_gmsh_geometry(loops, point_tags);

    // Size only from size_of (radial rule and boundary grading); quads by Blossom recombination of Delaunay triangles (kGmshAlgorithm2D).
    gmsh::model::mesh::setSizeCallback([size_of](int, int, double x, double y, double) { return size_of(x, y); });
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.Algorithm", kGmshAlgorithm2D);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", kGmshRecombination);
    gmsh::option::setNumber("Mesh.ElementOrder", 1);
    gmsh::model::mesh::generate(2);

    return read_gmsh_mesh(surface, point_tags);
  } catch (const InternalError&) {
    throw;
  } catch (...) {
    // gmsh throws its message as a string or an exception of its own; its logger keeps it.
    std::string message;
    gmsh::logger::getLastError(message);
    throw InputError("mesh_gear_outline: gmsh failed: " + (message.empty() ? "unknown error" : message));
  }
}

}  // namespace
}  // namespace mesher_detail

double mesh_size_at_radius(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing, double radius_m) {
  // Depth below the root circle, into the body.
  const double depth = kind == GearKind::External ? gear.dims.root_radius_m - radius_m : radius_m - gear.dims.root_radius_m;
  const double f = sizing.transition_m > 0 ? std::clamp(depth / sizing.transition_m, 0.0, 1.0) : (depth > 0 ? 1.0 : 0.0);
  return sizing.flank_size_m + (sizing.core_size_m - sizing.flank_size_m) * f;
}

GearMesh mesh_gear_outline(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing) {
  using namespace mesher_detail;
  validate_sizing(sizing);
  const Outline2& o = gear.outline;
  const bool external = kind == GearKind::External;
  if (external && o.holes.size() > 1)
    throw InputError("mesh_gear_outline: an external gear outline has at most one hole (the bore), got " + std::to_string(o.holes.size()));
  if (!external && o.holes.size() != 1)
    throw InputError("mesh_gear_outline: an internal gear outline has exactly one hole (the toothed loop), got " +
                     std::to_string(o.holes.size()));
  if (o.outer.points.size() < 3 || (!o.holes.empty() && o.holes.front().points.size() < 3))
    throw InputError("mesh_gear_outline: outline loops need at least 3 points");
  const double quads_bound = area(o) / (sizing.flank_size_m * sizing.flank_size_m);
  if (quads_bound > kMaxQuadCount)
    throw InputError("mesh sizing: flank_size_m = " + std::to_string(sizing.flank_size_m) + " m would make up to " +
                     std::to_string(quads_bound) + " quads (limit " + std::to_string(kMaxQuadCount) + ")");

  // The loops in gmsh's order (outer first), each with its role.
  std::vector<Loop> loops;
  loops.push_back({external ? LoopRole::Toothed : LoopRole::Rim, make_arc_polygon(o.outer), {}});
  if (!o.holes.empty()) loops.push_back({external ? LoopRole::Bore : LoopRole::Toothed, make_arc_polygon(o.holes.front()), {}});

  // Mesh, at twice the size and split when asked or when Blossom left triangles.
  auto attempt = [&](bool split) {
    const double scale = split ? 2.0 : 1.0;
    for (Loop& l : loops) {
      const double h =
          l.role == LoopRole::Toothed ? sizing.flank_size_m : mesh_size_at_radius(gear, kind, sizing, mean_radius(Polygon2{l.poly.points}));
      l.nodes = resample_loop(l.poly, scale * h, l.role == LoopRole::Toothed ? scale * scale * sizing.max_sagitta_m : 0.0);
    }
    const BoundaryGrading grading(loops, scale * sizing.flank_size_m);
    RawMesh raw = run_gmsh(loops, [&](double x, double y) {
      const double radial = scale * mesh_size_at_radius(gear, kind, sizing, std::hypot(x, y));
      return grading.size_at(x, y, radial);
    });
    if (split) raw = subdivide(raw, loops);
    return raw;
  };
  GearMesh result;
  result.subdivided = sizing.subdivide;
  RawMesh raw = attempt(sizing.subdivide);
  if (!raw.triangles.empty()) {
    result.subdivided = true;
    raw = attempt(true);
  }
  result.mesh = assemble(std::move(raw), loops);
  result.quality = quad_mesh_quality(result.mesh);
  GEARSIM_CHECK(result.quality.min_scaled_jacobian > 0, "gmsh made an inverted or degenerate quad (min scaled Jacobian " +
                                                            std::to_string(result.quality.min_scaled_jacobian) + ")");
  return result;
}

}  // namespace gearsim::fe
