// Mass properties against closed forms: the regular N-gon prism and N-gon annulus (exact for the
// polyhedron), the true cylinder (within the known polygon error), the cube and the box, and how
// the tensor moves under rotation and translation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace test_mass_properties {

using gearsim::constants::kPi;
constexpr double kSteel_kg_m3 = 7850.0;

// Ring of n points of radius r at height z, first at angle 0, counter-clockwise from +z.
void add_ring(TriMesh& m, int n, double r, double z) {
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
}

// Regular n-gon prism inscribed in the cylinder of radius r, z in [0, h]; end caps are fans.
TriMesh prism(int n, double r, double h) {
  TriMesh m;
  add_ring(m, n, r, 0.0);
  add_ring(m, n, r, h);
  m.vertices.emplace_back(0, 0, 0);
  m.vertices.emplace_back(0, 0, h);
  const auto N = static_cast<std::uint32_t>(n);
  for (std::uint32_t i = 0; i < N; ++i) {
    const std::uint32_t j = (i + 1) % N;
    m.triangles.push_back({i, j, N + j});  // side, outward
    m.triangles.push_back({i, N + j, N + i});
    m.triangles.push_back({2 * N, j, i});  // bottom, seen from -z
    m.triangles.push_back({2 * N + 1, N + i, N + j});  // top
  }
  return m;
}

// Regular n-gon annulus (hollow prism) between radii r1 < r2, z in [0, h].
TriMesh annulus(int n, double r1, double r2, double h) {
  TriMesh m;
  add_ring(m, n, r2, 0.0);  // outer bottom: 0..n-1
  add_ring(m, n, r2, h);  // outer top:    n..2n-1
  add_ring(m, n, r1, 0.0);  // inner bottom: 2n..3n-1
  add_ring(m, n, r1, h);  // inner top:    3n..4n-1
  const auto N = static_cast<std::uint32_t>(n);
  for (std::uint32_t i = 0; i < N; ++i) {
    const std::uint32_t j = (i + 1) % N;
    const std::uint32_t ob = 0, ot = N, ib = 2 * N, it = 3 * N;
    m.triangles.push_back({ob + i, ob + j, ot + j});  // outer side, facing out
    m.triangles.push_back({ob + i, ot + j, ot + i});
    m.triangles.push_back({ib + i, it + j, ib + j});  // inner side, facing the axis
    m.triangles.push_back({ib + i, it + i, it + j});
    m.triangles.push_back({ot + i, ot + j, it + j});  // top, facing +z
    m.triangles.push_back({ot + i, it + j, it + i});
    m.triangles.push_back({ob + i, ib + j, ob + j});  // bottom, facing -z
    m.triangles.push_back({ob + i, ib + i, ib + j});
  }
  return m;
}

// Box [0,a]×[0,b]×[0,c], faces counter-clockwise from outside.
TriMesh box(double a, double b, double c) {
  TriMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(a * (i & 1), b * ((i >> 1) & 1), c * ((i >> 2) & 1));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

TriMesh transformed(TriMesh m, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (Eigen::Vector3d& p : m.vertices) p = R * p + t;
  return m;
}

// Exact for the polyhedron: only double rounding of O(N) sums separates mesh and closed form.
constexpr double kExactRel = 1e-12;

// Closed forms of the regular N-gon (circumradius r, θ = 2π/N): area N r² sin θ / 2 and
// ∫x² dA = ∫y² dA = A r² (2 + cos θ) / 12 (sum of N triangles from the centre).
double ngon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2.0 * kPi / n); }
double ngon_k(int n) { return (2.0 + std::cos(2.0 * kPi / n)) / 6.0; }  // → 1/2 as N → ∞

TEST(MassProperties, NgonPrismMatchesItsClosedFormExactly) {
  const int n = 64;
  const double r = 0.02, h = 0.01;
  const MassProperties p = mass_properties(prism(n, r, h), kSteel_kg_m3);
  const double volume = ngon_area(n, r) * h, mass = kSteel_kg_m3 * volume;
  EXPECT_NEAR(p.volume_m3, volume, kExactRel * volume);
  EXPECT_NEAR(p.mass_kg, mass, kExactRel * mass);
  EXPECT_NEAR(p.centre_of_mass_m.z(), h / 2, kExactRel * h);
  EXPECT_NEAR(p.centre_of_mass_m.head<2>().norm(), 0.0, kExactRel * r);
  const double izz = mass * r * r * ngon_k(n);
  const double ixx = mass * (r * r * ngon_k(n) / 2 + h * h / 12);
  EXPECT_NEAR(p.inertia_com_kg_m2(2, 2), izz, kExactRel * izz);
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 0), ixx, kExactRel * ixx);
  EXPECT_NEAR(p.inertia_com_kg_m2(1, 1), ixx, kExactRel * ixx);
  // Products of inertia vanish by the N-gon's symmetry.
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 1), 0.0, kExactRel * izz);
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 2), 0.0, kExactRel * izz);
  EXPECT_NEAR(p.inertia_com_kg_m2(1, 2), 0.0, kExactRel * izz);
}

TEST(MassProperties, NgonPrismApproachesTheCylinderWithinThePolygonError) {
  // Inscribed N-gon over circle: V ratio sin θ/θ ≥ 1 − θ²/6; I_zz ratio
  // (sin θ/θ)(2 + cos θ)/3 ≥ 1 − θ²/3, θ = 2π/N. Both bounds are the tolerances.
  const int n = 128;
  const double r = 0.02, h = 0.01, theta = 2.0 * kPi / n;
  const MassProperties p = mass_properties(prism(n, r, h), kSteel_kg_m3);
  const double volume = kPi * r * r * h, mass = kSteel_kg_m3 * volume;
  EXPECT_NEAR(p.volume_m3, volume, volume * theta * theta / 6);
  EXPECT_NEAR(p.inertia_com_kg_m2(2, 2), mass * r * r / 2, mass * r * r / 2 * theta * theta / 3);
  EXPECT_LT(p.volume_m3, volume);  // inscribed: always inside the circle
}

TEST(MassProperties, NgonAnnulusMatchesItsClosedFormExactly) {
  // I_zz = m (r1² + r2²)·k and I_xx = m ((r1² + r2²)·k/2 + h²/12), k = (2 + cos θ)/6: the
  // N-gon forms of m (r1² + r2²)/2 and m (3 (r1² + r2²) + h²)/12.
  const int n = 96;
  const double r1 = 0.015, r2 = 0.025, h = 0.012;
  const MassProperties p = mass_properties(annulus(n, r1, r2, h), kSteel_kg_m3);
  const double volume = (ngon_area(n, r2) - ngon_area(n, r1)) * h;
  const double mass = kSteel_kg_m3 * volume, s = r1 * r1 + r2 * r2;
  EXPECT_NEAR(p.volume_m3, volume, kExactRel * volume);
  EXPECT_NEAR(p.centre_of_mass_m.z(), h / 2, kExactRel * h);
  const double izz = mass * s * ngon_k(n), ixx = mass * (s * ngon_k(n) / 2 + h * h / 12);
  EXPECT_NEAR(p.inertia_com_kg_m2(2, 2), izz, kExactRel * izz);
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 0), ixx, kExactRel * ixx);
  EXPECT_NEAR(p.inertia_com_kg_m2(1, 1), ixx, kExactRel * ixx);
}

TEST(MassProperties, UnitCubeHasASixthOfItsMassOnTheDiagonal) {
  const MassProperties p = mass_properties(box(1, 1, 1), 1000.0);
  EXPECT_NEAR(p.mass_kg, 1000.0, kExactRel * 1000.0);
  EXPECT_TRUE(p.centre_of_mass_m.isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), kExactRel));
  const Eigen::Matrix3d expected = 1000.0 / 6.0 * Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(p.inertia_com_kg_m2(i, j), expected(i, j), kExactRel * 1000.0 / 6.0);
    }
  }
}

TEST(MassProperties, RotatedTranslatedBoxGivesTheRotatedTensor) {
  const double a = 0.01, b = 0.02, c = 0.05;
  const MassProperties p0 = mass_properties(box(a, b, c), kSteel_kg_m3);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const Eigen::Vector3d t(0.3, -0.2, 0.5);
  const MassProperties p = mass_properties(transformed(box(a, b, c), R, t), kSteel_kg_m3);
  const double m = p0.mass_kg;
  const Eigen::Matrix3d i_box = Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal() * (m / 12);
  const Eigen::Matrix3d expected = R * i_box * R.transpose();
  // Positions 0.5 m from the origin on a 0.05 m part: ~1e-15 m rounding, 1e-12 relative.
  EXPECT_TRUE(p.centre_of_mass_m.isApprox(R * Eigen::Vector3d(a, b, c) / 2 + t, kExactRel));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.inertia_com_kg_m2(i, j), expected(i, j), kExactRel * i_box.norm());
  }
}

TEST(MassProperties, MassAlongTheXyDiagonalHasNegativeProductOfInertia) {
  // A rod along x turned +45° about z lies where xy > 0, so I_xy = −∫xy dm < 0;
  // exactly (I_xx − I_yy)/2 of the unturned rod.
  const MassProperties rod = mass_properties(box(0.1, 0.01, 0.01), 1000.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(kPi / 4, Eigen::Vector3d::UnitZ()).matrix();
  const MassProperties p = mass_properties(transformed(box(0.1, 0.01, 0.01), R, {0, 0, 0}), 1000.0);
  const double expected = (rod.inertia_com_kg_m2(0, 0) - rod.inertia_com_kg_m2(1, 1)) / 2;
  EXPECT_LT(p.inertia_com_kg_m2(0, 1), 0.0);
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 1), expected, kExactRel * rod.inertia_com_kg_m2(1, 1));
  EXPECT_EQ(p.inertia_com_kg_m2(0, 1), p.inertia_com_kg_m2(1, 0));
}

TEST(MassProperties, PrincipalAxesOfARotatedBoxAreItsEdges) {
  const double a = 0.01, b = 0.02, c = 0.05;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const MassProperties p = mass_properties(transformed(box(a, b, c), R, {0.1, 0, 0}), 1000.0);
  const double m = p.mass_kg;
  // Ascending: the long edge c (smallest moment) first, then b, then a.
  const Eigen::Vector3d moments(m / 12 * (a * a + b * b), m / 12 * (a * a + c * c), m / 12 * (b * b + c * c));
  EXPECT_TRUE(p.principal_moments_kg_m2.isApprox(moments, 1e-10));
  EXPECT_NEAR(std::abs(p.principal_axes.col(0).dot(R.col(2))), 1.0, 1e-10);
  EXPECT_NEAR(std::abs(p.principal_axes.col(1).dot(R.col(1))), 1.0, 1e-10);
  EXPECT_NEAR(std::abs(p.principal_axes.col(2).dot(R.col(0))), 1.0, 1e-10);
  EXPECT_NEAR(p.principal_axes.determinant(), 1.0, 1e-12);  // a rotation
  const Eigen::Matrix3d rebuilt = p.principal_axes * p.principal_moments_kg_m2.asDiagonal() * p.principal_axes.transpose();
  EXPECT_TRUE(rebuilt.isApprox(p.inertia_com_kg_m2, 1e-10));
}

TEST(MassProperties, PartFarFromTheOriginKeepsItsPrecision) {
  // A 10 mm cube 1 km away: about the origin the second moment is 1e10 times the central one,
  // which would leave ~1e-6 relative; from a reference point near the centroid only the
  // coordinates' own rounding (1e-13 m on 1e-2 m) remains. 1e-9 relative sits between.
  const double s = 0.01;
  const MassProperties p = mass_properties(transformed(box(s, s, s), Eigen::Matrix3d::Identity(), {1000, -1000, 1000}), 1000.0);
  const double i = p.mass_kg * s * s / 6;
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 0), i, 1e-9 * i);
  EXPECT_NEAR(p.inertia_com_kg_m2(0, 1), 0.0, 1e-9 * i);
}

TEST(MassProperties, SignedVolumeOfAnInsideOutMeshIsNegative) {
  TriMesh m = box(1, 2, 3);
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  EXPECT_NEAR(signed_volume_m3(m), -6.0, 1e-14);  // a few roundings of O(1) terms
}

TEST(MassProperties, InsideOutMeshIsAnInternalError) {
  // Callers validate first (require_valid_solid); a negative volume here is a bug.
  TriMesh m = box(1, 1, 1);
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  EXPECT_THROW(mass_properties(m, 1000.0), InternalError);
}

}  // namespace test_mass_properties
}  // namespace gearsim
