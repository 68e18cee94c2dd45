// Approximate (HACD) convex decomposition of non-prismatic solids: solids of revolution meshed
// here (a stepped shaft, an hourglass), a box, a mesh HACD gets decimated, and bad input.
#include "geometry/approx_decomposition.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_approx_decomposition {

using Vec3 = Eigen::Vector3d;
using gearsim::constants::kPi;

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

// The stepped shaft's decomposition with default options, computed once (HACD takes ~1 s).
const ApproxDecomposition& stepped_shaft() {
  static const ApproxDecomposition d = approximate_decomposition(revolve(kStepped, 32));
  return d;
}

// Hourglass: radius 10 mm at both ends, 6 mm at the waist, over 30 mm, with `rings` rings.
std::vector<Eigen::Vector2d> hourglass(int rings = 16) {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < rings; ++i) {
    const double z = 0.030 * i / (rings - 1);
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
  const ApproxDecomposition& d = stepped_shaft();
  EXPECT_GE(d.pieces.pieces.size(), 2u) << d.method;
  for (const auto& piece : d.pieces.pieces) {
    // Convex within 1e-9 m (1e-7 of the size), and points_m are exactly the hull's vertices.
    EXPECT_LE(worst_convexity_violation(piece), 1e-9);
    EXPECT_EQ(convex_hull(piece.points_m).vertices.size(), piece.points_m.size());
    EXPECT_EQ(piece.tooth, -1);
  }
}

TEST(ApproxDecomposition, SteppedShaftHullVolumesMatchTheSolid) {
  const ApproxDecomposition& d = stepped_shaft();
  double sum_m3 = 0.0;
  for (const auto& piece : d.pieces.pieces) sum_m3 += signed_volume_m3(convex_hull(piece.points_m));
  const double exact_m3 = revolved_volume(kStepped, 32);
  EXPECT_NEAR(d.input_volume_m3, exact_m3, 1e-12 * exact_m3);
  // Hulls may overlap and bridge the step: within 5 % of the solid.
  EXPECT_NEAR(sum_m3, exact_m3, 0.05 * exact_m3);
  EXPECT_NEAR(d.hull_volume_sum_m3, sum_m3, 1e-9 * exact_m3);
  // The union (divergence theorem over its clipped boundary) within 5 % too.
  EXPECT_NEAR(d.union_volume_m3, exact_m3, 0.05 * exact_m3);
}

TEST(ApproxDecomposition, SteppedShaftDeviationIsMeasuredAndSmall) {
  const ApproxDecomposition& d = stepped_shaft();
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

// A 40 × 20 × 10 mm box with its lowest corner at `corner_m`; 12 triangles.
TriMesh box(const Vec3& corner_m) {
  TriMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back(corner_m + Vec3(i & 1 ? 0.040 : 0.0, i & 2 ? 0.020 : 0.0, i & 4 ? 0.010 : 0.0));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(ApproxDecomposition, ConvexBoxIsOneExactPiece) {
  const ApproxDecomposition d = approximate_decomposition(box(Vec3::Zero()));
  ASSERT_EQ(d.pieces.pieces.size(), 1u) << d.method;
  EXPECT_EQ(d.pieces.pieces[0].points_m.size(), 8u);
  EXPECT_LE(d.deviation_m, 1e-9);  // the hull is the box: only rounding is left
  // Volume 8e-6 m^3, to rounding (1e-12 relative).
  EXPECT_NEAR(d.union_volume_m3, 8e-6, 1e-12 * 8e-6);
  EXPECT_NEAR(d.hull_volume_sum_m3, 8e-6, 1e-12 * 8e-6);
}

TEST(ApproxDecomposition, ToothLayoutLabelsPiecesByTheSectorOfTheirCentroid) {
  // Box centred at polar angle 100°, 60 mm out: with 4 teeth (centre lines at 0°, 90°, 180°,
  // 270°) its sector is tooth 1's (45°..135°); tooth 0 turned to 100° makes it tooth 0.
  const double a = 100.0 * kPi / 180.0;
  const Vec3 corner = 0.060 * Vec3(std::cos(a), std::sin(a), 0.0) - Vec3(0.020, 0.010, 0.005);
  ApproxDecompositionOptions options;
  options.tooth_layout = ToothLayout{4, 0.0};
  const ApproxDecomposition d = approximate_decomposition(box(corner), options);
  ASSERT_EQ(d.pieces.pieces.size(), 1u);
  EXPECT_EQ(d.pieces.pieces[0].tooth, 1);
  options.tooth_layout = ToothLayout{4, a};
  EXPECT_EQ(approximate_decomposition(box(corner), options).pieces.pieces[0].tooth, 0);
}

TEST(ApproxDecomposition, LargeMeshIsDecimatedForHacdAndMeasuredAgainstTheOriginal) {
  const TriMesh fine = revolve(kStepped, 128);  // 1024 triangles
  ApproxDecompositionOptions options;
  options.max_hacd_triangles = 300;  // HACD takes ~1 s on 300 triangles of this shaft
  const ApproxDecomposition d = approximate_decomposition(fine, options);
  EXPECT_LE(d.hacd_triangles, 300u);
  EXPECT_GE(d.pieces.pieces.size(), 2u) << d.method;
  ASSERT_GE(d.warnings.size(), 2u);
  EXPECT_NE(d.warnings[1].find("decimated"), std::string::npos) << d.warnings[1];
  // Measured against the fine input: the coarser rings cut chords into the Ø20 and Ø10 mm
  // cylinders (~50 µm measured); bounded like the other shapes, 2 × (concavity + spacing).
  ASSERT_TRUE(std::isfinite(d.deviation_m));
  EXPECT_GT(d.deviation_m, 1e-9);
  EXPECT_LE(d.deviation_m, 2.0 * (options.max_concavity_m + d.sample_spacing_m));
  EXPECT_NEAR(d.input_volume_m3, revolved_volume(kStepped, 128), 1e-12 * d.input_volume_m3);
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

}  // namespace test_approx_decomposition
}  // namespace gearsim
