// Helical gears: the transverse section of a gear given by its normal values (ISO 21771), the
// identities between normal and transverse base pitches, the overlap ratio, the twisted
// extrusion, and a helical gear's mesh: watertight, its section turned by b·tan β/r across the
// face, its volume the transverse section's area times the face width.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/gear_body.hpp"
#include "geometry/gear_mesh.hpp"
#include "geometry/helical.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_validate.hpp"

namespace gearsim {
namespace test_helical {

constexpr double kPi = std::numbers::pi, kDeg = kPi / 180;

// m_n 2 mm, α_n 20°, β 15°, z teeth, face 20 mm; + right hand.
GearSpec helical(int teeth, double beta_rad, GearKind kind = GearKind::External) {
  GearSpec s;
  s.name = "h" + std::to_string(teeth);
  s.kind = kind;
  s.teeth = teeth;
  s.face_width_m = 0.02;
  if (kind == GearKind::External)
    s.bore_diameter_m = 0.008;
  else
    s.rim_diameter_m = 2.5e-3 * teeth;
  NormalValues n;
  n.module_m = 0.002;
  n.pressure_angle_rad = 20 * kDeg;
  n.helix_angle_rad = beta_rad;
  n.addendum_coeff = 1.0;
  n.dedendum_coeff = 1.25;
  n.root_fillet_coeff = 0.38;
  set_transverse(s, n);
  return s;
}

TEST(Helical, TheTransverseSectionOfNormalValues) {
  const GearSpec s = helical(20, 15 * kDeg);
  EXPECT_NEAR(s.module_m, 0.002 / std::cos(15 * kDeg), 1e-18);
  EXPECT_NEAR(std::tan(s.pressure_angle_rad), std::tan(20 * kDeg) / std::cos(15 * kDeg), 1e-15);
  // Lengths kept: the addendum h_a*·m_n is the transverse section's too.
  EXPECT_NEAR(s.addendum_coeff * s.module_m, 0.002, 1e-18);
  EXPECT_NEAR(normal_module_m(s), 0.002, 1e-18);
  EXPECT_NEAR(normal_pressure_angle_rad(s), 20 * kDeg, 1e-15);
  // The base pitch in the normal plane is the transverse one foreshortened by the base helix:
  // p_bn = π·m_n·cos α_n = p_bt·cos β_b, with tan β_b = tan β·cos α_t.
  const double p_bt = kPi * s.module_m * std::cos(s.pressure_angle_rad);
  EXPECT_NEAR(p_bt * std::cos(base_helix_angle_rad(s)), kPi * 0.002 * std::cos(20 * kDeg), 1e-15);
  // And sin β_b = sin β·cos α_n (the same helix seen from the normal section).
  EXPECT_NEAR(std::sin(base_helix_angle_rad(s)), std::sin(15 * kDeg) * std::cos(20 * kDeg), 1e-15);
  // A left hand: the same section, the helix negative.
  const GearSpec left = helical(20, -15 * kDeg);
  EXPECT_DOUBLE_EQ(left.module_m, s.module_m);
  EXPECT_DOUBLE_EQ(base_helix_angle_rad(left), -base_helix_angle_rad(s));
  // A spur gear's normal values are its own.
  const GearSpec spur = helical(20, 0.0);
  EXPECT_EQ(spur.module_m, 0.002);
  EXPECT_EQ(normal_to_transverse_m(spur, 1e-5), 1e-5);
}

TEST(Helical, OverlapRatioAndTheMeshOfAPair) {
  const GearSpec a = helical(20, 15 * kDeg), b = helical(40, -15 * kDeg);
  // ε_β = b·sin β/(π·m_n) = 20·sin 15°/(2π).
  EXPECT_NEAR(overlap_ratio(a, b), 0.020 * std::sin(15 * kDeg) / (kPi * 0.002), 1e-15);
  const MeshGeometry m = analyse_mesh(a, b, zero_backlash_centre_distance(a, b));
  EXPECT_NEAR(m.centre_distance_m, 0.5 * a.module_m * 60, 1e-15);  // m_t·(z_1 + z_2)/2
  EXPECT_NEAR(m.overlap_ratio, overlap_ratio(a, b), 1e-15);
  // Two external gears of one hand, or different helix angles, cannot mesh; a ring meshes with a
  // pinion of its own hand.
  EXPECT_THROW(analyse_mesh(a, helical(40, 15 * kDeg), 0.062), InputError);
  EXPECT_THROW(analyse_mesh(a, helical(40, -20 * kDeg), 0.062), InputError);
  const GearSpec ring = helical(80, 15 * kDeg, GearKind::Internal);
  EXPECT_NO_THROW(analyse_mesh(a, ring, zero_backlash_centre_distance(a, ring)));
}

TEST(Helical, ATwistedExtrusionTurnsItsTopByTheTwistAndStaysASolid) {
  Outline2 square;
  square.outer.points = {{-0.01, -0.01}, {0.01, -0.01}, {0.01, 0.01}, {-0.01, 0.01}};
  const double twist = 2.0, length = 0.1;  // 0.2 rad over the length
  const TriMesh t = extrude_twisted(square, 0.0, length, twist, 0.01);
  const MeshReport r = validate_mesh(t);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.outward_oriented());
  // 20 layers; the bottom turned by −0.1 rad and the top by +0.1 about the middle.
  ASSERT_EQ(t.vertices.size(), 21u * 4u);
  const auto angle = [](const Eigen::Vector3d& v) { return std::atan2(v.y(), v.x()); };
  EXPECT_NEAR(angle(t.vertices[80]) - angle(t.vertices[0]), twist * length, 1e-12);
  EXPECT_NEAR(angle(t.vertices[0]), std::atan2(-0.01, -0.01) - 0.1, 1e-12);
  // Its volume tends to the section's area times the length as the layers get finer (a twisted
  // quad split in two triangles cuts a sliver off the ruled surface).
  const double exact = 4e-4 * length;
  const double coarse = std::abs(signed_volume_m3(extrude_twisted(square, 0.0, length, twist, 0.05)) - exact);
  const double fine = std::abs(signed_volume_m3(t) - exact);
  EXPECT_LT(fine, 1e-4 * exact);
  EXPECT_LT(fine, coarse);
  // No twist: extrude()'s mesh.
  EXPECT_EQ(extrude_twisted(square, 0.0, length, 0.0, 0.01).triangles.size(), extrude(square, 0.0, length).triangles.size());
}

TEST(Helical, AHelicalGearsMeshIsItsSectionTwistedAcrossTheFace) {
  const GearSpec s = helical(20, 15 * kDeg);
  const GearBody b = make_gear_body(s, 7850);
  const MeshReport r = validate_mesh(b.mesh);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.outward_oriented());
  // The volume of the straight prism of the same section (a twist moves no material off the
  // axis), within what the layers' straight edges cut off.
  const double prism = area(b.outline.outline) * s.face_width_m;
  EXPECT_NEAR(b.mass.volume_m3, prism, 1e-4 * prism);
  // The top face's outline is the bottom's turned by b·tan β/r: the outline's first point at
  // both ends (the vertices of the first and last layer).
  const std::size_t n = b.outline.outline.outer.points.size();
  std::size_t per_layer = n;
  for (const Polygon2& h : b.outline.outline.holes) per_layer += h.points.size();
  const Eigen::Vector3d &bottom = b.mesh.vertices.front(), &top = b.mesh.vertices[b.mesh.vertices.size() - per_layer];
  const double turn = std::remainder(std::atan2(top.y(), top.x()) - std::atan2(bottom.y(), bottom.x()), 2 * kPi);
  EXPECT_NEAR(turn, s.face_width_m * std::tan(15 * kDeg) / (0.5 * s.module_m * s.teeth), 1e-12);
  EXPECT_GT(turn, 0);  // right hand: counter-clockwise seen from +z as z grows
}

}  // namespace test_helical
}  // namespace gearsim
