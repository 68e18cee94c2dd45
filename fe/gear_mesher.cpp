#include "fe/gear_mesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <unordered_map>

#include "core/errors.hpp"
#include "fe/outline_resample.hpp"

namespace gearsim::fe {

using Eigen::Vector2d;

namespace {

// Which loop a boundary node list belongs to.
enum class LoopRole { Toothed, Bore, Rim };

struct Loop {
  LoopRole role;
  ArcPolygon poly;
  ResampledLoop nodes;  // the boundary nodes handed to gmsh
};

// What gmsh returns, renumbered from 0: quads and any triangles Blossom left, and each loop's
// nodes as mesh node indices in loop order.
struct RawMesh {
  std::vector<Vector2d> nodes;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::vector<int>> loop_nodes;
};

void require(bool ok, const std::string& field, const std::string& what) {
  if (!ok) throw InputError("mesh sizing: " + field + " " + what);
}

void validate_sizing(const MeshSizingDef& s) {
  require(std::isfinite(s.flank_size_m) && s.flank_size_m > 0, "flank_size_m",
          "must be a positive length in m, got " + std::to_string(s.flank_size_m));
  require(std::isfinite(s.core_size_m) && s.core_size_m >= s.flank_size_m, "core_size_m",
          "must be at least flank_size_m (" + std::to_string(s.flank_size_m) + " m), got " +
              std::to_string(s.core_size_m));
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

// One gmsh run: each loop's nodes joined by straight lines of one element each (so gmsh adds no
// boundary node), a plane surface, triangles of size size_of(x, y) recombined by Blossom.
template <class SizeFn>
RawMesh run_gmsh(const std::vector<Loop>& loops, SizeFn size_of) {
  GmshSession session;
  try {
    gmsh::model::add("gear");
    std::vector<std::vector<int>> point_tags(loops.size());
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

    // Size only from size_of (radial rule and boundary grading); quads by Blossom recombination of Frontal-Delaunay triangles.
    gmsh::model::mesh::setSizeCallback(
        [size_of](int, int, double x, double y, double) { return size_of(x, y); });
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.Algorithm", kGmshAlgorithm2D);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", kGmshRecombination);
    gmsh::option::setNumber("Mesh.ElementOrder", 1);
    gmsh::model::mesh::generate(2);

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
  } catch (const InternalError&) {
    throw;
  } catch (...) {
    // gmsh throws its message as a string or an exception of its own; its logger keeps it.
    std::string message;
    gmsh::logger::getLastError(message);
    throw InputError("mesh_gear_outline: gmsh failed: " + (message.empty() ? "unknown error" : message));
  }
}

// Element size near boundary nodes whose spacing is finer than the radial rule: the size grows
// from a node's spacing by kSpacingGrading per unit distance from it, so refined flanks and
// fillets grade into the interior size instead of meeting it abruptly. A bucket grid finds the
// nodes close enough to matter.
class BoundaryGrading {
 public:
  BoundaryGrading(const std::vector<Loop>& loops, double coarsest_m) : cell_(coarsest_m / kSpacingGrading) {
    for (const Loop& l : loops) {
      const auto& p = l.nodes.points;
      const std::size_t n = p.size();
      for (std::size_t i = 0; i < n; ++i) {
        const double h = 0.5 * ((p[(i + 1) % n] - p[i]).norm() + (p[i] - p[(i + n - 1) % n]).norm());
        if (h >= coarsest_m) continue;
        nodes_.push_back({p[i], h});
        grid_[key(cell_of(p[i].x()), cell_of(p[i].y()))].push_back(nodes_.size() - 1);
      }
    }
  }
  // Smallest graded size at (x, y), or `limit` when no refined node is close enough.
  double size_at(double x, double y, double limit) const {
    if (nodes_.empty()) return limit;
    const long cx = cell_of(x), cy = cell_of(y);
    double h = limit;
    for (long i = cx - 1; i <= cx + 1; ++i)
      for (long j = cy - 1; j <= cy + 1; ++j) {
        const auto it = grid_.find(key(i, j));
        if (it == grid_.end()) continue;
        for (std::size_t k : it->second) {
          const Node& nd = nodes_[k];
          h = std::min(h, nd.h + kSpacingGrading * std::hypot(x - nd.p.x(), y - nd.p.y()));
        }
      }
    return h;
  }

 private:
  struct Node {
    Vector2d p;
    double h;
  };
  long cell_of(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static std::uint64_t key(long i, long j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
  }
  double cell_;
  std::vector<Node> nodes_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
};

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

// Laplacian smoothing of the interior nodes (each moves to the mean of its edge neighbours,
// all at once per sweep), boundary nodes fixed: evens out the quads next to boundary midpoints
// that moved from their chord onto the outline.
void smooth_interior(RawMesh& m) {
  std::vector<char> fixed(m.nodes.size(), 0);
  for (const auto& ids : m.loop_nodes)
    for (int i : ids) fixed[i] = 1;
  std::vector<std::vector<int>> neighbours(m.nodes.size());
  for (const auto& q : m.quads)
    for (int e = 0; e < 4; ++e) {
      neighbours[q[e]].push_back(q[(e + 1) % 4]);
      neighbours[q[(e + 1) % 4]].push_back(q[e]);
    }
  for (int sweep = 0; sweep < kSubdivisionSmoothingSweeps; ++sweep) {
    std::vector<Vector2d> next = m.nodes;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      if (fixed[i] || neighbours[i].empty()) continue;
      Vector2d sum = Vector2d::Zero();
      for (int j : neighbours[i]) sum += m.nodes[j];
      next[i] = sum / static_cast<double>(neighbours[i].size());
    }
    m.nodes = std::move(next);
  }
}

// Splits quads into 4 and triangles into 3 quads. Edge midpoints of boundary edges go onto the
// outline polygon (half way along its arc between the edge's nodes); interior ones are midpoints.
RawMesh subdivide(const RawMesh& in, const std::vector<Loop>& loops) {
  RawMesh out;
  out.nodes = in.nodes;
  std::unordered_map<std::uint64_t, int> midpoint;
  // Boundary midpoints first, loop by loop, refining each loop's node list.
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& ids = in.loop_nodes[k];
    const auto& s = loops[k].nodes.s_m;
    const ArcPolygon& poly = loops[k].poly;
    std::vector<int> refined;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::size_t j = (i + 1) % ids.size();
      double ds = std::fmod(s[j] - s[i], poly.perimeter_m);
      if (ds <= 0) ds += poly.perimeter_m;
      const ArcPoint m = point_at_arc_length(poly, s[i] + 0.5 * ds, kSnapToVertexFraction * 0.5 * ds);
      midpoint[edge_key(ids[i], ids[j])] = static_cast<int>(out.nodes.size());
      refined.push_back(ids[i]);
      refined.push_back(static_cast<int>(out.nodes.size()));
      out.nodes.push_back(m.p);
    }
    out.loop_nodes.push_back(std::move(refined));
  }
  auto mid = [&](int a, int b) {
    const auto [it, added] = midpoint.try_emplace(edge_key(a, b), static_cast<int>(out.nodes.size()));
    if (added) out.nodes.push_back(0.5 * (in.nodes[a] + in.nodes[b]));
    return it->second;
  };
  auto centre = [&](const Vector2d& c) {
    out.nodes.push_back(c);
    return static_cast<int>(out.nodes.size()) - 1;
  };
  for (const auto& q : in.quads) {
    const int m01 = mid(q[0], q[1]), m12 = mid(q[1], q[2]), m23 = mid(q[2], q[3]), m30 = mid(q[3], q[0]);
    const int c = centre(0.25 * (in.nodes[q[0]] + in.nodes[q[1]] + in.nodes[q[2]] + in.nodes[q[3]]));
    out.quads.push_back({q[0], m01, c, m30});
    out.quads.push_back({m01, q[1], m12, c});
    out.quads.push_back({c, m12, q[2], m23});
    out.quads.push_back({m30, c, m23, q[3]});
  }
  for (const auto& t : in.triangles) {
    const int m01 = mid(t[0], t[1]), m12 = mid(t[1], t[2]), m20 = mid(t[2], t[0]);
    const int c = centre((in.nodes[t[0]] + in.nodes[t[1]] + in.nodes[t[2]]) / 3.0);
    out.quads.push_back({t[0], m01, c, m20});
    out.quads.push_back({m01, t[1], m12, c});
    out.quads.push_back({c, m12, t[2], m20});
  }
  smooth_interior(out);
  return out;
}

// The final mesh: quads turned counter-clockwise, boundary edges found per loop, checked closed.
QuadMesh2 assemble(RawMesh raw, const std::vector<Loop>& loops) {
  QuadMesh2 m;
  m.nodes = std::move(raw.nodes);
  m.quads = std::move(raw.quads);
  for (auto& q : m.quads) {
    double a = 0.0;
    for (int e = 0; e < 4; ++e) {
      const Vector2d& p = m.nodes[q[e]];
      const Vector2d& r = m.nodes[q[(e + 1) % 4]];
      a += p.x() * r.y() - p.y() * r.x();
    }
    if (a < 0) std::swap(q[1], q[3]);
  }
  // Edges used by exactly one quad are boundary edges.
  std::map<std::uint64_t, std::pair<QuadEdge, int>> edges;
  for (int qi = 0; qi < static_cast<int>(m.quads.size()); ++qi)
    for (int e = 0; e < 4; ++e) {
      auto& slot = edges[edge_key(m.quads[qi][e], m.quads[qi][(e + 1) % 4])];
      slot.first = {qi, e};
      ++slot.second;
    }
  std::size_t boundary = 0;
  for (const auto& [key, use] : edges) {
    GEARSIM_CHECK(use.second <= 2, "mesh edge shared by more than two quads");
    if (use.second == 1) ++boundary;
  }
  std::size_t on_loops = 0;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& ids = raw.loop_nodes[k];
    std::vector<QuadEdge>& list = loops[k].role == LoopRole::Toothed ? m.toothed_edges
                                  : loops[k].role == LoopRole::Bore  ? m.inner_edges
                                                                     : m.outer_edges;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const auto it = edges.find(edge_key(ids[i], ids[(i + 1) % ids.size()]));
      GEARSIM_CHECK(it != edges.end() && it->second.second == 1,
                    "outline segment is not a boundary edge of the mesh");
      list.push_back(it->second.first);
    }
    on_loops += ids.size();
    if (loops[k].role == LoopRole::Bore) m.bore_nodes = ids;
    if (loops[k].role == LoopRole::Rim) m.rim_nodes = ids;
  }
  GEARSIM_CHECK(boundary == on_loops, "mesh has " + std::to_string(boundary) +
                                          " boundary edges but its outline loops have " +
                                          std::to_string(on_loops));
  return m;
}

}  // namespace

double mesh_size_at_radius(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing,
                           double radius_m) {
  // Depth below the root circle, into the body.
  const double depth = kind == GearKind::External ? gear.dims.root_radius_m - radius_m
                                                  : radius_m - gear.dims.root_radius_m;
  const double f = sizing.transition_m > 0 ? std::clamp(depth / sizing.transition_m, 0.0, 1.0)
                                           : (depth > 0 ? 1.0 : 0.0);
  return sizing.flank_size_m + (sizing.core_size_m - sizing.flank_size_m) * f;
}

GearMesh mesh_gear_outline(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing) {
  validate_sizing(sizing);
  const Outline2& o = gear.outline;
  const bool external = kind == GearKind::External;
  if (external && o.holes.size() > 1)
    throw InputError("mesh_gear_outline: an external gear outline has at most one hole (the bore), got " +
                     std::to_string(o.holes.size()));
  if (!external && o.holes.size() != 1)
    throw InputError("mesh_gear_outline: an internal gear outline has exactly one hole (the toothed loop), got " +
                     std::to_string(o.holes.size()));
  if (o.outer.points.size() < 3 || (!o.holes.empty() && o.holes.front().points.size() < 3))
    throw InputError("mesh_gear_outline: outline loops need at least 3 points");
  const double quads_bound = area(o) / (sizing.flank_size_m * sizing.flank_size_m);
  if (quads_bound > kMaxQuadCount)
    throw InputError("mesh sizing: flank_size_m = " + std::to_string(sizing.flank_size_m) +
                     " m would make up to " + std::to_string(quads_bound) + " quads (limit " +
                     std::to_string(kMaxQuadCount) + ")");

  // The loops in gmsh's order (outer first), each with its role.
  std::vector<Loop> loops;
  loops.push_back({external ? LoopRole::Toothed : LoopRole::Rim, make_arc_polygon(o.outer), {}});
  if (!o.holes.empty())
    loops.push_back({external ? LoopRole::Bore : LoopRole::Toothed, make_arc_polygon(o.holes.front()), {}});

  // Mesh, at twice the size and split when asked or when Blossom left triangles.
  auto attempt = [&](bool split) {
    const double scale = split ? 2.0 : 1.0;
    for (Loop& l : loops) {
      const double h = l.role == LoopRole::Toothed
                           ? sizing.flank_size_m
                           : mesh_size_at_radius(gear, kind, sizing, mean_radius(Polygon2{l.poly.points}));
      l.nodes = resample_loop(l.poly, scale * h,
                              l.role == LoopRole::Toothed ? scale * scale * sizing.max_sagitta_m : 0.0);
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
  GEARSIM_CHECK(result.quality.min_scaled_jacobian > 0,
                "gmsh made an inverted or degenerate quad (min scaled Jacobian " +
                    std::to_string(result.quality.min_scaled_jacobian) + ")");
  return result;
}

}  // namespace gearsim::fe
