#include "geometry/approx_decomposition.hpp"

#include <HACD/hacdHACD.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "geometry/approx_decomposition_detail.hpp"
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

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string three_digits(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// The mesh and the options, refused (naming the value) when they cannot be decomposed.
void check_approx_input(const TriMesh& mesh, const ApproxDecompositionOptions& options, const std::string& who) {
  if (mesh.triangles.empty()) throw InputError(who + "mesh has no triangles");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t])
      if (v >= mesh.vertices.size())
        throw InputError(who + "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) + " of " +
                         std::to_string(mesh.vertices.size()));
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
}

// HACD on its own copies of the points and triangles (it normalises the points in place; they
// outlive hacd), concavity in its units: hacd_per_m of them per metre.
void run_hacd(HACD::HACD& hacd, std::vector<HACD::Vec3<HACD::Real>>& points, std::vector<HACD::Vec3<long>>& triangles, double hacd_per_m,
              const ApproxDecompositionOptions& options) {
  hacd.SetPoints(points.data());
  hacd.SetNPoints(points.size());
  hacd.SetTriangles(triangles.data());
  hacd.SetNTriangles(triangles.size());
  hacd.SetScaleFactor(kHacdScale);
  hacd.SetNClusters(std::size_t(options.min_clusters));
  hacd.SetConcavity(options.max_concavity_m * hacd_per_m);
  hacd.SetNVerticesPerCH(std::size_t(options.max_vertices_per_hull));
  hacd.SetCompacityWeight(options.compactness_weight);
  hacd.SetVolumeWeight(0.0);  // HACD's cost multiplies it by a local never set (0): only slows
  hacd.SetConnectDist(-1.0);  // never bridge separate shells
  hacd.SetAddFacesPoints(true);  // left uninitialised by HACD's constructor
  hacd.SetAddNeighboursDistPoints(options.add_neighbour_points);
  hacd.SetAddExtraDistPoints(options.add_opposite_points);
  GEARSIM_CHECK(hacd.Compute(/*fullCH=*/false, /*exportDistPoints=*/false), "HACD::Compute failed");
}

// Our own hull of each HACD cluster's hull points, each also a piece of `out` (its tooth from
// options.tooth_layout). Flat clusters are dropped with a warning; all of them flat is refused.
std::vector<approx_detail::Hull> cluster_hulls(HACD::HACD& hacd, double diag_m, const ApproxDecompositionOptions& options,
                                               const std::string& who, ApproxDecomposition& out) {
  std::vector<approx_detail::Hull> hulls;
  std::size_t flat = 0;
  for (std::size_t c = 0; c < hacd.GetNClusters(); ++c) {
    std::vector<HACD::Vec3<HACD::Real>> cp(hacd.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> ct(hacd.GetNTrianglesCH(c));
    hacd.GetCH(c, cp.data(), ct.data());
    std::vector<Vec3> pts;
    for (const auto& q : cp) pts.emplace_back(q.X(), q.Y(), q.Z());
    TriMesh h = approx_detail::hull_or_empty(pts, constants::kHullPlaneRelativeTolerance * diag_m);
    if (h.triangles.empty()) {
      ++flat;
      continue;
    }
    hulls.push_back(approx_detail::make_hull(std::move(h)));
  }
  if (hulls.empty())
    throw InputError(who + "every HACD cluster is flat (no volume) at max_concavity_m = " + std::to_string(options.max_concavity_m) +
                     " m; try a larger one");
  if (flat > 0) out.warnings.push_back("approximate decomposition: " + std::to_string(flat) + " flat HACD cluster(s) dropped (no volume)");
  const double pitch_rad = options.tooth_layout ? 2.0 * std::numbers::pi / options.tooth_layout->teeth : 0.0;
  for (const approx_detail::Hull& h : hulls) {
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
  return hulls;
}

}  // namespace

ApproxDecomposition approximate_decomposition(const TriMesh& mesh, const ApproxDecompositionOptions& options) {
  const std::string who = "approximate_decomposition: ";
  check_approx_input(mesh, options, who);
  const double diag_m = approx_detail::diagonal(mesh.vertices);
  const double spacing_m = options.sample_spacing_m.value_or(diag_m / constants::kDefaultDeviationSamplesPerDiagonal);
  if (!(spacing_m > 0) || !std::isfinite(spacing_m))
    throw InputError(who + "sample_spacing_m = " + std::to_string(spacing_m) + ": need > 0");

  ApproxDecomposition out;
  out.sample_spacing_m = spacing_m;
  // Decimate a large mesh first: HACD's run time is superlinear (see max_hacd_triangles).
  TriMesh work = mesh.triangles.size() > options.max_hacd_triangles ? approx_detail::decimate(mesh, options.max_hacd_triangles) : mesh;
  if (work.triangles.size() != mesh.triangles.size())
    out.warnings.push_back("approximate decomposition: " + std::to_string(mesh.triangles.size()) + " triangles decimated to " +
                           std::to_string(work.triangles.size()) + " for HACD (quadric-error edge collapses)");
  out.hacd_triangles = work.triangles.size();

  // HACD: its own copies (it normalises the points in place), concavity in its units.
  const auto t0 = Clock::now();
  std::vector<HACD::Vec3<HACD::Real>> points;
  for (const Vec3& v : work.vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<HACD::Vec3<long>> triangles;
  for (const auto& t : work.triangles) triangles.emplace_back(long(t[0]), long(t[1]), long(t[2]));
  const double hacd_per_m = 2.0 * kHacdScale / approx_detail::diagonal(work.vertices);
  HACD::HACD hacd;
  run_hacd(hacd, points, triangles, hacd_per_m, options);
  out.hacd_seconds = seconds_since(t0);

  // Our own hull of each cluster's hull points (input vertices, to HACD's normalisation round
  // trip of ~1e-16 of the size): no interior points, outward faces we can clip with.
  const auto t1 = Clock::now();
  const std::vector<approx_detail::Hull> hulls = cluster_hulls(hacd, diag_m, options, who, out);

  // Measure: the input surface against the union's boundary.
  const TriMesh boundary =
      approx_detail::union_surface(hulls, kUnionProbeRelative * diag_m, constants::kHullPlaneRelativeTolerance * diag_m);
  out.deviation_m = hausdorff_distance(mesh, boundary, spacing_m);
  out.input_volume_m3 = signed_volume_m3(mesh);
  out.union_volume_m3 = signed_volume_m3(boundary);
  out.measure_seconds = seconds_since(t1);
  const double volume_error = out.union_volume_m3 / out.input_volume_m3 - 1.0;
  if (std::abs(volume_error) > kUnionVolumeWarning)
    out.warnings.push_back("approximate decomposition: the union of the hulls is " + three_digits(100.0 * volume_error) +
                           " % off the input's volume (> 0: " + "hulls bridge concavities; < 0: voids between hulls inside the solid)");

  std::ostringstream method;
  method << "HACD (Bullet Extras libHACD): max concavity " << options.max_concavity_m * 1e3 << " mm, <= " << options.max_vertices_per_hull
         << " vertices per hull, neighbour points " << (options.add_neighbour_points ? "on" : "off") << ", " << out.hacd_triangles
         << " triangles in, " << out.pieces.pieces.size() << " hulls out";
  out.method = method.str();
  out.warnings.insert(out.warnings.begin(),
                      "approximate decomposition: µm-scale flank errors are not preserved "
                      "(measured deviation " +
                          three_digits(out.deviation_m * 1e6) + " µm)");
  return out;
}

}  // namespace gearsim
