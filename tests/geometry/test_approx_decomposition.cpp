// Approximate (HACD) convex decomposition of non-prismatic solids: solids of revolution meshed
// here (a stepped shaft, an hourglass), a box, and bad input.
#include "geometry/approx_decomposition.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/errors.hpp"
#include "geometry/mass_properties.hpp"

namespace gearsim {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

// A closed solid of revolution about z: the profile (radius, z) from the bottom cap to the top
// cap, each ring a regular `segments`-gon (counter-clockwise from +z), both caps fanned.
TriMesh revolve(const std::vector<Eigen::Vector2d>& profile_m, int segments) {
  TriMesh m;
  const auto n = static_cast<std::uint32_t>(segments);
  for (const auto& rz : profile_m)
    for (std::uint32_t j = 0; j < n; ++j) {
      const double a = 2.0 * kPi * j / n;
      m.vertices.emplace_back(rz.x() * std::cos(a), rz.x() * std::sin(a), rz.y());
    }
  const auto rings = static_cast<std::uint32_t>(profile_m.size());
  const std::uint32_t bottom = rings * n, top = bottom + 1;
  m.vertices.emplace_back(0.0, 0.0, profile_m.front().y());
  m.vertices.emplace_back(0.0, 0.0, profile_m.back().y());
  for (std::uint32_t j = 0; j < n; ++j) {
    const std::uint32_t k = (j + 1) % n;
    m.triangles.push_back({bottom, k, j});
    m.triangles.push_back({top, (rings - 1) * n + j, (rings - 1) * n + k});
    for (std::uint32_t r = 0; r + 1 < rings; ++r) {
      m.triangles.push_back({r * n + j, r * n + k, (r + 1) * n + k});
      m.triangles.push_back({r * n + j, (r + 1) * n + k, (r + 1) * n + j});
    }
  }
  return m;
}

// Volume of a revolved profile of regular n-gons: frustums of polygons, exact, m^3.
double revolved_volume(const std::vector<Eigen::Vector2d>& p, int n) {
  const double k = 0.5 * n * std::sin(2.0 * kPi / n);  // polygon area / r^2
  double v = 0.0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double r0 = p[i].x(), r1 = p[i + 1].x(), h = p[i + 1].y() - p[i].y();
    v += k * h * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
  }
  return v;
}

// Shaft: Ø20 mm × 20 mm, then Ø10 mm × 20 mm on top; 32-gons.
const std::vector<Eigen::Vector2d> kStepped = {{0.010, 0.0}, {0.010, 0.020}, {0.005, 0.020}, {0.005, 0.040}};

// Hourglass: radius 10 mm at both ends, 6 mm at the waist, over 30 mm; 24-gons, 16 rings.
std::vector<Eigen::Vector2d> hourglass() {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i <= 15; ++i) {
    const double z = 0.030 * i / 15.0;
    p.emplace_back(0.010 - 0.004 * std::sin(kPi * z / 0.030), z);
  }
  return p;
}

// Largest distance of any piece point in front of a face of its own hull, m (0 when convex).
double worst_convexity_violation(const ConvexPiece3& piece) {
  const TriMesh hull = convex_hull(piece.points_m);
  double worst = 0.0;
  for (const auto& t : hull.triangles) {
    const auto& v = hull.vertices;
    const Vec3 n = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
    for (const Vec3& p : piece.points_m) worst = std::max(worst, n.dot(p - v[t[0]]));
  }
  return worst;
}

TEST(ApproxDecomposition, SteppedShaftGivesSeveralConvexPieces) {
  const ApproxDecomposition d = approximate_decomposition(revolve(kStepped, 32));
  EXPECT_GE(d.pieces.pieces.size(), 2u) << d.method;
  for (const auto& piece : d.pieces.pieces) {
    // Convex within 1e-9 m (1e-7 of the size), and points_m are exactly the hull's vertices.
    EXPECT_LE(worst_convexity_violation(piece), 1e-9);
    EXPECT_EQ(convex_hull(piece.points_m).vertices.size(), piece.points_m.size());
    EXPECT_EQ(piece.tooth, -1);
  }
}

TEST(ApproxDecomposition, SteppedShaftHullVolumesMatchTheSolid) {
  const ApproxDecomposition d = approximate_decomposition(revolve(kStepped, 32));
  double sum_m3 = 0.0;
  for (const auto& piece : d.pieces.pieces) sum_m3 += signed_volume_m3(convex_hull(piece.points_m));
  const double exact_m3 = revolved_volume(kStepped, 32);
  EXPECT_NEAR(d.input_volume_m3, exact_m3, 1e-12 * exact_m3);
  // Hulls may overlap and bridge the step: within 5 % of the solid.
  EXPECT_NEAR(sum_m3, exact_m3, 0.05 * exact_m3);
  EXPECT_NEAR(d.hull_volume_sum_m3, sum_m3, 1e-9 * exact_m3);
  // The union (sampled boundary, ~0.1 mm spacing) within 5 % too.
  EXPECT_NEAR(d.union_volume_m3, exact_m3, 0.05 * exact_m3);
}

TEST(ApproxDecomposition, SteppedShaftDeviationIsMeasuredAndSmall) {
  const ApproxDecomposition d = approximate_decomposition(revolve(kStepped, 32));
  ASSERT_TRUE(std::isfinite(d.deviation_m));
  // Bounded by the 0.1 mm concavity allowance plus a sample spacing, with a factor 2 of slack
  // for HACD measuring concavity along normals only; the part is 40 mm tall.
  EXPECT_LE(d.deviation_m, 2.0 * (1e-4 + d.sample_spacing_m));
  ASSERT_FALSE(d.warnings.empty());
  EXPECT_NE(d.warnings.front().find("µm-scale flank errors are not preserved"), std::string::npos);
}

TEST(ApproxDecomposition, CurvedConcaveSolidDeviatesByAMeasuredNonZeroAmount) {
  const auto profile = hourglass();
  ApproxDecompositionOptions options;
  options.max_concavity_m = 0.5e-3;
  const ApproxDecomposition d = approximate_decomposition(revolve(profile, 24), options);
  EXPECT_GE(d.pieces.pieces.size(), 2u) << d.method;
  ASSERT_TRUE(std::isfinite(d.deviation_m));
  // Hulls bridge the curved waist: a real, non-zero gap, far above rounding (1 nm)...
  EXPECT_GT(d.deviation_m, 1e-9);
  // ...but within twice the allowed concavity plus a sample spacing (part: 30 mm tall).
  EXPECT_LE(d.deviation_m, 2.0 * (options.max_concavity_m + d.sample_spacing_m));
  for (const auto& piece : d.pieces.pieces) EXPECT_LE(worst_convexity_violation(piece), 1e-9);
}

TEST(ApproxDecomposition, ConvexBoxIsOneExactPiece) {
  // 40 × 20 × 10 mm box; 12 triangles.
  TriMesh box;
  for (int i = 0; i < 8; ++i)
    box.vertices.emplace_back(i & 1 ? 0.040 : 0.0, i & 2 ? 0.020 : 0.0, i & 4 ? 0.010 : 0.0);
  box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const ApproxDecomposition d = approximate_decomposition(box);
  ASSERT_EQ(d.pieces.pieces.size(), 1u) << d.method;
  EXPECT_EQ(d.pieces.pieces[0].points_m.size(), 8u);
  EXPECT_LE(d.deviation_m, 1e-9);  // the hull is the box: only rounding is left
  EXPECT_NEAR(d.union_volume_m3, 8e-6, 1e-12 * 8e-6 + 1e-18);
}

TEST(ApproxDecomposition, ToothLayoutLabelsPiecesBySector) {
  ApproxDecompositionOptions options;
  options.tooth_layout = ToothLayout{4, 0.0};
  const ApproxDecomposition d = approximate_decomposition(revolve(kStepped, 32), options);
  for (const auto& piece : d.pieces.pieces) {
    EXPECT_GE(piece.tooth, 0);
    EXPECT_LT(piece.tooth, 4);
  }
}

TEST(ApproxDecomposition, RejectsEmptyAndNonFiniteMeshes) {
  EXPECT_THROW(approximate_decomposition(TriMesh{}), InputError);
  TriMesh bad = revolve(kStepped, 8);
  bad.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(approximate_decomposition(bad), InputError);
  TriMesh out_of_range = revolve(kStepped, 8);
  out_of_range.triangles[0][1] = 1000;
  EXPECT_THROW(approximate_decomposition(out_of_range), InputError);
  ApproxDecompositionOptions options;
  options.max_concavity_m = -1.0;
  EXPECT_THROW(approximate_decomposition(revolve(kStepped, 8), options), InputError);
  EXPECT_THROW(convex_hull({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3(1, 1, 0)}), InputError);
}

}  // namespace
}  // namespace gearsim
namespace gearsim { TEST(Scratch, Timing) {
  for (int which = 0; which < 2; ++which) {
    ApproxDecompositionOptions o; if (which) o.max_concavity_m = 0.5e-3;
    auto d = approximate_decomposition(which ? revolve(hourglass(), 24) : revolve(kStepped, 32), o);
    std::printf("%s\n hacd %.3f s measure %.3f s dev %.3g um pieces %zu spacing %.3g um vol in %.6g union %.6g sum %.6g\n", d.method.c_str(), d.hacd_seconds, d.measure_seconds, d.deviation_m*1e6, d.pieces.pieces.size(), d.sample_spacing_m*1e6, d.input_volume_m3, d.union_volume_m3, d.hull_volume_sum_m3);
    for (auto& w : d.warnings) std::printf("  %s\n", w.c_str());
  }
}}
#include "geometry/gear_body.hpp"
#include "../support/gear_specs.hpp"
namespace gearsim { TEST(Scratch, Gear) {
  auto spec = test::external_gear(std::getenv("TEETH") ? std::atoi(std::getenv("TEETH")) : 20);
  if (std::getenv("CHORD")) spec.chordal_deviation_m = std::atof(std::getenv("CHORD"));
  auto body = make_gear_body(spec, 7800);
  ApproxDecompositionOptions o;
  if (std::getenv("MAXTRI")) o.max_hacd_triangles = std::size_t(std::atoi(std::getenv("MAXTRI")));
  if (std::getenv("CONC")) o.max_concavity_m = std::atof(std::getenv("CONC"));
  if (std::getenv("VPH")) o.max_vertices_per_hull = std::atoi(std::getenv("VPH"));
  if (std::getenv("SPACING")) o.sample_spacing_m = std::atof(std::getenv("SPACING"));
  o.tooth_layout = tooth_layout(spec);
  std::printf("gear %d teeth: %zu triangles\n", spec.teeth, body.mesh.triangles.size());
  auto d = approximate_decomposition(body.mesh, o);
  std::printf("%s\n hacd %.3f s measure %.3f s dev %.3g um pieces %zu spacing %.3g um vol in %.6g union %.6g sum %.6g\n", d.method.c_str(), d.hacd_seconds, d.measure_seconds, d.deviation_m*1e6, d.pieces.pieces.size(), d.sample_spacing_m*1e6, d.input_volume_m3, d.union_volume_m3, d.hull_volume_sum_m3);
  for (auto& w : d.warnings) std::printf("  %s\n", w.c_str());
}}
